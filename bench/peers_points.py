#!/usr/bin/env python3
"""1M points per frame from Python: phongvk against moderngl's POINTS draw of the same arrays.

    PYTHONPATH=build/python /usr/bin/python3 bench/peers_points.py [--rounds 5] [--frames 20] [--points N] [--quick] [--out FILE]

The workload is a point cloud of N points (default 1,000,000; --quick: 50,000): positions drawn
from a seeded standard normal, colours random uint8, no normals, drawn unlit in their own colour
(phongvk: `scene.add_points(..., material=Material(color=(1, 1, 1)))`; moderngl: a per-vertex
normalized uint8 attribute), one pixel a point (phongvk's `render_settings.point_size = 1`;
moderngl's `gl_PointSize = 1.0` with `PROGRAM_POINT_SIZE`), depth tested, at 1280x720, through
the same camera (vertical fov 40, near 0.1, far 100; moderngl's view-projection matrix built as
bench/peers.py builds it). The peer is moderngl (Debian's python3-moderngl: OpenGL through headless
EGL, a standalone context as bench/peers.py creates it) drawing `moderngl.POINTS`. Images need
not match pixel for pixel (the rules for a point's square differ); the work is the same. Loops:

- moving camera: the same cloud, the camera moving on a circle about the z axis each frame
  (phongvk: `scene.camera = ...; renderer.render(scene)`; moderngl: the uniform, clear, draw,
  `fbo.read` into numpy, the rows flipped to phongvk's top-first order);
- new cloud each frame: a fixed camera, new positions and colours every frame, as a depth-camera
  stream gives them (4 clouds made before timing, cycled; phongvk:
  `scene.set_mesh(handle, phongvk.Points(positions, colors))`; moderngl: `vbo.write` of both
  arrays), each image read back into numpy;
- cold process: a new python3 that imports its renderer, builds the N-point scene and renders one
  frame, as a user script that renders one picture runs; its wall clock.

Each loop renders one warm-up frame, then --frames frames, each timed alone. Rounds are
interleaved (phongvk gpu, moderngl, again, --rounds times); a loop's number is the median of all
its timed frames over the rounds, a cold process's the median over the rounds. Before timing, a
sanity check: both renderers' images are non-empty, and phongvk's gpu and cpu renderers give
identical bytes on a 20,000-point cloud. A peer that is not installed or has no device is
reported as such in its column. The report (markdown) goes to --out (default: printed only).
"""

import argparse
import os
import pathlib
import platform
import statistics
import subprocess
import sys
import time

import numpy as np

from gl_peer import look_at, perspective, unavailable

HERE = pathlib.Path(__file__).resolve().parent
SIZE = (1280, 720)
FOV, NEAR, FAR = 40.0, 0.1, 100.0
RADIUS, HEIGHT = 8.0, 3.0  # the camera's circle about the z axis, looking at the origin
CLOUDS = 4  # the new-cloud loop's arrays, made before timing and cycled
SEED = 1


# --- workload -----------------------------------------------------------------------------------

def cloud(n, seed=SEED):
    """N points: positions (N, 3) float32 from a standard normal, colours (N, 3) uint8."""
    rng = np.random.default_rng(seed)
    return rng.standard_normal((n, 3), dtype=np.float32), rng.integers(0, 256, (n, 3), dtype=np.uint8)


def eye_at(i, frames):
    """The camera's position at frame i of frames on its circle (frame 0: on +x)."""
    a = 2 * np.pi * i / max(frames, 1)
    return np.array([RADIUS * np.cos(a), RADIUS * np.sin(a), HEIGHT])


# --- renderers (each imports its own library, so that a cold process loads only its own) ----------

class PhongvkRenderer:
    def __init__(self, backend, positions, colors, size=SIZE):
        import phongvk
        self.phongvk, self.size = phongvk, size
        self.scene = phongvk.Scene(*size)
        self.scene.render_settings.point_size = 1
        self.handle = self.scene.add_points(positions, colors=colors, material=phongvk.Material(color=(1, 1, 1)))
        self.renderer = phongvk.Renderer(backend)
        self.look(eye_at(0, 1))

    def look(self, eye):
        self.scene.camera = self.phongvk.Camera(position=tuple(eye), look_at=(0, 0, 0), up=(0, 0, 1), width=self.size[0],
                                                height=self.size[1], fov=FOV, near=NEAR, far=FAR)

    def new_cloud(self, positions, colors):
        self.scene.set_mesh(self.handle, self.phongvk.Points(positions, colors=colors))

    def frame(self):
        return self.renderer.render(self.scene)

    def close(self):
        pass


VERTEX = """
#version 330
uniform mat4 view_projection;
in vec3 position;
in vec3 colour;
out vec3 shade;
void main() {
    shade = colour;
    gl_Position = view_projection * vec4(position, 1.0);
    gl_PointSize = 1.0;
}
"""
FRAGMENT = """
#version 330
in vec3 shade;
out vec4 rgba;
void main() { rgba = vec4(shade, 1.0); }
"""


