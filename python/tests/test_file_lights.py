"""A glTF file's own lights (KHR_lights_punctual): placed by their nodes, moved with the object that
holds the file, converted to this contract's units (intensity / pi, inverse-square fall-off with
glTF's range window), left out on request, refused with the file's name when they cannot be
rendered. The GLB files come from meshoptimizer's gltfpack, a packer that keeps the extension."""

import base64
import json
import math
import pathlib
import shutil
import struct
import subprocess

import numpy as np
import pytest

import phongvk

# A 4 m square floor in glTF's x-z plane (y up), facing +y.
FLOOR = struct.pack("<12f", -2, 0, -2, 2, 0, -2, 2, 0, 2, -2, 0, 2) + struct.pack("<12f", *(0, 1, 0) * 4) + \
    struct.pack("<6H", 0, 2, 1, 0, 3, 2)
DOWN = [-math.sqrt(0.5), 0, 0, math.sqrt(0.5)]  # a node turned so that its -z axis points down (-y)
SPOT = {"type": "spot", "intensity": 20, "color": [1, 0.9, 0.7], "spot": {"innerConeAngle": 0.3, "outerConeAngle": 0.5}}
POINT = {"type": "point", "intensity": 3, "color": [0.3, 0.5, 1], "range": 3}


def write_gltf(path: pathlib.Path, lights, nodes) -> pathlib.Path:
    """The floor and light nodes ({"translation", "rotation", "light"}) placing `lights`."""
    gltf = {
        "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": list(range(len(nodes) + 1))}],
        "nodes": [{"mesh": 0}] + [{**{k: v for k, v in n.items() if k != "light"},
                                   "extensions": {"KHR_lights_punctual": {"light": n["light"]}}} for n in nodes],
        "extensionsUsed": ["KHR_lights_punctual"],
        "extensions": {"KHR_lights_punctual": {"lights": lights}},
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2}]}],
        "buffers": [{"byteLength": len(FLOOR),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(FLOOR).decode()}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 48},
                        {"buffer": 0, "byteOffset": 96, "byteLength": 12}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-2, 0, -2], "max": [2, 0, 2]},
                      {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"},
                      {"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"}],
    }
    path.write_text(json.dumps(gltf))
    return path


def lamp(folder: pathlib.Path) -> pathlib.Path:
    """A spot light 2 m above the floor's centre pointing down, a blue point light near a corner."""
    return write_gltf(folder / "lamp.gltf", [SPOT, POINT],
                      [{"translation": [0, 2, 0], "rotation": DOWN, "light": 0}, {"translation": [1.5, 0.5, 1.5], "light": 1}])


def both(scene):
    cpu, gpu = phongvk.Renderer("cpu").render(scene), phongvk.Renderer("gpu").render(scene)
    assert np.array_equal(cpu, gpu)
    return cpu


def placed(file, translate=(0, 0, 0), lights=(), **object_keys):
    """The file as an object at `translate`, seen from 4 m above it, lit per pixel."""
    x, y, z = translate
    return phongvk.scene_from_dict({
        "camera": {"position": [x, y, z + 4], "look_at": [x, y, z], "up": [0, 1, 0], "projection": "orthographic",
                   "ortho_height": 4.2, "width": 65, "height": 65},
        "render": {"shading": "phong"}, "lights": list(lights),
        "materials": {"white": {"ka": 0, "kd": 1, "ks": 0, "color": [1, 1, 1]}},
        "objects": [{"shape": "mesh", "file": str(file), "up": "y", "translate": list(translate), "material": "white",
                     **object_keys}]})


def test_a_model_alone_is_lit_by_its_own_lights_on_both_backends(tmp_path):
    file = lamp(tmp_path)
    shutil.which("gltfpack") or pytest.fail("gltfpack is missing: bash scripts/setup.sh --test installs it")
    packed = tmp_path / "lamp.glb"
    subprocess.run(["gltfpack", "-i", str(file), "-o", str(packed), "-noq"], check=True, capture_output=True)
    scene = phongvk.load_scene(file)
    scene.render_settings.shading = "phong"
    own = both(scene)
    gpu = phongvk.Renderer("gpu")
    gpu.render(scene)
    assert gpu.stats.lights == 2  # the file's two, in place of the light at the camera
    # gltfpack's GLB carries the same lights and floor: the same picture.
    glb = phongvk.load_scene(packed)
    glb.render_settings.shading = "phong"
    assert np.abs(both(glb).astype(int) - own.astype(int)).max() <= 1
    # Left out, the model is lit from the camera as any other.
    camera_lit = phongvk.load_scene(file, file_lights=False)
    camera_lit.render_settings.shading = "phong"
    assert not np.array_equal(both(camera_lit), own)
    with pytest.raises(phongvk.ArgumentError, match="applies to a model file rendered alone"):
        phongvk.load_scene(pathlib.Path(__file__).parents[2] / "scenes" / "basic.json", file_lights=False)


