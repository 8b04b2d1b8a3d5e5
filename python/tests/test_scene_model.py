"""A scene from Python behaves as a scene graph: what it gives back is a live view that edits it
(or refuses the edit out loud), lights and objects have handles, object ids stay with their
objects, meshes take vertex colours from arrays and trimesh-like objects, paths may be
os.PathLike, masks write as grey PNGs and numpy arithmetic on an Image gives plain arrays."""

import pathlib
import types
import warnings

import numpy as np
import pytest

import phongvk
from conftest import scene_path


def octahedron(size=0.5):
    v = np.array([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]], np.float32) * size
    f = np.array([[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4], [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]])
    return v, f


def translation(x, y, z):
    pose = np.eye(4)
    pose[:3, 3] = (x, y, z)
    return pose


def both(scene, outputs=("color",)):
    """The scene's outputs on the reference and the compute port, which must agree."""
    cpu = phongvk.Renderer("cpu").render(scene, outputs=list(outputs))
    gpu = phongvk.Renderer("gpu").render(scene, outputs=list(outputs))
    for name in outputs:
        assert np.array_equal(cpu[name], gpu[name]), name
    return cpu


def small_scene():
    scene = phongvk.Scene(64, 48)
    scene.camera = phongvk.Camera(position=(0, -4, 0), look_at=(0, 0, 0), fov=40)
    return scene


# ---- live views ----

def test_editing_what_the_scene_gives_back_edits_the_scene():
    scene = small_scene()
    scene.add(*octahedron())
    before = both(scene)["color"]
    scene.camera.fov = 25
    assert scene.camera.fov == 25 and isinstance(scene.camera, phongvk.Camera)
    scene.lights[0].color = (1, 0, 0)
    assert scene.lights[0].color == (1.0, 0.0, 0.0)
    scene.render_settings.samples = 4
    assert scene.render_settings.samples == 4
    after = both(scene)["color"]
    assert not np.array_equal(before, after)
    assert after[..., 0].max() > 2 * after[..., 1].max()  # a red light (and the white ambient)


def test_a_view_is_a_value_another_scene_takes():
    scene, other = small_scene(), small_scene()
    scene.camera.position = (1, -5, 1)
    other.camera = scene.camera
    assert other.camera == scene.camera and tuple(other.camera.position) == (1, -5, 1)


def test_a_bad_edit_raises_and_changes_nothing():
    scene = small_scene()
    with pytest.raises(phongvk.SceneError, match=r"render\.samples"):
        scene.render_settings.samples = 3
    assert scene.render_settings.samples == 1
    with pytest.raises(phongvk.SceneError, match=r"camera\.fov"):
        scene.camera.fov = 0
    assert scene.camera.fov == 40


def test_three_numbers_refuse_item_assignment_instead_of_doing_nothing():
    scene = small_scene()
    with pytest.raises(TypeError):
        scene.camera.position[0] = 3
    with pytest.raises(TypeError):
        scene.ambient[0] = 0.5
    camera = phongvk.Camera()
    with pytest.raises(TypeError):
        camera.position[0] = 3
    with pytest.raises(AttributeError):
        scene.camera.fovy = 30  # a misspelt name is an error, not a new attribute


# ---- handles ----

def test_lights_have_handles_that_survive_other_changes():
    scene = small_scene()
    scene.add(*octahedron())
    first = scene.add_light(phongvk.Light(position=(3, -3, 3)))
    second = scene.add_light(phongvk.Light(position=(-3, -3, 3), color=(0, 0, 1)))
    assert scene.light_count == 3 and first != second
    scene.remove(first)
    assert scene.light(second).color == (0.0, 0.0, 1.0)
    scene.light(second).intensity = 2
    assert scene.lights[1].intensity == 2
    with pytest.raises(IndexError, match="was removed"):
        scene.light(first)
    scene.lights = [phongvk.Light(at_camera=True)]  # replaces every light, and retires the handles
    with pytest.raises(IndexError):
        scene.set_light(second, phongvk.Light())
    with pytest.raises(phongvk.SceneError, match=r"lights\[1\]\.intensity"):
        scene.add_light(phongvk.Light(intensity=-1))
    assert scene.light_count == 1


