#!/usr/bin/env python3
"""Writes fuzz/gltf_corpus: small valid glTF and GLB models in gltf_fuzzer.cpp's framing.

An input is: one byte (bit 0: 0 .gltf, 1 .glb), the model's length (2 bytes, little-endian), the
model, then the bytes written as buf.bin beside it (what a buffer's "uri": "buf.bin" reads).
Also takes a few small glTF 2.0 files from Debian's assimp-testmodels, where installed, with their
.bin renamed buf.bin. Run: python3 fuzz/make_gltf_seeds.py
"""
import base64
import json
import os
import struct

FLOAT, UBYTE, USHORT, UINT = 5126, 5121, 5123, 5125
TRIANGLES, STRIP, FAN = 4, 5, 6
ASSIMP = "/usr/share/assimp/models/glTF2"


def frame(binary, model, rest=b""):
    assert len(model) < 65536
    return bytes([1 if binary else 0]) + struct.pack("<H", len(model)) + model + rest


class Model:
    """A glTF document and the one buffer its accessors read."""

    def __init__(self):
        self.bin = bytearray()
        self.doc = {"asset": {"version": "2.0"}, "bufferViews": [], "accessors": [], "meshes": [], "nodes": [],
                    "scenes": [{"nodes": [0]}], "scene": 0}

    def view(self, data, stride=None, buffer=0):
        while len(self.bin) % 4:
            self.bin.append(0)
        view = {"buffer": buffer, "byteOffset": len(self.bin), "byteLength": len(data)}
        if stride:
            view["byteStride"] = stride
        self.bin += data
        self.doc["bufferViews"].append(view)
        return len(self.doc["bufferViews"]) - 1

    def accessor(self, view, component, kind, count, **extra):
        self.doc["accessors"].append(dict(bufferView=view, componentType=component, type=kind, count=count, **extra))
        return len(self.doc["accessors"]) - 1

    def floats(self, rows, kind="VEC3"):
        data = b"".join(struct.pack("<%df" % len(r), *r) for r in rows)
        extra = {}
        if kind == "VEC3":  # POSITION needs its bounds
            extra = {"min": [min(r[i] for r in rows) for i in range(3)], "max": [max(r[i] for r in rows) for i in range(3)]}
        return self.accessor(self.view(data), FLOAT, kind, len(rows), **extra)

    def indices(self, values, component):
        fmt = {UBYTE: "B", USHORT: "H", UINT: "I"}[component]
        return self.accessor(self.view(struct.pack("<%d%s" % (len(values), fmt), *values)), component, "SCALAR", len(values))

    def mesh(self, *primitives):
        self.doc["meshes"].append({"primitives": list(primitives)})
        return len(self.doc["meshes"]) - 1

    def node(self, **fields):
        self.doc["nodes"].append(fields)
        return len(self.doc["nodes"]) - 1

    def json(self):
        return json.dumps(self.doc, separators=(",", ":")).encode()

    # The three ways a buffer reaches the importer.
    def external(self):
        self.doc["buffers"] = [{"uri": "buf.bin", "byteLength": len(self.bin)}]
        return frame(False, self.json(), bytes(self.bin))

    def data_uri(self):
        uri = "data:application/octet-stream;base64," + base64.b64encode(bytes(self.bin)).decode()
        self.doc["buffers"] = [{"uri": uri, "byteLength": len(self.bin)}]
        return frame(False, self.json())

    def glb(self, extra_buffers=(), rest=b""):
        self.doc["buffers"] = [{"byteLength": len(self.bin)}, *extra_buffers]
        return frame(True, glb(self.json(), bytes(self.bin)), rest)


def glb(json_chunk, bin_chunk):
    json_chunk += b" " * (-len(json_chunk) % 4)
    bin_chunk += b"\0" * (-len(bin_chunk) % 4)
    chunks = struct.pack("<II", len(json_chunk), 0x4E4F534A) + json_chunk + struct.pack("<II", len(bin_chunk), 0x004E4942) + bin_chunk
    return struct.pack("<III", 0x46546C67, 2, 12 + len(chunks)) + chunks


TRIANGLE = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]
QUAD = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]


def triangle():
    m = Model()
    m.mesh({"attributes": {"POSITION": m.floats(TRIANGLE)}})
    m.node(mesh=0)
    return m


def hierarchy():
    """One mesh placed by four nodes: translation, rotation, scale, a matrix under a scaled node."""
    m = Model()
    m.mesh({"attributes": {"POSITION": m.floats(TRIANGLE), "NORMAL": m.floats([(0, 0, 1)] * 3)}})
    m.node(children=[1, 2], translation=[1, 0, 0])
    m.node(mesh=0, rotation=[0, 0, 0.7071068, 0.7071068])
    m.node(mesh=0, scale=[2, 2, 2], children=[3])
    m.node(mesh=0, matrix=[1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 3, 1])
    m.doc["scenes"].append({"nodes": [3]})
    return m


