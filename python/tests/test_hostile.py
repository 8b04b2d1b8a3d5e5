"""Python input made to crash or outgrow the memory limit: dicts that contain themselves or nest
100,000 levels deep, one renderer driven from eight threads, empty arrays, a renderer asked for a
larger frame than the limit allows. Each gets an exception that names the argument, never a crash."""

import os
import re
import subprocess
import sys
import threading

import numpy as np
import pytest

import phongvk
from conftest import child_environment, scene_path

CAMERA = {"position": [3, -2, 1.5], "look_at": [0, 0, 0], "width": 96, "height": 64}


def scene_dict(**extra):
    return dict({"camera": CAMERA, "lights": [{"position": [2, -3, 3]}], "objects": [{"shape": "sphere"}]}, **extra)


def test_a_dict_that_contains_itself_is_named():
    d = scene_dict()
    d["render"] = d
    with pytest.raises(phongvk.SceneError, match=r"^render: contains itself"):
        phongvk.scene_from_dict(d)
    loop = [1, 2]
    loop.append(loop)
    with pytest.raises(phongvk.SceneError, match=r"^camera\.position\[2\]: contains itself"):
        phongvk.scene_from_dict(scene_dict(camera=dict(CAMERA, position=loop)))


def test_the_same_dict_twice_is_not_a_cycle():
    material = {"ks": 0.2}
    d = scene_dict(objects=[{"shape": "sphere", "material": material},
                            {"shape": "cube", "center": [2, 0, 0], "material": material}])
    assert phongvk.scene_from_dict(d).object_count == 2


def test_nesting_100000_levels_deep_is_an_error_not_a_crash():
    deep = []
    for _ in range(100_000):
        deep = [deep]
    with pytest.raises(phongvk.SceneError, match=r"nested deeper than 64 levels of dicts and lists"):
        phongvk.scene_from_dict(scene_dict(extra=deep))
    nested = {}
    for _ in range(100_000):
        nested = {"a": nested}
    with pytest.raises(phongvk.SceneError, match=r"^render(\.a)+: nested deeper than 64"):
        phongvk.scene_from_dict(scene_dict(render=nested))
    assert sys.getrecursionlimit() > 0  # the interpreter is still standing


