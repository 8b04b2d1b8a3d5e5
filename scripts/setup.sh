#!/usr/bin/env bash
# Installs everything phongvk needs to build, render and test, from Debian 12 packages only.
# Idempotent: packages already present are skipped by apt-get. Run as root (or with sudo).
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config git
  libglm-dev libstb-dev libgtest-dev googletest nlohmann-json3-dev libcli11-dev libtinyobjloader-dev libdeflate-dev
  libtinygltf-dev assimp-testmodels  # glTF (scene/gltf_import.cpp); real PLY, STL and glTF files for the tests
  libvulkan-dev libvulkan-volk-dev glslang-tools spirv-tools mesa-vulkan-drivers vulkan-validationlayers vulkan-tools
  gnuplot-nox
  python3 python3-dev pybind11-dev python3-numpy python3-pytest  # the Python package and its tests (python/)
  python3-pil python3-matplotlib python3-nbconvert python3-ipykernel jupyter-core  # tests' PNG decoder, examples/python
  clang libclang-rt-14-dev  # scripts/fuzz.sh: libFuzzer and the sanitizer runtimes for clang
  libopenmpi-dev openmpi-bin  # phongvk render --mpi (optional at configure time) and its test
  slurm-wlm munge  # scripts/slurm/ and tests/slurm_test.sh, which starts a one-node cluster of its own
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -gt 0 ]; then
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -q
  $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
fi
echo "setup: all ${#packages[@]} packages present"
