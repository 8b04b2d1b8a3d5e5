#!/usr/bin/env bash
# gpu_check.sh [--bundle FILE] [--out DIR] [--skip STAGES] [--pin] — everything phongvk claims,
# checked on a machine with a GPU, in one command and under 8 minutes on an NVIDIA H100 machine
# (16 cores), ending in a short summary (also written to gpu_check.md in the output folder):
#
#   tests    the GPU suites (CTest's label gpu: GoogleTest's *_gpu_test, MPI's mpirun -np 2 and 3
#            ... --mpi, and off a bundle the Python suite)
#   sweep    every scene of scenes/ in every shading mode (gouraud, flat, phong; Blinn's highlight)
#            and sample count (1, 4, 9, 16): `phongvk diff --tolerance 0`, GPU against the
#            reference, colours and visibility keys
#   python   the Python suite against the GPU
#   lavapipe every scene in three shading modes on lavapipe, on this machine's CPU, and on the
#            reference: the bytes against tests/data/lavapipe_hashes.txt, written on a
#            development machine (another CPU vendor, likely) — the determinism claim across
#            CPUs, tested
#   rate     a 106M-triangle scene at 1920x1080 (18 x 18 icospheres of 327,680 triangles): the
#            device time of a frame, triangles per second, memory
#   bench    the benchmark (bench/), its report to BENCHMARKS_GPU.md in the output folder: commit it as
#            docs/BENCHMARKS_<GPU>.md
#
# On a Debian 12 machine with a GPU it sets up (scripts/setup.sh --test) and builds as
# scripts/test.sh does. A machine that cannot build phongvk (another distribution, no package
# archive) takes a bundle made on a Debian 12 machine by scripts/gpu_bundle.sh: `--bundle FILE`.
#   --out DIR     where the logs, the summary and the report go (default out/gpu_check)
#   --skip LIST   stages left out, comma-separated (e.g. --skip bench,rate)
#   --quick       a few scenes and suites of each stage: with --allow-cpu, CI's check that the
#                 script itself still works (scripts/ci.sh)
#   --no-setup    skip scripts/setup.sh (it has run already)
#   --allow-cpu   run on a machine without a GPU (lavapipe stands in): the script's own dry run
#   --budget S    seconds the stages may take together (default 480): each runs under what is
#                 left, and one that finds too little is reported as not run
#   --pin         rewrite tests/data/lavapipe_hashes.txt from this machine's lavapipe and exit: run
#                 it on a development machine after an intended change to the contract's bytes
#                 (scripts/repin.sh's case)
# The GPU is the first discrete or integrated GPU Vulkan lists; PHONGVK_GPU_ICD names its driver's
# manifest where the Vulkan loader does not find it (NVIDIA's under /usr/local/nvidia is found).
set -uo pipefail
cd "$(dirname "$0")/.."
repo=$PWD
bundle=
out=out/gpu_check
skip=
pin=0
allow_cpu=0
quick=0
budget=480
setup=1
while [ $# -gt 0 ]; do
  case $1 in
    --bundle) bundle=$(realpath "$2"); shift 2 ;;
    --out) out=$2; shift 2 ;;
    --skip) skip=$2; shift 2 ;;
    --pin) pin=1; shift ;;
    --allow-cpu) allow_cpu=1; shift ;;
    --quick) quick=1; shift ;;
    --no-setup) setup=0; shift ;;
    --budget) budget=$2; shift 2 ;;
    *) echo "gpu_check.sh: unknown argument '$1' (see the comment at the top of the script)" >&2; exit 2 ;;
  esac
done
mkdir -p "$out"
out=$(realpath "$out")
jobs=$(nproc)
summary=()
failures=0
start=$SECONDS

note() {  # note STAGE VERDICT DETAIL: one summary row
  summary+=("| $1 | $2 | $3 |")
  if [ "$2" = FAIL ]; then failures=$((failures + 1)); fi
  echo "== $1: $2 — $3"
}
left() { echo $((budget - (SECONDS - stages_start))); }
wanted() {  # wanted STAGE: not skipped, and time left for it
  [[ ",$skip," == *",$1,"* ]] && return 1
  if [ "$(left)" -lt 20 ]; then note "$1" "not run" "the budget of $budget s was spent"; return 1; fi
}