class ModernglRenderer:
    """The same arrays in two vertex buffers (positions 3 floats, colours 3 normalized bytes), one
    POINTS draw a frame."""

    def __init__(self, positions, colors, size=SIZE):
        import moderngl
        self.ctx = moderngl.create_standalone_context(backend="egl")
        self.ctx.enable(moderngl.DEPTH_TEST | moderngl.PROGRAM_POINT_SIZE)
        self.program = self.ctx.program(vertex_shader=VERTEX, fragment_shader=FRAGMENT)
        self.positions = self.ctx.buffer(np.ascontiguousarray(positions, dtype="f4").tobytes())
        self.colors = self.ctx.buffer(np.ascontiguousarray(colors, dtype="u1").tobytes())
        self.vao = self.ctx.vertex_array(self.program, [(self.positions, "3f", "position"),
                                                        (self.colors, "3f1", "colour")])
        self.mode = moderngl.POINTS
        width, height = size
        self.fbo = self.ctx.framebuffer(self.ctx.renderbuffer((width, height)),
                                        self.ctx.depth_renderbuffer((width, height)))
        self.size = size
        self.look(eye_at(0, 1))

    def look(self, eye):
        vp = perspective(FOV, self.size[0] / self.size[1], NEAR, FAR) @ look_at(eye, np.zeros(3), np.array([0.0, 0, 1]))
        self.program["view_projection"].write(vp.T.astype("f4").tobytes())

    def new_cloud(self, positions, colors):
        self.positions.write(positions)  # C-contiguous float32 and uint8 arrays: their buffers as they are
        self.colors.write(colors)

    def frame(self):
        width, height = self.size
        self.fbo.use()
        self.fbo.clear(0.0, 0.0, 0.0, 1.0)
        self.vao.render(mode=self.mode)
        image = np.frombuffer(self.fbo.read(components=3), dtype=np.uint8).reshape(height, width, 3)
        return image[::-1].copy()

    def close(self):
        self.ctx.release()


RENDERERS = {
    "phongvk gpu": lambda p, c: PhongvkRenderer("gpu", p, c),
    "moderngl": ModernglRenderer,
}


# --- measurement --------------------------------------------------------------------------------

def moving_camera_ms(name, base, frames):
    """Each frame's time (ms): the camera moved, the frame rendered and read back."""
    renderer = RENDERERS[name](*base)
    renderer.look(eye_at(0.5, frames))  # warm-up: start-up, pipelines and the upload are not a frame's
    renderer.frame()
    times = []
    for i in range(frames):
        start = time.perf_counter()
        renderer.look(eye_at(i, frames))
        image = renderer.frame()
        times.append(1000 * (time.perf_counter() - start))
    assert image.shape == (SIZE[1], SIZE[0], 3) and image.any()
    renderer.close()
    return times


def new_cloud_ms(name, base, clouds, frames):
    """Each frame's time (ms): a new cloud's arrays handed over, the frame rendered and read back."""
    renderer = RENDERERS[name](*base)
    renderer.new_cloud(*clouds[-1])  # warm-up
    renderer.frame()
    times = []
    for i in range(frames):
        start = time.perf_counter()
        renderer.new_cloud(*clouds[i % len(clouds)])
        image = renderer.frame()
        times.append(1000 * (time.perf_counter() - start))
    assert image.shape == (SIZE[1], SIZE[0], 3) and image.any()
    renderer.close()
    return times


def cold_frame(name, n):
    """What the cold process runs: build the N-point scene and render one frame."""
    RENDERERS[name](*cloud(n)).frame()


def cold_process_s(name, n):
    """A new interpreter that imports, builds the N-point scene and renders one frame; wall clock."""
    code = "import sys; sys.path.insert(0, %r); import peers_points; peers_points.cold_frame(%r, %d)" % (str(HERE), name, n)
    start = time.perf_counter()
    subprocess.run([sys.executable, "-c", code], check=True, capture_output=True, env=dict(os.environ))
    return time.perf_counter() - start


def sanity(names, n):
    """Both images non-empty; phongvk gpu and cpu identical bytes on an n-point cloud. Returns lines."""
    base = cloud(n)
    gpu = PhongvkRenderer("gpu", *base).frame()
    cpu = PhongvkRenderer("cpu", *base).frame()
    lit = lambda image: int(image.any(axis=2).sum())
    lines = [f"phongvk gpu and cpu on {n:,} points at {SIZE[0]}x{SIZE[1]}: "
             + ("identical bytes" if np.array_equal(gpu, cpu) else
                f"DIFFER in {int((gpu != cpu).any(axis=2).sum()):,} pixels")
             + f"; phongvk draws {lit(gpu):,} pixels"]
    if "moderngl" in names:
        peer = ModernglRenderer(*base)
        gl = peer.frame()
        peer.close()
        same = int(((gl == gpu).all(axis=2) & gpu.any(axis=2)).sum())
        lines.append(f"moderngl draws {lit(gl):,} pixels there, {same:,} of them the same colour as phongvk's "
                     "(the same work; pixels need not match)")
    ok = np.array_equal(gpu, cpu) and lit(gpu) > 0 and ("moderngl" not in names or lit(gl) > 0)
    return ok, lines


