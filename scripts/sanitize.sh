#!/usr/bin/env bash
# Builds phongvk with AddressSanitizer + UndefinedBehaviorSanitizer (-DPHONGVK_SANITIZE=ON, in
# build-asan) and runs the test suite under them (less the suites below). Any report fails the run: UBSan aborts on
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
# Left out, as they test the shaders rather than host code these suites do not already run here:
# every committed scene in every mode on SwiftShader (swiftshader_shading; its pinned set and the
# two-device diff stay: the only suites that run the host code of arrays in storage buffers,
# gpu_buffers.cpp texelViews), and of the suites CTest runs again with PHONGVK_KEY_PATH=32 (label
# keys32) the shading and points-and-lines ones, whose host code is the 64-bit path's but for
# the key path's choices and buffers, which keys32_pinned_images_gpu_test runs here (every pinned
# scene, frame and mode on the 32-bit path). Those two took 351 s of the 2,050 s of tests under the
# sanitizers on the 2-core machine; in the Release run (scripts/test.sh) all three keys32 suites run.
ctest --test-dir build-asan --output-on-failure -j"$jobs" \
  -E 'swiftshader_shading|keys32_(shading|points_lines)_gpu_test' | tee build-asan/ctest.log