# --- where the programs come from -------------------------------------------------------------
lavapipe_icd=/usr/share/vulkan/icd.d/lvp_icd.x86_64.json
if [ -n "$bundle" ]; then
  # The bundle's programs, its source tree in place of the path its build was made from, and the
  # libraries this machine lacks (ldconfig does not know their sonames) on LD_LIBRARY_PATH.
  b=$repo/build-bundle
  rm -rf "$b" && mkdir -p "$b/links" && tar -C "$b" -xJf "$bundle" || { echo "gpu_check.sh: cannot unpack $bundle" >&2; exit 1; }
  for f in "$b"/lib/*; do
    soname=$(basename "$f")
    if ! ldconfig -p | grep -q "^[[:space:]]*$soname "; then ln -s "$f" "$b/links/$soname"; fi
  done
  # The layer and lavapipe, named without a folder, come from the bundle even where the machine
  # has its own: the same lavapipe as the development machine's.
  ln -sf "$b/lib/libvulkan_lvp.so" "$b/lib/libVkLayer_khronos_validation.so" "$b/links/"
  export LD_LIBRARY_PATH=$b/links${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
  export VK_ADD_LAYER_PATH=$b/layers
  lavapipe_icd=$b/icd/lvp_icd.json
  # The mesh tests' real files (Debian's assimp-testmodels), where the tests look for them.
  if [ ! -e /usr/share/assimp/models ]; then mkdir -p /usr/share/assimp && ln -s "$b/models" /usr/share/assimp/models; fi
  if [ -d "$b/mpi" ]; then
    export OPAL_PREFIX=$b/mpi/usr PATH=$b/mpi/usr/bin:$PATH
    export LD_LIBRARY_PATH=$LD_LIBRARY_PATH:$b/mpi/usr/lib/x86_64-linux-gnu/openmpi/lib:$b/mpi/usr/lib/x86_64-linux-gnu/pmix2/lib
  fi
  source_dir=$(cat "$b/SOURCE_DIR")
  if [ ! -e "$source_dir" ]; then
    mkdir -p "$(dirname "$source_dir")" && ln -s "$b/source" "$source_dir"
  elif [ "$(realpath "$source_dir")" != "$(realpath "$b/source")" ]; then
    echo "gpu_check.sh: the bundle was built in $source_dir, which exists here: run it where that path is free" >&2
    exit 1
  fi
  # The programs and CTest's files name the build folder they were made in.
  build_dir=$(cat "$b/BUILD_DIR")
  if [ ! -e "$build_dir" ]; then mkdir -p "$(dirname "$build_dir")" && ln -s "$b/build" "$build_dir"; fi
  build=$b/build
  src=$b/source
  revision="$(cat "$b/REVISION") (bundle)"
else
  if [ "$pin" = 0 ] && [ "$setup" = 1 ]; then bash scripts/setup.sh --test || exit 1; fi
  cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DPHONGVK_TESTS=ON >"$out/build.log" 2>&1 &&
    cmake --build build -j"$jobs" >>"$out/build.log" 2>&1 || { tail -30 "$out/build.log"; echo "gpu_check.sh: build failed" >&2; exit 1; }
  build=$repo/build
  src=$repo
  revision=$(git describe --always --dirty 2>/dev/null || echo unknown)
fi
phongvk=$build/phongvk
export phongvk jobs
cd "$src"

# Every scene file a user can render: scenes/ and its folders, frame 0.
export scenes
scenes=$(find scenes -name '*.json' -not -path '*/meshes/*' | LC_ALL=C sort | tr '\n' ' ')
samples="1 4 9 16"
suites=.
pytests=python/tests
if [ "$quick" = 1 ]; then
  scenes="scenes/basic.json scenes/directional.json scenes/paper/fig1_cube.json"
  samples="1 4"
  suites='^(PinnedImages|Api|mpi_render)'
  pytests=python/tests/test_api.py
fi
rate_subdivide=7  # 18 x 18 icospheres of 20 * 4^7 triangles: 106M
bench_args="--repeat 7"
if [ "$quick" = 1 ]; then rate_subdivide=3; bench_args=--quick; fi

# tests/data/lavapipe_hashes.txt: one line per scene and shading mode, the sha256 of the PNG the
# backend writes at level 0 (stored blocks: the pixels and a fixed header, no compressor's choices).
hash_renders() {  # hash_renders BACKEND: "scene shading hash" lines on stdout, in parallel
  local backend=$1
  for s in $scenes; do for m in gouraud flat phong; do echo "$s $m"; done; done |
    xargs -P "$jobs" -n 2 sh -c '
      f=$(mktemp --suffix=.png)
      if "$0" render "$1" --shading "$2" --backend '"$backend"' --png-level 0 -o "$f" >/dev/null 2>"$f.log"; then
        echo "$1 $2 $(sha256sum "$f" | cut -c1-16)"
      else
        echo "$1 $2 failed: $(tail -1 "$f.log")"
      fi
      rm -f "$f" "$f.log"' "$phongvk" | LC_ALL=C sort
}
hash_file=tests/data/lavapipe_hashes.txt
if [ "$pin" = 1 ]; then
  VK_DRIVER_FILES=$lavapipe_icd hash_renders gpu >"$out/lavapipe.txt"
  if grep -q failed "$out/lavapipe.txt"; then grep failed "$out/lavapipe.txt"; exit 1; fi
  { echo "# Written by scripts/gpu_check.sh --pin on lavapipe ($("$phongvk" devices | head -1 | sed 's/^\[0\] //;s/ — .*//'));"
    echo "# gpu_check.sh renders each scene and mode there again, on lavapipe and the reference, and"
    echo "# compares. Columns: scene, shading, first 16 hex digits of the sha256 of the PNG (level 0)."
    cat "$out/lavapipe.txt"; } >"$repo/$hash_file"
  echo "gpu_check.sh: $(grep -vc '^#' "$repo/$hash_file") hashes written to $hash_file"
  exit 0
