#!/usr/bin/env bash
# Re-pins the contract's images: rewrites tests/data/pinned_images.txt from what the renderers
# give now (docs/DECISIONS.md "Pinned images"). Run it only after an intended change to the
# contract (shaders/phong.h or the other shared maths, mesh building, the scene's defaults), then
# read the diff it prints and commit the file with the change that moved it, saying why.
# It builds pinned_images_gpu_test in build/ (as scripts/test.sh does) and runs it with
# PHONGVK_REPIN=1, which renders every pinned case on the reference and the compute port and writes
# the file only where the two agree on every case. A few seconds on lavapipe.
set -euo pipefail
cd "$(dirname "$0")/.."

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DPHONGVK_TESTS=ON
cmake --build build --target pinned_images_gpu_test -j"${JOBS:-$(nproc)}"
PHONGVK_REPIN=1 ./build/tests/pinned_images_gpu_test --gtest_filter='PinnedImagesRepin.*'
git status --short -- tests/data/pinned_images.txt && git --no-pager diff --stat -- tests/data/pinned_images.txt || true
