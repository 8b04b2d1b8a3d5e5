"""A scene driven from code: typed cameras (look-at, camera-to-world poses in OpenGL's and
OpenCV's conventions, pinhole intrinsics), lights, and meshes placed, moved and removed by handle,
each checked against the same scene written as a dict, and against a numpy projection."""

import math
import time

import numpy as np
import pytest

import phongvk
from conftest import scene_path

LIGHTS = [{"position": [2, -3, 3]}]


def square(size=0.02):
    """A small square in the x-z plane about the origin, facing -y, as (vertices, faces)."""
    s = size / 2
    vertices = np.array([[-s, 0, -s], [s, 0, -s], [s, 0, s], [-s, 0, s]], np.float32)
    return vertices, np.array([[0, 1, 2], [0, 2, 3]])


def octahedron():
    v = np.array([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]], np.float32) * 0.5
    f = np.array([[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4], [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]])
    return v, f


def both(scene):
    """The scene on the reference and the compute port, which must agree; the image."""
    cpu, gpu = phongvk.Renderer("cpu").render(scene), phongvk.Renderer("gpu").render(scene)
    assert np.array_equal(cpu, gpu)
    return cpu


def translation(x, y, z):
    pose = np.eye(4)
    pose[:3, 3] = (x, y, z)
    return pose


def look_at_pose_opencv(eye, target, up=(0, 0, 1)):
    """A camera-to-world pose in OpenCV's convention (looks down +z, y down)."""
    eye, target, up = (np.asarray(a, float) for a in (eye, target, up))
    forward = (target - eye) / np.linalg.norm(target - eye)
    right = np.cross(forward, up)
    right /= np.linalg.norm(right)
    down = np.cross(forward, right)
    pose = np.eye(4)
    pose[:3, 0], pose[:3, 1], pose[:3, 2], pose[:3, 3] = right, down, forward, eye
    return pose


def test_a_typed_camera_and_lights_render_as_the_same_scene_written_as_a_dict():
    camera = {"position": [3, -2, 1.5], "look_at": [0, 0, 0], "up": [0, 0, 1], "fov": 50, "width": 96, "height": 64}
    lights = [{"position": [2, -3, 3], "intensity": 0.8, "color": [1, 0.9, 0.8]}, {"position": "camera"}]
    written = phongvk.scene_from_dict({"camera": camera, "lights": lights,
                                       "objects": [{"shape": "sphere", "radius": 0.6}]})
    built = phongvk.scene_from_dict({"camera": {"position": [0, -9, 0], "look_at": [0, 0, 0]}, "lights": [],
                                     "objects": [{"shape": "sphere", "radius": 0.6}]})
    built.camera = phongvk.Camera(position=(3, -2, 1.5), look_at=(0, 0, 0), fov=50, width=96, height=64)
    built.lights = [phongvk.Light(position=(2, -3, 3), intensity=0.8, color=(1, 0.9, 0.8)),
                    phongvk.Light(at_camera=True)]
    assert np.array_equal(both(built), both(written))
    assert (built.width, built.height) == (96, 64)
    assert built.camera.fov == 50 and tuple(built.camera.position) == (3, -2, 1.5)
    assert [light.at_camera for light in built.lights] == [False, True]
    assert repr(built.camera).startswith("phongvk.Camera(position=(3.0, -2.0, 1.5), look_at=(0.0, 0.0, 0.0)")


def test_a_camera_without_a_size_keeps_the_scenes():
    scene = phongvk.scene_from_dict({"camera": {"position": [3, 0, 0], "look_at": [0, 0, 0], "width": 80,
                                                "height": 60}, "objects": [{"shape": "cube"}]})
    scene.camera = phongvk.Camera(position=(0, -4, 1), look_at=(0, 0, 0))
    assert (scene.width, scene.height) == (80, 60)


CENTRED = (140.0, 140.0, 79.5, 59.5)  # fx, fy, cx, cy of a 160 x 120 image


@pytest.mark.parametrize("eye, intrinsics", [((3, -2, 1.5), CENTRED), ((-1.5, 2.5, 0.5), CENTRED),
                                             ((0.3, -3, -1), CENTRED), ((3, -2, 1.5), (150.0, 120.0, 70.25, 66.0)),
                                             ((-1.5, 2.5, 0.5), (110.0, 160.0, 95.0, 41.5))])
