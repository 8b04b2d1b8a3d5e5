"""The Python API: scenes from files and dicts, meshes from numpy arrays, the visibility buffer,
diff, PNG files, devices, and the documented errors with their words."""

import json
import math

import numpy as np
import pytest

import phongvk
from conftest import scene_path

CAMERA = {"position": [3, -2, 1.5], "look_at": [0, 0, 0], "width": 96, "height": 64}


def octahedron():
    """An octahedron as float32 vertices and int faces, counter-clockwise seen from outside."""
    v = np.array([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]], dtype=np.float32) * 0.7
    f = np.array([[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4], [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]])
    return v + np.float32(0.1), f


def test_load_scene_and_render():
    scene = phongvk.load_scene(scene_path("scenes/basic.json"))
    assert (scene.width, scene.height) == (1385, 923)
    image = phongvk.Renderer("cpu").render(scene, width=120, height=80)
    assert image.shape == (80, 120, 3) and image.dtype == np.uint8
    assert isinstance(image, np.ndarray) and isinstance(image, phongvk.Image)


def test_numpy_mesh_renders_exactly_as_the_same_obj_file(tmp_path):
    vertices, faces = octahedron()
    obj = tmp_path / "octahedron.obj"
    # %.9g of a float32 reads back as the same float32.
    obj.write_text("".join("v %.9g %.9g %.9g\n" % tuple(p) for p in vertices.tolist()) +
                   "".join("f %d %d %d\n" % tuple(x + 1 for x in t) for t in faces.tolist()))
    base = {"camera": CAMERA, "lights": [{"position": [2, -3, 3]}], "materials": {"red": {"color": [1, 0.2, 0.2]}}}
    from_file = phongvk.scene_from_dict(dict(base, objects=[{"shape": "mesh", "file": "octahedron.obj",
                                                             "material": "red"}]), base_dir=str(tmp_path))
    from_arrays = phongvk.scene_from_dict(dict(base, objects=[]))
    from_arrays.add_mesh(vertices, faces, material="red")
    for backend in ("cpu", "gpu"):
        renderer = phongvk.Renderer(backend)
        a, b = renderer.render(from_file), renderer.render(from_arrays)
        assert np.array_equal(a, b)
        assert a.any()


def test_given_normals_and_inline_materials():
    vertices, faces = octahedron()
    scene = phongvk.scene_from_dict({"camera": CAMERA, "lights": [{"position": [2, -3, 3]}], "objects": []})
    normals = vertices / np.linalg.norm(vertices, axis=1, keepdims=True)
    scene.add_mesh(vertices, faces, normals=normals, material={"ks": 0.5, "color": [0.2, 0.4, 1.0]}, closed=True)
    assert scene.object_count == 1
    cpu, gpu = phongvk.Renderer("cpu").render(scene), phongvk.Renderer("gpu").render(scene)
    assert np.array_equal(cpu, gpu)


@pytest.mark.parametrize("args, message", [
    (dict(vertices=np.zeros((4, 2), np.float32)), "vertices: expected shape (N, 3), got (4, 2)"),
    (dict(vertices=np.zeros((4, 3), np.int32)), "vertices: expected a floating-point array of shape (N, 3), got dtype int32"),
    (dict(faces=np.zeros((2, 3), np.float64)), "faces: expected an integer array of shape (N, 3), got dtype float64"),
    (dict(faces=np.zeros((6,), np.int64)), "faces: expected shape (N, 3), got (6,)"),
    (dict(faces=np.array([[0, 1, 2], [0, 1, 9]])), "faces: row 1 has index 9, but there are 4 vertices"),
    (dict(faces=np.array([[0, 1, 2], [-1, 1, 2]])), "faces: row 1 has index -1, but there are 4 vertices"),
    (dict(vertices=np.array([[0, 0, 0], [1, 0, 0], [0, np.nan, 0], [0, 0, 1]], np.float32)),
     "vertices: row 2 is not finite: [0, nan, 0]"),
    (dict(normals=np.ones((3, 3), np.float32)), "normals: expected one row per vertex (4), got 3"),
    (dict(normals=np.array([[1, 0, 0], [0, 1, 0], [0, 0, 0], [0, 0, 1]], np.float32)),
     "normals: row 2 has no direction: [0, 0, 0]"),
])
def test_bad_arrays_raise_value_error_naming_the_argument_and_row(args, message):
    scene = phongvk.scene_from_dict({"camera": CAMERA, "objects": []})
    kwargs = dict(vertices=np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], np.float32),
                  faces=np.array([[0, 1, 2], [0, 2, 3]]))
    kwargs.update(args)
    with pytest.raises(ValueError) as error:
        scene.add_mesh(**kwargs)
    assert message in str(error.value)
    assert scene.object_count == 0  # nothing half-added


