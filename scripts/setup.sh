#!/usr/bin/env bash
# Installs what phongvk needs, from Debian 12 packages only. Run as root (or with sudo).
#
#   bash scripts/setup.sh          # to build the library, the phongvk command, the Python package and
#                                  # the benchmark, and to render (27 packages)
#   bash scripts/setup.sh --test   # and everything the tests and the full CI need: scripts/test.sh,
#                                  # scripts/ci.sh (fuzz.sh, sanitize.sh) (20 more)
#
# Idempotent: when every package is there it does nothing (no apt-get at all). When another
# apt-get or dpkg holds a lock (unattended-upgrades, a second setup), it waits for it, up to
# PHONGVK_APT_LOCK_TIMEOUT seconds (default 600), instead of failing at once.
set -euo pipefail

usage() { sed -n '2,11s/^# \{0,1\}//p' "$0"; }

with_tests=0
for arg in "$@"; do
  case $arg in
    --test) with_tests=1 ;;
    -h|--help) usage; exit 0 ;;
    *) echo "setup: unknown option '$arg'" >&2; usage >&2; exit 2 ;;
  esac
done

# Building and rendering: every find_package/find_program the default configure requires
# (CMakeLists.txt, cmake/dependencies.cmake, cmake/shaders.cmake, python/CMakeLists.txt), the
# headers the sources include, and the Vulkan driver the default backend renders with. The
# README's render command configures with -DPHONGVK_TESTS=OFF, so GoogleTest is not among them.
packages=(
  build-essential cmake ninja-build pkg-config git  # git: the revision `phongvk --version` reports
  libglm-dev libstb-dev nlohmann-json3-dev libcli11-dev libdeflate-dev
  libpng-dev libjpeg62-turbo-dev  # texture decoding (image/png_decode.cpp, image/jpeg_decode.cpp)
  libtinyobjloader-dev libtinygltf-dev  # OBJ and glTF import (scene/)
  libdraco-dev  # glTF's KHR_draco_mesh_compression (meshio/gltf_draco.cpp)
  libvulkan-dev libvulkan-volk-dev glslang-tools spirv-tools  # Vulkan loader and headers, volk, shader compilers
  mesa-vulkan-drivers  # lavapipe: the GPU backend on a machine without a GPU
  python3 python3-dev pybind11-dev python3-numpy  # import phongvk (python/: built by default)
  python3-setuptools python3-pip python3-venv  # pip install . (pyproject.toml, setup.py), offline
)

# The tests and the full CI (scripts/test.sh, scripts/ci.sh).
test_packages=(
  libgtest-dev googletest  # tests/CMakeLists.txt: find_package(GTest REQUIRED)
  python3-pytest python3-pil  # python/tests (CTest's python_* entries); Pillow decodes PNGs there
  python3-pytest-xdist  # the Python suite against the pip-installed package, two files at a time (scripts/pip_check.sh)
  python3-matplotlib python3-nbconvert python3-ipykernel jupyter-core  # examples/python, run by python/tests/test_examples.py
  assimp-testmodels  # real PLY, STL and glTF files (/usr/share/assimp/models) for the mesh tests
  vulkan-validationlayers  # PHONGVK_VALIDATE=1 in every GPU test, and `phongvk --validate`
  vulkan-tools  # vulkaninfo, to see what a device offers when a gpu test fails there
  gnuplot-nox  # the benchmark's plot: CTest's bench_smoke and scripts/bench.sh
  python3-moderngl libegl1  # the benchmark's peer (bench/peers.py, headless EGL): CTest's bench_peers_smoke
  libopenmpi-dev openmpi-bin  # phongvk render --mpi (built where found) and CTest's mpi_render
  slurm-wlm munge  # scripts/slurm/ and CTest's slurm_array (tests/slurm_test.sh starts a one-node cluster)
  clang libclang-rt-14-dev  # scripts/fuzz.sh: libFuzzer and clang's sanitizer runtimes
  gltfpack  # meshoptimizer's glTF packer: real GLB files with KHR_lights_punctual lights (python/tests/test_file_lights.py)
  chromium-common  # SwiftShader (/usr/lib/chromium/libvk_swiftshader.so): a second Vulkan, without 64-bit integers (CTest's swiftshader label)
)
if [ "$with_tests" -eq 1 ]; then
  packages+=("${test_packages[@]}")
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

as_root=()
[ "$(id -u)" -eq 0 ] || as_root=(sudo)
lock_timeout=${PHONGVK_APT_LOCK_TIMEOUT:-600}

# apt_get ARGS...: apt-get, non-interactive, waiting for another package manager's locks.
# DPkg::Lock::Timeout makes apt wait for dpkg's locks (/var/lib/dpkg/lock-frontend and lock), as
# `apt` does for 120 s by default and `apt-get` not at all; apt 2.6 applies it to no other lock, so
# the package lists' lock (apt-get update) and the download cache's (apt-get install) are waited
# for here: apt-get gives up on them at once, before it changes anything, and is run again every
# 5 s (its lock errors and the lines before them shown the first time only).
apt_get() {
  local log status waited=0 quiet=''
  local lock_error='/(lists|archives)/lock\b|^E: Unable to lock directory'
  log=$(mktemp)
  while :; do
    status=0
    "${as_root[@]}" env DEBIAN_FRONTEND=noninteractive \
      apt-get -o DPkg::Lock::Timeout="$lock_timeout" "$@" 2>&1 | tee "$log" | sed -E "${quiet:+\\%$quiet%d}" || status=$?
    if [ "$status" -ne 0 ] && grep -qE "$lock_error" "$log" && [ "$waited" -lt "$lock_timeout" ]; then
      [ "$waited" -gt 0 ] || echo "setup: another package manager holds apt's lock; waiting up to $lock_timeout s"
      quiet="$lock_error|^(Reading package lists|Building dependency tree|Reading state information)"
      sleep 5
      waited=$((waited + 5))
      continue
    fi
    [ "$status" -eq 0 ] || [ "$waited" -eq 0 ] || grep -E "$lock_error" "$log" >&2 || true
    rm -f "$log"
    return "$status"
  done
}

if [ ${#missing[@]} -gt 0 ]; then
  apt_get update -q
  apt_get install -y -q --no-install-recommends "${missing[@]}"
fi
if [ "$with_tests" -eq 1 ]; then
  echo "setup: all ${#packages[@]} packages present (building, rendering and testing)"
else
  echo "setup: all ${#packages[@]} packages present (building and rendering; add --test for the tests)"
fi