def index_types():
    """A quad three times: 8-bit triangle indices, a 16-bit strip, a 32-bit fan; colours, a material."""
    m = Model()
    attributes = {"POSITION": m.floats(QUAD), "NORMAL": m.floats([(0, 0, 1)] * 4)}
    colors = m.view(bytes([255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 128]))
    attributes["COLOR_0"] = m.accessor(colors, UBYTE, "VEC4", 4, normalized=True)
    m.doc["materials"] = [{"pbrMetallicRoughness": {"baseColorFactor": [1, 0.5, 0.25, 1]}}]
    m.mesh({"attributes": attributes, "indices": m.indices([0, 1, 2, 0, 2, 3], UBYTE), "material": 0},
           {"attributes": attributes, "indices": m.indices([1, 2, 0, 3], USHORT), "mode": STRIP},
           {"attributes": attributes, "indices": m.indices([0, 1, 2, 3], UINT), "mode": FAN})
    m.node(mesh=0)
    return m


def sparse():
    """Positions whose second vertex a sparse accessor moves (the importer refuses sparse accessors)."""
    m = Model()
    positions = m.floats(TRIANGLE)
    m.doc["accessors"][positions]["sparse"] = {
        "count": 1,
        "indices": {"bufferView": m.view(struct.pack("<I", 1)), "componentType": UINT},
        "values": {"bufferView": m.view(struct.pack("<3f", 2, 0, 0))},
    }
    m.mesh({"attributes": {"POSITION": positions}})
    m.node(mesh=0)
    return m


def glb_interleaved_external():
    """A GLB: positions and normals interleaved (byteStride) in its BIN chunk, indices in buf.bin."""
    m = Model()
    rows = b"".join(struct.pack("<6f", *p, 0, 0, 1) for p in QUAD)
    view = m.view(rows, stride=24)
    position = m.accessor(view, FLOAT, "VEC3", 4, min=[0, 0, 0], max=[1, 1, 0])
    normal = m.accessor(view, FLOAT, "VEC3", 4, byteOffset=12)
    indices = struct.pack("<6H", 0, 1, 2, 0, 2, 3)
    m.doc["bufferViews"].append({"buffer": 1, "byteOffset": 0, "byteLength": len(indices)})
    index = m.accessor(len(m.doc["bufferViews"]) - 1, USHORT, "SCALAR", 6)
    m.mesh({"attributes": {"POSITION": position, "NORMAL": normal}, "indices": index})
    m.node(mesh=0)
    return m.glb([{"uri": "buf.bin", "byteLength": len(indices)}], indices)


def assimp_seeds():
    """Small glTF 2.0 test files (a strip, a fan, 8-bit indices; a node cycle; infinite and bad
    normals), their external buffer renamed buf.bin."""
    seeds = {}
    if not os.path.isdir(ASSIMP):
        return seeds
    for name in ("Mesh_PrimitiveMode_04", "Mesh_PrimitiveMode_12", "Mesh_PrimitiveMode_14"):
        folder = os.path.join(ASSIMP, "glTF-Asset-Generator", "Mesh_PrimitiveMode")
        doc = json.load(open(os.path.join(folder, name + ".gltf")))
        data = open(os.path.join(folder, doc["buffers"][0]["uri"]), "rb").read()
        doc["buffers"][0]["uri"] = "buf.bin"
        seeds["assimp_" + name] = frame(False, json.dumps(doc, separators=(",", ":")).encode(), data)
    seeds["assimp_RecursiveNodes"] = frame(False, open(os.path.join(ASSIMP, "RecursiveNodes", "RecursiveNodes.gltf"), "rb").read())
    for name in ("BoxWithInfinites", "BoxBadNormals"):
        seeds["assimp_" + name] = frame(True, open(os.path.join(ASSIMP, name + "-glTF-Binary", name + ".glb"), "rb").read())
    return seeds


def main():
    seeds = {
        "triangle_external": triangle().external(),
        "triangle_data_uri": triangle().data_uri(),
        "triangle_glb": triangle().glb(),
        "hierarchy_instancing": hierarchy().external(),
        "index_types": index_types().external(),
        "sparse_accessor": sparse().external(),
        "glb_interleaved_external": glb_interleaved_external(),
        **assimp_seeds(),
    }
    folder = os.path.join(os.path.dirname(os.path.abspath(__file__)), "gltf_corpus")
    os.makedirs(folder, exist_ok=True)
    for name, data in seeds.items():
        assert len(data) <= 8192, name  # scripts/fuzz.sh's -max_len
        with open(os.path.join(folder, name), "wb") as f:
            f.write(data)


if __name__ == "__main__":
    main()