def test_bad_material_is_a_scene_error_at_its_path():
    scene = phongvk.load_scene(scene_path("scenes/basic.json"))
    vertices, faces = octahedron()
    with pytest.raises(phongvk.SceneError, match=r"scenes/basic.json: objects\[6\].material.ks: must be >= 0, got -1"):
        scene.add_mesh(vertices, faces, material={"ks": -1})
    with pytest.raises(phongvk.SceneError, match=r"objects\[6\].material: unknown material 'gold' \(known: "):
        scene.add_mesh(vertices, faces, material="gold")


def test_bad_scenes_raise_scene_error_a_value_error():
    assert issubclass(phongvk.SceneError, ValueError)
    with pytest.raises(phongvk.SceneError, match=r"^objects\[0\].radius: must be > 0, got -1$"):
        phongvk.scene_from_dict({"camera": CAMERA, "objects": [{"shape": "sphere", "radius": -1}]})
    with pytest.raises(phongvk.SceneError, match=r"^camera.position\[1\]: must be finite, got nan$"):
        phongvk.scene_from_dict({"camera": dict(CAMERA, position=[3, math.nan, 1]), "objects": []})
    with pytest.raises(phongvk.SceneError, match=r"^lamps: unknown key \(allowed: camera, "):
        phongvk.scene_from_dict({"camera": CAMERA, "objects": [], "lamps": []})
    with pytest.raises(phongvk.SceneError, match=r"no_such\.json: cannot read file"):
        phongvk.load_scene(scene_path("scenes/no_such.json"))
    with pytest.raises(phongvk.SceneError, match=r"objects: scene has no objects"):
        phongvk.Renderer("cpu").render(phongvk.scene_from_dict({"camera": CAMERA, "objects": []}))


def test_scene_from_dict_takes_numpy_values():
    scene = phongvk.scene_from_dict({"camera": {"position": np.array([3.0, -2.0, 1.5]), "look_at": [0, 0, 0],
                                                "width": np.int64(64), "height": 48},
                                     "objects": [{"shape": "cube", "size": np.float32(0.5)}]})
    assert (scene.width, scene.height) == (64, 48)


def test_animation_frames():
    scene = phongvk.load_scene(scene_path("scenes/paper/fig6_orbit_red.json"))
    assert scene.frame_count == 120
    renderer = phongvk.Renderer("cpu")
    first, later = renderer.render(scene.frame(0), 96, 64), renderer.render(scene.frame(30), 96, 64)
    assert np.array_equal(first, renderer.render(scene, 96, 64))
    assert not np.array_equal(first, later)
    with pytest.raises(IndexError):
        scene.frame(120)
    assert phongvk.load_scene(scene_path("scenes/basic.json")).frame_count == 1


def test_added_meshes_follow_the_scene_into_its_frames():
    scene = phongvk.load_scene(scene_path("scenes/paper/fig6_orbit_red.json"))
    before = scene.object_count
    vertices, faces = octahedron()
    scene.add_mesh(vertices, faces, material={"color": [0.2, 0.4, 1.0]})
    renderer = phongvk.Renderer("cpu")
    for index in (0, 30):
        frame = scene.frame(index)
        assert frame.object_count == before + 1
        without = phongvk.load_scene(scene_path("scenes/paper/fig6_orbit_red.json")).frame(index)
        assert not np.array_equal(renderer.render(frame, 96, 64), renderer.render(without, 96, 64))


class MeshLike:
    """What a trimesh.Trimesh offers phongvk: .vertices and .faces arrays."""

    def __init__(self, vertices, faces):
        self.vertices, self.faces = vertices, faces


