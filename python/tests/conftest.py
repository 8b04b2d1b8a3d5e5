"""What the pytest suites share: where the repository and the phongvk command are (CTest sets
PHONGVK_SOURCE_DIR and PHONGVK_CLI; run by hand, they default to this checkout and build/)."""

import os
import pathlib

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("PHONGVK_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
CLI = pathlib.Path(os.environ.get("PHONGVK_CLI", SOURCE_DIR / "build" / "phongvk"))


def scene_path(relative):
    return str(SOURCE_DIR / relative)


def child_environment():
    """This process's environment for a child process, its PYTHONPATH made absolute (the child may
    run in another folder) and led by the folder this process imports phongvk from, so that the
    child imports the same phongvk: the build tree's, or a virtual environment's (a notebook's
    kernel is the system's Python, which does not see the environment's packages)."""
    import phongvk
    env = dict(os.environ)
    paths = [str(pathlib.Path(phongvk.__file__).resolve().parents[1])]
    paths += [str(pathlib.Path(p).resolve()) for p in env.get("PYTHONPATH", "").split(os.pathsep) if p]
    env["PYTHONPATH"] = os.pathsep.join(paths)
    return env


@pytest.fixture
def source_dir():
    return SOURCE_DIR
