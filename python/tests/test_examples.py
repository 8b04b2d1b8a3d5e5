"""examples/python: the ka sweep and dataset scripts and notebooks run from a clean process and
produce their files and figures (a notebook's cells executed by nbconvert; images show as PNGs there)."""

import json
import subprocess
import sys

import PIL.Image
import pytest

from conftest import SOURCE_DIR, child_environment

EXAMPLES = SOURCE_DIR / "examples" / "python"


def test_ka_sweep_script_writes_its_grid(tmp_path):
    out = tmp_path / "ka.png"
    result = subprocess.run([sys.executable, str(EXAMPLES / "ka_sweep.py"), str(out), "--backend", "cpu"],
                            capture_output=True, text=True, env=child_environment(), check=True)
    assert "12 frames" in result.stdout and "meshes built 1 time(s)" in result.stdout
    assert PIL.Image.open(out).size == (960, 540)


@pytest.mark.parametrize("notebook", ["ka_sweep.ipynb", "dataset.ipynb"])
def test_notebook_runs_and_shows_images(tmp_path, notebook):
    """ka_sweep: the Image itself and the grid; dataset: the views' grid and the lifted points,
    every view's points inside the model's box."""
    out = tmp_path / notebook
    subprocess.run([sys.executable, "-m", "nbconvert", "--to", "notebook", "--execute",
                    str(EXAMPLES / notebook), "--output", str(out)],
                   capture_output=True, text=True, env=child_environment(), cwd=EXAMPLES, check=True)
    cells = [c for c in json.loads(out.read_text())["cells"] if c["cell_type"] == "code"]
    outputs = [o for c in cells for o in c["outputs"]]
    assert not [o for o in outputs if o["output_type"] == "error"]
    assert sum("image/png" in o.get("data", {}) for o in outputs) >= 2
    if notebook == "dataset.ipynb":
        assert "100.0% inside the model's box" in "".join(outputs[-2]["data"]["text/plain"])


def test_dataset_script_writes_views_whose_cameras_and_depths_agree(tmp_path):
    """The dataset example: every view's files, and its cameras.json and depth consistent: each
    masked pixel, lifted by its depth through the intrinsics and the pose, lands in the model's box."""
    import numpy as np
    import phongvk
    model = "/usr/share/assimp/models/PLY/Wuson.ply"
    subprocess.run([sys.executable, str(EXAMPLES / "dataset.py"), model, str(tmp_path), "3", "y"],
                   capture_output=True, text=True, env=child_environment(), check=True)
    cameras = json.loads((tmp_path / "cameras.json").read_text())
    k = cameras["intrinsics"]
    low, high = np.array(phongvk.load_scene(model, up="y").bounds)
    margin = 0.01 * np.linalg.norm(high - low)
    assert cameras["convention"] == "opencv" and len(cameras["views"]) == 3
    for i, view in enumerate(cameras["views"]):
        mask = np.array(PIL.Image.open(tmp_path / f"{i:03d}_mask.png")) > 0  # 8-bit grey
        depth = np.load(tmp_path / f"{i:03d}_depth.npy")
        assert PIL.Image.open(tmp_path / view["file"]).size == (k["width"], k["height"])
        assert mask.sum() > 1000 and np.array_equal(mask, np.isfinite(depth))
        ys, xs = np.nonzero(mask)
        camera = np.stack([(xs - k["cx"]) / k["fx"], (ys - k["cy"]) / k["fy"], np.ones(len(xs))]) * depth[ys, xs]
        pose = np.array(view["camera_to_world"])
        world = (pose[:3, :3] @ camera).T + pose[:3, 3]
        assert (world >= low - margin).all() and (world <= high + margin).all()