def test_add_mesh_takes_lists_and_mesh_objects():
    vertices, faces = octahedron()
    base = {"camera": CAMERA, "lights": [{"position": [2, -3, 3]}], "objects": []}
    from_arrays = phongvk.scene_from_dict(base)
    from_arrays.add_mesh(vertices, faces)
    from_lists = phongvk.scene_from_dict(base)
    from_lists.add_mesh(vertices.tolist(), faces.tolist())
    from_object = phongvk.scene_from_dict(base)
    from_object.add_mesh(MeshLike(vertices, faces))
    renderer = phongvk.Renderer("cpu")
    expected = renderer.render(from_arrays)
    assert expected.any()
    assert np.array_equal(renderer.render(from_lists), expected)
    assert np.array_equal(renderer.render(from_object), expected)
    with pytest.raises(TypeError, match=r"one object with \.vertices and \.faces arrays .*, got int"):
        from_arrays.add_mesh(3)
    with pytest.raises(ValueError, match=r"faces: expected an integer array of shape \(N, 3\), got dtype float64"):
        from_arrays.add_mesh(vertices.tolist(), [[0.5, 1, 2]])
    with pytest.raises(ValueError, match=r"vertices: expected an array of shape \(N, 3\) or rows of 3 numbers, got list"):
        from_arrays.add_mesh([[0, 0, 0], [1, 0]], [[0, 1, 2]])


def test_up_axis_of_a_model_alone(tmp_path):
    """A model exported y-up renders with up="y" exactly as the same model exported z-up."""
    z_up = np.array([[0, 0, 0], [1, 0, 0], [0, 0.5, 0], [0.25, 0.2, 1.5]], np.float32)
    faces = "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 2 0 3\n"
    header = ("ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
              "element face 4\nproperty list uchar int vertex_indices\nend_header\n")
    for name, points in (("z_up.ply", z_up), ("y_up.ply", z_up[:, [0, 2, 1]] * np.float32([1, 1, -1]))):
        (tmp_path / name).write_text(header + "".join("%r %r %r\n" % tuple(map(float, p)) for p in points) + faces)
    renderer = phongvk.Renderer("cpu")
    expected = renderer.render(phongvk.load_scene(str(tmp_path / "z_up.ply")), 120, 90)
    assert np.array_equal(renderer.render(phongvk.load_scene(str(tmp_path / "y_up.ply"), up="y"), 120, 90), expected)
    assert not np.array_equal(renderer.render(phongvk.load_scene(str(tmp_path / "y_up.ply")), 120, 90), expected)
    with pytest.raises(ValueError, match=r"up: expected 'y' or 'z', got 'x'"):
        phongvk.load_scene(str(tmp_path / "y_up.ply"), up="x")
    with pytest.raises(phongvk.ArgumentError, match=r"an up axis applies to a model file rendered alone"):
        phongvk.load_scene(scene_path("scenes/basic.json"), up="z")


def test_renderer_repr_names_backend_and_device():
    assert repr(phongvk.Renderer("cpu")) == "<phongvk.Renderer cpu on cpu (reference)>"
    gpu = phongvk.Renderer("gpu")
    assert repr(gpu) == "<phongvk.Renderer gpu on %s>" % gpu.device_name


def test_import_without_numpy_says_which_python_to_use():
    import subprocess
    import sys
    code = "import sys; sys.modules['numpy'] = None; import phongvk"
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert result.returncode != 0
    assert "phongvk needs numpy, which this Python (%s) cannot import" % sys.executable in result.stderr
    assert "/usr/bin/python3" in result.stderr


def test_visibility_buffer_is_the_same_on_both_backends():
    scene = phongvk.load_scene(scene_path("scenes/paper/fig1_cube.json"))
    a_image, a_tri, a_depth = phongvk.Renderer("gpu").render_visibility(scene, 200, 130)
    b_image, b_tri, b_depth = phongvk.Renderer("cpu").render_visibility(scene, 200, 130)
    assert a_tri.shape == (130, 200) and a_tri.dtype == np.uint32 and a_depth.dtype == np.float32
    assert np.array_equal(a_image, b_image) and np.array_equal(a_tri, b_tri)
    assert np.array_equal(a_depth, b_depth)
    uncovered = a_tri == phongvk.NO_TRIANGLE
    assert uncovered.any() and (~uncovered).any()
    assert np.all(np.isinf(a_depth[uncovered])) and np.all(a_depth[~uncovered] > 0)
    with pytest.raises(ValueError, match="graphics backend has no visibility keys"):
        phongvk.Renderer("graphics").render_visibility(scene)


