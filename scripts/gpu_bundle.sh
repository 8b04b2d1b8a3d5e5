#!/usr/bin/env bash
# gpu_bundle.sh [--build DIR] [--out FILE] — packs a Release build of phongvk and the Debian 12
# libraries it runs with (Vulkan loader, validation layer, lavapipe, Open MPI, tinyobjloader, ...)
# into one archive, for `scripts/gpu_check.sh --bundle FILE` on a GPU machine that cannot build
# phongvk itself: another distribution, no package archive, nothing but a GPU driver. Run it on the
# Debian 12 machine where `bash scripts/setup.sh --test` has run.
#
#   --build DIR  a configured and built Release tree (default: build/, built here as
#                scripts/test.sh builds it). Its tests carry the absolute path of their source
#                tree; the archive records it (SOURCE_DIR) and gpu_check.sh points it at the
#                checkout it runs in.
#   --out FILE   the archive (default .gpu/bundle.tar.xz; .gpu/ is ignored by git)
#
# The archive holds the build's programs, libraries and CTest files (objects left out, programs
# stripped), every shared library they load but the C and C++ runtimes (gpu_check.sh links only
# those the machine lacks), lavapipe and the validation layer with their manifests, and Open MPI
# laid out for OPAL_PREFIX, and the source tree. About 50 MB; two minutes to make on two cores (xz).
set -euo pipefail
cd "$(dirname "$0")/.."
build=build
out=.gpu/bundle.tar.xz
while [ $# -gt 0 ]; do
  case $1 in
    --build) build=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    *) echo "gpu_bundle.sh: unknown argument '$1' (see the comment at the top of the script)" >&2; exit 2 ;;
  esac
done
if [ "$build" = build ]; then
  cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DPHONGVK_TESTS=ON
  cmake --build build -j"${JOBS:-$(nproc)}"
fi
build=$(realpath "$build")
source_dir=$(sed -n 's/^CMAKE_HOME_DIRECTORY:INTERNAL=//p' "$build/CMakeCache.txt")
mpi_ok=$(sed -n 's/^PHONGVK_MPI:BOOL=//p' "$build/CMakeCache.txt")
lib=/usr/lib/x86_64-linux-gnu

stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
mkdir -p "$stage/build" "$stage/lib" "$stage/icd" "$stage/layers"

# The build: the programs, the GPU suites (the others run wherever CI runs), shared libraries
# (their links too), CTest's files, the Python package's own files; no objects, static libraries
# or Ninja state.
(cd "$build" && find . \( -name CMakeFiles -prune \) -o \( -type f -o -type l \) -print |
  grep -E '(CTestTestfile\.cmake|_tests?\.cmake|_include\.cmake|\.so(\.[0-9.]+)?|\.py|\.pyi|py\.typed)$|^\./(phongvk|bench/phongvk_bench|tests/[a-z_]+_gpu_test)$' |
  grep -v '_phongvk\.cpython' >"$stage/files")
tar -C "$build" -cf - -T "$stage/files" | tar -C "$stage/build" -xf -
is_elf() { [ "$(head -c4 "$1" | tail -c3)" = ELF ]; }
elves=$(find "$stage/build" -type f | while read -r f; do if is_elf "$f"; then echo "$f"; fi; done)
for f in $elves; do strip --strip-unneeded "$f"; done

