#!/usr/bin/env python3
"""Regenerates the stress meshes and lights_64.json (scenes/stress/README.md says what each is for).

Deterministic: a fixed seed, and numbers printed with repr() so a rerun writes identical files.
Run from anywhere: python3 scenes/stress/meshes/generate.py
"""
import json
import math
import os
import random

HERE = os.path.dirname(os.path.abspath(__file__))
STRESS = os.path.dirname(HERE)


def write_obj(name, header, vertices, faces):
    with open(os.path.join(HERE, name), "w") as f:
        for line in header:
            f.write("# " + line + "\n")
        for v in vertices:
            f.write("v %r %r %r\n" % tuple(v))
        for face in faces:
            f.write("f %d %d %d\n" % tuple(i + 1 for i in face))


def slivers():
    # A fan of 4000 triangles 1 m long and 1e-5 m wide (aspect 1e5) sharing their long edges, so
    # they tile a thin wedge; plus zero-area triangles the importer must drop.
    count, width = 4000, 1e-5
    vertices = [(0.0, 0.0, 0.0)] + [(1.0, (k - count / 2) * width, 0.0) for k in range(count + 1)]
    faces = [(0, k + 1, k + 2) for k in range(count)]  # counter-clockwise from +z
    # Zero area: a repeated index, and three exactly collinear points (on the fan's own rim).
    faces += [(0, 1, 1), (0, 0, 0), (1, 2, 3)]
    write_obj("slivers.obj", ["4000 slivers of aspect ratio 1e5 in a fan, and 3 zero-area triangles"],
              vertices, faces)


def degenerate():
    # Two real triangles (a unit square) and every kind of degenerate one.
    vertices = [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (1.0, 1.0, 0.0), (0.0, 1.0, 0.0),
                (1.0, 0.0, 0.0),                                   # 5: same position as 2
                (0.0, 0.0, 0.5), (0.5, 0.5, 0.5), (1.0, 1.0, 0.5),  # 6-8: exactly collinear
                (0.1, 0.3, 0.0), (0.37, 1.11, 0.0), (0.71, 2.13, 0.0)]  # 9-11: y = 3x in decimal only
    faces = [(0, 1, 2), (0, 2, 3),
             (0, 1, 1),     # repeated index
             (0, 1, 4),     # repeated position under another index
             (5, 6, 7),     # collinear: cross product exactly zero
             (8, 9, 10)]    # collinear as decimals, not as floats: a sliver the raster must handle
    write_obj("degenerate.obj", ["2 real triangles, 3 exactly zero-area ones, 1 nearly collinear sliver"],
              vertices, faces)


def jittered_grid():
    # A 40x40-quad grid of the unit square, interior vertices moved by up to 0.15 of a cell (no triangle can fold over), shared
    # by index: every point inside is covered by exactly one triangle.
    rng = random.Random(5)
    n = 40
    vertices = []
    for j in range(n + 1):
        for i in range(n + 1):
            dx = rng.uniform(-0.15, 0.15) if 0 < i < n else 0.0
            dy = rng.uniform(-0.15, 0.15) if 0 < j < n else 0.0
            vertices.append(((i + dx) / n - 0.5, (j + dy) / n - 0.5, 0.0))
    faces = []
    for j in range(n):
        for i in range(n):
            a, b = j * (n + 1) + i, j * (n + 1) + i + 1
            c, d = a + n + 1, b + n + 1
            faces += [(a, b, d), (a, d, c)] if (i + j) % 2 else [(a, b, c), (b, d, c)]
    write_obj("jittered_grid.obj", ["40x40 quads of the unit square, interior vertices jittered"],
              vertices, faces)


def behind_camera():
    # Seen from near_plane.json's camera at (0, 0, 1) looking along +x: one triangle with a vertex
    # behind the eye, one with two, one wholly behind, one through the eye's own plane.
    vertices = [(-2.0, 0.0, 0.8), (3.0, -2.0, 0.2), (3.0, 2.0, 0.4),    # one vertex behind
                (-1.0, -1.0, 1.3), (-1.5, 1.0, 1.5), (2.0, 0.5, 1.6),   # two behind
                (-1.0, -1.0, 0.0), (-2.0, 1.0, 0.5), (-3.0, 0.0, 1.0),  # all behind
                (0.0, -3.0, 1.2), (0.0, 3.0, 1.2), (1.0, 0.0, 2.0)]     # two on the eye plane x = 0
    faces = [(0, 1, 2), (3, 4, 5), (6, 7, 8), (9, 10, 11)]
    write_obj("behind_camera.obj", ["triangles crossing the near plane and behind the camera"],
              vertices, faces)


def huge_triangle():
    # Two vertices 0.5 m ahead of huge_triangles.json's camera and 5000 m to either side: at ~166
    # px/m they project ~1e6 pixels out, past the 2^19-pixel guard band, so clipping must cut it.
    vertices = [(0.5, -5000.0, 0.0), (5000.0, 0.0, 0.0), (0.5, 5000.0, 0.0)]
    write_obj("huge_triangle.obj", ["one triangle 10 km across, ~2e6 pixels on screen"], vertices, [(0, 1, 2)])


def lights_64():
    lights = []
    for k in range(64):
        angle = 2 * math.pi * k / 64
        hue = [0.5 + 0.5 * math.cos(angle + phase) for phase in (0, 2.1, 4.2)]
        lights.append({"position": [round(2 * math.cos(angle), 6), round(2 * math.sin(angle), 6),
                                    round(0.5 + (k % 4) * 0.4, 6)],
                       "intensity": 0.08, "color": [round(c, 4) for c in hue]})
    scene = {
        "camera": {"position": [-3.0, -2.0, 2.0], "look_at": [0, 0, 0], "width": 192, "height": 128},
        "lights": lights,
        "materials": {"shiny": {"ka": 0.05, "kd": 0.8, "ks": 0.6, "n": 30, "color": [0.9, 0.9, 0.9]}},
        "objects": [
            {"shape": "sphere", "center": [0, 0, 0], "radius": 0.6, "segments": 48, "material": "shiny"},
            {"shape": "cylinder", "center": [0, 0, -0.65], "radius": 2.5, "height": 0.1, "segments": 64,
             "subdivide": 2, "material": "shiny"}]}
    with open(os.path.join(STRESS, "lights_64.json"), "w") as f:
        json.dump(scene, f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    slivers()
    degenerate()
    jittered_grid()
    behind_camera()
    huge_triangle()
    lights_64()