def test_diff_has_the_numbers_the_cli_prints():
    result = phongvk.diff(phongvk.load_scene(scene_path("scenes/two_lights.json")))
    assert result["pixels"] == 1385 * 923 and result["differing"] == 0 and result["triangle_mismatch"] == 0
    assert result["max_abs"] == (0, 0, 0) and math.isinf(result["psnr"])
    assert "pixels differing:    0" in result["report"]
    renderer = phongvk.Renderer("gpu")
    again = renderer.diff(phongvk.load_scene(scene_path("scenes/two_lights.json")))
    assert again["differing"] == 0 and again["report"] == result["report"]
    assert renderer.stats["frames_rendered"] == 1


def test_png_round_trip_and_jupyter(tmp_path):
    image = phongvk.Renderer("cpu").render(phongvk.load_scene(scene_path("scenes/basic.json")), 64, 40)
    phongvk.write_png(str(tmp_path / "a.png"), image)
    assert np.array_equal(phongvk.read_png(str(tmp_path / "a.png")), image)
    assert image._repr_png_().startswith(b"\x89PNG\r\n\x1a\n")
    with pytest.raises(phongvk.OutputError, match=r"cannot write '.*missing/a.png': folder '.*missing' does not exist"):
        phongvk.write_png(str(tmp_path / "missing" / "a.png"), image)
    with pytest.raises(ValueError, match=r"image: expected a uint8 array of shape \(height, width, 3\)"):
        phongvk.write_png(str(tmp_path / "b.png"), image.astype(np.float32))


def test_png_levels_change_size_not_pixels(tmp_path):
    from PIL import Image as PilImage  # zlib's inflate, a decoder of its own

    image = phongvk.Renderer("cpu").render(phongvk.load_scene(scene_path("scenes/basic.json")), 160, 100)
    sizes = []
    for level in (0, 1, 2, 12):
        path = tmp_path / f"level{level}.png"
        phongvk.write_png(str(path), image, level=level)
        assert np.array_equal(np.asarray(PilImage.open(path).convert("RGB")), image)
        assert phongvk.encode_png(image, level=level) == path.read_bytes()
        sizes.append(path.stat().st_size)
    assert sizes == sorted(sizes, reverse=True)
    assert phongvk.encode_png(image) == phongvk.encode_png(image, level=phongvk.PNG_LEVEL_DEFAULT)
    with pytest.raises(ValueError, match=r"PNG level 13 is out of range: 0 \(no compression\) to 12"):
        phongvk.write_png(str(tmp_path / "bad.png"), image, level=13)


def test_devices_and_version():
    devices = phongvk.devices()
    assert any(d["usable"] for d in devices)
    assert set(devices[0]) == {"index", "name", "type", "api_version", "usable", "missing", "keys"}
    assert phongvk.__version__.count(".") == 2 and phongvk.__revision__


def test_help_reads_well():
    doc = phongvk.Renderer.__doc__
    assert "backend" in doc and "keeps what it uploaded" in doc
    assert "add_mesh" in phongvk.Scene.__doc__ and "vertices: (N, 3)" in phongvk.Scene.add_mesh.__doc__


def test_mesh_files_load_as_scenes_and_in_scenes(tmp_path):
    # A model file alone is a scene (fitted camera, light at the eye); PLY, STL and GLB files made by
    # other tools (Debian's assimp-testmodels) render the same on both backends.
    models = "/usr/share/assimp/models/"
    for name in ["PLY/Wuson.ply", "STL/Spider_binary.stl", "glTF2/BoxTextured-glTF-Binary/BoxTextured.glb"]:
        scene = phongvk.load_scene(models + name)
        assert (scene.width, scene.height) == (960, 720)
        result = phongvk.diff(scene)
        assert result["differing"] == 0 and result["triangle_mismatch"] == 0
    scene = phongvk.scene_from_dict({
        "camera": {"fit": True, "direction": [0, 1, -0.3], "width": 80, "height": 60},
        "lights": [{"position": "camera"}],
        "objects": [{"shape": "mesh", "file": models + "PLY/Wuson.ply", "up": "y", "rotate": [0, 0, 30],
                     "scale": [1, 1, 1.5]}]})
    image = phongvk.Renderer("cpu").render(scene)
    assert (image != 0).any()
    with pytest.raises(phongvk.SceneError, match=r"objects\[0\]\.file: .*: the extension says PLY but the content is STL"):
        bad = tmp_path / "part.ply"
        bad.write_text("solid x\nendsolid x\n")
        phongvk.scene_from_dict({"camera": {"fit": True}, "objects": [{"shape": "mesh", "file": str(bad)}]})