def test_one_renderer_from_eight_threads_renders_one_frame_at_a_time():
    scene = phongvk.scene_from_dict(scene_dict())
    renderer = phongvk.Renderer("gpu")
    expected = phongvk.Renderer("cpu").render(scene)
    images, errors = [], []

    def work():
        try:
            for _ in range(3):
                images.append(renderer.render(scene))
        except Exception as e:  # noqa: BLE001 - any failure is the test's finding
            errors.append(e)

    threads = [threading.Thread(target=work) for _ in range(8)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert not errors
    assert len(images) == 24
    for image in images:
        assert np.array_equal(image, expected)


def test_write_png_of_an_empty_array_is_a_value_error(tmp_path):
    for shape in [(0, 0, 3), (0, 5, 3), (5, 0, 3)]:
        with pytest.raises(ValueError, match=r"image: expected a non-empty"):
            phongvk.write_png(str(tmp_path / "x.png"), np.zeros(shape, dtype=np.uint8))
    assert not (tmp_path / "x.png").exists()


@pytest.mark.parametrize("backend", ["cpu", "gpu"])
def test_a_renderer_checks_every_frame_against_the_memory_limit(backend, monkeypatch):
    scene = phongvk.load_scene(scene_path("scenes/basic.json"))
    renderer = phongvk.Renderer(backend)
    monkeypatch.setenv("PHONGVK_MAX_MEMORY_GB", "0.0625")
    assert renderer.render(scene, width=320, height=240).shape == (240, 320, 3)
    with pytest.raises(phongvk.SceneError, match=r"the scene needs about 0\.500 GiB .* more than the 0\.062 GiB limit"):
        renderer.render(scene, width=4096, height=4096)
    with pytest.raises(phongvk.SceneError, match=r"more than the 0\.062 GiB limit"):
        renderer.render(scene.with_render(samples=16), width=1024, height=1024)
    monkeypatch.setenv("PHONGVK_MAX_MEMORY_GB", "lots")
    with pytest.raises(phongvk.SceneError, match=r"PHONGVK_MAX_MEMORY_GB is 'lots': expected a number of GiB"):
        renderer.render(scene, width=320, height=240)
    assert os.environ["PHONGVK_MAX_MEMORY_GB"] == "lots"


def test_values_json_cannot_hold_are_named():
    with pytest.raises(phongvk.SceneError, match=r"^ambient\[0\]: must be a JSON value .* got (longdouble|float128)"):
        phongvk.scene_from_dict(scene_dict(ambient=[np.longdouble(1), 1, 1]))
    with pytest.raises(phongvk.SceneError, match=r"^ambient\[0\]: must be a JSON value .* got (longdouble|float128)"):
        phongvk.scene_from_dict(scene_dict(ambient=np.ones(3, dtype=np.longdouble)))
    with pytest.raises(phongvk.SceneError, match=r"^ambient\[1\]: must be a number a scene can hold, got an integer of 16001 bits"):
        phongvk.scene_from_dict(scene_dict(ambient=[1, 1 << 16000, 1]))
    with pytest.raises(phongvk.SceneError, match=r"^render: keys must be text that UTF-8 can hold"):
        phongvk.scene_from_dict(scene_dict(render={"\udcff": 1}))


def test_a_list_shared_down_40_levels_is_refused_not_written_2_to_the_40_times(monkeypatch):
    """Refused once its values pass what the memory limit holds at 128 bytes a value: 2^19 of them
    under 0.0625 GiB."""
    shared = []
    for _ in range(40):
        shared = [shared, shared]
    monkeypatch.setenv("PHONGVK_MAX_MEMORY_GB", "0.0625")
    with pytest.raises(phongvk.SceneError, match=r"the scene holds more than 524288 values, the most the memory limit "
                                                 r"allows at 128 bytes each"):
        phongvk.scene_from_dict(scene_dict(extra=shared))


def test_a_mesh_of_more_than_four_million_values_goes_through_to_dict_and_back():
    """A scene's mesh is written by to_dict and read back by scene_from_dict whatever its size: the
    reader's bound on values is the memory limit's."""
    rows = 350_000  # 4.55M values: 350,000 vertices with normals and uvs, 350,000 faces
    angles = np.linspace(0, 2 * np.pi, rows, endpoint=False)
    vertices = np.stack([np.cos(angles), np.sin(angles), np.linspace(-1, 1, rows)], axis=1)
    faces = np.stack([np.arange(rows), (np.arange(rows) + 1) % rows, (np.arange(rows) + 7) % rows], axis=1)
    scene = phongvk.Scene(64, 48)
    scene.camera = phongvk.Camera(position=(0, -4, 0), look_at=(0, 0, 0))
    scene.add(phongvk.Mesh(vertices, faces, normals=vertices, uvs=vertices[:, :2]))
    again = phongvk.scene_from_dict(scene.to_dict())
    assert again.to_json() == scene.to_json()


def test_a_key_that_is_not_a_string_is_named_by_its_type():
    with pytest.raises(phongvk.SceneError, match=r"^render: keys must be strings, got a key of type int$"):
        phongvk.scene_from_dict(scene_dict(render={1 << 16000: 1}))


def test_every_error_is_a_phongvk_error_and_the_python_kind_it_names():
    assert issubclass(phongvk.SceneError, phongvk.Error) and issubclass(phongvk.SceneError, ValueError)
    assert issubclass(phongvk.ArgumentError, phongvk.Error) and issubclass(phongvk.ArgumentError, ValueError)
    assert issubclass(phongvk.RangeError, phongvk.ArgumentError) and issubclass(phongvk.RangeError, IndexError)
    assert issubclass(phongvk.OutputError, phongvk.Error) and issubclass(phongvk.OutputError, OSError)
    assert issubclass(phongvk.NoDeviceError, phongvk.Error) and issubclass(phongvk.DeviceError, RuntimeError)
    scene = phongvk.load_scene(scene_path("scenes/basic.json"))
    with pytest.raises(phongvk.RangeError, match=r"frame 5 is out of range"):
        scene.frame(5)
    with pytest.raises(phongvk.ArgumentError, match=r"unknown backend 'opengl'"):
        phongvk.Renderer("opengl")
    with pytest.raises(phongvk.Error):
        phongvk.read_png(scene_path("scenes/basic.json"))


def run_child(code, limit_gib=None, address_space=None):
    """`code` run by a child interpreter (with PHONGVK_MAX_MEMORY_GB=limit_gib, under an address-space
    limit of `address_space` bytes): its return code, what it printed, and its peak resident memory
    in bytes, which it prints last: its ru_maxrss, or its VmHWM where that is smaller (ru_maxrss
    starts from the parent's resident memory at the fork, which a test before may have grown)."""
    env = child_environment()
    env.pop("PHONGVK_MAX_MEMORY_GB", None)
    if limit_gib is not None:
        env["PHONGVK_MAX_MEMORY_GB"] = str(limit_gib)
    prologue = "import resource, numpy as np, phongvk\n"
    if address_space is not None:
        prologue += "resource.setrlimit(resource.RLIMIT_AS, (%d, %d))\n" % (address_space, address_space)
    body = "try:\n" + "".join("    " + line + "\n" for line in code.splitlines()) + \
           "except Exception as e:\n    print(type(e).__name__ + ': ' + str(e))\n"
    epilogue = ("hwm = [int(line.split()[1]) for line in open('/proc/self/status') if line.startswith('VmHWM:')]\n"
                "print(min(hwm + [resource.getrusage(resource.RUSAGE_SELF).ru_maxrss]) * 1024)\n")
    done = subprocess.run([sys.executable, "-c", prologue + body + epilogue], env=env, capture_output=True, text=True,
                          timeout=120)
    lines = done.stdout.splitlines()
    return done.returncode, "\n".join(lines[:-1]) + done.stderr, int(lines[-1]) if lines else 0


BROADCAST = "np.broadcast_to(np.zeros((1, 1, 3), np.uint8), (%d, %d, 3))"


def test_a_texture_array_too_large_is_refused_before_it_is_copied():
    gib = 1 << 30
    code, out, peak = run_child("phongvk.Material(texture=%s)" % (BROADCAST % (30000, 30000)), limit_gib=1)
    assert code == 0 and out.startswith("ArgumentError: texture: a texture is 1 to 16384 texels a side, got 30000 x 30000")
    assert peak < 1.25 * gib
    # 12000 x 12000 fits a texture's sides, but not its 0.54 GiB of texels in a 0.25 GiB limit.
    code, out, peak = run_child("phongvk.Material(texture=%s)" % (BROADCAST % (12000, 12000)), limit_gib=0.25)
    assert code == 0 and out.startswith("SceneError: texture needs about 0.54 GiB (12000 x 12000 texels")
    assert peak < 1.25 * gib / 4


@pytest.mark.parametrize("backend", ["cpu", "gpu"])
def test_a_texture_array_that_fits_renders_within_the_limit(backend):
    # An 8000^2 photo-like (incompressible) RGB array, 0.18 GiB, as a material's texture under a
    # 0.6 GiB limit: its 0.24 GiB of texels are written from the array directly (no PNG, no data
    # URI, no copy of the array), so beside the caller's own array the peak stays within 1.25x the
    # limit on both backends (the GPU's copy of the texels counted too).
    gib = 1 << 30
    code = ("a = np.random.default_rng(7).integers(0, 256, (8000, 8000, 3), dtype=np.uint8)\n"
            "scene = phongvk.Scene(64, 48)\n"
            "scene.add_mesh(np.float32([[-1, 0, -1], [1, 0, -1], [1, 0, 1], [-1, 0, 1]]), [[0, 1, 2], [0, 2, 3]],\n"
            "               uvs=[[0, 1], [1, 1], [1, 0], [0, 0]], material=phongvk.Material(texture=a))\n"
            "image = phongvk.Renderer('%s').render(scene)\n"
            "print('rendered', image.shape)\n" % backend)
    code, out, peak = run_child(code, limit_gib=0.6)
    assert code == 0 and out.startswith("rendered (48, 64, 3)"), out
    assert peak < 1.25 * 0.6 * gib + 8000 * 8000 * 3, f"peak {peak / gib:.2f} GiB"


@pytest.mark.parametrize("call", ["phongvk.encode_png(%s)", "phongvk.write_png('/dev/null', %s)",
                                  "phongvk.Material(texture=%s)"])
def test_an_image_copy_that_finds_no_memory_raises_not_crashes(call):
    """Under a 1.9 GB address space a copy of a 1.2 GB broadcast image cannot be made (nor a 16000^2
    texture's 1.02 GB of texels under 1 GB: a texture's sides stop at 16384): MemoryError naming the
    argument (or phongvk's error, a write's), never a segfault of the interpreter."""
    side, address_space = (16000, 1_000_000_000) if "Material" in call else (20000, 1_900_000_000)
    code, out, _ = run_child(call % (BROADCAST % (side, side)), address_space=address_space)
    assert code == 0, out
    name = "texture" if "Material" in call else "image"
    assert re.match(r"(MemoryError: %s: no memory (for a copy of its|to encode its|for its)|OutputError: cannot write "
                    r"'/dev/null': no memory to encode its|SceneError: texture needs about)" % name, out), out


@pytest.mark.parametrize("backend", ["cpu", "gpu"])
@pytest.mark.parametrize("output", ["depth", "normal", "object_id", "triangle_id", "alpha", "rgba", "color"])
def test_an_output_asked_for_twice_is_refused(backend, output):
    scene = phongvk.scene_from_dict(scene_dict())
    with pytest.raises(phongvk.ArgumentError, match=r"^outputs: '%s' is asked for more than once$" % output):
        phongvk.Renderer(backend).render(scene, outputs=[output, "color", output])


TRIANGLE = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], np.float32)
FACE = np.array([[0, 1, 2]])


