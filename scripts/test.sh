#!/usr/bin/env bash
# Builds phongvk and runs the whole test suite (CTest over GoogleTest). This is what CI runs
# (.ci/run) and what the README's test command runs. Run scripts/setup.sh first.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc)

echo "== build (Release)"
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$jobs"

echo "== tests"
ctest --test-dir build --output-on-failure -j"$jobs"
