#!/usr/bin/env bash
# Builds phongvk and runs the whole test suite (CTest over GoogleTest), then the same suite under
# ASan + UBSan (scripts/sanitize.sh) and a bounded fuzzing run of the scene loader, the mesh and
# glTF importers and scene_from_dict's path (scripts/fuzz.sh). This is what CI runs (.ci/run) and
# what the README's test command runs.
# Run scripts/setup.sh first. Each stage prints how long it took.
set -euo pipefail
cd "$(dirname "$0")/.."
export JOBS=${JOBS:-$(nproc)}

# Runs "$@" as a named stage and reports its wall time.
stage() {
  local name=$1 start=$SECONDS
  shift
  "$@"
  echo "== stage '$name' took $((SECONDS - start)) s"
}

build_and_test() {
  echo "== build (Release)"
  cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
  cmake --build build -j"$JOBS"
  echo "== tests"
  ctest --test-dir build --output-on-failure -j"$JOBS" | tee build/ctest.log
}

stage "build + tests" build_and_test
stage "fuzz" bash scripts/fuzz.sh
stage "sanitizers" bash scripts/sanitize.sh

# CTest's verdicts close the log, so whoever reads its tail sees what the suites said.
echo "== summary: Release, then ASan + UBSan"
grep -h 'tests passed' build/ctest.log build-asan/ctest.log