def test_poses_and_intrinsics_project_as_numpy_does(eye, intrinsics):
    """Markers rendered with a camera from intrinsics (square or not, centred or not) and an OpenCV
    pose land where numpy's pinhole projection u = fx X / Z + cx, v = fy Y / Z + cy puts them (the
    centroid of each marker's pixels within 0.5 px); a centred camera's pose in OpenGL's
    convention gives the same image."""
    width, height = 160, 120
    fx, fy, cx, cy = intrinsics
    pose = look_at_pose_opencv(eye, (0, 0, 0))
    scene = phongvk.scene_from_dict({"camera": {"position": [9, 9, 9], "look_at": [0, 0, 0]},
                                     "lights": [{"position": "camera"}], "objects": []})
    scene.camera = phongvk.Camera.from_intrinsics(fx, fy, cx, cy, width, height, pose=pose, convention="opencv")
    assert scene.camera.intrinsics == intrinsics
    points = np.array([[0, 0, 0], [0.4, 0.2, 0.1], [-0.3, 0.1, 0.3], [0.1, -0.4, -0.2]])
    vertices, faces = square(0.15)  # about 5 pixels across
    rotation = pose[:3, :3]
    marker = np.eye(4)
    marker[:3, :3] = rotation @ np.array([[1, 0, 0], [0, 0, 1], [0, -1, 0]]).T  # its -y toward the camera
    handle = scene.add(vertices, faces)
    gpu, cpu = phongvk.Renderer("gpu"), phongvk.Renderer("cpu")
    for x, y, z in (points - pose[:3, 3]) @ rotation:  # world to camera: R^T (p - t)
        marker[:3, 3] = pose[:3, 3] + rotation @ (x, y, z)
        scene.set_pose(handle, marker)  # one marker at a time: none hides another
        image, triangle, _ = gpu.render_visibility(scene)
        cpu_image, cpu_triangle, _ = cpu.render_visibility(scene)
        assert np.array_equal(image, cpu_image) and np.array_equal(triangle, cpu_triangle)
        ys, xs = np.nonzero(triangle != phongvk.NO_TRIANGLE)
        assert len(xs) > 4
        assert abs(xs.mean() - (fx * x / z + cx)) < 0.5 and abs(ys.mean() - (fy * y / z + cy)) < 0.5
    if intrinsics != CENTRED:
        return
    gl_pose = pose @ np.diag([1, -1, -1, 1])
    fov = math.degrees(2 * math.atan(height / (2 * fy)))
    as_gl = phongvk.Camera.from_pose(gl_pose, convention="opengl", fov=fov, width=width, height=height)
    same = scene.frame(0)
    same.camera = as_gl
    assert np.array_equal(phongvk.Renderer("cpu").render(same), cpu_image)


def test_an_orthographic_camera_projects_as_numpy_does():
    """Markers seen by an orthographic camera land where numpy's parallel projection puts them
    (u = (W - 1) / 2 + s r.(p - eye), v = (H - 1) / 2 - s u.(p - eye), s = H / ortho_height pixels
    per metre), with the same size and place however far along the view they are; both renderers
    give the same bytes, and the camera survives to_dict."""
    width, height, ortho_height = 160, 120, 3.0
    eye = np.array([3.0, -2.0, 1.5])
    pose = look_at_pose_opencv(eye, (0, 0, 0))
    rotation = pose[:3, :3]  # columns: right, down, forward
    scene = phongvk.scene_from_dict({"camera": {"position": [9, 9, 9], "look_at": [0, 0, 0]},
                                     "lights": [{"direction": list(rotation[:, 2])}], "objects": []})
    scene.camera = phongvk.Camera(position=tuple(eye), look_at=(0, 0, 0), width=width, height=height,
                                  ortho_height=ortho_height, near=0.1, far=30)
    assert scene.camera.ortho_height == ortho_height and "ortho_height=3.0" in repr(scene.camera)
    vertices, faces = square(0.15)
    marker = np.eye(4)
    marker[:3, :3] = rotation @ np.array([[1, 0, 0], [0, 0, 1], [0, -1, 0]]).T  # its -y toward the camera
    handle = scene.add(vertices, faces)
    gpu, cpu = phongvk.Renderer("gpu"), phongvk.Renderer("cpu")
    s = height / ortho_height
    for point in ([0, 0, 0], [0.9, 0.3, 0.2], [-0.7, 0.1, 0.6]):
        seen = []
        for along in (0.0, 8.0):  # the same marker 8 m further along the view
            marker[:3, 3] = np.array(point) + along * rotation[:, 2]
            scene.set_pose(handle, marker)
            image, triangle, _ = gpu.render_visibility(scene)
            cpu_image, cpu_triangle, _ = cpu.render_visibility(scene)
            assert np.array_equal(image, cpu_image) and np.array_equal(triangle, cpu_triangle)
            ys, xs = np.nonzero(triangle != phongvk.NO_TRIANGLE)
            seen.append((len(xs), xs.mean(), ys.mean()))
        x, y, _ = (np.array(point) - eye) @ rotation  # camera axes: right, down, forward
        count, u, v = seen[0]
        assert count > 16 and abs(seen[1][0] - count) <= 2  # one subpixel of rounding may move an edge
        assert abs(seen[1][1] - u) < 0.05 and abs(seen[1][2] - v) < 0.05
        assert abs(u - ((width - 1) / 2 + s * x)) < 0.5 and abs(v - ((height - 1) / 2 + s * y)) < 0.5
    assert phongvk.scene_from_dict(scene.to_dict()).camera == scene.camera
    posed = phongvk.Camera.from_pose(pose, convention="opencv", width=width, height=height, ortho_height=ortho_height)
    posed.near, posed.far = 0.1, 30
    assert posed.ortho_height == ortho_height and np.allclose(posed.position, eye)
    _, looking, _ = cpu.render_visibility(scene)
    scene.camera = posed  # the same camera from its pose: the same picture, to float rounding of its axes
    _, posed_ids, _ = cpu.render_visibility(scene)
    covered = looking != phongvk.NO_TRIANGLE
    assert covered.sum() > 16 and abs(int((posed_ids != phongvk.NO_TRIANGLE).sum()) - int(covered.sum())) <= 2
    assert (posed_ids[covered] == looking[covered]).mean() > 0.9


