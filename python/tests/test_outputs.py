"""A frame's outputs besides its colours: alpha (RGBA), depth, object and triangle ids, normals, the
same bytes on both backends in every shading mode and sample count, and depth and normals against
an analytic ray cast of a sphere."""

import math
import os

import numpy as np
import pytest

import phongvk
from conftest import scene_path

ALL = ["color", "rgba", "alpha", "depth", "object_id", "triangle_id", "normal"]


@pytest.mark.parametrize("name", ["scenes/basic.json", "scenes/paper/fig1_cube.json", "scenes/mesh_torus.json",
                                  "scenes/orthographic.json"])
@pytest.mark.parametrize("shading", ["gouraud", "flat", "phong"])
@pytest.mark.parametrize("samples", [1, 4])
def test_every_output_is_the_same_bytes_on_both_backends(name, shading, samples):
    scene = phongvk.load_scene(scene_path(name)).with_render(shading=shading, samples=samples)
    cpu = phongvk.Renderer("cpu").render(scene, 160, 120, outputs=ALL)
    gpu = phongvk.Renderer("gpu").render(scene, 160, 120, outputs=ALL)
    for key in ALL:
        assert cpu[key].dtype == gpu[key].dtype and np.array_equal(cpu[key], gpu[key]), key
    assert np.array_equal(cpu["color"], phongvk.Renderer("cpu").render(scene, 160, 120))
    assert np.array_equal(cpu["rgba"][..., :3], cpu["color"]) and np.array_equal(cpu["rgba"][..., 3], cpu["alpha"])
    covered = cpu["triangle_id"] >= 0
    assert covered.any()
    assert np.array_equal(covered, cpu["object_id"] >= 0) and np.array_equal(covered, np.isfinite(cpu["depth"]))
    assert (cpu["alpha"][~covered] == 0).all()
    assert cpu["normal"].shape == (120, 160, 3) and cpu["normal"].dtype == np.float32
    assert (cpu["normal"][~covered] == 0).all()
    assert np.allclose(np.linalg.norm(cpu["normal"][covered], axis=1), 1, atol=1e-6)
    if samples == 1:
        assert np.array_equal(cpu["alpha"], np.where(covered, 255, 0).astype(np.uint8))


