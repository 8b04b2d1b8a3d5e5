#!/usr/bin/env bash
# Fuzzes the scene loader, the mesh file importers, the glTF importer with its external buffers, the
# PNG and JPEG texture decoder (fuzz/texture_fuzzer.cpp, seeds fuzz/texture_corpus) and
# scene_from_dict's path from Python values, each for a bounded time (default 60 s a target;
# FUZZ_SECONDS overrides), with libFuzzer, ASan and UBSan (fuzz/scene_fuzzer.cpp,
# fuzz/mesh_fuzzer.cpp, fuzz/gltf_fuzzer.cpp, fuzz/dict_fuzzer.cpp). Seeds: fuzz/corpus (small bad
# scenes) and every file under scenes/ for the first; fuzz/mesh_corpus (small PLY, STL, glTF, GLB
# and OBJ files, each behind the byte that picks its extension) for the second; fuzz/gltf_corpus
# (models with buf.bin beside them, fuzz/make_gltf_seeds.py) for the third; fuzz/dict_corpus
# (programs that build Python values, fuzz/make_dict_seeds.py) for the fourth. New inputs go to
# build-fuzz/, outside the repo. A crash, a sanitizer report, a hang (> 10 s on one input) or a
# leak fails the run and leaves the input in build-fuzz/crash-*: add it to the tests once fixed.
# The targets run JOBS at a time (default: every core), each on one core as libFuzzer does, so
# each still gets its whole time.
# Part of the full CI (scripts/ci.sh). Needs clang and libclang-rt-14-dev (`scripts/setup.sh --test`),
# and for the fourth python3-dev, pybind11-dev and python3-numpy (`scripts/setup.sh`).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${FUZZ_SECONDS:-60}
jobs=${JOBS:-$(nproc)}

echo "== fuzz: build (clang, libFuzzer + ASan + UBSan)"
cmake -S fuzz -B build-fuzz -G Ninja -DCMAKE_CXX_COMPILER=clang++ >/dev/null
cmake --build build-fuzz -j"$jobs"

# run NAME SEEDS... [-FLAG=VALUE...]: NAME's target for $seconds on build-fuzz/NAME-corpus and the
# seeds, with any extra libFuzzer flags.
# -max_len 8192: the seeds are up to a few KB; longer inputs only slow each run down.
# -rss_limit_mb: an input that asks for gigabytes is a finding, not a reason to swap.
# The full log only when something was found (the report and its input); else just the totals,
# each target's printed whole when it ends.
run() {
  local name=$1
  shift
  mkdir -p "build-fuzz/$name-corpus"
  if ! "build-fuzz/${name}_fuzzer" "build-fuzz/$name-corpus" "$@" \
      -max_total_time="$seconds" -max_len=8192 -timeout=10 -rss_limit_mb=2048 \
      -artifact_prefix="build-fuzz/$name-" -print_final_stats=1 >"build-fuzz/$name.log" 2>&1; then
    { cat "build-fuzz/$name.log"
      echo "== fuzz: $name FAILED; the input is in build-fuzz/ ($name-crash-*, -timeout-*, -leak-* or -oom-*)"; }
    return 1
  fi
  { echo "== fuzz: $name for ${seconds} s"; grep -E '^(Done|stat::)' "build-fuzz/$name.log"; }
}

# start NAME SEEDS... [-FLAG=VALUE...]: run in the background, $jobs targets at a time (each runs
# for $seconds, so a batch ends together); a target's failure ends the script (set -e on `wait`)
# and stops the others.
running=()
trap 'kill "${running[@]}" 2>/dev/null || true' EXIT
finish() {
  for pid in "${running[@]}"; do wait "$pid"; done
  running=()
}
start() {
  run "$@" &
  running+=($!)
  if (( ${#running[@]} >= jobs )); then finish; fi
}

start scene fuzz/corpus scenes
start mesh fuzz/mesh_corpus
start gltf fuzz/gltf_corpus
start texture fuzz/texture_corpus
# -detect_leaks=0: CPython keeps freed objects on free lists and cyclic garbage until its collector
# runs, so nearly every input ends with more mallocs than frees, and libFuzzer would then run a
# leak check after each one (about 30 inputs a second instead of 1,800). LSan's check at exit still
# runs, and fails the run on a leak, though without the input that made it.
start dict fuzz/dict_corpus -detect_leaks=0
finish
