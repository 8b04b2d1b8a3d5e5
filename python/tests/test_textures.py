"""Base-colour textures against an independent sampling in numpy: a square facing an orthographic
camera, lit by the ambient term alone (so a pixel is its texel), its texture coordinates running
across the image; every pixel compared with numpy's nearest and bilinear lookups (float64, repeat
wrap), on both backends, which give the same bytes."""

import json
import pathlib

import numpy as np
import pytest

import phongvk
from conftest import scene_path

N = 96  # image side, pixels
K = 16  # texture side, texels: each texel spans 6 pixels


def textured_square(folder: pathlib.Path, texture: np.ndarray, repeat: float) -> phongvk.Scene:
    """A square x, z in [-1, 1] at y = 0 facing -y, u = repeat (x + 1) / 2 across and OBJ's v up the
    square, seen by an orthographic camera whose image it fills exactly."""
    phongvk.write_png(str(folder / "tex.png"), texture)
    (folder / "square.mtl").write_text("newmtl t\nKd 1 1 1\nmap_Kd tex.png\n")
    r = repeat
    (folder / "square.obj").write_text(
        "mtllib square.mtl\nusemtl t\n"
        "v -1 0 -1\nv 1 0 -1\nv 1 0 1\nv -1 0 1\n"
        f"vt 0 0\nvt {r} 0\nvt {r} {r}\nvt 0 {r}\n"
        "f 1/1 2/2 3/3 4/4\n")
    return phongvk.scene_from_dict({
        "camera": {"projection": "orthographic", "position": [0, -5, 0], "look_at": [0, 0, 0],
                   "ortho_height": 2, "width": N, "height": N},
        "ambient": [1, 1, 1],
        "materials": {"m": {"ka": 1, "kd": 0, "ks": 0, "color": [1, 1, 1]}},
        "objects": [{"shape": "mesh", "file": "square.obj", "material": "m"}],
    }, base_dir=str(folder))


def taps(c: np.ndarray, filtering: str):
    """Texel coordinates c (one axis) as the two taps' indices, wrapped, and the second's weight."""
    p = c - (0.5 if filtering == "bilinear" else 0.0)
    i0 = np.floor(p).astype(int)
    f = p - i0 if filtering == "bilinear" else np.zeros_like(p)
    return i0 % K, (i0 + 1) % K, f


def expected(texture: np.ndarray, repeat: float, filtering: str) -> np.ndarray:
    """Each pixel centre's texel in numpy: u = repeat * (x + 0.5) / N across; OBJ's v runs up the
    square from 0 to repeat, so phongvk's (1 - v) runs from 1 - repeat at the top to 1."""
    t = texture.astype(np.float64)
    s = (np.arange(N) + 0.5) / N * repeat
    x0, x1, fx = taps(s * K, filtering)
    y0, y1, fy = taps((1 - repeat + s) * K, filtering)
    fy, fx = fy[:, None, None], fx[None, :, None]
    return ((1 - fy) * ((1 - fx) * t[y0[:, None], x0[None, :]] + fx * t[y0[:, None], x1[None, :]]) +
            fy * ((1 - fx) * t[y1[:, None], x0[None, :]] + fx * t[y1[:, None], x1[None, :]]))


@pytest.mark.parametrize("filtering", ["nearest", "bilinear"])
@pytest.mark.parametrize("repeat", [1.0, 2.5])
def test_a_textured_square_shows_numpys_lookups(tmp_path, filtering, repeat):
    texture = np.random.default_rng(7).integers(0, 256, (K, K, 3), dtype=np.uint8)
    scene = textured_square(tmp_path, texture, repeat).with_render(texture_filter=filtering)
    gpu = phongvk.Renderer("gpu").render(scene)
    cpu = phongvk.Renderer("cpu").render(scene)
    assert np.array_equal(gpu, cpu)
    want = expected(texture, repeat, filtering)
    error = np.abs(gpu.astype(np.float64) - want)
    # Nearest: the texel itself. Bilinear: the position floored to 1/256 of a texel (at most 255/256 of
    # a level between neighbours 255 apart), after the float interpolation of uv (a few ulps more),
    # and the blend rounded (half a level): within 2 levels.
    assert error.max() <= (0 if filtering == "nearest" else 2.0), error.max()
    assert error.mean() < 0.5, error.mean()


