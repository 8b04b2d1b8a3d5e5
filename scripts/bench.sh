#!/usr/bin/env bash
# Regenerates docs/BENCHMARKS.md and docs/bench_error.png: builds phongvk_bench in Release (in
# build/, as scripts/test.sh does, so either reuses the other's work) and runs the benchmark
# harness (bench/): every scene on the reference, the compute port and the graphics pipeline,
# median of 5 frames after a warm-up, then the peer section (bench/peers.py: phongvk against
# moderngl from Python, docs/BENCHMARKS_PEERS.md). Run `bash scripts/setup.sh --test` first (gnuplot draws the plot).
# Extra arguments go to phongvk_bench, e.g. `--repeat 9`, `--device 1`.
# On the 2-core CPU-only machine (lavapipe) the harness's first renders (every committed scene on a
# new machine, twice) take about 2 minutes and the peer section about 4; each backend is measured in
# interleaved rounds, so load from elsewhere on a shared machine biases no comparison.
set -euo pipefail
cd "$(dirname "$0")/.."

echo "== build (Release)"
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build --target phongvk_bench phongvk -j"$(nproc)"

echo "== benchmark"
revision=$(git describe --always --dirty 2>/dev/null || echo unknown)
./build/bench/phongvk_bench --revision "$revision" --out docs/BENCHMARKS.md --plot docs/bench_error.png "$@"

echo "== peers (phongvk against moderngl from Python)"
PYTHONPATH=build/python /usr/bin/python3 bench/peers.py --out docs/BENCHMARKS_PEERS.md

echo "== peers, point clouds (phongvk against moderngl's POINTS from Python)"
PYTHONPATH=build/python /usr/bin/python3 bench/peers_points.py --out docs/BENCHMARKS_PEERS_POINTS.md