def test_objects_are_placed_moved_and_removed_by_handle(tmp_path):
    vertices, faces = octahedron()
    obj = tmp_path / "octahedron.obj"
    obj.write_text("".join("v %.9g %.9g %.9g\n" % tuple(p) for p in vertices.tolist()) +
                   "".join("f %d %d %d\n" % tuple(x + 1 for x in t) for t in faces.tolist()))
    camera = {"position": [3, -4, 2], "look_at": [0.5, 0, 0], "width": 96, "height": 64}

    def written(*translates):
        objects = [{"shape": "mesh", "file": "octahedron.obj", "translate": list(t)} for t in translates]
        return phongvk.scene_from_dict({"camera": camera, "lights": LIGHTS, "objects": objects},
                                       base_dir=str(tmp_path))

    scene = phongvk.scene_from_dict({"camera": camera, "lights": LIGHTS, "objects": []})
    a = scene.add(vertices, faces, pose=translation(1, 0, 0))
    b = scene.add(vertices, faces, pose=translation(0, 0.5, 0.25))
    assert scene.object_count == 2
    assert np.array_equal(both(scene), both(written((1, 0, 0), (0, 0.5, 0.25))))
    scene.set_pose(a, translation(-0.5, 0, 0.5))
    assert np.array_equal(both(scene), both(written((-0.5, 0, 0.5), (0, 0.5, 0.25))))
    scene.remove(a)
    assert scene.object_count == 1
    assert np.array_equal(both(scene), both(written((0, 0.5, 0.25))))
    with pytest.raises(IndexError, match=r"object %d was removed from this scene" % a):
        scene.set_pose(a, np.eye(4))
    with pytest.raises(IndexError):
        scene.remove(a)
    scene.set_pose(b, translation(0, 0, 0))
    assert np.array_equal(both(scene), both(written((0, 0, 0))))


def test_a_pose_turns_the_mesh_as_its_matrix_says():
    """A quarter turn about z in the pose: the rendered image equals the mesh whose vertices numpy
    turned, up to where both round (the keys name the same triangles at every pixel but edges)."""
    vertices = np.array([[0, 0, 0], [2.4, 0, 0], [0, 0.9, 0]], np.float32)  # in the x-y plane, facing the camera
    faces = np.array([[0, 1, 2]])
    turn = np.array([[0, -1, 0, 0], [1, 0, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]], float)
    base = {"camera": {"position": [0, 0, 4], "look_at": [0, 0, 0], "up": [0, 1, 0], "width": 128, "height": 128},
            "lights": [{"position": [0, 0, 4]}], "objects": []}
    by_pose, by_numpy = phongvk.scene_from_dict(base), phongvk.scene_from_dict(base)
    by_pose.add(vertices, faces, pose=turn, closed=False)
    by_numpy.add((vertices @ turn[:3, :3].T).astype(np.float32), faces, closed=False)
    renderer = phongvk.Renderer("cpu")
    covered_pose = renderer.render_visibility(by_pose)[1] != phongvk.NO_TRIANGLE
    covered_numpy = renderer.render_visibility(by_numpy)[1] != phongvk.NO_TRIANGLE
    assert covered_pose.sum() > 100
    assert (covered_pose != covered_numpy).sum() <= 2 * 128


def test_triangles_are_the_built_geometry_in_world_coordinates():
    """Scene.triangles: a posed mesh's vertices as numpy moves them, the tessellated shapes of a
    scene file within its bounds, each triangle with its object."""
    vertices = np.array([[0, 0, 0], [2.4, 0, 0], [0, 0.9, 0]], np.float32)
    pose = translation(1, 2, 3)
    pose[:3, :3] = [[0, -1, 0], [1, 0, 0], [0, 0, 1]]
    scene = phongvk.load_scene(scene_path("scenes/paper/fig3_two_lights.json"))
    scene.add(vertices, np.array([[0, 1, 2]]), pose=pose)
    t = scene.triangles()
    assert t["vertices"].dtype == np.float32 and t["normals"].shape == t["vertices"].shape
    assert t["faces"].shape == (len(t["objects"]), 3) and t["objects"].dtype == np.int32
    assert sorted(set(t["objects"].tolist())) == [0, 1, 2]  # sphere, ground, the added triangle
    added = t["vertices"][t["faces"][t["objects"] == 2][0]]
    np.testing.assert_allclose(added, vertices @ pose[:3, :3].T + pose[:3, 3], atol=1e-6)
    np.testing.assert_allclose(np.linalg.norm(t["normals"], axis=1), 1, atol=1e-6)
    low, high = np.array(scene.bounds)
    assert (t["vertices"] >= low - 1e-6).all() and (t["vertices"] <= high + 1e-6).all()
    assert np.allclose(t["vertices"].min(0), low, atol=1e-6) and np.allclose(t["vertices"].max(0), high, atol=1e-6)


