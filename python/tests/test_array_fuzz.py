"""The typed API's array arguments fuzzed: arrays of many dtypes, shapes and strides (slices, negative
strides, transposes, broadcasts, read-only and zero-size arrays, nested lists) thrown at Mesh,
Material(texture=...), Scene.add and encode_png. Each call succeeds or raises a Python exception of
the kinds phongvk documents; the cases run in a child interpreter, so a crash fails the test instead
of ending the suite. Seeded: the same cases every run."""

import subprocess
import sys

from conftest import child_environment

CASES = 600

FUZZ = r'''
import sys
import numpy as np
import phongvk

DTYPES = [np.uint8, np.int8, np.uint16, np.int16, np.int32, np.uint32, np.int64, np.uint64, np.float16,
          np.float32, np.float64, np.longdouble, np.complex64, np.complex128, np.bool_, object, "U3", "S2",
          "datetime64[s]", [("a", np.float32), ("b", np.int32)]]
CLEAN = (phongvk.Error, ValueError, TypeError, IndexError, MemoryError)


def values(rng, shape, dtype):
    """Small integers (indices in range, a plain triangle's coordinates) or, one time in five, numbers of
    every scale, NaN and infinities, as `dtype`."""
    numbers = rng.integers(0, 3, size=shape).astype(np.float64)
    if rng.random() < 0.2:
        numbers = rng.choice([0.0, 1.0, -1.0, 0.5, 1e20, -1e38, np.nan, np.inf, 7.0, 255.0, 65535.0], size=shape)
    try:
        with np.errstate(all="ignore"):
            return numbers.astype(dtype)
    except (TypeError, ValueError):
        return np.zeros(shape, dtype=dtype)


def shaped(rng, columns):
    """An array of a shape near (N, columns): often right, sometimes not."""
    roll = rng.random()
    if roll < 0.7:
        return (int(rng.integers(3, 6)), columns)
    if roll < 0.75:
        return (0, columns)
    if roll < 0.8:
        return tuple(int(n) for n in rng.integers(0, 5, size=rng.integers(0, 5)))
    return (int(rng.integers(0, 6)), int(rng.integers(0, 6)))


def strided(rng, array):
    """The same values, or a view of them with other strides, flags or form."""
    roll = rng.random()
    if array.ndim == 0 or roll < 0.3:
        return array
    if roll < 0.4:
        return array[::-1]
    if roll < 0.5:
        return np.repeat(array, 2, axis=0)[::2]
    if roll < 0.6:
        return np.asfortranarray(array)
    if roll < 0.7:
        view = array.view()
        view.setflags(write=False)
        return view
    if roll < 0.8:
        return np.broadcast_to(array[:1], array.shape) if array.shape[0] else array
    if roll < 0.9 and array.ndim >= 2:
        return array.T.copy().T  # column-major strides
    return array.tolist()


def argument(rng, columns):
    dtype = DTYPES[rng.integers(len(DTYPES))] if rng.random() < 0.5 else (np.float32 if columns != "i" else np.int64)
    return strided(rng, values(rng, shaped(rng, 3 if columns == "i" else columns), dtype))


def image(rng):
    shape = [int(rng.integers(0, 5)), int(rng.integers(0, 5))] + ([int(rng.integers(1, 6))] if rng.random() < 0.8 else [])
    dtype = np.uint8 if rng.random() < 0.5 else (np.uint16 if rng.random() < 0.5 else DTYPES[rng.integers(len(DTYPES))])
    return strided(rng, values(rng, tuple(shape), dtype))


def case(rng, scene):
    target = rng.integers(6)
    if target == 0:
        return phongvk.Mesh(argument(rng, 3), argument(rng, "i"))
    if target == 1:
        return phongvk.Mesh(argument(rng, 3), argument(rng, "i"), normals=argument(rng, 3), uvs=argument(rng, 2))
    if target == 2:
        return phongvk.Material(texture=image(rng))
    if target == 3:
        return phongvk.encode_png(image(rng))
    if target == 4:
        return scene.add(argument(rng, 3), argument(rng, "i"), pose=strided(rng, values(rng, shaped(rng, 4), np.float64)))
    return scene.add_mesh(argument(rng, 3), argument(rng, "i"), uvs=argument(rng, 2))


rng = np.random.default_rng(45)
scene = phongvk.Scene(16, 16)
kinds = {}
for i in range(int(sys.argv[1])):
    try:
        case(rng, scene)
        kinds["ok"] = kinds.get("ok", 0) + 1
    except CLEAN as e:
        kinds[type(e).__name__] = kinds.get(type(e).__name__, 0) + 1
    except Exception as e:  # noqa: BLE001 - an exception of another kind is the finding
        print("case %d: %s: %s" % (i, type(e).__name__, e))
        sys.exit(1)
print(kinds)
'''


def test_array_arguments_succeed_or_raise_cleanly():
    done = subprocess.run([sys.executable, "-c", FUZZ, str(CASES)], env=child_environment(), capture_output=True,
                          text=True, timeout=120)
    assert done.returncode == 0, done.stdout + done.stderr
    kinds = eval(done.stdout.strip().splitlines()[-1])  # noqa: S307 - the child's own dict of counts
    assert sum(kinds.values()) == CASES
    assert kinds.get("ok", 0) > CASES // 40  # some cases get past every check