def test_object_ids_stay_with_their_objects():
    scene = small_scene()
    handles = [scene.add(*octahedron(0.3), pose=translation(x, 0, 0)) for x in (-1, 0, 1)]
    assert [scene.object_id(h) for h in handles] == [0, 1, 2]
    scene.remove(handles[1])
    later = scene.add(*octahedron(0.3), pose=translation(0, 0, 0.8))
    assert [scene.object_id(h) for h in (handles[0], handles[2], later)] == [0, 2, 3]
    ids = both(scene, ["object_id"])["object_id"]
    assert set(np.unique(ids)) == {-1, 0, 2, 3}
    scene.set_object_id(handles[2], 7)
    labelled = both(scene, ["object_id"])["object_id"]
    assert set(np.unique(labelled)) == {-1, 0, 3, 7}
    # The ids travel with the scene written out and read back.
    back = phongvk.scene_from_dict(scene.to_dict())
    assert np.array_equal(both(back, ["object_id"])["object_id"], labelled)
    with pytest.raises(ValueError, match="object_id"):
        scene.set_object_id(handles[0], -2)


def test_an_object_id_can_be_given_when_adding():
    scene = small_scene()
    scene.add(*octahedron(), object_id=41)
    assert set(np.unique(both(scene, ["object_id"])["object_id"])) == {-1, 41}


def test_set_mesh_swaps_the_geometry_and_keeps_id_pose_and_material():
    scene = small_scene()
    keep = scene.add(*octahedron(0.3), pose=translation(-1, 0, 0))
    moved = scene.add(*octahedron(0.3), pose=translation(1, 0, 0), material={"color": [0, 1, 0]})
    scene.set_mesh(moved, *octahedron(0.6))
    swapped = both(scene, ["color", "object_id"])
    reference = small_scene()
    reference.add(*octahedron(0.3), pose=translation(-1, 0, 0))
    reference.add(*octahedron(0.6), pose=translation(1, 0, 0), material={"color": [0, 1, 0]})
    assert np.array_equal(swapped["color"], both(reference)["color"])
    assert scene.object_id(moved) == 1 and scene.object_id(keep) == 0


# ---- arrays ----

def test_vertex_colours_from_bytes_and_from_floats_render_alike():
    v, f = octahedron()
    rgb = np.array([[255, 0, 0], [0, 255, 0], [0, 0, 255], [255, 255, 0], [0, 255, 255], [255, 0, 255]], np.uint8)
    images = []
    for colors in (rgb, rgb / 255.0, np.concatenate([rgb, np.full((6, 1), 255, np.uint8)], axis=1)):
        scene = small_scene()
        scene.add(phongvk.Mesh(v, f, colors=colors))
        images.append(both(scene)["color"])
    assert np.array_equal(images[0], images[1]) and np.array_equal(images[0], images[2])
    white = small_scene()
    white.add(v, f)
    assert not np.array_equal(images[0], both(white)["color"])
    with pytest.raises(ValueError, match=r"colors: row 0 has 2.0, outside 0..1"):
        phongvk.Mesh(v, f, colors=np.full((6, 3), 2.0))
    with pytest.raises(ValueError, match=r"colors: expected one row per vertex \(6\), got 5"):
        phongvk.Mesh(v, f, colors=rgb[:5])


def trimesh_like(vertices, faces, **visual):
    """An object laid out as a trimesh.Trimesh is (trimesh is not a Debian package)."""
    return types.SimpleNamespace(vertices=vertices, faces=faces, visual=types.SimpleNamespace(**visual))


def test_a_trimesh_like_object_brings_its_vertex_colours():
    v, f = octahedron()
    rgba = np.tile(np.array([[200, 30, 60, 255]], np.uint8), (6, 1))
    scene, given = small_scene(), small_scene()
    scene.add(trimesh_like(v, f, kind="vertex", vertex_colors=rgba))
    given.add(v, f, colors=rgba)
    assert np.array_equal(both(scene)["color"], both(given)["color"])
    # trimesh's default colours (kind None) are not the mesh's own: white, as without any.
    plain, white = small_scene(), small_scene()
    plain.add(trimesh_like(v, f, kind=None, vertex_colors=rgba))
    white.add(v, f)
    assert np.array_equal(both(plain)["color"], both(white)["color"])


