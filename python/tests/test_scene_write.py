"""Scenes written back as the scene file's JSON (Scene.to_json, Scene.to_dict): read by
scene_from_dict they render the same bytes and write the same text, for a scene built in code and
for scene files."""

import json

import numpy as np
import pytest

import phongvk
from conftest import scene_path


def tetrahedron():
    v = np.array([[0.1, 0.2, 0.3], [1.1, 0.05, 0.1], [0.3, 0.9, 0.2], [0.4, 0.35, 1.2]], np.float32)
    return v, np.array([[0, 2, 1], [0, 1, 3], [1, 2, 3], [2, 0, 3]])


def round_trip(scene):
    """The scene read back from its dict renders the same bytes and writes the same text."""
    d = scene.to_dict()
    assert d == json.loads(scene.to_json())
    back = phongvk.scene_from_dict(d)
    assert back.to_json() == scene.to_json()
    cpu = phongvk.Renderer("cpu")
    want = cpu.render(scene)
    assert np.array_equal(cpu.render(back), want)
    return want


def test_a_scene_built_in_code_renders_the_same_bytes_from_its_dict():
    scene = phongvk.Scene(160, 120)
    pose = np.array([[1, 0, 0, 0.4], [0, 0, 1, -3.1], [0, -1, 0, 1.3], [0, 0, 0, 1]])  # OpenCV: along +y, z up
    scene.camera = phongvk.Camera.from_intrinsics(141.5, 127.25, 83.5, 52.0, 160, 120, pose=pose, convention="opencv")
    scene.lights = [phongvk.Light(position=(1.3, -2.2, 2.9), intensity=0.7, color=(1, 0.9, 0.8)),
                    phongvk.Light(at_camera=True, intensity=0.3),
                    phongvk.Light(direction=(-0.3, 0.6, -1), intensity=0.45, color=(0.2, 0.4, 1))]
    scene.ambient = (0.31, 0.2, 0.17)
    scene.render_settings = phongvk.RenderSettings(shading="phong", specular="blinn", interpolation="screen",
                                                   samples=4, background=(0.05, 0.1, 0.15))
    v, f = tetrahedron()
    sheared = np.array([[0.9, 0.35, -0.2, 0.25], [-0.1, 1.3, 0.45, -0.4], [0.3, -0.2, -0.7, 0.15], [0, 0, 0, 1]])
    scene.add(v, f, pose=sheared, material=phongvk.Material(ka=0.21, kd=0.7, ks=0.55, n=23.5,
                                                             attenuation=(1, 0.1, 0.05), color=(0.9, 0.3, 0.2)))
    moved = scene.add(v, f, material={"ks": 0.1}, closed=True)
    scene.set_pose(moved, np.array([[0.5, 0, 0, -1.2], [0, 0.7, 0.2, 0.3], [0, 0, 2, -0.5], [0, 0, 0, 1]]))
    scene.add_mesh(v * 0.5, f, normals=v - v.mean(axis=0))
    image = round_trip(scene)
    assert (image != image[0, 0]).any(axis=2).sum() > 1000
    d = scene.to_dict()
    assert d["camera"]["fx"] == 141.5 and d["camera"]["cy"] == 52.0
    assert d["objects"][0]["pose"] == sheared.tolist()
    assert len(d["objects"][2]["vertices"]) == 4 and len(d["objects"][2]["normals"]) == 4
    back = phongvk.scene_from_dict(d)
    assert back.camera.intrinsics == scene.camera.intrinsics
    assert back.render_settings == scene.render_settings
    assert tuple(back.ambient) == tuple(scene.ambient)


@pytest.mark.parametrize("path", ["scenes/basic.json", "scenes/mesh_torus.json", "scenes/intrinsics.json",
                                  "scenes/shading/samples.json"])
def test_a_file_scene_renders_the_same_bytes_from_its_dict(path):
    round_trip(phongvk.load_scene(scene_path(path)))


def test_to_dict_says_everything_and_names_mesh_files_absolutely():
    d = phongvk.load_scene(scene_path("scenes/mesh_torus.json")).to_dict()
    assert set(d) == {"camera", "background", "ambient", "lights", "materials", "objects", "render"}
    mesh = [o for o in d["objects"] if o["shape"] == "mesh"][0]
    assert mesh["file"] == scene_path("scenes/meshes/torus.obj")
    assert {"scale", "rotate", "translate", "up", "closed", "subdivide", "material"} <= set(mesh)


def test_a_model_files_textures_survive_the_dict():
    # A textured OBJ added as a Mesh: its texture travels in the dict as a PNG data URI, so the
    # scene read back renders every texel, not the untextured colours.
    scene = phongvk.Scene(120, 90)
    scene.camera = phongvk.Camera(position=(2.2, -3.1, 2.4), look_at=(0, 0, 0))
    scene.add(phongvk.Mesh.from_file(scene_path("scenes/meshes/textured_cube.obj")))
    image = round_trip(scene)
    assert len(np.unique(image.reshape(-1, 3), axis=0)) > 100
    mesh = scene.to_dict()["objects"][0]
    assert mesh["textures"][0]["image"].startswith("data:image/png;base64,")
    assert len(mesh["texture_ids"]) == len(mesh["vertices"])