fi

# --- the GPU ---------------------------------------------------------------------------------
if [ -z "${PHONGVK_GPU_ICD:-}" ]; then
  for f in /usr/local/nvidia/share/vulkan/icd.d/*.json; do [ -e "$f" ] && PHONGVK_GPU_ICD=$f && break; done
fi
if [ -n "${PHONGVK_GPU_ICD:-}" ]; then export VK_DRIVER_FILES=$PHONGVK_GPU_ICD; fi
"$phongvk" devices >"$out/devices.txt" 2>&1
gpu=$(grep -E 'discrete GPU|integrated GPU' "$out/devices.txt" | grep usable | head -1)
[ -z "$gpu" ] && [ "$allow_cpu" = 1 ] && gpu=$(grep usable "$out/devices.txt" | head -1)
if [ -z "$gpu" ]; then
  cat "$out/devices.txt"
  echo "gpu_check.sh: no usable GPU among the Vulkan devices above (PHONGVK_GPU_ICD names a driver's manifest)" >&2
  exit 1
fi
echo "== GPU: $gpu"
stages_start=$SECONDS
echo "== CPU: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ //'), $jobs cores"

# --- tests ---------------------------------------------------------------------------------------
if wanted tests; then
  t=$SECONDS
  # A bundle has no Debian python3 for the Python suite: it runs in its own stage.
  exclude='^$'
  [ -n "$bundle" ] && exclude='^python_'
  timeout "$(left)" ctest --test-dir "$build" -j"$jobs" -L gpu -R "$suites" -E "$exclude" --timeout 300 >"$out/ctest.log" 2>&1
  result=$(grep -h 'tests passed' "$out/ctest.log" || echo "no result")
  mpi=$(grep -E 'mpi_render' "$out/ctest.log" | grep -oE 'Passed|Failed|Not Run' | head -1)
  if grep -q '100% tests passed' "$out/ctest.log"; then v=pass; else v=FAIL; grep -A40 'The following tests' "$out/ctest.log" | head -40; fi
  note tests "$v" "$result; mpirun -np 2 and 3 (mpi_render): ${mpi:-not run}; $((SECONDS - t)) s"
fi

# --- every scene, every mode, GPU against the reference ------------------------------------------
if wanted sweep; then
  t=$SECONDS
  for s in $scenes; do
    for m in gouraud flat phong; do for n in $samples; do echo "$s --shading $m --samples $n"; done; done
    echo "$s --specular blinn --samples 1"
  done | timeout "$(left)" xargs -P "$jobs" -L 1 sh -c '
    if "$0" diff "$@" --tolerance 0 >/dev/null 2>&1; then echo "ok $*"; else echo "FAIL $*"; fi' "$phongvk" \
    >"$out/sweep.log"
  n=$(wc -l <"$out/sweep.log")
  bad=$(grep -c ^FAIL "$out/sweep.log")
  if [ "$bad" = 0 ]; then v=pass; else v=FAIL; grep ^FAIL "$out/sweep.log" | head -20; fi
  note sweep "$v" "$((n - bad)) of $n renders (scenes x modes x samples) bit-identical to the reference; $((SECONDS - t)) s"
fi

# --- Python --------------------------------------------------------------------------------------
if wanted python && [ -n "$bundle" ]; then
  t=$SECONDS
  py=$(command -v python3)
  pkg=$build/python-here/phongvk
  mkdir -p "$pkg" && cp python/phongvk/__init__.py python/phongvk/_phongvk.pyi python/phongvk/py.typed "$pkg/"
  ext=$("$py" -c "import sysconfig; print(sysconfig.get_config_var('EXT_SUFFIX'))")
  pyinc=$("$py" -c "import sysconfig; print(sysconfig.get_paths()['include'])")
  pbinc=$("$py" -c "import pybind11; print(pybind11.get_include())" 2>/dev/null)
  [ -z "$pbinc" ] && [ -d /usr/include/pybind11 ] && pbinc=/usr/include  # Debian's, headers only
  if ! command -v c++ >/dev/null || [ -z "$pbinc" ] || [ ! -e "$pyinc/Python.h" ]; then
    note python FAIL "this machine's python3 ($py) lacks pybind11 or Python.h, or there is no c++: the module was not built"
  elif ! c++ -O2 -std=c++20 -shared -fPIC -fvisibility=hidden -DNDEBUG python/*.cpp -Iinclude -Ipython \
      -I"$pyinc" -I"$pbinc" -L"$build/api" -lphongvk -Wl,-rpath,"$build/api" -o "$pkg/_phongvk$ext" >"$out/python_build.log" 2>&1; then
    tail -20 "$out/python_build.log"
    note python FAIL "the module did not build for $py (python_build.log)"
  else
    xdist=; "$py" -c "import xdist" 2>/dev/null && xdist="-n $jobs"
    # The notebook's test runs Jupyter (Debian's nbconvert), which a bundle cannot bring.
    nb=; "$py" -c "import nbconvert" 2>/dev/null || nb="--deselect python/tests/test_examples.py::test_notebook_runs_and_shows_images"
    PYTHONPATH=$build/python-here PHONGVK_CLI=$phongvk PHONGVK_SOURCE_DIR=$src PHONGVK_VALIDATE=1 \
      timeout "$(left)" "$py" -m pytest -q -p no:cacheprovider $xdist $nb $pytests >"$out/python.log" 2>&1
    code=$?
    result=$(tail -1 "$out/python.log")
    if [ "$code" = 0 ]; then v=pass; else v=FAIL; grep -E '^(FAILED|ERROR)' "$out/python.log" | head -20; fi
    note python "$v" "$result${nb:+ (the notebook test deselected: no nbconvert here)} ($("$py" --version 2>&1), numpy $("$py" -c 'import numpy; print(numpy.__version__)')); $((SECONDS - t)) s"
  fi
fi

# --- lavapipe on this machine's CPU, and the reference, against a development machine's bytes ------
if wanted lavapipe; then
  t=$SECONDS
  VK_DRIVER_FILES=$lavapipe_icd timeout "$(left)" bash -c "$(declare -f hash_renders); hash_renders gpu" >"$out/lavapipe.txt"
  timeout "$(left)" bash -c "$(declare -f hash_renders); hash_renders cpu" >"$out/reference.txt"
  grep -v '^#' "$hash_file" | while read -r s m h; do
    if [[ " $scenes " == *" $s "* ]]; then echo "$s $m $h"; fi
  done | LC_ALL=C sort >"$out/expected.txt"
  n=$(wc -l <"$out/expected.txt")
  lvp_bad=$(LC_ALL=C comm -13 "$out/expected.txt" "$out/lavapipe.txt" | wc -l)
  ref_bad=$(LC_ALL=C comm -13 "$out/expected.txt" "$out/reference.txt" | wc -l)
  lvp_name=$(VK_DRIVER_FILES=$lavapipe_icd "$phongvk" devices 2>&1 | head -1 | sed 's/^\[0\] //;s/ — .*//')
  if [ "$lvp_bad" = 0 ] && [ "$ref_bad" = 0 ] && [ "$(wc -l <"$out/lavapipe.txt")" = "$n" ]; then v=pass; else
    v=FAIL; LC_ALL=C comm -13 "$out/expected.txt" "$out/lavapipe.txt" | head; LC_ALL=C comm -13 "$out/expected.txt" "$out/reference.txt" | head
  fi
  [ "$v" = FAIL ] && echo "(a scene added or an intended change to the contract: re-pin with scripts/gpu_check.sh --pin)"
  note lavapipe "$v" "$((n - lvp_bad)) of $n on $lvp_name, $((n - ref_bad)) of $n on the reference, equal to $hash_file; $((SECONDS - t)) s"