def test_a_trimesh_like_object_brings_its_uvs_and_texture():
    v = np.array([[-1, 0, -1], [1, 0, -1], [1, 0, 1], [-1, 0, 1]], np.float32)
    f = np.array([[0, 1, 2], [0, 2, 3]])
    uv_up = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], np.float32)  # trimesh: v runs up
    image = np.zeros((8, 8, 3), np.uint8)
    image[:4] = (255, 0, 0)  # the top half red
    image[4:] = (0, 0, 255)
    scene = small_scene()
    scene.add(trimesh_like(v, f, uv=uv_up, material=types.SimpleNamespace(image=image)))
    given = small_scene()
    given.add(v, f, uvs=np.column_stack([uv_up[:, 0], 1 - uv_up[:, 1]]), material=phongvk.Material(texture=image))
    color = both(scene)["color"]
    assert np.array_equal(color, both(given)["color"])
    assert color[12, 32, 0] > color[12, 32, 2] and color[36, 32, 2] > color[36, 32, 0]  # red above, blue below


# ---- files, PNGs, images ----

def test_paths_may_be_pathlike(tmp_path):
    scene = phongvk.load_scene(pathlib.Path(scene_path("scenes/basic.json")))
    mesh = phongvk.Mesh.from_file(pathlib.Path(scene_path("scenes/meshes/textured_cube.obj")))
    assert mesh.triangle_count > 0
    image = phongvk.Renderer("cpu").render(scene, 32, 24)
    phongvk.write_png(tmp_path / "basic.png", image)
    assert np.array_equal(phongvk.read_png(tmp_path / "basic.png"), image)


def test_masks_and_grey_bytes_write_as_grey_pngs(tmp_path):
    PIL = pytest.importorskip("PIL.Image")
    mask = np.zeros((5, 7), bool)
    mask[1:3, 2:5] = True
    phongvk.write_png(tmp_path / "mask.png", mask)
    read = PIL.open(tmp_path / "mask.png")
    assert read.mode == "L" and np.array_equal(np.array(read), mask.astype(np.uint8) * 255)
    grey = np.arange(35, dtype=np.uint8).reshape(5, 7)
    phongvk.write_png(tmp_path / "grey.png", grey)
    assert np.array_equal(np.array(PIL.open(tmp_path / "grey.png")), grey)
    with pytest.raises(ValueError, match="bool array of shape"):
        phongvk.write_png(tmp_path / "bad.png", np.zeros((5, 7), np.int32))


def test_numpy_arithmetic_on_an_image_gives_plain_arrays_that_still_show():
    image = phongvk.Renderer("cpu").render(phongvk.load_scene(scene_path("scenes/basic.json")), 32, 24)
    assert type(image) is phongvk.Image
    scaled = image / 255
    assert type(scaled) is np.ndarray and scaled.dtype == np.float64
    as_floats = image.astype(np.float32) / 255
    assert type(as_floats) is np.ndarray
    # astype keeps the subclass; its picture shows where it can and is skipped (None) where not.
    assert image.astype(np.float32)._repr_png_() is None
    assert (image.astype(np.float32) / 255).view(phongvk.Image)._repr_png_().startswith(b"\x89PNG")
    assert image[..., 0]._repr_png_().startswith(b"\x89PNG")


# ---- renderers and conventions ----

def test_a_renderer_closes_at_the_end_of_a_with_block():
    scene = phongvk.load_scene(scene_path("scenes/basic.json"))
    with phongvk.Renderer("gpu") as renderer:
        assert renderer.render(scene, 32, 24).shape == (24, 32, 3)
    with pytest.raises(ValueError, match="the renderer is closed"):
        renderer.render(scene, 32, 24)
    renderer.close()  # twice is fine


def test_a_camera_looking_away_from_everything_says_so():
    scene = small_scene()
    scene.add(*octahedron())
    # An OpenCV-style pose (looking down its +z at the model) read in OpenGL's convention looks away.
    pose = np.array([[1, 0, 0, 0], [0, 0, 1, -4], [0, -1, 0, 0], [0, 0, 0, 1]], float)
    scene.camera = phongvk.Camera.from_pose(pose, convention="opencv")
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert phongvk.Renderer("cpu").render(scene).max() > 0
    scene.camera = phongvk.Camera.from_pose(pose)  # the one default, "opengl"
    with pytest.warns(phongvk.NoticeWarning, match="looks away from every object"):
        assert phongvk.Renderer("cpu").render(scene).max() == 0