def test_alpha_with_samples_is_the_covered_share():
    scene = phongvk.scene_from_dict({
        "camera": {"position": [0, -6, 0], "look_at": [0, 0, 0], "width": 64, "height": 48},
        "objects": [{"shape": "sphere", "radius": 1}], "render": {"samples": 16}})
    alpha = phongvk.Renderer("gpu").render(scene, outputs=["alpha"])["alpha"]
    assert alpha.max() == 255 and alpha.min() == 0
    partial = alpha[(alpha > 0) & (alpha < 255)]
    assert len(partial) > 20  # the silhouette's pixels
    assert set(np.unique(partial)) <= {(255 * k + 8) // 16 for k in range(1, 16)}


def test_object_ids_name_the_objects_in_order():
    scene = phongvk.scene_from_dict({
        "camera": {"position": [0, -6, 0], "look_at": [0, 0, 0], "width": 120, "height": 80},
        "lights": [{"position": [0, -5, 3]}],
        "objects": [{"shape": "cube", "center": [-1.2, 0, 0]}, {"shape": "sphere", "center": [1.2, 0, 0]}]})
    out = phongvk.Renderer("gpu").render(scene, outputs=["object_id", "triangle_id"])
    ids = out["object_id"]
    assert ids.dtype == np.int32 and set(np.unique(ids)) == {-1, 0, 1}
    assert (ids[:, :60] != 1).all() and (ids[:, 60:] != 0).all()  # the cube left, the sphere right
    assert out["triangle_id"][ids == 0].max() < out["triangle_id"][ids == 1].min()  # objects' triangles in order


def test_depth_is_the_distance_along_the_camera_axis_to_the_sphere():
    """Every pixel's depth against the analytic ray cast of the sphere the icosphere approximates:
    within the tessellation's sagitta (subdivide 5: under 0.2% of the radius)."""
    distance, radius, width, height, fov = 4.0, 1.0, 96, 96, 40.0
    scene = phongvk.scene_from_dict({
        "camera": {"position": [0, -distance, 0], "look_at": [0, 0, 0], "fov": fov, "width": width, "height": height},
        "objects": [{"shape": "icosphere", "radius": radius, "subdivide": 5}]})
    depth = phongvk.Renderer("gpu").render(scene, outputs=["depth"])["depth"]
    assert depth.dtype == np.float32
    focal = height / (2 * math.tan(math.radians(fov) / 2))
    ys, xs = np.mgrid[0:height, 0:width]
    # The ray through each pixel centre in camera coordinates (x right, y down, z forward), z = 1:
    # |t (rx, ry, 1) - (0, 0, distance)| = radius, whose near root t is the depth along the axis.
    rx, ry = (xs + 0.5 - width / 2) / focal, (ys + 0.5 - height / 2) / focal
    a, b, c = rx ** 2 + ry ** 2 + 1, -2 * distance, distance ** 2 - radius ** 2
    disc = b * b - 4 * a * c
    t = (-b - np.sqrt(np.maximum(disc, 0))) / (2 * a)
    inner, outer = disc > 0.05 * b * b, disc < -0.05 * b * b  # away from the silhouette
    assert inner.sum() > 500 and np.isfinite(depth[inner]).all()
    assert np.abs(depth[inner] - t[inner]).max() < 0.002 * radius
    assert np.isinf(depth[outer]).all()


def test_visibility_with_samples_is_the_nearest_samples():
    scene = phongvk.load_scene(scene_path("scenes/basic.json")).with_render(samples=4)
    image, triangle, depth = phongvk.Renderer("gpu").render_visibility(scene, 96, 64)
    assert image.shape == (64, 96, 3) and triangle.shape == (64, 96) and depth.shape == (64, 96)
    cpu = phongvk.Renderer("cpu").render_visibility(scene, 96, 64)
    assert np.array_equal(triangle, cpu[1]) and np.array_equal(depth, cpu[2])
    assert (triangle == phongvk.NO_TRIANGLE).any() and (triangle != phongvk.NO_TRIANGLE).any()


def test_bad_outputs_are_clear_errors():
    scene = phongvk.load_scene(scene_path("scenes/basic.json"))
    with pytest.raises(ValueError, match=r"outputs: unknown output 'normals' \(color, rgba, alpha, depth"):
        phongvk.Renderer("cpu").render(scene, 32, 24, outputs=["normals"])
    with pytest.raises(ValueError, match=r"the graphics backend has no visibility keys"):
        phongvk.Renderer("graphics").render(scene, 32, 24, outputs=["depth"])
    color = phongvk.Renderer("graphics").render(scene, 32, 24, outputs="color")["color"]
    assert color.shape == (24, 32, 3) and isinstance(color, phongvk.Image)


def test_rgba_and_16_bit_depth_pngs_read_back_by_pil(tmp_path):
    from PIL import Image as PilImage  # zlib's inflate and PIL's PNG reader, decoders of their own

    scene = phongvk.load_scene(scene_path("scenes/basic.json"))
    frame = phongvk.Renderer("cpu").render(scene, 96, 64, outputs=["rgba", "depth"])
    depth_mm = np.where(np.isfinite(frame["depth"]), np.round(frame["depth"] * 1000), 0).astype(np.uint16)
    for level in (0, 1, 6, 12):
        phongvk.write_png(str(tmp_path / "rgba.png"), frame["rgba"], level)
        phongvk.write_png(str(tmp_path / "depth.png"), depth_mm, level)
        with PilImage.open(tmp_path / "rgba.png") as rgba, PilImage.open(tmp_path / "depth.png") as depth:
            assert rgba.mode == "RGBA" and np.array_equal(np.asarray(rgba), frame["rgba"])
            assert depth.mode.startswith("I") and np.array_equal(np.asarray(depth), depth_mm)
        assert phongvk.encode_png(frame["rgba"], level) == (tmp_path / "rgba.png").read_bytes()
        assert phongvk.encode_png(depth_mm, level) == (tmp_path / "depth.png").read_bytes()
    assert 0 < (depth_mm == 0).sum() < depth_mm.size and depth_mm.max() > 255  # empty pixels, and a high byte
    assert np.array_equal(phongvk.read_png(str(tmp_path / "rgba.png")), frame["rgba"][..., :3])
    rgba, depth = phongvk.read_png(str(tmp_path / "rgba.png"), "rgba"), phongvk.read_png(str(tmp_path / "depth.png"), "grey16")
    assert rgba.dtype == np.uint8 and np.array_equal(rgba, frame["rgba"])
    assert depth.dtype == np.uint16 and np.array_equal(depth, depth_mm)
    phongvk.write_png(str(tmp_path / "rgb.png"), frame["rgba"][..., :3].copy())
    opaque = phongvk.read_png(str(tmp_path / "rgb.png"), "rgba")  # a file without alpha reads as opaque
    assert np.array_equal(opaque[..., :3], frame["rgba"][..., :3]) and (opaque[..., 3] == 255).all()
    with pytest.raises(ValueError, match=r"mode: expected 'rgb', 'rgba' or 'grey16', got 'rgb16'"):
        phongvk.read_png(str(tmp_path / "rgba.png"), "rgb16")


@pytest.mark.parametrize("array", [np.zeros((4, 5, 2), np.uint8), np.zeros((4, 5, 3), bool),
                                   np.zeros((4, 5, 4), np.uint16), np.zeros((4, 5), np.float32)])
def test_write_png_names_the_arrays_it_takes(tmp_path, array):
    message = (r"image: expected a uint8 array of shape \(height, width, 3\) or \(height, width, 4\), "
               r"or a uint8, uint16 or bool array of shape \(height, width\), got " + str(array.dtype))
    with pytest.raises(ValueError, match=message):
        phongvk.write_png(str(tmp_path / "x.png"), array)
    with pytest.raises(ValueError, match=message):
        phongvk.encode_png(array)
    assert not (tmp_path / "x.png").exists()
    with pytest.raises(ValueError, match=r"image: expected a non-empty array, got shape \(0, 5\)"):
        phongvk.encode_png(np.zeros((0, 5), np.uint16))


def test_normals_are_the_sphere_normals_in_camera_axes():
    """The normals of a Phong-shaded icosphere (subdivide 5) against the analytic sphere's where
    each pixel centre's ray meets it, in camera axes x right, y up, z forward: within 0.1 degrees
    (0.044 measured) where the ray passes within 95% of the radius from the centre."""
    distance, width, height, fov = 4.0, 96, 96, 40.0
    scene = phongvk.scene_from_dict({
        "camera": {"position": [0, -distance, 0], "look_at": [0, 0, 0], "fov": fov, "width": width, "height": height},
        "objects": [{"shape": "icosphere", "radius": 1, "subdivide": 5}], "render": {"shading": "phong"}})
    normal = phongvk.Renderer("gpu").render(scene, outputs=["normal"])["normal"]
    assert normal.shape == (height, width, 3) and normal.dtype == np.float32
    focal = height / (2 * math.tan(math.radians(fov) / 2))
    ys, xs = np.mgrid[0:height, 0:width]
    ray = np.stack([(xs + 0.5 - width / 2) / focal, -(ys + 0.5 - height / 2) / focal, np.ones(xs.shape)], axis=-1)
    a = (ray ** 2).sum(axis=-1)
    inner = distance ** 2 * (1 - 1 / a) < 0.95 ** 2  # the ray's distance from the centre, squared
    discriminant = np.maximum(4 * distance ** 2 - 4 * a * (distance ** 2 - 1), 0)  # < 0: rays that miss
    t = (2 * distance - np.sqrt(discriminant)) / (2 * a)
    expected = t[..., None] * ray - np.array([0, 0, distance])
    cosine = (expected[inner] * normal[inner]).sum(axis=-1)
    assert inner.sum() > 3000
    assert np.degrees(np.arccos(np.minimum(cosine, 1))).max() < 0.1
    assert normal[height // 2, width // 2, 2] < -0.99  # facing the camera: z toward it is negative


def test_orthographic_depth_and_normals_are_the_spheres():
    """Through an orthographic camera every pixel's ray runs along the axis from its own point of
    the eye's plane (x, y = pixel offset / pixels per metre): the depth is distance - sqrt(r^2 -
    x^2 - y^2) and the normal (x, y, depth - distance) / r, within the same bounds as for a
    perspective camera, on both backends alike."""
    distance, width, height, ortho_height = 4.0, 96, 96, 2.4
    scene = phongvk.scene_from_dict({
        "camera": {"projection": "orthographic", "ortho_height": ortho_height, "position": [0, -distance, 0],
                   "look_at": [0, 0, 0], "width": width, "height": height},
        "objects": [{"shape": "icosphere", "radius": 1, "subdivide": 5}], "render": {"shading": "phong"}})
    out = phongvk.Renderer("gpu").render(scene, outputs=["depth", "normal"])
    cpu = phongvk.Renderer("cpu").render(scene, outputs=["depth", "normal"])
    assert all(np.array_equal(out[k], cpu[k]) for k in ("depth", "normal"))
    scale = height / ortho_height
    ys, xs = np.mgrid[0:height, 0:width]
    x, y = (xs + 0.5 - width / 2) / scale, -(ys + 0.5 - height / 2) / scale
    rr = x ** 2 + y ** 2
    inner, outer = rr < 0.95 ** 2, rr > 1.05 ** 2
    t = distance - np.sqrt(np.maximum(1 - rr, 0))
    assert inner.sum() > 3000 and np.isinf(out["depth"][outer]).all()
    assert np.abs(out["depth"][inner] - t[inner]).max() < 0.002
    expected = np.stack([x, y, t - distance], axis=-1)
    cosine = (expected[inner] * out["normal"][inner]).sum(axis=-1)
    assert np.degrees(np.arccos(np.minimum(cosine, 1))).max() < 0.1


def test_the_renderer_names_its_key_path():
    # CTest's keys32_python_test_outputs runs this file with PHONGVK_KEY_PATH=32.
    name = phongvk.Renderer("gpu").device_name
    forced = os.environ.get("PHONGVK_KEY_PATH")
    assert ("keys: %s-bit atomics" % forced if forced else "keys: ") in name, name
