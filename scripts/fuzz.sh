#!/usr/bin/env bash
# Fuzzes the scene loader for a bounded time (default 60 s; FUZZ_SECONDS overrides) with libFuzzer,
# ASan and UBSan (fuzz/scene_fuzzer.cpp). Seeds: fuzz/corpus (small bad cases) and every file
# under scenes/. New inputs go to build-fuzz/corpus, outside the repo. A crash, a sanitizer
# report, a hang (> 10 s on one input) or a leak fails the run and leaves the input in
# build-fuzz/crash-*: add it to tests/bad_input_test.cpp once fixed. Needs clang and
# libclang-rt-14-dev (scripts/setup.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${FUZZ_SECONDS:-60}

echo "== fuzz: build (clang, libFuzzer + ASan + UBSan)"
cmake -S fuzz -B build-fuzz -G Ninja -DCMAKE_CXX_COMPILER=clang++ >/dev/null
cmake --build build-fuzz -j"${JOBS:-$(nproc)}"

echo "== fuzz: scene loader for ${seconds} s"
mkdir -p build-fuzz/corpus
# -max_len 8192: the seeds are up to a few KB; longer inputs only slow each run down.
# -rss_limit_mb: a scene that asks for gigabytes is a finding, not a reason to swap.
# The full log only when something was found (the report and its input); else just the totals.
if ! build-fuzz/scene_fuzzer build-fuzz/corpus fuzz/corpus scenes \
    -max_total_time="$seconds" -max_len=8192 -timeout=10 -rss_limit_mb=2048 \
    -artifact_prefix=build-fuzz/ -print_final_stats=1 >build-fuzz/fuzz.log 2>&1; then
  cat build-fuzz/fuzz.log
  echo "== fuzz: FAILED; the input is in build-fuzz/ (crash-*, timeout-*, leak-* or oom-*)"
  exit 1
fi
grep -E '^(Done|stat::)' build-fuzz/fuzz.log
