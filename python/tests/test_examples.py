"""examples/python: the ka sweep script and notebook run from a clean process and produce their
figure (the notebook's cells executed by nbconvert; the rendered image shows as a PNG there)."""

import json
import subprocess
import sys

import PIL.Image

from conftest import SOURCE_DIR, child_environment

EXAMPLES = SOURCE_DIR / "examples" / "python"


def test_ka_sweep_script_writes_its_grid(tmp_path):
    out = tmp_path / "ka.png"
    result = subprocess.run([sys.executable, str(EXAMPLES / "ka_sweep.py"), str(out), "--backend", "cpu"],
                            capture_output=True, text=True, env=child_environment(), check=True)
    assert "12 frames" in result.stdout and "meshes built 1 time(s)" in result.stdout
    assert PIL.Image.open(out).size == (960, 540)


def test_notebook_runs_and_shows_images(tmp_path):
    out = tmp_path / "ka_sweep.ipynb"
    subprocess.run([sys.executable, "-m", "nbconvert", "--to", "notebook", "--execute",
                    str(EXAMPLES / "ka_sweep.ipynb"), "--output", str(out)],
                   capture_output=True, text=True, env=child_environment(), cwd=EXAMPLES, check=True)
    cells = [c for c in json.loads(out.read_text())["cells"] if c["cell_type"] == "code"]
    outputs = [o for c in cells for o in c["outputs"]]
    assert not [o for o in outputs if o["output_type"] == "error"]
    assert sum("image/png" in o.get("data", {}) for o in outputs) >= 2  # the Image itself and the grid