def test_added_objects_keep_their_poses_in_every_frame():
    path = scene_path("scenes/paper/fig6_orbit_red.json")
    scene = phongvk.load_scene(path)
    vertices, faces = octahedron()
    handle = scene.add(vertices, faces, pose=translation(0, 0, 1.5))
    scene.set_pose(handle, translation(0, 0, 2))
    expected = phongvk.load_scene(path).frame(10)
    expected.add(vertices, faces, pose=translation(0, 0, 2))
    frame = scene.frame(10)
    assert frame.object_count == expected.object_count
    renderer = phongvk.Renderer("cpu")
    assert np.array_equal(renderer.render(frame, 96, 64), renderer.render(expected, 96, 64))


@pytest.mark.parametrize("call, error, message", [
    (lambda s: setattr(s, "camera", phongvk.Camera(position=(3, 0, 0), fov=200)), phongvk.SceneError,
     r"camera.fov: must be > 0 and < 180, got 200"),
    (lambda s: setattr(s, "camera", phongvk.Camera(position=(math.nan, 0, 0))), ValueError,
     r"camera.position\[0\]: must be finite, got nan"),
    (lambda s: setattr(s, "camera", phongvk.Camera(position=(0, 0, 3), look_at=(0, 0, 0), up=(0, 0, 1))),
     phongvk.SceneError, r"camera.up: parallel to the view direction"),
    (lambda s: setattr(s, "lights", [phongvk.Light(intensity=-1)]), phongvk.SceneError,
     r"lights\[0\].intensity: must be >= 0, got -1"),
    (lambda s: phongvk.Camera.from_pose(np.diag([1, 1, 2, 1])), ValueError, r"pose: the upper 3x3 block is not a rotation"),
    (lambda s: phongvk.Camera.from_pose(np.diag([1, 1, -1, 1])), ValueError, r"pose: the upper 3x3 block mirrors"),
    (lambda s: phongvk.Camera.from_pose(np.eye(4), convention="blender"), ValueError, r"convention: expected 'opengl'"),
    (lambda s: phongvk.Camera.from_intrinsics(0, 110, 79.5, 59.5, 160, 120), ValueError,
     r"fx: must be a positive focal length in pixels, got 0"),
    (lambda s: setattr(s, "camera", phongvk.Camera.from_intrinsics(100, 100, 40000.5, 59.5, 160, 120)),
     phongvk.SceneError, r"camera.cx: must be between -16384 and 32768, got 40000.5"),
    (lambda s: s.add(*square(), pose=np.zeros((4, 4))), ValueError, r"pose: the last row must be 0 0 0 1"),
    (lambda s: s.add(*square(), pose=np.diag([1, 0, 1, 1])), ValueError, r"pose: the upper 3x3 block is not invertible"),
    (lambda s: s.add(*square(), pose=np.eye(3)), ValueError, r"pose: expected a 4x4 matrix, got shape \(3, 3\)"),
    (lambda s: s.add(*square(), pose=translation(2e15, 0, 0)), ValueError, r"pose: the translation 2e\+15 is beyond"),
])
def test_bad_values_are_clear_errors_and_change_nothing(call, error, message):
    scene = phongvk.scene_from_dict({"camera": {"position": [3, -2, 1], "look_at": [0, 0, 0], "width": 32, "height": 24},
                                     "lights": LIGHTS, "objects": [{"shape": "cube"}]})
    before = phongvk.Renderer("cpu").render(scene)
    with pytest.raises(error, match=message):
        call(scene)
    assert scene.object_count == 1
    assert np.array_equal(phongvk.Renderer("cpu").render(scene), before)


