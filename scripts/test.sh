#!/usr/bin/env bash
# Builds phongvk (Release, in build/) and runs the whole test suite with CTest: every GoogleTest
# suite, the Python suites, the installed package, the benchmark's smoke run, MPI and Slurm. This
# is the README's test command (12 to 16 min from a fresh clone on a 2-core machine, the tests about 9; run it before each commit).
# scripts/ci.sh, the full CI (.ci/run), runs it and then fuzzing and the sanitizers.
# Run `bash scripts/setup.sh --test` first. JOBS sets the parallelism (default: every core).
set -euo pipefail
cd "$(dirname "$0")/.."
export JOBS=${JOBS:-$(nproc)}
start=$SECONDS

echo "== build (Release)"
# PHONGVK_TESTS=ON: the README's render command configures build/ without the tests.
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DPHONGVK_TESTS=ON
cmake --build build -j"$JOBS"
echo "== tests"
# Every committed scene in every mode on SwiftShader (label swiftshader_full, minutes of its shader
# compiler) is the full CI's (scripts/ci.sh), not this command's.
ctest --test-dir build --output-on-failure -j"$JOBS" -LE swiftshader_full | tee build/ctest.log
echo "== stage 'build + tests' took $((SECONDS - start)) s"

# CTest's verdict closes the log, so whoever reads its tail sees what the suites said.
echo "== summary: Release"
grep -h 'tests passed' build/ctest.log