fi

# --- a 100M-triangle frame -------------------------------------------------------------------------
if wanted rate; then
  t=$SECONDS
  scene=$out/rate.json
  {
    echo '{"camera": {"position": [8.5, 8.5, 30], "look_at": [8.5, 8.5, 0], "up": [0, 1, 0], "fov": 38, "width": 1920, "height": 1080},'
    echo ' "lights": [{"position": [8.5, -10, 30]}], "objects": ['
    for i in $(seq 0 17); do for j in $(seq 0 17); do
      sep=','; [ "$i$j" = 1717 ] && sep=
      echo "  {\"shape\": \"icosphere\", \"center\": [$i, $j, 0], \"radius\": 0.45, \"subdivide\": $rate_subdivide}$sep"
    done; done
    echo ']}'
  } >"$scene"
  if timeout "$(left)" "$phongvk" render "$scene" -o "$out/rate.png" --repeat 10 >"$out/rate.log" 2>&1; then
    device_ms=$(grep -oE 'device [0-9.]+' "$out/rate.log" | head -1 | cut -d' ' -f2)
    triangles=$(grep -oE '[0-9]+ triangles' "$out/rate.log" | head -1 | cut -d' ' -f1)
    rate=$(awk -v t="$triangles" -v ms="$device_ms" 'BEGIN { printf "%.2f", t / (ms / 1000) / 1e9 }')
    note rate pass "$triangles triangles at 1920x1080: $device_ms ms device, $rate G triangles/s; $(grep -oE 'scene [0-9.]+ ms' "$out/rate.log" | head -1) to build; $((SECONDS - t)) s"
    grep -E '^(frame ms|device ms|rendered)' "$out/rate.log"
  else
    tail -5 "$out/rate.log"
    note rate FAIL "the grid of icospheres did not render (rate.log)"
  fi
fi

# --- the benchmark ---------------------------------------------------------------------------------
if wanted bench; then
  t=$SECONDS
  if timeout "$(left)" "$build/bench/phongvk_bench" --revision "$revision" --source "$src" --cli "$phongvk" $bench_args \
      --out "$out/BENCHMARKS_GPU.md" --plot "$out/bench_error.png" >"$out/bench.log" 2>&1; then
    note bench pass "report in $out/BENCHMARKS_GPU.md; $((SECONDS - t)) s"
  else
    tail -10 "$out/bench.log"
    note bench FAIL "the benchmark failed (bench.log)"
  fi
fi

{
  echo "# gpu_check.sh at $revision"
  echo
  echo "GPU: $gpu  "
  echo "CPU: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ //'), $jobs cores  "
  echo "$(date -u '+%Y-%m-%d %H:%M UTC'), $((SECONDS - start)) s in all"
  echo
  echo "| stage | verdict | what |"
  echo "|---|---|---|"
  printf '%s\n' "${summary[@]}"
} >"$out/gpu_check.md"
echo
cat "$out/gpu_check.md"
[ "$failures" = 0 ]
