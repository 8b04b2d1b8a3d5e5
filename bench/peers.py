#!/usr/bin/env python3
"""phongvk against the renderer a Python user would pick instead, per frame, from Python.

    PYTHONPATH=build/python /usr/bin/python3 bench/peers.py [--rounds 5] [--frames 30] [--quick] [--out FILE]

The peer is moderngl (Debian's python3-moderngl: OpenGL through headless EGL, on the same llvmpipe
that runs lavapipe here, or on the GPU's driver) with a per-vertex Phong shader (Gouraud), the
model phongvk renders by default: each object drawn with its material's uniforms, up to four
point lights with their colours and each material's attenuation. Each workload is the same
triangles, normals, lights, camera path and image size for every renderer, and the same work:
back faces culled by both (moderngl's `CULL_FACE`, phongvk's `closed=True`; the models are closed
surfaces). The workloads: icospheres and a real model, each with one material and one light, and
the paper's scenes, which phongvk renders from their files and moderngl from their triangles as
phongvk builds them (`Scene.triangles()`), their materials and lights (`Scene.to_dict()`):

- per frame: one warm-up frame, then `--frames` frames with the camera moving on a circle about the
  up axis through its target (a model's centre; a scene's look-at point, from its camera), each
  frame's image read back into a numpy array (phongvk: `scene.camera = ...;
  renderer.render(scene)`; moderngl: the uniforms, clear, a draw per object, `fbo.read` into
  numpy, the rows flipped to phongvk's top-first order); the time per frame;
- cold process: a new python3 that imports, builds the workload and renders one frame, as a user
  script that renders one picture runs; its wall clock.

Rounds are interleaved (phongvk gpu, phongvk cpu, moderngl, again); each number is the median over
the rounds. A peer that is not installed or has no device is reported as such in its column.
The report (markdown) goes to --out (default: printed only); scripts/bench.sh writes
docs/BENCHMARKS_PEERS.md with it.
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

import phongvk

ROOT = pathlib.Path(__file__).resolve().parents[1]
WUSON = "/usr/share/assimp/models/PLY/Wuson.ply"


# --- workloads ---------------------------------------------------------------------------------

def icosphere(subdivide):
    """The unit icosphere: 20 * 4^subdivide triangles, vertices on the sphere, normals = positions."""
    t = (1 + 5 ** 0.5) / 2
    v = np.array([[-1, t, 0], [1, t, 0], [-1, -t, 0], [1, -t, 0], [0, -1, t], [0, 1, t], [0, -1, -t], [0, 1, -t],
                  [t, 0, -1], [t, 0, 1], [-t, 0, -1], [-t, 0, 1]], dtype=np.float64)
    f = np.array([[0, 11, 5], [0, 5, 1], [0, 1, 7], [0, 7, 10], [0, 10, 11], [1, 5, 9], [5, 11, 4], [11, 10, 2],
                  [10, 7, 6], [7, 1, 8], [3, 9, 4], [3, 4, 2], [3, 2, 6], [3, 6, 8], [3, 8, 9], [4, 9, 5], [2, 4, 11],
                  [6, 2, 10], [8, 6, 7], [9, 8, 1]], dtype=np.int64)
    v /= np.linalg.norm(v, axis=1, keepdims=True)
    for _ in range(subdivide):
        edges = np.sort(np.concatenate([f[:, [0, 1]], f[:, [1, 2]], f[:, [2, 0]]]), axis=1)
        keys = edges[:, 0] * len(v) + edges[:, 1]
        unique, inverse = np.unique(keys, return_inverse=True)
        a, b = unique // len(v), unique % len(v)
        mid = v[a] + v[b]
        mid /= np.linalg.norm(mid, axis=1, keepdims=True)
        m = (inverse + len(v)).reshape(3, -1).T  # the midpoints of edges 01, 12, 20 of each face
        v = np.concatenate([v, mid])
        f = np.concatenate([np.stack([f[:, 0], m[:, 0], m[:, 2]], 1), np.stack([f[:, 1], m[:, 1], m[:, 0]], 1),
                            np.stack([f[:, 2], m[:, 2], m[:, 1]], 1), m])
    return v.astype(np.float32), f.astype(np.int32), v.astype(np.float32)


def ascii_ply(path):
    """Vertices, triangles and normals of an ASCII PLY with x y z nx ny nz first (Wuson.ply)."""
    lines = pathlib.Path(path).read_text().splitlines()
    end = lines.index("end_header")
    count = {l.split()[1]: int(l.split()[2]) for l in lines[:end] if l.startswith("element")}
    rows = np.array([l.split() for l in lines[end + 1:end + 1 + count["vertex"]]], dtype=np.float32)
    faces = []
    for l in lines[end + 1 + count["vertex"]:end + 1 + count["vertex"] + count["face"]]:
        idx = [int(x) for x in l.split()[1:]]
        faces += [[idx[0], idx[k], idx[k + 1]] for k in range(1, len(idx) - 1)]
    normals = rows[:, 3:6] / np.linalg.norm(rows[:, 3:6], axis=1, keepdims=True)
    return rows[:, :3].copy(), np.array(faces, dtype=np.int32), normals.astype(np.float32)


def workloads(quick):
    small = {"name": "icosphere, 1,280 triangles", "mesh": ("icosphere", 3), "size": (640, 480)}
    if quick:
        return [small, paper_workload("fig1_cube")]
    return [small,
            {"name": "icosphere, 1.3M triangles", "mesh": ("icosphere", 8), "size": (1920, 1080)},
            {"name": "Wuson.ply (assimp-testmodels)", "mesh": ("ply", WUSON), "size": (960, 720)}] + [
        paper_workload(p.stem) for p in sorted((ROOT / "scenes" / "paper").glob("*.json"))]


def paper_workload(name):
    path = str(ROOT / "scenes" / "paper" / f"{name}.json")
    scene = phongvk.load_scene(path)
    return {"name": f"paper: {name}", "mesh": ("scene", path), "size": (scene.width, scene.height)}


# What a mesh workload is drawn with, by every renderer: one material, one white light.
MESH_MATERIAL = {"ka": 0.15, "kd": 1.0, "ks": 0.8, "n": 10.0, "attenuation": [1.0, 0.0, 0.0], "color": [0.8, 0.6, 0.4]}
LIGHT_OFFSET = np.array([1.0, -2.0, 3.0])
FOV = 45.0


def mesh_of(spec):
    """What every renderer draws: world vertices, faces, normals, each face's object, the objects'
    materials, the lights (position, RGB times intensity), the ambient light and the camera (its
    first position, target, up, fov, near, far); for a scene file, its path too."""
    kind, arg = spec
    if kind == "scene":
        scene = phongvk.load_scene(arg)
        t = scene.triangles()
        d = scene.to_dict()
        materials = [d["materials"][o["material"]] if isinstance(o["material"], str) else o["material"]
                     for o in d["objects"]]
        lights = [{"position": l["position"], "colour": (np.array(l["color"]) * l["intensity"]).tolist()}
                  for l in d["lights"]]
        c = d["camera"]
        eye = np.array(c["position"])
        camera = {"eye": eye, "target": eye + np.array(c["direction"]), "up": np.array(c["up"]), "fov": c["fov"],
                  "near": c["near"], "far": c["far"]}
        return {"vertices": t["vertices"], "faces": t["faces"].astype(np.int32), "normals": t["normals"],
                "objects": t["objects"], "materials": materials, "lights": lights, "ambient": d["ambient"],
                "camera": camera, "scene": arg}
    vertices, faces, normals = icosphere(arg) if kind == "icosphere" else ascii_ply(arg)
    low, high = vertices.min(0), vertices.max(0)
    centre, radius = (low + high) / 2, float(np.linalg.norm(high - low)) / 2
    camera = {"eye": centre + 2.6 * radius * np.array([0.87, 0.0, 0.5]), "target": centre,
              "up": np.array([0.0, 0.0, 1.0]), "fov": FOV, "near": 0.01 * radius, "far": 100 * radius}
    return {"vertices": vertices, "faces": faces, "normals": normals, "objects": np.zeros(len(faces), np.int32),
            "materials": [MESH_MATERIAL], "lights": [{"position": (centre + LIGHT_OFFSET * radius).tolist(),
                                                      "colour": [1.0, 1.0, 1.0]}],
            "ambient": [1.0, 1.0, 1.0], "camera": camera, "scene": None}


def orbit(mesh, frames):
    """Camera positions on a circle about the up axis through the camera's target, starting at its
    first position (a mesh's: 30 degrees above its box, z up)."""
    c = mesh["camera"]
    up = c["up"] / np.linalg.norm(c["up"])
    offset = c["eye"] - c["target"]
    along = np.dot(offset, up) * up
    across = offset - along
    out = []
    for i in range(frames):
        a = 2 * np.pi * i / max(frames, 1)
        out.append(c["target"] + along + np.cos(a) * across + np.sin(a) * np.cross(up, across))
    return out


# --- renderers ----------------------------------------------------------------------------------

class PhongvkRenderer:
    def __init__(self, backend, mesh, size):
        self.camera, self.size = mesh["camera"], size
        if mesh["scene"]:  # the scene file itself: its shapes, materials and lights
            self.scene = phongvk.load_scene(mesh["scene"])
        else:
            self.scene = phongvk.scene_from_dict({
                "camera": {"position": [0, -1, 0], "look_at": [0, 0, 0], "width": size[0], "height": size[1]},
                "lights": [{"position": mesh["lights"][0]["position"]}],
                "materials": {"m": MESH_MATERIAL},
                "objects": []})
            self.scene.add_mesh(mesh["vertices"], mesh["faces"], mesh["normals"], material="m",
                                closed=True)  # as moderngl's CULL_FACE
        self.renderer = phongvk.Renderer(backend)

    def frame(self, eye):
        c = self.camera
        self.scene.camera = phongvk.Camera(position=eye.tolist(), look_at=c["target"].tolist(), up=c["up"].tolist(),
                                           fov=c["fov"], width=self.size[0], height=self.size[1], near=c["near"],
                                           far=c["far"])
        return self.renderer.render(self.scene)


MAX_LIGHTS = 4
VERTEX = """
#version 330
const int MAX_LIGHTS = %d;
uniform mat4 view_projection;
uniform vec3 eye, ambient, colour, attenuation;
uniform vec4 material;  // ka, kd, ks, n
uniform int light_count;
uniform vec3 light_position[MAX_LIGHTS], light_colour[MAX_LIGHTS];
in vec3 position, normal;
out vec3 shade;
void main() {
    vec3 n = normalize(normal), v = normalize(eye - position), c = material.x * ambient * colour;
    for (int i = 0; i < light_count; ++i) {
        vec3 d = light_position[i] - position;
        float r = length(d);
        vec3 l = d / r;
        float nl = dot(n, l);
        float s = nl > 0.0 ? pow(max(dot(2.0 * nl * n - l, v), 0.0), material.w) : 0.0;
        float fall = 1.0 / (attenuation.x + attenuation.y * r + attenuation.z * r * r);
        c += fall * light_colour[i] * (material.y * colour * max(nl, 0.0) + material.z * s);
    }
    shade = clamp(c, 0.0, 1.0);
    gl_Position = view_projection * vec4(position, 1.0);
}
""" % MAX_LIGHTS
FRAGMENT = """
#version 330
in vec3 shade;
out vec4 rgba;
void main() { rgba = vec4(shade, 1.0); }
"""


class ModernglRenderer:
    """The same triangles with per-vertex Phong (Gouraud) as an OpenGL program draws them: one
    vertex buffer, an index buffer and a draw with its material's uniforms per object."""

    def __init__(self, mesh, size):
        import moderngl
        self.ctx = moderngl.create_standalone_context(backend="egl")
        self.ctx.enable(moderngl.DEPTH_TEST | moderngl.CULL_FACE)
        self.program = self.ctx.program(vertex_shader=VERTEX, fragment_shader=FRAGMENT)
        data = np.concatenate([mesh["vertices"], mesh["normals"]], axis=1).astype("f4")
        self.vbo = self.ctx.buffer(data.tobytes())
        self.objects = []
        for k, m in enumerate(mesh["materials"]):
            faces = mesh["faces"][mesh["objects"] == k]
            if len(faces):
                ibo = self.ctx.buffer(faces.astype("i4").tobytes())
                vao = self.ctx.vertex_array(self.program, [(self.vbo, "3f 3f", "position", "normal")], ibo)
                self.objects.append((vao, m))
        width, height = size
        self.fbo = self.ctx.framebuffer(self.ctx.renderbuffer((width, height)),
                                        self.ctx.depth_renderbuffer((width, height)))
        self.size, self.camera = size, mesh["camera"]
        lights = mesh["lights"][:MAX_LIGHTS]
        self.program["light_count"].value = len(lights)
        pad = [(0.0, 0.0, 0.0)] * (MAX_LIGHTS - len(lights))
        self.program["light_position"].value = [tuple(l["position"]) for l in lights] + pad
        self.program["light_colour"].value = [tuple(l["colour"]) for l in lights] + pad
        self.program["ambient"].value = tuple(mesh["ambient"])

    def frame(self, eye):
        width, height = self.size
        c = self.camera
        vp = perspective(c["fov"], width / height, c["near"], c["far"]) @ look_at(eye, c["target"], c["up"])
        self.program["view_projection"].write(vp.T.astype("f4").tobytes())
        self.program["eye"].value = tuple(eye)
        self.fbo.use()
        self.fbo.clear(0.0, 0.0, 0.0, 1.0)
        for vao, m in self.objects:
            self.program["material"].value = (m["ka"], m["kd"], m["ks"], m["n"])
            self.program["colour"].value = tuple(m["color"])
            self.program["attenuation"].value = tuple(m["attenuation"])
            vao.render()
        image = np.frombuffer(self.fbo.read(components=3), dtype=np.uint8).reshape(height, width, 3)
        return image[::-1].copy()


RENDERERS = {
    "phongvk gpu": lambda mesh, size: PhongvkRenderer("gpu", mesh, size),
    "phongvk cpu": lambda mesh, size: PhongvkRenderer("cpu", mesh, size),
    "moderngl": ModernglRenderer,
}


# --- measurement --------------------------------------------------------------------------------

def per_frame_ms(name, mesh, size, frames):
    renderer = RENDERERS[name](mesh, size)
    eyes = orbit(mesh, frames)
    target = mesh["camera"]["target"]
    renderer.frame(target + (eyes[-1] - target) * 1.01)  # warm-up: start-up, pipelines and the upload are not a frame's
    start = time.perf_counter()
    for eye in eyes:
        image = renderer.frame(eye)
    elapsed = time.perf_counter() - start
    assert image.shape == (size[1], size[0], 3) and image.any()
    return 1000 * elapsed / frames


def cold_process_s(name, workload):
    """A new interpreter that imports, builds the workload and renders one frame."""
    code = ("import sys, time; t = time.perf_counter(); sys.path.insert(0, %r); import peers; "
            "w = %r; m = peers.mesh_of(w['mesh']); r = peers.RENDERERS[%r](m, w['size']); "
            "r.frame(peers.orbit(m, 1)[0]); print(time.perf_counter() - t)") % (
                str(pathlib.Path(__file__).parent), workload, name)
    start = time.perf_counter()
    subprocess.run([sys.executable, "-c", code], check=True, capture_output=True, env=dict(os.environ))
    return time.perf_counter() - start


def measure(workload, names, rounds, frames):
    mesh = mesh_of(workload["mesh"])
    results = {n: {"frame": [], "cold": []} for n in names}
    for _ in range(rounds):
        for n in names:
            results[n]["frame"].append(per_frame_ms(n, mesh, workload["size"], frames))
        for n in names:
            results[n]["cold"].append(cold_process_s(n, workload))
    return len(mesh["faces"]), {n: {k: statistics.median(v) for k, v in r.items()} for n, r in results.items()}


# --- report -------------------------------------------------------------------------------------

def device_of(names):
    lines = []
    for d in phongvk.devices():
        lines.append(f"{d['name']} ({d['type']})" if isinstance(d, dict) else str(d))
    gl = ""
    if "moderngl" in names:
        import moderngl
        ctx = moderngl.create_standalone_context(backend="egl")
        gl = f"{ctx.info['GL_RENDERER']} (OpenGL {ctx.info['GL_VERSION']})"
        ctx.release()
    return ", ".join(lines), gl


def report(rows, missing, rounds, frames):
    names = [n for n in RENDERERS]
    vulkan, gl = device_of([n for n in names if n not in missing])
    out = ["# Peers: phongvk against moderngl from Python", "",
           "Generated by `bench/peers.py` (scripts/bench.sh); do not edit by hand, rerun it.", "",
           f"Machine: {platform.processor() or platform.machine()}, {os.cpu_count()} logical cores; Vulkan: {vulkan}; "
           f"OpenGL (moderngl): {gl or 'none'}; Python {platform.python_version()}; "
           f"{time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}; revision `{phongvk.__revision__}`.", "",
           f"Per frame: the median over {rounds} interleaved rounds of each round's mean over {frames} frames with the "
           "camera moving (after a warm-up frame), the image read back into numpy. Cold process: a new python3 "
           "importing, building the workload and rendering one frame, wall clock. Ratios are phongvk's time over "
           "moderngl's: below 1 phongvk is faster.", ""]
    for n, why in missing.items():
        out.append(f"- **{n}**: {why}")
    if missing:
        out.append("")
    out += ["| workload | triangles | image | phongvk gpu ms | phongvk cpu ms | moderngl ms | gpu / moderngl | "
            "cpu / moderngl | cold process s (gpu / cpu / moderngl) |",
            "|---|--:|--:|--:|--:|--:|--:|--:|--:|"]

    def fmt(r, n, k, spec):
        return format(r[n][k], spec) if n in r else "–"

    def ratio(r, a, b):
        return f"{r[a]['frame'] / r[b]['frame']:.2f}x" if a in r and b in r else "–"

    for w, triangles, r in rows:
        cold = " / ".join(fmt(r, n, "cold", ".2f") for n in names)
        out.append(f"| {w['name']} | {triangles:,} | {w['size'][0]}x{w['size'][1]} | {fmt(r, 'phongvk gpu', 'frame', '.2f')} | "
                   f"{fmt(r, 'phongvk cpu', 'frame', '.2f')} | {fmt(r, 'moderngl', 'frame', '.2f')} | "
                   f"{ratio(r, 'phongvk gpu', 'moderngl')} | {ratio(r, 'phongvk cpu', 'moderngl')} | {cold} |")
    return "\n".join(out) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--frames", type=int, default=30)
    parser.add_argument("--quick", action="store_true", help="the small workload, one round of 3 frames (the smoke test)")
    parser.add_argument("--out", help="write the markdown report here")
    parser.add_argument("--require-peers", action="store_true",
                        help="fail when a peer is not available (CTest's smoke run, where setup.sh --test installed it)")
    args = parser.parse_args()
    if args.quick:
        args.rounds, args.frames = 1, 3
    missing = {n: why for n in RENDERERS if (why := unavailable(n))}
    if missing and args.require_peers:
        sys.exit("peers.py: " + "; ".join(f"{n} {why}" for n, why in missing.items()))
    names = [n for n in RENDERERS if n not in missing]
    rows = []
    for w in workloads(args.quick):
        if not w["mesh"][0] == "ply" or pathlib.Path(w["mesh"][1]).exists():
            triangles, r = measure(w, names, args.rounds, args.frames)
            rows.append((w, triangles, r))
            print(f"{w['name']}: " + ", ".join(f"{n} {r[n]['frame']:.2f} ms/frame, {r[n]['cold']:.2f} s cold" for n in names),
                  flush=True)
    text = report(rows, missing, args.rounds, args.frames)
    if args.out:
        pathlib.Path(args.out).write_text(text)
    print(text)


if __name__ == "__main__":
    main()