@pytest.mark.parametrize("argument", ["vertices", "faces", "normals", "uvs"])
@pytest.mark.parametrize("value, got", [
    ("strings", r"got list of dtype <U"), ("dict", r"got dict of dtype object"),
    ("ragged", r"got list \(ValueError: setting an array element with a sequence"),
    ("complex", r"got ndarray of dtype complex128"), ("objects", r"got ndarray of dtype object"),
    ("booleans", r"got ndarray of dtype bool")])
def test_every_array_argument_refuses_what_is_not_numbers_by_name(argument, value, got):
    arrays = {"vertices": TRIANGLE, "faces": FACE, "normals": np.float32([[0, 0, 1]] * 3),
              "uvs": np.float32([[0, 0], [1, 0], [0, 1]])}
    columns = arrays[argument].shape[1]
    arrays[argument] = {"strings": [["a"] * columns] * 3, "dict": {"a": 1}, "ragged": [[0] * columns, [0]],
                        "complex": np.ones((3, columns), complex), "objects": np.array([[None] * columns] * 3),
                        "booleans": np.ones((3, columns), bool)}[value]
    with pytest.raises(ValueError, match=r"^%s: expected .*, %s" % (argument, got)):
        phongvk.Mesh(**arrays)
    if argument != "uvs":
        with pytest.raises(ValueError, match=r"^%s: expected .*, %s" % (argument, got)):
            phongvk.Scene(8, 8).add_mesh(arrays["vertices"], arrays["faces"], arrays["normals"])


