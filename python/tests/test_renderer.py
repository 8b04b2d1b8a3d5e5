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
