"""`pip install .`: the Python package as CMake builds it (python/CMakeLists.txt: the extension
_phongvk, linked statically to the library, and python/phongvk's files), put into the wheel.
pyproject.toml names setuptools as the backend; CMake, Ninja and the library's dependencies come
from scripts/setup.sh."""

import os
import pathlib
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent


class CMakeBuild(build_ext):
    """Configures and builds the package target with CMake, for the interpreter running pip."""

    def build_extension(self, ext):
        build = pathlib.Path(self.build_temp).resolve() / "cmake"
        generator = ["-G", "Ninja"] if shutil.which("ninja") else []
        subprocess.run(["cmake", "-S", str(ROOT), "-B", str(build), *generator, "-DCMAKE_BUILD_TYPE=Release",
                        "-DPHONGVK_TESTS=OFF", "-DPHONGVK_MPI=OFF", f"-DPython_EXECUTABLE={sys.executable}"],
                       check=True)
        jobs = os.environ.get("JOBS", str(os.cpu_count() or 1))
        subprocess.run(["cmake", "--build", str(build), "--target", "phongvk_python", "-j", jobs], check=True)
        package = pathlib.Path(self.get_ext_fullpath(ext.name)).parent
        package.mkdir(parents=True, exist_ok=True)
        for built in (build / "python" / "phongvk").iterdir():
            shutil.copy2(built, package / built.name)


setup(
    packages=["phongvk"],
    package_dir={"phongvk": "python/phongvk"},
    package_data={"phongvk": ["_phongvk.pyi", "py.typed"]},
    ext_modules=[Extension("phongvk._phongvk", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    # Not build/: that is CMake's build tree.
    options={"build": {"build_base": "build-pip"}, "egg_info": {"egg_base": "build-pip"}},
)
