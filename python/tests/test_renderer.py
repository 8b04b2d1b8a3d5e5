"""The renderer across calls and threads: meshes uploaded once while the geometry stays, the same
images from two threads at once as one after the other, bounded memory over 1,000 renders."""

import threading

import numpy as np

import phongvk
from conftest import scene_path


def test_repeated_renders_upload_no_mesh_again():
    scene = phongvk.load_scene(scene_path("scenes/paper/fig7_orbit_white_red.json"))
    renderer = phongvk.Renderer("gpu")
    for i in range(0, scene.frame_count, 10):  # 12 camera poses
        renderer.render(scene.frame(i), 120, 80)
    renderer.render(scene, 64, 48)
    stats = renderer.stats
    assert stats["frames_rendered"] == 13
    assert stats["scene_builds"] == 1
    renderer.render(phongvk.load_scene(scene_path("scenes/basic.json")), 64, 48)
    assert renderer.stats["scene_builds"] == 2


def test_two_renderers_in_two_threads_give_the_serial_images():
    scenes = [phongvk.load_scene(scene_path(p)) for p in ("scenes/paper/fig1_cube.json", "scenes/floor_and_walls.json")]
    serial = [phongvk.Renderer("gpu").render(s, 320, 200) for s in scenes]
    results = [None, None]
    errors = []

    def work(k):
        try:
            renderer = phongvk.Renderer("gpu")
            for _ in range(5):
                image = renderer.render(scenes[k], 320, 200)
                assert results[k] is None or np.array_equal(results[k], image)
                results[k] = image
        except Exception as e:  # noqa: BLE001 - reported below, on the main thread
            errors.append(e)

    threads = [threading.Thread(target=work, args=(k,)) for k in (0, 1)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert not errors
    for k in (0, 1):
        assert np.array_equal(results[k], serial[k])


def test_reference_and_compute_in_two_threads():
    scene = phongvk.load_scene(scene_path("scenes/two_lights.json"))
    out = {}
    threads = [threading.Thread(target=lambda b=b: out.__setitem__(b, phongvk.Renderer(b).render(scene, 200, 130)))
               for b in ("cpu", "gpu")]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert np.array_equal(out["cpu"], out["gpu"])


def resident_kib():
    with open("/proc/self/status") as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1])
    raise RuntimeError("no VmRSS")


def test_no_memory_growth_over_a_thousand_renders():
    scene = phongvk.load_scene(scene_path("scenes/paper/fig3_two_lights.json"))
    renderer = phongvk.Renderer("gpu")
    poses = [scene.frame(0)]
    for _ in range(100):
        renderer.render(poses[0], 64, 48)
    settled = resident_kib()
    for _ in range(1000):
        image = renderer.render(poses[0], 64, 48)
        del image
    grown = resident_kib() - settled
    assert grown < 4 * 1024, f"resident memory grew {grown} KiB over 1,000 renders"


def test_render_options_from_python_match_the_scene_files():
    """with_render(...) is the scene file's "render" block: the same bytes on both backends, and
    a bad value names the option."""
    scene = phongvk.load_scene(scene_path("scenes/paper/fig3_two_lights.json"))
    phong = scene.with_render(shading="phong", specular="blinn", samples=4)
    from_dict = phongvk.scene_from_dict(
        {"camera": {"position": [-3.5, -2.45, 2.1], "look_at": [0, 0, 0]},
         "lights": [{"position": [-0.7, -0.6, 0.8]}],
         "objects": [{"shape": "icosphere", "center": [0, 0, 0], "radius": 0.5, "subdivide": 1}],
         "render": {"shading": "phong", "specular": "blinn", "samples": 4}})
    plain = phongvk.scene_from_dict(
        {"camera": {"position": [-3.5, -2.45, 2.1], "look_at": [0, 0, 0]},
         "lights": [{"position": [-0.7, -0.6, 0.8]}],
         "objects": [{"shape": "icosphere", "center": [0, 0, 0], "radius": 0.5, "subdivide": 1}]})
    gpu, cpu = phongvk.Renderer("gpu"), phongvk.Renderer("cpu")
    assert np.array_equal(gpu.render(phong, 160, 120), cpu.render(phong, 160, 120))
    assert np.array_equal(gpu.render(from_dict, 160, 120),
                          gpu.render(plain.with_render(shading="phong", specular="blinn", samples=4), 160, 120))
    assert not np.array_equal(gpu.render(scene, 160, 120), gpu.render(phong, 160, 120))
    try:
        scene.with_render(samples=8)
        raise AssertionError("no error for 8 samples")
    except phongvk.SceneError as e:
        assert "render.samples: must be 1, 4, 9 or 16" in str(e)
