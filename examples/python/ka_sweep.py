#!/usr/bin/env python3
"""The paper's Fig. 4 from Python: the sphere's ambient coefficient ka swept from 0 to 1 (frames of
scenes/paper/fig4_ka_sweep.json, whose "animate" block sets ka = i/(n-1)), rendered on the GPU
backend and laid out as a matplotlib grid.

    /usr/bin/python3 examples/python/ka_sweep.py [OUT.png] [--backend gpu|cpu]

Needs the phongvk package (docs/PYTHON.md): installed, or PYTHONPATH=build/python.
"""

import argparse
import pathlib

import matplotlib

matplotlib.use("Agg")  # headless: draw into a file, no window
import matplotlib.pyplot as plt  # noqa: E402

import phongvk  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[2]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out", nargs="?", default="ka_sweep.png", help="the figure (PNG)")
    parser.add_argument("--backend", default="gpu", choices=["gpu", "cpu"])
    parser.add_argument("--columns", type=int, default=4)
    parser.add_argument("--rows", type=int, default=3)
    args = parser.parse_args()

    scene = phongvk.load_scene(str(ROOT / "scenes/paper/fig4_ka_sweep.json"))
    renderer = phongvk.Renderer(args.backend)
    count = args.columns * args.rows
    frames = [round(k * (scene.frame_count - 1) / (count - 1)) for k in range(count)]

    fig, axes = plt.subplots(args.rows, args.columns, figsize=(2.4 * args.columns, 1.8 * args.rows))
    for ax, i in zip(axes.flat, frames):
        ax.imshow(renderer.render(scene.frame(i), width=360, height=240))
        ax.set_title(f"ka = {i / (scene.frame_count - 1):.2f}", fontsize=9)
        ax.axis("off")
    fig.suptitle("Fig. 4: ambient coefficient ka of the sphere, 0 to 1")
    fig.tight_layout()
    fig.savefig(args.out, dpi=100)
    stats = renderer.stats
    print(f"{args.out}: {count} frames on {renderer.device_name}, meshes built {stats['scene_builds']} time(s)")


if __name__ == "__main__":
    main()
