#!/usr/bin/env bash
# Fuzzes the scene loader and the mesh file importers, each for a bounded time (default 60 s;
# FUZZ_SECONDS overrides), with libFuzzer, ASan and UBSan (fuzz/scene_fuzzer.cpp,
# fuzz/mesh_fuzzer.cpp). Seeds: fuzz/corpus (small bad scenes) and every file under scenes/ for
# the first; fuzz/mesh_corpus (small PLY, STL, glTF, GLB and OBJ files, each behind the byte that
# picks its extension) for the second. New inputs go to build-fuzz/, outside the repo. A crash, a
# sanitizer report, a hang (> 10 s on one input) or a leak fails the run and leaves the input in
# build-fuzz/crash-*: add it to the tests once fixed. Needs clang and libclang-rt-14-dev
# (scripts/setup.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${FUZZ_SECONDS:-60}

echo "== fuzz: build (clang, libFuzzer + ASan + UBSan)"
cmake -S fuzz -B build-fuzz -G Ninja -DCMAKE_CXX_COMPILER=clang++ >/dev/null
cmake --build build-fuzz -j"${JOBS:-$(nproc)}"

# run NAME SEEDS...: NAME's target for $seconds on build-fuzz/NAME-corpus and the seeds.
# -max_len 8192: the seeds are up to a few KB; longer inputs only slow each run down.
# -rss_limit_mb: an input that asks for gigabytes is a finding, not a reason to swap.
# The full log only when something was found (the report and its input); else just the totals.
run() {
  local name=$1
  shift
  echo "== fuzz: $name for ${seconds} s"
  mkdir -p "build-fuzz/$name-corpus"
  if ! "build-fuzz/${name}_fuzzer" "build-fuzz/$name-corpus" "$@" \
      -max_total_time="$seconds" -max_len=8192 -timeout=10 -rss_limit_mb=2048 \
      -artifact_prefix="build-fuzz/$name-" -print_final_stats=1 >"build-fuzz/$name.log" 2>&1; then
    cat "build-fuzz/$name.log"
    echo "== fuzz: $name FAILED; the input is in build-fuzz/ ($name-crash-*, -timeout-*, -leak-* or -oom-*)"
    exit 1
  fi
  grep -E '^(Done|stat::)' "build-fuzz/$name.log"
}

run scene fuzz/corpus scenes
run mesh fuzz/mesh_corpus
