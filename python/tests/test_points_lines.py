"""Points and lines from numpy (docs/DESIGN.md "Points and lines"): phongvk.Points and phongvk.Lines,
Scene.add_points and add_lines, the render settings' point_size and line_width as live views, the
ids they get, Scene.triangles()' companions, and both renderers giving the same bytes."""

import numpy as np
import pytest

import phongvk


def pixel_scene(width=16, height=16):
    """An orthographic view down -z at one pixel a metre: world (x, y) is screen (8 + x, 8 - y)."""
    scene = phongvk.Scene(width, height)
    scene.camera = phongvk.Camera(position=(0, 0, 10), look_at=(0, 0, 0), up=(0, 1, 0), width=width, height=height,
                                  ortho_height=float(height))
    scene.lights = []
    return scene


def both(scene, **outputs):
    gpu = phongvk.Renderer("gpu").render(scene)
    cpu = phongvk.Renderer("cpu").render(scene)
    assert np.array_equal(gpu, cpu)
    assert phongvk.diff(scene)["differing"] == 0
    return gpu


def test_a_point_cloud_from_numpy_in_a_few_lines():
    rng = np.random.default_rng(7)
    points = rng.normal(size=(5000, 3)).astype(np.float32)
    colors = rng.integers(0, 256, size=(5000, 3), dtype=np.uint8)
    scene = phongvk.Scene(160, 120)
    scene.add_points(points, colors=colors)
    scene.camera = phongvk.Camera(position=(0, -8, 2), look_at=(0, 0, 0), width=160, height=120)
    scene.render_settings.point_size = 2
    assert scene.render_settings.point_size == 2
    image = both(scene)
    assert (image.max(axis=2) > 0).sum() > 2000


def test_points_cover_their_square_and_take_their_colour_unlit():
    scene = pixel_scene()
    # Screen (3.5, 4.5) and (10, 10): a pixel centre and a pixel corner.
    scene.add(phongvk.Points(np.array([[-4.5, 3.5, 0], [2, -2, 0]], np.float32),
                             colors=np.array([[200, 100, 50], [0, 255, 0]], np.uint8)),
              material=phongvk.Material(color=(1, 1, 1)))
    scene.render_settings.point_size = 2
    image = both(scene)
    covered = np.argwhere(image.max(axis=2) > 0)
    # (row, column): the first square spans x 2.5..4.5 and y 3.5..5.5, taking the centres on its top and
    # left edges and leaving those on its bottom and right ones.
    assert sorted(map(tuple, covered)) == [(3, 2), (3, 3), (4, 2), (4, 3), (9, 9), (9, 10), (10, 9), (10, 10)]
    assert tuple(image[4, 3]) == (200, 100, 50)
    assert tuple(image[9, 9]) == (0, 255, 0)


def test_lines_pairs_strips_and_loops():
    square = np.array([[-4, -4, 0], [4, -4, 0], [4, 4, 0], [-4, 4, 0]], np.float32)
    assert phongvk.Lines(square).line_count == 2
    assert phongvk.Lines(square, strip=True).line_count == 3
    assert phongvk.Lines(square, loop=True).line_count == 4
    assert phongvk.Lines(square, np.array([[0, 2]])).line_count == 1
    with pytest.raises(ValueError, match="segments"):
        phongvk.Lines(square, np.array([[0, 2]]), strip=True)
    with pytest.raises(ValueError, match="lines: row 0 has index 9"):
        phongvk.Lines(square, np.array([[0, 9]]))
    scene = pixel_scene()
    scene.add_lines(square + np.float32(0.5), loop=True)
    scene.render_settings.line_width = 1
    image = both(scene)
    # Four sides of 8 pixels, without caps: each side takes its start and leaves its end, so one corner
    # is taken twice and the opposite one by neither (as OpenGL's non-antialiased wide lines).
    assert (image.max(axis=2) > 0).sum() == 31


def test_ids_number_lines_and_points_after_triangles():
    scene = pixel_scene()
    scene.add_mesh(np.array([[-8, -8, -1], [8, -8, -1], [0, 8, -1]], np.float32), np.array([[0, 1, 2]]))
    scene.add_lines(np.array([[-6, 0.5, 0], [6, 0.5, 0]], np.float32))
    scene.add_points(np.array([[4.5, -4.5, 1], [-4.5, -4.5, 1]], np.float32))
    out = phongvk.Renderer("gpu").render(scene, outputs=["triangle_id", "object_id"])
    ids = out["triangle_id"]
    assert set(np.unique(ids)) == {-1, 0, 1, 2, 3}
    assert ids[12, 12] == 2 and ids[12, 3] == 3
    assert out["object_id"][12, 12] == 2
    t = scene.triangles()
    assert t["faces"].shape == (1, 3) and t["lines"].shape == (1, 2) and t["points"].shape == (2,)
    assert list(t["line_objects"]) == [1] and list(t["point_objects"]) == [2, 2]


def test_sizes_are_checked_where_they_are_set():
    scene = pixel_scene()
    with pytest.raises(phongvk.SceneError, match="point_size"):
        scene.render_settings.point_size = 0
    with pytest.raises(phongvk.SceneError, match="line_width"):
        scene.render_settings = phongvk.RenderSettings(line_width=10000)
    with pytest.raises(ValueError, match="points: expected an integer array"):
        phongvk.Mesh(np.zeros((3, 3), np.float32), points=np.array([0.5]))
    with pytest.raises(ValueError, match="vertices: row 1 is not finite"):
        phongvk.Points(np.array([[0, 0, 0], [np.nan, 0, 0]], np.float32))
    assert "3 points" in repr(phongvk.Points(np.zeros((3, 3), np.float32)))


def test_the_readmes_point_cloud_runs(tmp_path, monkeypatch):
    """The README's point-cloud example, as written there."""
    import os
    import re
    readme = open(os.path.join(os.environ["PHONGVK_SOURCE_DIR"], "README.md")).read()
    block = next(b for b in re.findall(r"```python\n(.*?)```", readme, re.S) if "add_points" in b)
    monkeypatch.chdir(tmp_path)
    exec("import numpy as np\nimport phongvk\ngpu = phongvk.Renderer('gpu')\n" + block, {})
    assert phongvk.read_png(str(tmp_path / "cloud.png")).shape == (480, 640, 3)
