#!/usr/bin/env python3
"""A 120-pose Python loop against `phongvk sequence`, per frame, on the paper's orbit (Fig. 7).

    PYTHONPATH=build/python /usr/bin/python3 bench/python_loop.py [--rounds 5] [--cli build/phongvk]

Interleaved rounds (Python loop, then the CLI, then again), medians over the rounds:
- python: Renderer("gpu").render(scene.frame(i)) for the 120 frames, after one warm-up frame;
- sequence: `phongvk sequence` over the same 120 frames, a process's wall clock / 120 (start-up
  and PNG writing included);
- sequence without PNGs: the same less the time phongvk.encode_png takes for the 120 images (the
  encoder `sequence` writes its frames with).
"""

import argparse
import pathlib
import statistics
import subprocess
import tempfile
import time

import phongvk

ROOT = pathlib.Path(__file__).resolve().parents[1]


def python_loop(scene_file):
    scene = phongvk.load_scene(scene_file)
    renderer = phongvk.Renderer("gpu")
    renderer.render(scene)  # warm-up: start-up and pipelines are not a frame's
    images = []
    start = time.perf_counter()
    for i in range(scene.frame_count):
        images.append(renderer.render(scene.frame(i)))
    per_frame = (time.perf_counter() - start) / scene.frame_count
    assert renderer.stats["scene_builds"] == 1
    return per_frame, images


def cli_sequence(cli, scene_file, frames):
    with tempfile.TemporaryDirectory() as out:
        start = time.perf_counter()
        subprocess.run([cli, "sequence", scene_file, "-o", out], check=True, capture_output=True)
        return (time.perf_counter() - start) / frames


def png_time(images):
    start = time.perf_counter()
    for image in images:
        phongvk.encode_png(image)
    return (time.perf_counter() - start) / len(images)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--cli", default=str(ROOT / "build" / "phongvk"))
    parser.add_argument("--scene", default=str(ROOT / "scenes/paper/fig7_orbit_white_red.json"))
    args = parser.parse_args()
    python, sequence, png = [], [], []
    for _ in range(args.rounds):
        per_frame, images = python_loop(args.scene)
        python.append(per_frame)
        png.append(png_time(images))
        sequence.append(cli_sequence(args.cli, args.scene, len(images)))
    ms = lambda values: statistics.median(values) * 1000  # noqa: E731
    print(f"{args.scene}: {len(images)} frames, {args.rounds} interleaved rounds, median ms per frame")
    print(f"  python loop (render only):       {ms(python):7.2f}")
    print(f"  phongvk sequence (PNGs written): {ms(sequence):7.2f}")
    print(f"  phongvk sequence without PNGs:   {ms(sequence) - ms(png):7.2f}  (PNG encoding {ms(png):.2f})")


if __name__ == "__main__":
    main()