def test_the_texture_filter_is_a_render_setting():
    settings = phongvk.RenderSettings(texture_filter="nearest")
    assert settings.texture_filter == "nearest"
    with pytest.raises(phongvk.SceneError, match="render.texture_filter: must be one of nearest, bilinear"):
        phongvk.RenderSettings(texture_filter="trilinear")
    scene = phongvk.load_scene(scene_path("scenes/textured.json"))
    assert scene.render_settings.texture_filter == "bilinear"
    nearest = scene.with_render(texture_filter="nearest")
    assert nearest.render_settings.texture_filter == "nearest"
    assert '"texture_filter": "nearest"' in nearest.to_json()
    renderer = phongvk.Renderer("gpu")
    assert not np.array_equal(renderer.render(scene, 160, 120), renderer.render(nearest, 160, 120))


def test_a_gltf_with_maps_it_does_not_render_says_so(tmp_path):
    model = "/usr/share/assimp/models/glTF2/ClearCoat-glTF/ClearCoatTest.gltf"
    with pytest.warns(phongvk.NoticeWarning, match="normal.* maps are not rendered"):
        phongvk.Renderer("cpu").render(phongvk.load_scene(model), 64, 48)


def test_textures_are_counted_in_the_stats():
    renderer = phongvk.Renderer("gpu")
    renderer.render(phongvk.load_scene(scene_path("scenes/textured.json")), 64, 48)
    stats = renderer.stats
    # checker.png (64 x 64 texels, 4 bytes each), a 16-byte coordinate per vertex and the table entry.
    assert stats["texture_bytes"] >= 64 * 64 * 4 + 16
    assert stats["device_bytes"] > stats["texture_bytes"]
    renderer.render(phongvk.load_scene(scene_path("scenes/basic.json")), 64, 48)
    assert renderer.stats["texture_bytes"] == 0
    assert phongvk.Renderer("cpu").stats["device_bytes"] == 0


def square_arrays(repeat=1.0):
    """The square of textured_square as arrays: x, z in [-1, 1] at y = 0, facing -y, and its uvs
    in phongvk's convention (v down the image)."""
    vertices = np.array([[-1, 0, -1], [1, 0, -1], [1, 0, 1], [-1, 0, 1]], dtype=np.float64)
    faces = np.array([[0, 1, 2], [0, 2, 3]])
    uvs = np.array([[0, 1], [repeat, 1], [repeat, 1 - repeat], [0, 1 - repeat]], dtype=np.float64)
    return vertices, faces, uvs


def camera_on_square():
    return phongvk.Camera(position=[0, -5, 0], look_at=[0, 0, 0], ortho_height=2, width=N, height=N)


@pytest.mark.parametrize("filtering", ["nearest", "bilinear"])
def test_a_material_takes_a_texture_array_and_a_mesh_uvs(filtering):
    texture = np.random.default_rng(11).integers(0, 256, (K, K, 3), dtype=np.uint8)
    scene = phongvk.Scene(N, N)
    scene.camera = camera_on_square()
    scene.ambient = [1, 1, 1]
    vertices, faces, uvs = square_arrays(2.5)
    scene.add_mesh(vertices, faces, uvs=uvs, material=phongvk.Material(ka=1, kd=0, ks=0, color=[1, 1, 1], texture=texture))
    scene = scene.with_render(texture_filter=filtering)
    gpu = phongvk.Renderer("gpu").render(scene)
    assert np.array_equal(gpu, phongvk.Renderer("cpu").render(scene))
    error = np.abs(gpu.astype(np.float64) - expected(texture, 2.5, filtering))
    assert error.max() <= (0 if filtering == "nearest" else 2.0), error.max()
    # Written back, the texture travels as a data URI of its PNG, and renders the same bytes.
    text = scene.to_json()
    assert '"texture": "data:image/png;base64,' in text
    again = phongvk.scene_from_dict(json.loads(text))
    assert np.array_equal(phongvk.Renderer("gpu").render(again), gpu)