def test_stats_diff_and_devices_read_by_attribute_and_stay_dicts():
    import json
    scene = phongvk.load_scene(scene_path("scenes/basic.json")).with_render(samples=1)
    renderer = phongvk.Renderer("gpu")
    renderer.render(scene, 32, 24)
    stats = renderer.stats
    assert stats.frames_rendered == stats["frames_rendered"] == 1 and isinstance(stats, dict)
    assert json.loads(json.dumps(stats))["frames_rendered"] == 1
    with pytest.raises(AttributeError, match="has no 'frames'"):
        stats.frames
    result = phongvk.diff(phongvk.load_scene(scene_path("scenes/basic.json")).with_render(samples=1))
    assert isinstance(result, phongvk.DiffResult) and result.differing == result["differing"] == 0
    devices = phongvk.devices()
    assert devices and devices[0].name == devices[0]["name"]


# ---- poses ----

def turn(angle, shift=(0, 0, 0), scale=1.0):
    c, s = np.cos(angle), np.sin(angle)
    pose = np.eye(4)
    pose[:3, :3] = np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]]) @ np.diag([scale, 1, 1])
    pose[:3, 3] = shift
    return pose


def test_a_moving_object_builds_nothing_and_renders_as_one_placed_there():
    scene = small_scene()
    handle = scene.add(*octahedron(), pose=turn(0.3))
    renderers = {name: phongvk.Renderer(name) for name in ("cpu", "gpu")}
    for k, pose in enumerate([turn(0.5, (0.2, 0, 0)), turn(1.1, (0, 0.3, 0.1), 1.5), np.eye(4), turn(2.0)]):
        scene.set_pose(handle, pose)
        moved = {name: r.render(scene, outputs=["color", "depth", "normal"]) for name, r in renderers.items()}
        fresh = small_scene()
        fresh.add(*octahedron(), pose=pose)
        built = both(fresh, ["color", "depth", "normal"])
        for name in ("color", "depth", "normal"):
            assert np.array_equal(moved["cpu"][name], moved["gpu"][name]), (k, name)
            assert np.array_equal(moved["gpu"][name], built[name]), (k, name)
    assert renderers["gpu"].stats.scene_builds == 1 and renderers["cpu"].stats.scene_builds == 1


def test_a_posed_object_writes_its_pose_and_reads_back_the_same():
    scene = small_scene()
    scene.add(*octahedron(), pose=turn(0.7, (0.1, 0.2, 0), 1.3), material={"color": [1, 0.5, 0.2]})
    written = scene.to_dict()
    assert written["objects"][0]["pose"][0][3] == pytest.approx(0.1)
    assert "rotate" not in written["objects"][0]
    assert np.array_equal(both(phongvk.scene_from_dict(written))["color"], both(scene)["color"])
    bad = dict(written, objects=[dict(written["objects"][0], pose=[[1, 0, 0, 0]] * 4)])
    with pytest.raises(phongvk.SceneError, match=r"objects\[0\]\.pose: the last row must be 0 0 0 1"):
        phongvk.scene_from_dict(bad)
    both_keys = dict(written, objects=[dict(written["objects"][0], scale=2)])
    with pytest.raises(phongvk.SceneError, match=r"objects\[0\]\.scale: cannot be given with 'pose'"):
        phongvk.scene_from_dict(both_keys)


def test_poses_no_float_can_carry_are_clear_errors():
    scene = small_scene()
    with pytest.raises(ValueError, match=r"pose: row 0 has 1e\+300, beyond"):
        scene.add(*octahedron(), pose=np.diag([1e300, 1, 1, 1]))
    with pytest.raises(ValueError, match=r"pose: the upper 3x3 block is too close to singular"):
        scene.add(*octahedron(), pose=np.diag([1e-20, 1, 1, 1]))
    far = np.diag([1e15, 1, 1, 1])
    far[0, 3] = 9e14
    scene.add(*octahedron(), pose=far)
    with pytest.raises(phongvk.SceneError, match=r"objects\[0\]\.pose: places the mesh beyond the 1e\+15 m"):
        phongvk.Renderer("cpu").render(scene)
    written = {"camera": {"position": [0, -4, 0], "look_at": [0, 0, 0]}, "objects": [
        {"shape": "mesh", "vertices": [[0, 0, 0], [1, 0, 0], [0, 0, 1]], "faces": [[0, 1, 2]],
         "pose": [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 1e300, 1]]}]}
    with pytest.raises(phongvk.SceneError, match=r"objects\[0\]\.pose: the last row must be 0 0 0 1"):
        phongvk.scene_from_dict(written)
