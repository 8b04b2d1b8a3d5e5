#!/usr/bin/env bash
# Builds phongvk with AddressSanitizer + UndefinedBehaviorSanitizer (-DPHONGVK_SANITIZE=ON, in
# build-asan) and runs the whole test suite under them. Any report fails the run: UBSan aborts on
# the first finding, ASan on the first memory error, LeakSanitizer at exit. The only leaks
# suppressed are third-party Vulkan code's (tests/lsan.supp). Part of the full CI (scripts/ci.sh).
# Run `bash scripts/setup.sh --test` first.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=${JOBS:-$(nproc)}

echo "== sanitizer build (ASan + UBSan)"
# -O2 rather than Release's -O3: instrumented code took a quarter to a half longer to compile at
# -O3 (the test code is at -O1 in every build: tests/CMakeLists.txt).
cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_FLAGS_RELEASE=-O2 -DNDEBUG" -DPHONGVK_SANITIZE=ON
cmake --build build-asan -j"$jobs"

echo "== tests under ASan + UBSan"
# detect_leaks: on by default on x86-64, stated so it is not lost. The CLI runs the tests start
# inherit these settings too.
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1
export LSAN_OPTIONS=suppressions=$PWD/tests/lsan.supp:print_suppressions=0
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# The whole-scene SwiftShader tests are left out: they test the shaders on a second driver, and the
# host code they run is the 32-bit key path's, which the keys32 tests run here on lavapipe. Its
# 32-bit arithmetic self-test (swiftshader_wide_int) stays.
ctest --test-dir build-asan --output-on-failure -j"$jobs" -E 'swiftshader_(pinned|shading|diff)' | tee build-asan/ctest.log
