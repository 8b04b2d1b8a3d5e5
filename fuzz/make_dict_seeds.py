#!/usr/bin/env python3
"""Writes fuzz/dict_corpus: Python values as programs for dict_fuzzer.cpp's stack machine.

Run it with Debian's interpreter (numpy): /usr/bin/python3 fuzz/make_dict_seeds.py. OPS and DTYPES
mirror Op and kDtypes in dict_fuzzer.cpp, in order; change them together.
"""
import math
import os
import struct

import numpy as np

OPS = ["None", "False", "True", "Int8", "Int64", "BigInt", "Shift", "Float", "Str", "List", "Tuple", "Dict",
       "Append", "Recurse", "Pick", "Array", "Scalar", "Other"]
DTYPES = ["", "float64", "float32", "float16", "longdouble", "clongdouble", "int8", "int64", "uint64", "bool",
          "complex128", "object", "U", "S", "datetime64[s]"]


def op(name, *operands):
    return bytes([OPS.index(name), *operands])


class Raw(bytes):
    """A program written out by hand, to stand for a value inside encode()'s argument."""


def dtype_index(dtype):
    for i, name in enumerate(DTYPES):
        if name and (np.dtype(name) == dtype or (name in ("U", "S") and dtype.kind == name)):
            return i
    raise TypeError(dtype)


def encode(value):
    """The program that pushes `value` (tree-shaped: an object met twice is built twice)."""
    if isinstance(value, Raw):
        return value
    if value is None:
        return op("None")
    if isinstance(value, np.ndarray):
        return encode(value.tolist()) + op("Array", dtype_index(value.dtype))
    if isinstance(value, np.generic):
        return encode(value.item()) + op("Scalar", dtype_index(value.dtype))
    if isinstance(value, bool):
        return op("True" if value else "False")
    if isinstance(value, int):
        if -128 <= value < 128:
            return op("Int8", value & 0xFF)
        if -2**63 <= value < 2**63:
            return op("Int64") + struct.pack("<q", value)
        raw = value.to_bytes((value.bit_length() + 8) // 8, "little", signed=True)
        return op("BigInt", len(raw)) + raw
    if isinstance(value, float):
        return op("Float") + struct.pack("<d", value)
    if isinstance(value, str):
        raw = value.encode("utf-8", "surrogateescape")
        return op("Str", len(raw)) + raw
    if isinstance(value, (list, tuple)):
        return b"".join(encode(v) for v in value) + op("List" if isinstance(value, list) else "Tuple", len(value))
    if isinstance(value, dict):
        return b"".join(encode(k) + encode(v) for k, v in value.items()) + op("Dict", len(value))
    raise TypeError(type(value))


CAMERA = {"position": [-3.5, -2.45, 2.1], "look_at": [0, 0, 0], "fov": 60, "resolution": 64}
SPHERE = {"shape": "sphere", "center": [0, 0, 0], "radius": 0.5, "segments": 16}


def scene(**fields):
    return encode({"camera": CAMERA, **fields})


SEEDS = {
    # A valid scene: camera, light, material, a sphere; numpy values where a user might pass them.
    "valid_scene": encode({
        "camera": dict(CAMERA, resolution=np.int64(64), fov=np.float32(60)),
        "lights": [{"position": np.array([-0.7, -0.6, 0.8]), "intensity": np.float64(1.0), "color": (1, 1, 1)}],
        "materials": {"grey": {"ka": 0.15, "kd": 1.0, "ks": 0.8, "n": 10, "color": np.array([0.8, 0.8, 0.8], np.float32)}},
        "objects": [dict(SPHERE, material="grey"),
                    {"shape": "cube", "center": np.array([1, 0, 0], np.int8), "size": np.float16(0.5)}],
    }),
    # An empty object list: scene_from_dict's scene that gets its meshes from add_mesh.
    "objects_later": scene(objects=[]),
    # 100 lists deep, past MAX_JSON_DEPTH (64).
    "deep_nesting": scene(objects=Raw(op("None") + op("List", 1) * 100)),
    # A list that holds itself, as the objects.
    "self_list": scene(objects=Raw(op("List", 0) + op("Recurse"))),
    # A dict that holds itself; a list that holds a dict that holds the list.
    "self_dict": scene(materials=Raw(op("Dict", 0) + op("Recurse")),
                       objects=Raw(op("List", 0) + op("Dict", 0) + op("Pick", 1) + op("Append") + op("Append"))),
    # One list in two places (the camera's position and look_at): shared, not a cycle.
    "shared_list": encode({"camera": {"fov": 60, "position": [1.0, 2.0, 3.0], "look_at": Raw(op("Pick", 1))},
                           "objects": [SPHERE]}),
    # Numbers JSON cannot hold or a scene must refuse: nan, inf, 2^100, -0.0, a huge exponent.
    "numbers": scene(background=[1e308, 5e-324, -(2**70)], lights=[{"position": [2**100, -0.0, math.inf]}],
                     objects=[dict(SPHERE, radius=math.nan)]),
    # Values of types JSON has no form for (bytes, complex, set), and a key that is not a string.
    "other_types": scene(objects=[SPHERE], extra=Raw(op("Other", 0) + op("Other", 1) + op("Other", 2) + op("List", 3)),
                         keys={1: "one"}),
    # numpy arrays of each kind the writer flattens: 2-D floats, ints, bools, strings, a 0-d array.
    "numpy_arrays": scene(objects=[{"shape": "mesh", "vertices": np.zeros((3, 3), np.float32),
                                    "faces": np.array([[0, 1, 2]], np.uint64)}],
                          extra=[np.array([True, False]), np.array(["a", "b"]), np.array(2.5)]),
    # An array of byte strings cast to datetime64, which crashes Debian 12's numpy: the machine skips it.
    "bytes_to_datetime": scene(extra=Raw(op("True") + op("List", 1) + op("Array", DTYPES.index("S"))
                                         + op("Array", DTYPES.index("datetime64[s]")))),
}


def main():
    folder = os.path.join(os.path.dirname(os.path.abspath(__file__)), "dict_corpus")
    os.makedirs(folder, exist_ok=True)
    for name, program in SEEDS.items():
        with open(os.path.join(folder, name), "wb") as f:
            f.write(program)


if __name__ == "__main__":
    main()