def test_a_directional_light_renders_as_the_same_light_written():
    written = phongvk.scene_from_dict({"camera": {"position": [3, -2, 1.5], "look_at": [0, 0, 0], "width": 96,
                                                  "height": 64},
                                       "lights": [{"direction": [-1, 1, -2], "intensity": 0.8, "color": [1, 0.9, 0.7]}],
                                       "objects": [{"shape": "sphere", "radius": 0.6}]})
    built = phongvk.scene_from_dict({"camera": {"position": [3, -2, 1.5], "look_at": [0, 0, 0], "width": 96,
                                                "height": 64}, "objects": [{"shape": "sphere", "radius": 0.6}]})
    built.lights = [phongvk.Light(direction=(-1, 1, -2), intensity=0.8, color=(1, 0.9, 0.7))]
    image = both(built)
    assert np.array_equal(image, both(written))
    assert tuple(built.lights[0].direction) == (-1.0, 1.0, -2.0) and phongvk.Light().direction is None
    # The sun reaches a far copy of the sphere as brightly as the near one: no fall-off.
    far = phongvk.scene_from_dict({"camera": {"position": [3003, -2, 1.5], "look_at": [3000, 0, 0], "width": 96,
                                              "height": 64},
                                   "lights": [{"direction": [-1, 1, -2], "intensity": 0.8, "color": [1, 0.9, 0.7]}],
                                   "objects": [{"shape": "sphere", "center": [3000, 0, 0], "radius": 0.6}]})
    assert np.abs(both(far).astype(int) - image.astype(int)).max() <= 1
    with pytest.raises(phongvk.SceneError, match=r"lights\[0\].direction: must have a non-zero finite length"):
        built.lights = [phongvk.Light(direction=(0, 0, 0))]


def test_a_spot_light_renders_as_the_same_light_written_and_lights_only_its_cone():
    def scene(lights):
        return phongvk.scene_from_dict({
            "camera": {"position": [0, -4, 4], "look_at": [0, 0, 0], "width": 96, "height": 64},
            "render": {"shading": "phong"}, "lights": lights,
            "objects": [{"shape": "cube", "center": [0, 0, -0.05], "size": 4, "scale": [1, 1, 0.025]}]})
    spot = {"position": [0, 0, 2], "direction": [0, 0, -1], "inner_cone": 10, "outer_cone": 20}
    written, built, dark = scene([spot]), scene([]), both(scene([]))
    built.lights = [phongvk.Light(position=(0, 0, 2), spot=(0, 0, -1), inner_cone=10, outer_cone=20)]
    image = both(built)
    assert np.array_equal(image, both(written))
    assert built.to_dict()["lights"] == [{"direction": [0.0, 0.0, -1.0], "position": [0.0, 0.0, 2.0],
                                          "intensity": 1.0, "color": [1.0, 1.0, 1.0], "inner_cone": 10.0,
                                          "outer_cone": 20.0}]
    lit = np.any(image != dark, axis=2)
    # The lit disc's radius on the floor (at 2 m below the light) is 2 tan 20 = 0.73 m of the 4 m floor.
    assert 0 < lit.sum() < 0.25 * lit.size
    light = built.lights[0]
    assert light.spot == (0.0, 0.0, -1.0) and light.direction is None and "spot=(0.0, 0.0, -1.0)" in repr(light)
    light.outer_cone = 40  # a live view: the wider cone lights more of the floor
    assert np.any(both(built) != dark, axis=2).sum() > lit.sum()
    with pytest.raises(phongvk.ArgumentError, match="direction= .* or spot= .*, not both"):
        phongvk.Light(direction=(0, 0, -1), spot=(0, 0, -1))
    with pytest.raises(phongvk.SceneError, match=r"lights\[0\].outer_cone: must be more than 0 and at most 90"):
        light.outer_cone = 100
    assert built.lights[0].outer_cone == 40

def test_a_shadowed_light_darkens_what_an_object_hides_from_it_on_both_backends():
    def scene(shadows, casts=True):
        return phongvk.scene_from_dict({
            "camera": {"position": [0, -3, 4], "look_at": [0, 0, 0], "width": 96, "height": 64},
            "render": {"shading": "phong"}, "lights": [{"position": [0, 0, 3], "shadows": shadows}],
            "objects": [{"shape": "cube", "center": [0, 0, -0.05], "size": 4, "scale": [1, 1, 0.025]},
                        {"shape": "sphere", "center": [0, 0, 1], "radius": 0.4, "cast_shadows": casts}]})
    lit, shadowed, uncast = both(scene(False)), both(scene(True)), both(scene(True, casts=False))
    assert shadowed.sum() < lit.sum() and np.array_equal(uncast, lit)
    built = scene(False)
    built.lights = [phongvk.Light(position=(0, 0, 3), shadows=True)]
    assert np.array_equal(both(built), shadowed)
    assert built.to_dict()["lights"][0]["shadows"] is True
    assert scene(True, casts=False).to_dict()["objects"][1]["cast_shadows"] is False
    counts = [phongvk.Renderer(b).render(built, outputs=["lights"])["lights"] for b in ("cpu", "gpu")]
    assert np.array_equal(counts[0], counts[1]) and counts[0].dtype == np.int32
    assert set(np.unique(counts[0])) == {-1, 0, 1}  # empty, in the sphere's shadow, lit
    built.lights[0].shadows = False  # a live view: the shadow goes
    assert np.array_equal(both(built), lit)

