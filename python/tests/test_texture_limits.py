"""Textures against the memory limit, as a user meets them: the phongvk command rendering scenes
whose textures would not fit, each run in a child process whose peak resident memory (wait4's
ru_maxrss) is measured. A texture is counted from its header (width x height x 4 bytes) before
its pixels are decoded, beside every texture already held, so the peak stays near the limit
whatever the files ask for (docs/DESIGN.md "Textures")."""

import json
import struct
import subprocess
import sys
import time
import zlib

import pytest

from conftest import CLI

GIB = 1 << 30


def png_of(width, height):
    """An 8-bit RGB PNG of black pixels, compressed row by row (small on disk, big decoded)."""
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    compressor = zlib.compressobj(9)
    row = b"\0" * (1 + 3 * width)
    pixels = b"".join(compressor.compress(row) for _ in range(height)) + compressor.flush()
    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", pixels) + chunk(b"IEND", b"")


def quad(material):
    return {"shape": "mesh", "vertices": [[-1, 0, -1], [1, 0, -1], [1, 0, 1], [-1, 0, 1]],
            "faces": [[0, 1, 2], [0, 2, 3]], "uvs": [[0, 1], [1, 1], [1, 0], [0, 0]], "material": material}


def scene_with(objects):
    return {"camera": {"position": [0, -3, 0], "look_at": [0, 0, 0], "width": 64, "height": 48},
            "lights": [{"position": [0, -3, 1]}], "objects": objects}


# Starts the command and prints its exit code and peak resident memory. A child's ru_maxrss starts
# from its parent's resident memory at the fork, and pytest may have grown to a gigabyte by the
# time these tests run, so the command's parent is this small, fresh interpreter instead.
LAUNCHER = """
import os, subprocess, sys
child = subprocess.Popen(sys.argv[1:], stdout=subprocess.DEVNULL)
_, status, usage = os.wait4(child.pid, 0)
print(os.waitstatus_to_exitcode(status), usage.ru_maxrss * 1024)
"""


def run_measured(args):
    """The phongvk command's exit code, its standard error and its peak resident memory in bytes."""
    done = subprocess.run([sys.executable, "-c", LAUNCHER, str(CLI)] + args, capture_output=True, text=True,
                          timeout=300)
    code, peak = done.stdout.split()
    return int(code), done.stderr, int(peak)


def test_distinct_big_textures_are_refused_before_they_blow_the_limit(tmp_path):
    # Six distinct 8192^2 textures (256 MiB each decoded, 200 KB each on disk) under a 0.6 GiB
    # limit: two fit, the third is refused from its header, never decoded.
    image = png_of(8192, 8192)
    objects = []
    for k in range(6):
        (tmp_path / f"t{k}.png").write_bytes(image)
        objects.append(quad({"color": [1, 1, 1], "texture": f"t{k}.png"}))
    (tmp_path / "scene.json").write_text(json.dumps(scene_with(objects)))
    out = tmp_path / "out.png"
    code, err, peak = run_measured(["render", str(tmp_path / "scene.json"), "-o", str(out), "--max-memory-gb", "0.6"])
    assert code == 2, err
    assert "t2.png" in err and "a 8192x8192 texture needs about" in err and "more than the 0.60 GiB limit" in err, err
    assert not out.exists()
    assert peak <= 1.25 * 0.6 * GIB, f"peak {peak / GIB:.2f} GiB"


@pytest.mark.parametrize("backend", ["cpu", "gpu"])
def test_a_texture_that_fits_renders_within_the_limit_on_both_backends(tmp_path, backend):
    # One 8192^2 texture (256 MiB decoded) under a 0.6 GiB limit, counted twice (the host's texels
    # and the device's copy): it fits, and the peak stays within 1.25x the limit on the GPU backend
    # too, whose uploads stage 64 MiB at a time rather than a third copy of the texture.
    (tmp_path / "t.png").write_bytes(png_of(8192, 8192))
    (tmp_path / "scene.json").write_text(json.dumps(scene_with([quad({"texture": "t.png"})])))
    out = tmp_path / "out.png"
    code, err, peak = run_measured(["render", str(tmp_path / "scene.json"), "-o", str(out), "--backend", backend,
                                    "--max-memory-gb", "0.6"])
    assert code == 0, err
    assert out.exists()
    assert peak <= 1.25 * 0.6 * GIB, f"peak {peak / GIB:.2f} GiB"


def glb_sharing_one_image(png, textures):
    """A GLB of one textured triangle per texture, every texture sampling the same image."""
    positions = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 0, 1)
    uvs = struct.pack("<6f", 0, 0, 1, 0, 0, 1)
    blob = positions + uvs + png + b"\0" * (-len(png) % 4)
    gltf = {
        "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": list(range(textures))}],
        "nodes": [{"mesh": k} for k in range(textures)],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "material": k}]} for k in range(textures)],
        "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": k}}} for k in range(textures)],
        "textures": [{"source": 0} for _ in range(textures)],
        "images": [{"bufferView": 2, "mimeType": "image/png"}],
        "buffers": [{"byteLength": len(blob)}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 24},
                        {"buffer": 0, "byteOffset": 60, "byteLength": len(png)}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 0, 1]},
                      {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC2"}],
    }
    text = json.dumps(gltf).encode()
    text += b" " * (-len(text) % 4)
    body = struct.pack("<II", len(text), 0x4E4F534A) + text + struct.pack("<II", len(blob), 0x004E4942) + blob
    return struct.pack("<III", 0x46546C67, 2, 12 + len(body)) + body


def test_a_gltf_image_shared_by_five_textures_is_decoded_once(tmp_path):
    # One 8192^2 image (256 MiB decoded) behind five textures, under a 0.6 GiB limit: decoded
    # once it fits, and renders; decoded per texture it would take 1.25 GiB.
    (tmp_path / "shared.glb").write_bytes(glb_sharing_one_image(png_of(8192, 8192), 5))
    out = tmp_path / "out.png"
    code, err, peak = run_measured(["render", str(tmp_path / "shared.glb"), "-o", str(out), "--backend", "cpu",
                                    "--max-memory-gb", "0.6"])
    assert code == 0, err
    assert out.exists()
    assert peak <= 1.25 * 0.6 * GIB, f"peak {peak / GIB:.2f} GiB"


def test_a_small_jpeg_claiming_a_huge_image_fails_at_once(tmp_path):
    # A JPEG whose header says 16384^2 and whose scan ends after a few hundred bytes: an error
    # naming the damage, in well under a second, its texture's pages never touched.
    from PIL import Image
    Image.new("RGB", (16, 16), (90, 120, 200)).save(tmp_path / "small.jpg", quality=90)
    data = bytearray((tmp_path / "small.jpg").read_bytes())
    sof = data.index(b"\xff\xc0")
    data[sof + 5:sof + 9] = struct.pack(">HH", 16384, 16384)
    (tmp_path / "claims.jpg").write_bytes(bytes(data))
    (tmp_path / "scene.json").write_text(json.dumps(scene_with([quad({"texture": "claims.jpg"})])))
    start = time.monotonic()
    code, err, peak = run_measured(["render", str(tmp_path / "scene.json"), "-o", str(tmp_path / "out.png"), "--backend", "cpu"])
    assert code == 2, err
    assert "claims.jpg': JPEG: cannot decode its pixels: Corrupt JPEG data: premature end of data segment" in err, err
    assert time.monotonic() - start < 1.0
    assert peak < 0.25 * GIB, f"peak {peak / GIB:.2f} GiB"
