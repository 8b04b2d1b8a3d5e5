#!/usr/bin/env bash
# `pip install .` as a user would run it, offline: into a fresh virtual environment that sees
# Debian's packages (numpy, pytest), built by setup.py through CMake; then the Python suite against
# the installed package, from outside the build tree. Part of the full CI (scripts/ci.sh); needs
# scripts/setup.sh --test and, for the suites that run the command, build/phongvk (scripts/test.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
venv=$(mktemp -d)/venv
trap 'rm -rf "$(dirname "$venv")"' EXIT
/usr/bin/python3 -m venv --system-site-packages "$venv"
"$venv/bin/pip" install --no-index --no-build-isolation --quiet .
# The package imported is the installed one, not the source tree's.
(cd "$(dirname "$venv")" && "$venv/bin/python" -c "import phongvk; assert phongvk.__file__.startswith('$venv'), phongvk.__file__; print('pip install: phongvk', phongvk.__version__, 'at', phongvk.__file__)")
PHONGVK_SOURCE_DIR=$root PHONGVK_CLI=$root/build/phongvk "$venv/bin/python" -m pytest -q -p no:cacheprovider python/tests