def test_the_spot_lights_the_disc_its_cone_reaches_and_moves_with_the_object(tmp_path):
    file = lamp(tmp_path)
    image = both(placed(file))
    # 2 m below the spot, its outer cone (0.5 rad) reaches 2 tan 0.5 = 1.093 m from the centre and
    # its inner one (0.3 rad) 0.619 m: 15.5 px a metre in this 65-pixel, 4.2 m view.
    brightness = image.astype(int).sum(axis=2)
    centre = brightness[32, 32]
    assert centre > 0
    assert brightness[32, 32 + int(0.55 * 15.5)] == centre  # inside the inner cone: as bright
    assert brightness[32, 32 + int(1.2 * 15.5)] < centre / 8  # beyond the outer cone: the point light's rim only
    # The same file 100 m away, the camera with it: the same bytes (lighting is relative to the objects).
    assert np.array_equal(both(placed(file, translate=(100, -50, 3))), image)
    # "file_lights": false, and the floor is dark (no other light, no ambient term).
    assert both(placed(file, file_lights=False)).max() == 0
    written = placed(file, file_lights=False).to_dict()
    assert written["objects"][0]["file_lights"] is False


def test_a_point_light_of_pi_candela_at_one_metre_gives_kd_times_its_colour(tmp_path):
    # intensity / pi (glTF's Lambert term is albedo / pi), 1 / d^2 at d = 1: 0.4 pi cd gives 0.4.
    file = write_gltf(tmp_path / "bulb.gltf", [{"type": "point", "intensity": 0.4 * math.pi}],
                      [{"translation": [0, 1, 0], "light": 0}])
    image = both(placed(file))
    assert tuple(image[32, 32]) == (102, 102, 102)
    # The same light written in the scene file, with the fall-off glTF's lights have.
    written = placed(tmp_path / "bulb.gltf", file_lights=False,
                     lights=[{"position": [0, 0, 1], "intensity": 0.4, "falloff": "inverse_square"}])
    assert np.array_equal(both(written), image)


@pytest.mark.parametrize("light, node, message", [
    ({"type": "area"}, {"light": 0}, r"KHR_lights_punctual.lights\[0\]: type is 'area', expected point, spot or directional"),
    ({"type": "point", "intensity": -1}, {"light": 0}, r"KHR_lights_punctual.lights\[0\]: intensity is -1, expected 0 to 1e\+30"),
    ({"type": "point"}, {"light": 3}, r"KHR_lights_punctual.lights\[3\] does not exist \(the file has 1 lights\)"),
    ({"type": "spot", "spot": {"innerConeAngle": 0.6, "outerConeAngle": 0.5}}, {"light": 0},
     r"KHR_lights_punctual.lights\[0\]: spot.innerConeAngle is 0.6, expected 0 or more and less than outerConeAngle"),
    ({"type": "point", "range": -2}, {"light": 0}, r"KHR_lights_punctual.lights\[0\]: range is -2, expected 1e-06 to 1e\+15"),
])
def test_a_light_that_cannot_be_rendered_is_an_error_naming_the_file(tmp_path, light, node, message):
    file = write_gltf(tmp_path / "bad.gltf", [light], [node])
    with pytest.raises(phongvk.SceneError, match=r"^objects\[0\].file: .*/bad.gltf: " + message):
        phongvk.Renderer("cpu").render(placed(file))


def test_the_scene_and_its_files_together_have_at_most_1024_lights(tmp_path):
    file = write_gltf(tmp_path / "many.gltf", [POINT], [{"translation": [0, 1, 0], "light": 0}])
    lights = [{"position": [0, 0, 1]}] * 1024
    with pytest.raises(phongvk.SceneError, match=r"the scene's 1024 lights and the 1 its model files place are more than "
                                                 r"the 1024 a scene may have"):
        phongvk.Renderer("cpu").render(placed(file, lights=lights))


def test_a_files_lights_cast_shadows_when_the_object_says_so(tmp_path):
    # A ball 1 m above the floor's centre, under the file's spot light 2 m up: its shadow on the
    # floor reaches about twice its 0.3 m radius, so the floor 0.45 m from the centre (7 pixels) is
    # seen past the ball and, with "file_light_shadows", in its shadow.
    file = lamp(tmp_path)

    def scene(**object_keys):
        d = placed(file, **object_keys).to_dict()
        d["objects"].append({"shape": "sphere", "center": [0, 0, 1], "radius": 0.3, "material": "white"})
        return phongvk.scene_from_dict(d)

    lit, shadowed = both(scene()), both(scene(file_light_shadows=True))
    bright = lit.astype(int).sum(axis=2)
    dark = shadowed.astype(int).sum(axis=2)
    assert bright[32, 39] > 0 and dark[32, 39] < bright[32, 39] / 4
    assert dark[32, 32 + 20] == bright[32, 32 + 20]  # the lit floor beyond the shadow, unchanged
    assert scene(file_light_shadows=True).to_dict()["objects"][0]["file_light_shadows"] is True
    assert "file_light_shadows" not in scene().to_dict()["objects"][0]
    # A model alone, likewise; the option is a model's alone, and needs the file's lights.
    gpu = phongvk.Renderer("gpu")
    gpu.render(phongvk.load_scene(file, file_light_shadows=True))
    assert gpu.stats.lights == 2
    with pytest.raises(phongvk.ArgumentError, match="need its lights"):
        phongvk.load_scene(file, file_lights=False, file_light_shadows=True)
    with pytest.raises(phongvk.ArgumentError, match="file_light_shadows"):
        phongvk.load_scene(pathlib.Path(__file__).parents[2] / "scenes" / "basic.json", file_light_shadows=True)
    with pytest.raises(phongvk.SceneError, match=r"objects\[0\].file_light_shadows: needs the file's lights"):
        scene(file_lights=False, file_light_shadows=True)