def test_a_texture_file_on_a_material_and_its_errors(tmp_path):
    texture = np.zeros((4, 4, 4), dtype=np.uint8)
    texture[..., 0] = 200
    texture[..., 3] = 255
    phongvk.write_png(str(tmp_path / "red.png"), texture)
    material = phongvk.Material(ka=1, kd=0, ks=0, color=[1, 1, 1], texture=tmp_path / "red.png")
    assert material.texture == str(tmp_path / "red.png") and "texture='" in repr(material)
    scene = phongvk.Scene(N, N)
    scene.camera = camera_on_square()
    scene.ambient = [1, 1, 1]
    vertices, faces, uvs = square_arrays()
    scene.add_mesh(vertices, faces, uvs=uvs, material=material)
    image = phongvk.Renderer("gpu").render(scene)
    assert (image[N // 2, N // 2] == [200, 0, 0]).all()
    with pytest.raises(ValueError, match=r"uvs: expected shape \(N, 2\)"):
        scene.add_mesh(vertices, faces, uvs=np.zeros((4, 3)))
    with pytest.raises(ValueError, match="uvs: row 1 is not finite"):
        scene.add_mesh(vertices, faces, uvs=[[0, 0], [np.nan, 0], [0, 0], [0, 0]])
    with pytest.raises(phongvk.SceneError, match=r"objects\[1\].material.texture: '.*missing.png': cannot open"):
        scene.add_mesh(vertices, faces, uvs=uvs, material=phongvk.Material(texture=str(tmp_path / "missing.png")))
    bare = phongvk.Scene(N, N)
    bare.add_mesh(vertices, faces, material=material)  # no uvs
    with pytest.raises(phongvk.SceneError, match=r"objects\[0\].material.texture: the object's mesh has no texture coordinates"):
        phongvk.Renderer("cpu").render(bare)


def test_box_textured_shows_its_logo_where_a_numpy_ray_cast_of_its_uvs_says(tmp_path):
    """The Khronos BoxTextured (Debian's assimp-testmodels, the glTF with its buffer and PNG in data
    URIs), lit by the ambient term alone so a pixel is its texel (nearest): at every 3rd pixel a ray
    cast in numpy against the file's own triangles, uvs and image gives the texel to expect."""
    import base64
    path = "/usr/share/assimp/models/glTF2/BoxTextured-glTF-Embedded/BoxTextured.gltf"
    gltf = json.loads(pathlib.Path(path).read_text())
    data = lambda uri: base64.b64decode(uri.split(",", 1)[1])
    buffer = data(gltf["buffers"][0]["uri"])

    def accessor(i, dtype, width):
        a = gltf["accessors"][i]
        view = gltf["bufferViews"][a["bufferView"]]
        start = view.get("byteOffset", 0) + a.get("byteOffset", 0)
        stride = view.get("byteStride", np.dtype(dtype).itemsize * width)
        rows = [np.frombuffer(buffer, dtype, width, start + k * stride) for k in range(a["count"])]
        return np.array(rows, dtype=np.float64)

    primitive = gltf["meshes"][0]["primitives"][0]
    faces = accessor(primitive["indices"], np.uint16, 1).astype(int).reshape(-1, 3)
    local = accessor(primitive["attributes"]["POSITION"], np.float32, 3)
    uvs = accessor(primitive["attributes"]["TEXCOORD_0"], np.float32, 2)
    node = np.array(gltf["nodes"][0]["matrix"]).reshape(4, 4).T  # column-major in the file
    world = local @ node[:3, :3].T + node[:3, 3]
    (tmp_path / "logo.png").write_bytes(data(gltf["images"][0]["uri"]))
    logo = phongvk.read_png(str(tmp_path / "logo.png"))
    th, tw = logo.shape[:2]

    eye, centre, fov, w, h = np.array([1.3, -1.7, 1.1]), np.zeros(3), 50.0, 240, 180
    scene = phongvk.scene_from_dict({
        "camera": {"position": eye.tolist(), "look_at": centre.tolist(), "fov": fov, "width": w, "height": h},
        "ambient": [1, 1, 1], "lights": [],
        "materials": {"m": {"ka": 1, "kd": 0, "ks": 0, "color": [1, 1, 1]}},
        "objects": [{"shape": "mesh", "file": path, "material": "m"}],
        "render": {"texture_filter": "nearest"}})
    image = phongvk.Renderer("gpu").render(scene)
    assert np.array_equal(image, phongvk.Renderer("cpu").render(scene))

    forward = (centre - eye) / np.linalg.norm(centre - eye)
    right = np.cross(forward, [0, 0, 1])
    right /= np.linalg.norm(right)
    up = np.cross(right, forward)
    focal = h / (2 * np.tan(np.radians(fov) / 2))
    checked = matched = 0
    for y in range(1, h, 3):
        for x in range(1, w, 3):
            d = forward + (x + 0.5 - w / 2) / focal * right - (y + 0.5 - h / 2) / focal * up
            best = None
            for f in faces:  # Möller–Trumbore: the nearest hit, its barycentrics
                p0, p1, p2 = world[f]
                e1, e2 = p1 - p0, p2 - p0
                q = np.cross(d, e2)
                det = e1 @ q
                if abs(det) < 1e-12:
                    continue
                s = eye - p0
                b1 = (s @ q) / det
                r = np.cross(s, e1)
                b2 = (d @ r) / det
                t = (e2 @ r) / det
                if b1 >= 0 and b2 >= 0 and b1 + b2 <= 1 and t > 0 and (best is None or t < best[0]):
                    best = (t, f, b1, b2)
            if best is None:
                continue
            t, f, b1, b2 = best
            if min(b1, b2, 1 - b1 - b2) < 0.02:
                continue  # near an edge: the raster's snapping may pick the neighbour
            u, v = uvs[f[0]] + b1 * (uvs[f[1]] - uvs[f[0]]) + b2 * (uvs[f[2]] - uvs[f[0]])
            tx, ty = (u % 1.0) * tw, (v % 1.0) * th
            if min(tx % 1, 1 - tx % 1, ty % 1, 1 - ty % 1) < 0.1:
                continue  # near a texel boundary: float rounding may take either texel
            checked += 1
            matched += np.array_equal(image[y, x], logo[int(ty) % th, int(tx) % tw])
    assert checked > 300, checked
    assert matched >= 0.98 * checked, (matched, checked)


def test_a_texture_of_the_largest_size_samples_to_its_last_texel(tmp_path):
    """16384 x 16384 texels (1 GiB decoded): the square shows its last 32 x 32 texels, nearest, so
    the bottom-right pixel samples the very last texel (index 2^28 - 1 in the pool)."""
    side = 16384
    texture = np.full((side, side, 3), (30, 0, 0), np.uint8)
    texture[-1, -1] = (0, 255, 0)
    phongvk.write_png(str(tmp_path / "big.png"), texture, level=1)
    del texture
    scene = phongvk.Scene(32, 32)
    scene.camera = phongvk.Camera(position=[0, -5, 0], look_at=[0, 0, 0], ortho_height=2, width=32, height=32)
    scene.ambient = [1, 1, 1]
    vertices, faces, _ = square_arrays()
    low = 1 - 32 / side  # u and v from here to 1 across the square: one texel a pixel
    uvs = np.array([[low, 1], [1, 1], [1, low], [low, low]])
    material = phongvk.Material(ka=1, kd=0, ks=0, color=[1, 1, 1], texture=str(tmp_path / "big.png"))
    scene.add_mesh(vertices, faces, uvs=uvs, material=material)
    scene = scene.with_render(texture_filter="nearest")
    gpu = phongvk.Renderer("gpu")
    image = gpu.render(scene)
    assert np.array_equal(image, phongvk.Renderer("cpu").render(scene))
    assert (image[-1, -1] == [0, 255, 0]).all() and (image[-2, -2] == [30, 0, 0]).all() and (image[0, 0] == [30, 0, 0]).all()
    assert gpu.stats["texture_bytes"] >= side * side * 4