# Every library the programs, lavapipe, the layer and Open MPI load, found as this machine finds
# them, under its soname; the C and C++ runtimes stay the machine's own (newer ones run these).
runtime='^(linux-vdso|ld-linux-x86-64|libc|libm|libpthread|libdl|librt|libstdc\+\+|libgcc_s)\.so'
extra="$lib/libvulkan.so.1 $lib/libvulkan_lvp.so $lib/libVkLayer_khronos_validation.so"
mpi_root=
if [ "$mpi_ok" = ON ]; then
  mpi_root="$stage/mpi/usr"
  mkdir -p "$mpi_root/bin" "$mpi_root/share" "$mpi_root/lib/x86_64-linux-gnu" "$stage/mpi/etc"
  cp -a "$lib/openmpi" "$lib/pmix2" "$mpi_root/lib/x86_64-linux-gnu/"
  rm -rf "$mpi_root"/lib/x86_64-linux-gnu/{openmpi,pmix2}/include "$mpi_root"/lib/x86_64-linux-gnu/openmpi/lib/{libmpi_java,libmpi_mpifh,libmpi_usempi,liboshmem}*
  cp -a /usr/bin/orterun /usr/bin/orted "$mpi_root/bin/"
  ln -s orterun "$mpi_root/bin/mpirun"
  cp -a /usr/share/openmpi "$mpi_root/share/"
  cp -a /etc/openmpi "$stage/mpi/etc/"
  extra="$extra $(find "$mpi_root" -name '*.so*' -type f) $mpi_root/bin/orterun $mpi_root/bin/orted"
fi
for f in $elves $extra; do
  ldd "$f" 2>/dev/null | awk '$3 ~ /^\// {print $1, $3}'
done | sort -u | while read -r soname path; do
  if ! [[ $soname =~ $runtime ]] && [[ $path != "$build"/* ]] && [ ! -e "$stage/lib/$soname" ]; then cp -L "$path" "$stage/lib/$soname"; fi
done
# glvnd's dispatch libraries too: NVIDIA's Vulkan driver (libGLX_nvidia) loads them, and a machine
# with the driver alone may not have them.
for f in libvulkan.so.1 libvulkan_lvp.so libVkLayer_khronos_validation.so; do cp -L "$lib/$f" "$stage/lib/$f"; done
for f in libGLdispatch.so.0 libGLX.so.0 libEGL.so.1 libOpenGL.so.0; do
  if [ -e "$lib/$f" ]; then cp -L "$lib/$f" "$stage/lib/$f"; fi
done

# The manifests name their libraries without a folder, so the loader finds them on LD_LIBRARY_PATH.
sed 's|"library_path": *"[^"]*"|"library_path": "libvulkan_lvp.so"|' /usr/share/vulkan/icd.d/lvp_icd.x86_64.json \
  >"$stage/icd/lvp_icd.json"
sed 's|"library_path": *"[^"]*"|"library_path": "libVkLayer_khronos_validation.so"|' \
  /usr/share/vulkan/explicit_layer.d/VkLayer_khronos_validation.json >"$stage/layers/VkLayer_khronos_validation.json"

# The source tree the build came from (its tracked files as they are now): the scenes, the test
# data and the Python module's source the checks use, matching the programs whatever the checkout
# the archive travels with holds.
mkdir -p "$stage/source"
git -C "$source_dir" ls-files -z --cached --others --exclude-standard |
  (cd "$source_dir" && xargs -0 tar -cf - --no-recursion) | tar -C "$stage/source" -xf -
# The real model files the mesh tests read (Debian's assimp-testmodels, /usr/share/assimp/models).
models=/usr/share/assimp/models
mkdir -p "$stage/models"
(cd "$models" && tar -cf - PLY/cube.ply PLY/cube_binary.ply PLY/Wuson.ply PLY/float-color.ply STL/Spider_ascii.stl \
  STL/Spider_binary.stl glTF2/BoxTextured-glTF glTF2/BoxTextured-glTF-Binary glTF2/2CylinderEngine-glTF-Binary) |
  tar -C "$stage/models" -xf -
echo "$source_dir" >"$stage/SOURCE_DIR"
echo "$build" >"$stage/BUILD_DIR"
git -C "$source_dir" describe --always --dirty >"$stage/REVISION" 2>/dev/null || echo unknown >"$stage/REVISION"
rm "$stage/files"
mkdir -p "$(dirname "$out")"
tar -C "$stage" -cf - . | xz -6 -T"${JOBS:-$(nproc)}" >"$out"
echo "gpu_bundle.sh: $out ($(du -h "$out" | cut -f1)), build $(cat "$stage/REVISION") from $source_dir"