def measure(names, n, rounds, frames):
    base = cloud(n)
    clouds = [cloud(n, SEED + 1 + k) for k in range(CLOUDS)]
    results = {n_: {"moving": [], "new": [], "cold": []} for n_ in names}
    for r in range(rounds):
        for name in names:
            results[name]["moving"] += moving_camera_ms(name, base, frames)
            results[name]["new"] += new_cloud_ms(name, base, clouds, frames)
        for name in names:
            results[name]["cold"].append(cold_process_s(name, n))
        print(f"round {r + 1}/{rounds}: " + "; ".join(
            f"{name} {statistics.median(results[name]['moving'][-frames:]):.1f} / "
            f"{statistics.median(results[name]['new'][-frames:]):.1f} ms/frame, {results[name]['cold'][-1]:.2f} s cold"
            for name in names), flush=True)
    return {name: {k: statistics.median(v) for k, v in r.items()} for name, r in results.items()}


# --- report -------------------------------------------------------------------------------------

def report(n, results, missing, sanity_lines, rounds, frames):
    sys.path.insert(0, str(HERE))
    import peers  # the machine line, as bench/peers.py writes it
    import phongvk
    vulkan, gl = peers.device_of([n_ for n_ in peers.RENDERERS if n_ not in missing])
    out = ["# Peers: points per frame, phongvk against moderngl from Python", "",
           "Generated by `bench/peers_points.py`; do not edit by hand, rerun it.", "",
           f"Machine: {platform.processor() or platform.machine()}, {os.cpu_count()} logical cores; Vulkan: {vulkan}; "
           f"OpenGL (moderngl): {gl or 'none'}; Python {platform.python_version()}; "
           f"{time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}; revision `{phongvk.__revision__}`.", "",
           f"{n:,} points (positions standard normal, random uint8 colours, no normals: unlit), one pixel each, "
           f"depth tested, at {SIZE[0]}x{SIZE[1]}, every image read back into numpy; moderngl draws `moderngl.POINTS` "
           f"with `gl_PointSize = 1.0`. Per frame: the median of every timed frame ({frames} a round, after a warm-up "
           f"frame) over {rounds} interleaved rounds. Cold process: a new python3 importing its renderer, building the "
           "scene and rendering one frame, wall clock, the median over the rounds. Ratios are phongvk's time over "
           "moderngl's: below 1 phongvk is faster.", ""]
    out += [f"- {line}" for line in sanity_lines]
    out += [f"- **{name}**: {why}" for name, why in missing.items()]
    out += ["", "| workload | phongvk gpu ms/frame | moderngl ms/frame | phongvk / moderngl |", "|---|--:|--:|--:|"]
    rows = [("moving camera (same cloud)", "moving", 1), ("new cloud each frame (`set_mesh` / `vbo.write`)", "new", 1),
            ("cold process (one frame, ms wall clock)", "cold", 1000)]
    for label, key, scale in rows:
        cells = [format(results[name][key] * scale, ".1f") if name in results else "–" for name in RENDERERS]
        ratio = (f"{results['phongvk gpu'][key] / results['moderngl'][key]:.2f}x"
                 if "phongvk gpu" in results and "moderngl" in results else "–")
        out.append(f"| {label} | {' | '.join(cells)} | {ratio} |")
    return "\n".join(out) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--frames", type=int, default=20)
    parser.add_argument("--points", type=int, default=1_000_000)
    parser.add_argument("--quick", action="store_true", help="50,000 points, one round of 3 frames (the smoke test)")
    parser.add_argument("--out", help="write the markdown report here")
    parser.add_argument("--require-peers", action="store_true", help="fail when moderngl is not available")
    args = parser.parse_args()
    if args.quick:
        args.points, args.rounds, args.frames = 50_000, 1, 3
    missing = {name: why for name in RENDERERS if (why := unavailable(name))}
    if missing and args.require_peers:
        sys.exit("peers_points.py: " + "; ".join(f"{name} {why}" for name, why in missing.items()))
    names = [name for name in RENDERERS if name not in missing]
    ok, sanity_lines = sanity(names, 20_000)
    print("\n".join(sanity_lines), flush=True)
    if not ok:
        sys.exit("peers_points.py: the sanity check failed")
    results = measure(names, args.points, args.rounds, args.frames)
    text = report(args.points, results, missing, sanity_lines, args.rounds, args.frames)
    if args.out:
        pathlib.Path(args.out).write_text(text)
    print(text)


if __name__ == "__main__":
    main()