# ---- materials and render settings as values ----

def written_scene(tmp_path, material=None, **more):
    """The scene Scene(96, 64) starts from, as a dict: the default camera at that size, a light at
    the camera, and the octahedron as an OBJ file with `material` (none: the default)."""
    vertices, faces = octahedron()
    obj = tmp_path / "octahedron.obj"
    if not obj.exists():
        obj.write_text("".join("v %.9g %.9g %.9g\n" % tuple(p) for p in vertices.tolist()) +
                       "".join("f %d %d %d\n" % tuple(x + 1 for x in t) for t in faces.tolist()))
    mesh = {"shape": "mesh", "file": "octahedron.obj"}
    if material is not None:
        mesh["material"] = material
    return phongvk.scene_from_dict(dict({"camera": {"position": [0, -5, 2], "look_at": [0, 0, 0], "width": 96,
                                                    "height": 64},
                                         "lights": [{"position": "camera"}], "objects": [mesh]}, **more),
                                   base_dir=str(tmp_path))


# Material() and the material a mesh added without one gets in Scene(width, height): the file's
# default without fall-off, as a model file rendered alone has.
NO_FALL_OFF = {"attenuation": [1, 0, 0]}


def built_scene(material=None):
    scene = phongvk.Scene(96, 64)
    scene.add(*octahedron(), material=material)
    return scene


MATERIAL_FIELDS = [{"ka": 0.6}, {"kd": 0.3}, {"ks": 0.1}, {"n": 40}, {"attenuation": [1, 0.05, 0]},
                   {"color": [0.9, 0.3, 0.1]},
                   {"ka": 0.3, "kd": 0.7, "ks": 1, "n": 3, "attenuation": [0.5, 0, 0.01], "color": [0.2, 1, 0.6]}]


@pytest.mark.parametrize("fields", MATERIAL_FIELDS)
def test_every_material_field_renders_as_the_file_says_it(tmp_path, fields):
    expected = both(written_scene(tmp_path, dict(NO_FALL_OFF, **fields)))
    assert np.array_equal(both(built_scene(phongvk.Material(**fields))), expected)
    assert np.array_equal(both(built_scene(fields)), expected)  # a dict of the fields, as before
    material = phongvk.Material()
    for key, value in fields.items():
        setattr(material, key, value)
    assert np.array_equal(both(built_scene(material)), expected)


RENDER_FIELDS = [({"shading": "flat"}, {}), ({"shading": "phong"}, {}), ({"specular": "blinn"}, {}),
                 ({"interpolation": "screen"}, {}), ({"samples": 4}, {}), ({"samples": 16}, {}),
                 ({}, {"background": [0.25, 0.5, 0.75]}),
                 ({"shading": "phong", "specular": "blinn", "interpolation": "screen", "samples": 9},
                  {"background": [1, 0.5, 0]})]


@pytest.mark.parametrize("render, top", RENDER_FIELDS)
def test_every_render_setting_renders_as_the_file_says_it(tmp_path, render, top):
    file = written_scene(tmp_path, NO_FALL_OFF, render=render, **top)
    expected = both(file)
    settings = phongvk.RenderSettings(**render, **top)
    assert file.render_settings == settings
    scene = built_scene()
    assert np.array_equal(both(scene.with_render(settings)), expected)
    assert np.array_equal(both(scene.with_render(dict(render, **top))), expected)
    assert np.array_equal(both(scene.with_render(**render, **top)), expected)
    scene.render_settings = settings
    assert scene.render_settings == settings
    assert np.array_equal(both(scene), expected)


def test_a_scene_built_in_code_is_well_exposed_by_default():
    # The light at the camera, 5.4 m from the grey mesh: with the file's fall-off [1, 0.2, 0.2] the
    # brightest pixel is 55 of 255; without it, as a model file alone, 196.
    scene = built_scene()
    scene.camera = phongvk.Camera(position=[0, -5, 2], look_at=[0, 0, 0], width=96, height=64)
    assert phongvk.Renderer("cpu").render(scene).max() > 180
    dim = built_scene(phongvk.Material(attenuation=(1, 0.2, 0.2)))
    dim.camera = scene.camera
    assert phongvk.Renderer("cpu").render(dim).max() < 100


def test_the_ambient_light_renders_as_the_file_says_it(tmp_path):
    scene = built_scene(phongvk.Material(ka=0.8))
    assert tuple(scene.ambient) == (1, 1, 1)
    scene.ambient = (0.5, 0.25, 0)
    assert tuple(scene.ambient) == (0.5, 0.25, 0)
    assert np.array_equal(both(scene), both(written_scene(tmp_path, dict(NO_FALL_OFF, ka=0.8), ambient=[0.5, 0.25, 0])))
    with pytest.raises(phongvk.SceneError, match=r"^ambient\[1\]: must be >= 0, got -1$"):
        scene.ambient = (1, -1, 0)