def test_a_pose_refuses_what_is_not_numbers_by_name():
    with pytest.raises(ValueError, match=r"^pose: expected a 4x4 matrix of numbers, got ndarray of dtype complex128"):
        phongvk.Scene(8, 8).add(phongvk.Mesh(TRIANGLE, FACE), pose=np.eye(4, dtype=complex))
    with pytest.raises(ValueError, match=r"^pose: expected a 4x4 matrix of numbers, got list of dtype <U"):
        phongvk.Scene(8, 8).add(phongvk.Mesh(TRIANGLE, FACE), pose=[["1"] * 4] * 4)


def test_a_texture_arrays_errors_name_texture():
    with pytest.raises(ValueError, match=r"^texture: expected a uint8 array .* got float32 of shape \(2, 2\)"):
        phongvk.Material(texture=np.zeros((2, 2), np.float32))
    with pytest.raises(ValueError, match=r"^texture: expected a non-empty array, got shape \(0, 4, 3\)"):
        phongvk.Material(texture=np.zeros((0, 4, 3), np.uint8))
    with pytest.raises(ValueError, match=r"^texture: expected a uint8 array .* got dict of dtype object"):
        phongvk.Material(texture={"pixels": 1})


ICOSPHERE = ("scene = phongvk.scene_from_dict({'camera': {'position': [0, -3, 0], 'look_at': [0, 0, 0], 'width': 64, "
             "'height': 48}, 'objects': [{'shape': 'icosphere', 'subdivide': %d}]})\n")


@pytest.mark.parametrize("call", ["scene.triangles()", "scene.bounds"])
def test_triangles_and_bounds_check_the_memory_limit_before_they_build(call):
    """A scene a renderer refuses (21M triangles, about 2.2 GiB, under a 1 GiB limit) is refused by
    triangles() and bounds too, before anything is built (they took 1.5 GiB and 1.2 GiB)."""
    code, out, peak = run_child(ICOSPHERE % 10 + call, limit_gib=1)
    assert code == 0 and out.startswith("SceneError: the scene needs about 2.2 GiB (20971520 triangles, 0 pixels), "
                                        "more than the 1.0 GiB limit"), out
    assert peak < 0.25 * (1 << 30)


def test_triangles_count_the_arrays_they_return():
    """5.2M triangles take 0.55 GiB to build, under a 0.6 GiB limit, but with the arrays triangles()
    returns (0.2 GiB more) they do not fit: refused once built, before the arrays are made."""
    code, out, peak = run_child(ICOSPHERE % 9 + "scene.triangles()", limit_gib=0.6)
    assert code == 0 and out.startswith("SceneError: Scene::triangles needs about 0.7"), out
    assert peak < 1.25 * 0.6 * (1 << 30)
    code, out, _ = run_child(ICOSPHERE % 9 + "print(len(scene.triangles()['faces']))", limit_gib=0.8)
    assert out.startswith("5242880"), out
