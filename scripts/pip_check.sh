#!/usr/bin/env bash
# `pip install .` as a user would run it, offline: into a fresh virtual environment that sees
# Debian's packages (numpy, pytest), built by setup.py through CMake; then the Python suite against
# the installed package, from outside the build tree. Then into the system itself, as Debian 12
# lets root do it past PEP 668 (--break-system-packages): the API's and the renderer's suites against that install,
# which is removed afterwards (a machine that already has phongvk in the system is left alone and
# says so). Part of the full CI (scripts/ci.sh); needs scripts/setup.sh --test and, for the
# suites that run the command, build/phongvk (scripts/test.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
venv=$(mktemp -d)/venv
trap 'rm -rf "$(dirname "$venv")"' EXIT
/usr/bin/python3 -m venv --system-site-packages "$venv"
"$venv/bin/pip" install --no-index --no-build-isolation --quiet .
# The package imported is the installed one, not the source tree's.
(cd "$(dirname "$venv")" && "$venv/bin/python" -c "import phongvk; assert phongvk.__file__.startswith('$venv'), phongvk.__file__; print('pip install: phongvk', phongvk.__version__, 'at', phongvk.__file__)")
# A file's tests on one worker, JOBS workers (pytest-xdist): CTest runs the same files side by side.
PHONGVK_SOURCE_DIR=$root PHONGVK_CLI=$root/build/phongvk "$venv/bin/python" -m pytest -q -p no:cacheprovider \
  -n "${JOBS:-$(nproc)}" --dist loadfile python/tests

# Into the system. setup.py's build folder (build-pip) is kept, so this install rebuilds nothing: it
# installs the module the suite above has just passed, so the suites it takes there are those of
# the API and the renderer (the package found and working from its system place), not all of them.
system_python() { (cd / && env -u PYTHONPATH /usr/bin/python3 "$@"); }
if system_python -c "import phongvk" 2>/dev/null; then
  echo "pip install --break-system-packages: not tried, phongvk is already in the system at $(system_python -c 'import phongvk; print(phongvk.__file__)')"
  exit 0
fi
trap 'system_python -m pip uninstall --break-system-packages -y --quiet phongvk; rm -rf "$(dirname "$venv")"' EXIT
/usr/bin/python3 -m pip install --break-system-packages --no-index --no-build-isolation --quiet .
system_python -c "import phongvk; assert not phongvk.__file__.startswith('$root'), phongvk.__file__; print('pip install --break-system-packages: phongvk', phongvk.__version__, 'at', phongvk.__file__)"
(cd / && env -u PYTHONPATH PHONGVK_SOURCE_DIR="$root" PHONGVK_CLI="$root/build/phongvk" \
  /usr/bin/python3 -m pytest -q -p no:cacheprovider "$root/python/tests/test_api.py" "$root/python/tests/test_renderer.py")

