"""A model drawn only from its back says so: a fitted camera that sees the back of every triangle
(normals facing away) gives a notice in the renderer's stats, a NoticeWarning from Python and a
line on the CLI's standard error; a model seen from its front gives none."""

import subprocess
import warnings

import pytest

import phongvk
from conftest import CLI, child_environment

# One triangle in the z = 0 plane; the fitted camera (direction [0.5, 1, -0.5]) looks from -y, +z.
FACING_CAMERA = [(0, 0, 0), (1, 0, 0), (0, 0, 1)]   # normal (P1 - P0) x (P2 - P0) = (0, -1, 0)
FACING_AWAY = [(0, 0, 0), (0, 0, 1), (1, 0, 0)]     # normal (0, 1, 0)


def write_ply(path, corners):
    lines = ["ply", "format ascii 1.0", "element vertex 3", "property float x", "property float y",
             "property float z", "element face 1", "property list uchar int vertex_indices", "end_header"]
    lines += ["%g %g %g" % c for c in corners] + ["3 0 1 2"]
    path.write_text("\n".join(lines) + "\n")
    return str(path)


@pytest.mark.parametrize("backend", ["cpu", "gpu"])
def test_a_model_seen_only_from_its_back_says_so(tmp_path, backend):
    renderer = phongvk.Renderer(backend)
    away = write_ply(tmp_path / "away.ply", FACING_AWAY)
    with pytest.warns(phongvk.NoticeWarning, match=r"away.ply: the fitted camera sees only the back of every triangle"):
        renderer.render(phongvk.load_scene(away))
    assert "only the back" in renderer.stats["notice"]
    towards = write_ply(tmp_path / "towards.ply", FACING_CAMERA)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        renderer.render(phongvk.load_scene(towards))
    assert renderer.stats["notice"] == ""


def test_the_cli_prints_the_notice(tmp_path):
    away = write_ply(tmp_path / "away.ply", FACING_AWAY)
    run = subprocess.run([str(CLI), "render", away, "-o", str(tmp_path / "a.png"), "--backend", "cpu"],
                         capture_output=True, text=True, env=child_environment(), check=True)
    assert "phongvk: notice: " + away + ": the fitted camera sees only the back" in run.stderr
    towards = write_ply(tmp_path / "towards.ply", FACING_CAMERA)
    run = subprocess.run([str(CLI), "render", towards, "-o", str(tmp_path / "t.png"), "--backend", "cpu"],
                         capture_output=True, text=True, env=child_environment(), check=True)
    assert "notice" not in run.stderr


def write_gltf(path, corners):
    """A one-triangle glTF 2.0 file, its buffer a data: URI."""
    import base64
    import json
    import struct
    data = struct.pack("<9f", *[v for c in corners for v in c])
    gltf = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
            "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
            "buffers": [{"byteLength": len(data),
                         "uri": "data:application/octet-stream;base64," + base64.b64encode(data).decode()}],
            "bufferViews": [{"buffer": 0, "byteLength": len(data)}],
            "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                           "min": [min(c[i] for c in corners) for i in range(3)],
                           "max": [max(c[i] for c in corners) for i in range(3)]}]}
    path.write_text(json.dumps(gltf))
    return str(path)


@pytest.mark.parametrize("writer, suffix", [(write_gltf, ".gltf"), (None, ".obj")])
def test_the_fitted_camera_sees_a_y_up_models_front(tmp_path, writer, suffix):
    """glTF's front faces +Z with Y up (and OBJ, exported y-up, is read the same way): a triangle
    facing +Z is seen from its front, one facing -Z from its back."""
    front, back = [(0, 0, 0), (1, 0, 0), (0, 1, 0)], [(0, 0, 0), (0, 1, 0), (1, 0, 0)]
    renderer = phongvk.Renderer("cpu")
    for corners, seen_from_back in ((front, False), (back, True)):
        path = tmp_path / ("model" + suffix)
        if writer:
            writer(path, corners)
        else:
            path.write_text("".join("v %g %g %g\n" % c for c in corners) + "f 1 2 3\n")
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            renderer.render(phongvk.load_scene(str(path)))
        assert ("only the back" in renderer.stats["notice"]) == seen_from_back