def test_defaults_are_the_files_defaults(tmp_path):
    material = phongvk.Material()
    assert (material.ka, material.kd, material.ks, material.n) == (0.15, 1.0, 0.8, 10.0)
    assert tuple(material.attenuation) == (1, 0, 0) and tuple(material.color) == (0.8, 0.8, 0.8)
    assert written_scene(tmp_path).render_settings == phongvk.RenderSettings()
    settings = phongvk.RenderSettings()
    assert (settings.shading, settings.specular, settings.interpolation, settings.samples) == \
        ("gouraud", "phong", "perspective", 1)
    assert tuple(settings.background) == (0, 0, 0)
    expected = both(written_scene(tmp_path, NO_FALL_OFF))
    assert np.array_equal(both(built_scene(phongvk.Material())), expected)
    assert np.array_equal(both(built_scene()), expected)
    file_default = phongvk.Material(attenuation=(1, 0.2, 0.2))
    assert np.array_equal(both(built_scene(file_default)), both(written_scene(tmp_path)))
    empty = phongvk.Scene(96, 64)
    assert (empty.width, empty.height, empty.object_count) == (96, 64, 0)
    assert [light.at_camera for light in empty.lights] == [True]
    with pytest.raises(phongvk.SceneError, match="objects: scene has no objects"):
        phongvk.Renderer("cpu").render(empty)


@pytest.mark.parametrize("fields", [{"ka": -0.5}, {"kd": -1}, {"ks": -1}, {"n": -2}, {"ks": 1e39},
                                    {"attenuation": [0, 0, 0]}, {"attenuation": [1, -3, 1]},
                                    {"color": [0.5, -0.1, 0]}])
def test_a_bad_material_fails_with_the_files_message(tmp_path, fields):
    with pytest.raises(phongvk.SceneError) as file_error:
        written_scene(tmp_path, fields)
    message = str(file_error.value)
    assert "objects[0].material." + next(iter(fields)) in message
    scene = phongvk.Scene(96, 64)
    for material in (phongvk.Material(**fields), fields):
        with pytest.raises(phongvk.SceneError) as error:
            scene.add(*octahedron(), material=material)
        assert str(error.value) == message
    assert scene.object_count == 0


@pytest.mark.parametrize("call, error, message", [
    (lambda s: s.add(*octahedron(), material=phongvk.Material(ka=math.nan)), ValueError,
     r"material.ka: must be finite, got nan"),
    (lambda s: s.add(*octahedron(), material={"shine": 3}), phongvk.SceneError,
     r"material: unknown key 'shine' \(allowed: attenuation, color, ka, kd, ks, n, texture\)"),
    (lambda s: s.add(*octahedron(), material="gold"), phongvk.SceneError,
     r"objects\[0\].material: unknown material 'gold'"),
    (lambda s: s.add(*octahedron(), material=3), TypeError, r"material: expected a phongvk.Material"),
    (lambda s: setattr(s, "render_settings", phongvk.RenderSettings(samples=3)), phongvk.SceneError,
     r"render.samples: must be 1, 4, 9 or 16 \(a regular grid of samples per pixel\), got 3"),
    (lambda s: setattr(s, "render_settings", phongvk.RenderSettings(background=(1.5, 0, 0))), phongvk.SceneError,
     r"background\[0\]: must be between 0 and 1, got 1.5"),
    (lambda s: phongvk.RenderSettings(shading="smooth"), phongvk.SceneError,
     r"render.shading: must be one of gouraud, flat, phong, got 'smooth'"),
    (lambda s: setattr(phongvk.RenderSettings(), "specular", "cook"), phongvk.SceneError,
     r"render.specular: must be one of phong, blinn, got 'cook'"),
    (lambda s: s.with_render(shading="smooth"), phongvk.SceneError, r"render.shading: must be one of"),
    (lambda s: s.with_render(gamma=2.2), phongvk.SceneError,
     r"render: unknown key 'gamma' \(allowed: background, interpolation, line_width, point_size, samples, shading, specular, "
     r"texture_filter\)"),
    (lambda s: s.with_render("phong"), TypeError, r"settings: expected a phongvk.RenderSettings"),
])
def test_bad_materials_and_settings_are_clear_errors(call, error, message):
    scene = phongvk.Scene(32, 24)
    with pytest.raises(error, match=message):
        call(scene)
    assert scene.object_count == 0 and scene.render_settings == phongvk.RenderSettings()


def test_materials_and_settings_say_what_they_are():
    assert repr(phongvk.Material(ks=0.2)) == ("phongvk.Material(ka=0.15, kd=1.0, ks=0.2, n=10.0, "
                                              "attenuation=(1.0, 0.0, 0.0), color=(0.8, 0.8, 0.8))")
    assert repr(phongvk.RenderSettings(shading="phong", samples=4)) == (
        "phongvk.RenderSettings(shading='phong', specular='phong', interpolation='perspective', samples=4, "
        "background=(0.0, 0.0, 0.0), texture_filter='bilinear', point_size=1.0, line_width=1.0)")
    assert "shininess" in phongvk.Material.__doc__ and "samples" in phongvk.RenderSettings.__doc__
    assert "width x height" in phongvk.Scene.__init__.__doc__
    assert phongvk.Material(ks=0.2) != phongvk.Material()


