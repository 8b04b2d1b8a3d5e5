#!/usr/bin/env bash
# The full CI, what .ci/run runs (42 to 53 min from a fresh clone on a 2-core machine: 42 at 9bd5545 on an AMD EPYC, 53 at 576d043 on an Intel Xeon): scripts/test.sh (build
# and the whole test suite), every committed scene in every mode on SwiftShader, then `pip install .` into a fresh virtual environment and the Python
# suite against it (scripts/pip_check.sh), the GPU check's dry run on lavapipe (scripts/gpu_check.sh),
# a bounded fuzzing run of the scene loader, the mesh and
# glTF importers and scene_from_dict's path (scripts/fuzz.sh), then the test suite again under
# ASan + UBSan, less the suites that check only shaders there (scripts/sanitize.sh). Each stage prints how long it took; the last lines are CTest's verdicts.
# Run `bash scripts/setup.sh --test` first. JOBS sets the parallelism (default: every core).
set -euo pipefail
cd "$(dirname "$0")/.."
export JOBS=${JOBS:-$(nproc)}
start=$SECONDS

# Runs "$@" as a named stage and reports its wall time.
stage() {
  local name=$1 start=$SECONDS
  shift
  "$@"
  echo "== stage '$name' took $((SECONDS - start)) s"
}

bash scripts/test.sh  # prints its own stage time, 'build + tests'
# Every committed scene in every shading mode on SwiftShader, the second Vulkan implementation (the
# 32-bit key path), against the reference: the tests scripts/test.sh leaves out for time.
stage "swiftshader (every scene, every mode)" bash -c 'set -o pipefail; ctest --test-dir build --output-on-failure -j"$JOBS" -L swiftshader_full | tee build/ctest-swiftshader.log'
stage "pip install" bash scripts/pip_check.sh
# The GPU check's own dry run (a few scenes and suites of each stage, lavapipe standing in for the
# GPU), so the script a GPU machine runs does not rot between the times one is at hand.
stage "gpu check (dry run)" bash scripts/gpu_check.sh --allow-cpu --quick --no-setup --skip bench --out build/gpu_check
stage "fuzz" bash scripts/fuzz.sh
stage "sanitizers" bash scripts/sanitize.sh
echo "== ci took $((SECONDS - start)) s"

# CTest's verdicts close the log, so whoever reads its tail sees what the suites said.
echo "== summary: Release, SwiftShader's every scene and mode, then ASan + UBSan"
grep -h 'tests passed' build/ctest.log build/ctest-swiftshader.log build-asan/ctest.log
