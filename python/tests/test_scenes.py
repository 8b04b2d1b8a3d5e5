"""Every scene in scenes/, rendered from Python on both backends, is byte for byte the image that
`phongvk render` writes for it (the PNG decoded by Pillow, a decoder of its own)."""

import subprocess

import numpy as np
import PIL.Image
import pytest

import phongvk
from conftest import CLI, SOURCE_DIR

SCENES = sorted(str(p.relative_to(SOURCE_DIR)) for p in (SOURCE_DIR / "scenes").rglob("*.json"))


@pytest.fixture(scope="module")
def renderers():
    return {"gpu": phongvk.Renderer("gpu"), "cpu": phongvk.Renderer("cpu")}


@pytest.mark.parametrize("backend", ["gpu", "cpu"])
@pytest.mark.parametrize("scene", SCENES)
def test_array_equals_the_cli_png(scene, backend, renderers, tmp_path):
    image = renderers[backend].render(phongvk.load_scene(str(SOURCE_DIR / scene)))
    assert image.dtype == np.uint8 and image.ndim == 3 and image.shape[2] == 3
    assert image.flags["C_CONTIGUOUS"]
    out = tmp_path / "cli.png"
    subprocess.run([str(CLI), "render", str(SOURCE_DIR / scene), "-o", str(out), "--backend", backend],
                   check=True, capture_output=True)
    png = np.asarray(PIL.Image.open(out).convert("RGB"))
    assert image.shape == png.shape
    assert np.array_equal(image, png)


def test_there_are_scenes_to_check():
    assert len(SCENES) >= 30