def test_a_mesh_built_once_is_placed_many_times():
    """phongvk.Mesh: from arrays or a file, placed by add and add_mesh as often as asked; the
    picture is that of the same arrays added each time, or of the scene file's mesh object."""
    vertices, faces = square(0.3)
    mesh = phongvk.Mesh(vertices, faces)
    assert (mesh.vertex_count, mesh.triangle_count) == (4, 2) and repr(mesh) == "<phongvk.Mesh: 4 vertices, 2 triangles>"
    shared, copied = phongvk.Scene(80, 60), phongvk.Scene(80, 60)
    for x in (-0.4, 0.0, 0.4):
        shared.add(mesh, pose=translation(x, 0, 0.1 * x))
        copied.add(vertices, faces, pose=translation(x, 0, 0.1 * x))
    shared.add_mesh(mesh, material=phongvk.Material(color=(1, 0, 0)))
    copied.add_mesh(vertices, faces, material=phongvk.Material(color=(1, 0, 0)))
    gpu, cpu = phongvk.Renderer("gpu"), phongvk.Renderer("cpu")
    assert np.array_equal(gpu.render(shared), cpu.render(copied))
    torus = scene_path("scenes/meshes/torus.obj")
    written = phongvk.scene_from_dict({"camera": {"position": [0, -4, 2], "look_at": [0, 0, 0], "width": 80, "height": 60},
                                       "lights": [{"position": "camera"}],
                                       "objects": [{"shape": "mesh", "file": torus, "up": "z",
                                                    "material": {"attenuation": [1, 0, 0]}}]})
    built = phongvk.Scene(80, 60)
    built.camera = written.camera
    built.add(phongvk.Mesh.from_file(torus, up="z"))
    assert np.array_equal(cpu.render(built), cpu.render(written))
    with pytest.raises(TypeError, match=r"faces, normals, uvs and colors: not given with a phongvk.Mesh"):
        built.add(mesh, faces)
    with pytest.raises(phongvk.ArgumentError, match=r"path: expected a mesh file"):
        phongvk.Mesh.from_file(scene_path("scenes/basic.json"))
    with pytest.raises(phongvk.ArgumentError, match=r"up: expected 'y' or 'z', got 'x'"):
        phongvk.Mesh.from_file(torus, up="x")


def test_a_handle_names_one_object_of_the_scene_that_gave_it():
    """Handles do not restart in every scene: one scene's handle given to another is an error there,
    not that scene's object of the same number. A derived scene holds the objects it was made with,
    under their handles, and gives handles of its own from then on."""
    mesh = phongvk.Mesh(*octahedron())
    a, b = phongvk.Scene(8, 8), phongvk.Scene(8, 8)
    from_a = a.add(mesh)
    from_b = b.add(mesh, pose=translation(1, 0, 0))
    assert from_a != from_b
    bounds = b.bounds
    for call in (lambda: b.set_pose(from_a, np.eye(4)), lambda: b.remove(from_a)):
        with pytest.raises(IndexError, match=r"^object %d belongs to another scene" % from_a):
            call()
    assert b.object_count == 1 and b.bounds == bounds
    derived = a.with_render(samples=4)
    derived.set_pose(from_a, translation(0, 0, 1))
    assert derived.bounds != a.bounds
    later_in_a, later_in_derived = a.add(mesh), derived.add(mesh)
    assert later_in_a != later_in_derived
    with pytest.raises(IndexError, match=r"belongs to another scene"):
        a.remove(later_in_derived)
    a.remove(from_a)
    with pytest.raises(IndexError, match=r"^object %d was removed from this scene$" % from_a):
        a.remove(from_a)


def test_a_hundred_thousand_adds_take_seconds_not_hours():
    """An add changes the scene in place (no copy of the objects before it): 100,000 adds of a small
    sphere take well under 10 s (each copying the scene, 20,000 took a minute)."""
    sphere = phongvk.scene_from_dict({"camera": {"position": [0, -3, 0], "look_at": [0, 0, 0], "width": 8, "height": 8},
                                      "objects": [{"shape": "icosphere", "radius": 0.01, "subdivide": 1}]}).triangles()
    mesh = phongvk.Mesh(sphere["vertices"], sphere["faces"])
    scene = phongvk.Scene(64, 48)
    start = time.perf_counter()
    for i in range(100_000):
        scene.add(mesh, pose=translation(i % 100 * 0.02, i // 100 % 100 * 0.02, i // 10_000 * 0.02))
    assert time.perf_counter() - start < 10
    assert scene.object_count == 100_000
