"""Python input made to crash or outgrow the memory limit: dicts that contain themselves or nest
100,000 levels deep, one renderer driven from eight threads, empty arrays, a renderer asked for a
larger frame than the limit allows. Each gets an exception that names the argument, never a crash."""

import os
import sys
import threading

import numpy as np
import pytest

import phongvk
from conftest import scene_path

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


def test_a_list_shared_down_40_levels_is_refused_not_written_2_to_the_40_times():
    shared = []
    for _ in range(40):
        shared = [shared, shared]
    with pytest.raises(phongvk.SceneError, match=r"the scene holds more than 4194304 values"):
        phongvk.scene_from_dict(scene_dict(extra=shared))


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
