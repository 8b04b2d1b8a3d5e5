"""phongvk: a headless Phong/Gouraud renderer, Vulkan compute checked against a C++ reference.

    import phongvk
    scene = phongvk.load_scene("scenes/basic.json")
    image = phongvk.Renderer("gpu").render(scene)   # uint8 array, (height, width, 3)
    phongvk.write_png("basic.png", image)

Both renderers ("gpu", the Vulkan compute port, and "cpu", the reference) give the same bytes;
phongvk.diff(scene) compares them. Meshes come from scene files or as numpy arrays
(Scene.add, Scene.add_mesh) with typed cameras, lights, materials and render settings (Camera,
Light, Material, RenderSettings). Everything here is the C++ library's public API (include/phongvk/phongvk.h);
this package only shapes it for Python.
"""

import sys as _sys
import warnings as _warnings

try:
    import numpy as _np
except ImportError as _error:
    raise ImportError(
        "phongvk needs numpy, which this Python (%s) cannot import. phongvk is built for Debian's "
        "Python: run it with /usr/bin/python3 (scripts/setup.sh installs python3-numpy), or install "
        "numpy for this interpreter." % _sys.executable) from _error

from . import _phongvk
from ._phongvk import (
    NO_TRIANGLE,
    PNG_LEVEL_DEFAULT,
    ArgumentError,
    Camera,
    DeviceError,
    Error,
    Light,
    Material,
    Mesh,
    NoDeviceError,
    OutputError,
    RangeError,
    RenderSettings,
    Scene,
    SceneError,
    Texture,
    __revision__,
    __version__,
    encode_png,
    load_scene,
    scene_from_dict,
    write_png,
)

# What the compiled module defines reads as phongvk's own (phongvk.SceneError in a traceback).
for _name in ("ArgumentError", "Camera", "DeviceError", "Error", "Light", "Material", "Mesh", "NoDeviceError",
              "OutputError", "RangeError", "RenderSettings", "Scene", "SceneError", "Texture"):
    getattr(_phongvk, _name).__module__ = __name__

__all__ = [
    "ArgumentError", "Camera", "DeviceError", "Error", "Image", "Light", "Material", "Mesh", "NO_TRIANGLE",
    "NoticeWarning", "PNG_LEVEL_DEFAULT",
    "NoDeviceError", "OutputError", "RangeError", "RenderSettings", "Renderer", "Scene", "SceneError", "Texture",
    "RendererStats", "DiffResult", "Device",
    "devices", "diff", "encode_png", "load_scene", "read_png", "scene_from_dict", "write_png",
]


class Image(_np.ndarray):
    """An RGB image: a C-contiguous uint8 numpy array of shape (height, width, 3), row 0 at the
    top, that shows itself as a picture in Jupyter. Everything numpy does with arrays works; what
    numpy's functions compute from it (img / 255, img.mean(axis=2)) is a plain array."""

    def __array_wrap__(self, array, context=None, return_scalar=False):
        return array.view(_np.ndarray) if isinstance(array, _np.ndarray) else array

    def _repr_png_(self):
        return _displayable_png(_np.asarray(self))


def _displayable_png(array):
    """The PNG Jupyter shows for an image-like array: uint8 as it is (RGB, RGBA or grey), bool as
    black and white, floats within 0..1 scaled to 0..255; None (Jupyter shows the text instead)
    for anything else."""
    if array.ndim not in (2, 3) or (array.ndim == 3 and array.shape[2] not in (3, 4)) or array.size == 0:
        return None
    if array.dtype == _np.bool_:
        array = array.astype(_np.uint8) * 255
    elif array.dtype.kind == "f":
        if not (_np.isfinite(array).all() and array.min() >= 0 and array.max() <= 1):
            return None
        array = _np.rint(array * 255).astype(_np.uint8)
    elif array.dtype != _np.uint8:
        return None
    return encode_png(_np.ascontiguousarray(array))


class NoticeWarning(UserWarning):
    """What a user may not expect of a picture (Renderer.stats["notice"]): a fitted camera that
    sees only the back of every triangle, so the model is drawn dark."""


class _Record(dict):
    """A result read by attribute (stats.triangles) that is still the dict it was (stats["triangles"],
    dict(stats), json.dumps(stats))."""

    def __getattr__(self, name):
        try:
            return self[name]
        except KeyError:
            raise AttributeError("%s has no %r (it has %s)" % (type(self).__name__, name, ", ".join(self))) from None

    def __dir__(self):
        return sorted(set(self) | set(dir(dict)))


class RendererStats(_Record):
    """Renderer.stats: what a renderer has done so far (keys as its help says)."""


class DiffResult(_Record):
    """phongvk.diff and Renderer.diff: the reference against the compute port."""


class Device(_Record):
    """One entry of phongvk.devices(): a Vulkan device, whether phongvk can use it, its key path."""


def diff(scene, device=None):
    return DiffResult(_phongvk.diff(scene, device))


def devices():
    return [Device(d) for d in _phongvk.devices()]


diff.__doc__ = _phongvk.diff.__doc__
devices.__doc__ = _phongvk.devices.__doc__


class Renderer(_phongvk.Renderer):
    __doc__ = _phongvk.Renderer.__doc__

    @property
    def stats(self):
        return RendererStats(_phongvk.Renderer.stats.fget(self))

    stats.__doc__ = _phongvk.Renderer.stats.__doc__

    def diff(self, scene):
        return DiffResult(super().diff(scene))

    diff.__doc__ = _phongvk.Renderer.diff.__doc__

    def __enter__(self):
        return self

    def __exit__(self, *exception):
        self.close()
        return False

    def render(self, scene, width=None, height=None, outputs=None):
        """One frame of `scene` as an Image (a uint8 array of shape (height, width, 3)); at
        width x height pixels when both are given (the vertical field of view is kept).

        With outputs (names among "color", "rgba", "alpha", "depth", "object_id", "triangle_id",
        "normal", "lights"), a dict of arrays by name instead: color an Image, rgba a (height, width, 4) uint8
        array with alpha where triangles cover the pixel (255: every sample), alpha that
        (height, width) uint8 coverage alone, depth float32 metres along the camera's axis (inf
        where empty), object_id (the index in the scene's objects) and triangle_id int32 (-1 where
        empty), normal a (height, width, 3) float32 array of unit shading normals in camera space,
        x right, y up, z forward along the depth's axis (a surface facing the camera has z < 0;
        0, 0, 0 where empty): the face normal with flat shading, the vertex normals interpolated at
        the pixel and normalized with Gouraud and Phong, as stored on a back face (not flipped);
        lights int32, how many lights reach the pixel's surface (a shadowed light whose ray is
        blocked does not; -1 where empty).
        With samples per pixel, depth, ids and normal are the pixel's nearest sample's. Every output
        is the same bytes on the gpu and cpu backends; the graphics backend gives color only."""
        if outputs is None:
            result = super().render(scene, width, height).view(Image)
        else:
            result = self.render_outputs(scene, [outputs] if isinstance(outputs, str) else list(outputs), width, height)
            if "color" in result:
                result["color"] = result["color"].view(Image)
        notice = self.notice
        if notice:
            _warnings.warn(notice, NoticeWarning, stacklevel=2)
        return result

    def render_visibility(self, scene, width=None, height=None):
        image, triangle, depth = super().render_visibility(scene, width, height)
        return image.view(Image), triangle, depth

    render_visibility.__doc__ = _phongvk.Renderer.render_visibility.__doc__


def read_png(path, mode="rgb"):
    """Reads a PNG as an Image (a uint8 array of shape (height, width, 3)); with mode="rgba" as a
    (height, width, 4) uint8 array (alpha 255 where the file has none), with mode="grey16" as a
    (height, width) uint16 array (what render --depth and --ids write: millimetres, index + 1;
    8-bit samples scaled by 257)."""
    pixels = _phongvk.read_png(path, mode)
    return pixels.view(Image) if mode == "rgb" else pixels


# ---- live views: what a scene gives back edits the scene ----
#
# scene.camera, scene.render_settings, scene.lights[i] and scene.light(handle) are live views:
# reading an attribute reads the scene as it is now, and assigning one checks the new value as the
# scene file's section would and sets it in the scene at once (SceneError, the scene unchanged, for
# a bad one). Each view is also a plain phongvk.Camera, RenderSettings or Light, holding the value it
# had when taken plus what was set through it, so it can be kept, compared or given to another
# scene. Three numbers (a position, a colour) read back as a tuple, which refuses item assignment:
# assign the whole attribute (scene.camera.position = (0, -4, 2)).

class _Live:
    """The live-view behaviour, mixed into a subclass of each value class."""

    def __init__(self, value, read, write):
        self._BASE.__init__(self)
        for name in self._FIELDS:
            self._BASE.__dict__[name].__set__(self, getattr(value, name))
        object.__setattr__(self, "_read", read)
        object.__setattr__(self, "_write", write)

    def __getattribute__(self, name):
        if name.startswith("_") or name not in type(self)._FIELDS:
            return object.__getattribute__(self, name)
        return getattr(object.__getattribute__(self, "_read")(), name)

    def __setattr__(self, name, value):
        if name not in self._FIELDS:
            raise AttributeError("%s has no attribute %r" % (self._BASE.__name__, name))
        current = self._read()
        setattr(current, name, value)
        self._write(current)
        self._BASE.__dict__[name].__set__(self, value)


def _live_class(base, fields):
    return type(base.__name__, (_Live, base),
                {"_BASE": base, "_FIELDS": fields, "__doc__": base.__doc__, "__module__": __name__})


_LiveCamera = _live_class(Camera, ("position", "look_at", "up", "fov", "width", "height", "near", "far", "intrinsics",
                                   "ortho_height"))
_LiveLight = _live_class(Light, ("position", "direction", "spot", "inner_cone", "outer_cone", "falloff", "range",
                                 "intensity", "color", "at_camera", "shadows"))
_LiveRenderSettings = _live_class(RenderSettings, ("shading", "specular", "interpolation", "samples", "background",
                                                   "texture_filter", "point_size", "line_width"))


class _LightList:
    """scene.lights: a sequence of live views of the scene's lights, by index (scene.light(handle)
    follows a light added with add_light wherever it moves)."""

    def __init__(self, scene):
        self._scene = scene

    def __len__(self):
        return self._scene.light_count

    def _view(self, index):
        scene = self._scene
        return _LiveLight(_LIGHTS.fget(scene)[index], lambda: _LIGHTS.fget(scene)[index],
                          lambda value: scene._set_light_at(index, value))

    def __getitem__(self, index):
        if isinstance(index, slice):
            return [self._view(i) for i in range(*index.indices(len(self)))]
        count = len(self)
        if not -count <= index < count:
            raise IndexError("light %d is out of range: the scene has %d lights" % (index, count))
        return self._view(index % count)

    def __iter__(self):
        return (self._view(i) for i in range(len(self)))

    def __eq__(self, other):
        return list(_LIGHTS.fget(self._scene)) == list(other)

    def __add__(self, other):
        return list(self) + list(other)

    def __repr__(self):
        return repr(_LIGHTS.fget(self._scene))


_CAMERA = Scene.camera
_LIGHTS = Scene.lights
_RENDER_SETTINGS = Scene.render_settings
_LIGHT = Scene.light

Scene.camera = property(
    lambda scene: _LiveCamera(_CAMERA.fget(scene), lambda: _CAMERA.fget(scene), lambda v: _CAMERA.fset(scene, v)),
    _CAMERA.fset, doc=_CAMERA.__doc__ + " A live view: assigning an attribute (scene.camera.fov = 30) sets it in the scene.")
Scene.render_settings = property(
    lambda scene: _LiveRenderSettings(_RENDER_SETTINGS.fget(scene), lambda: _RENDER_SETTINGS.fget(scene),
                                      lambda v: _RENDER_SETTINGS.fset(scene, v)),
    _RENDER_SETTINGS.fset,
    doc=_RENDER_SETTINGS.__doc__ + " A live view: scene.render_settings.samples = 4 sets it in the scene.")
Scene.lights = property(
    _LightList, lambda scene, lights: _LIGHTS.fset(scene, list(lights)),
    doc=_LIGHTS.__doc__ + " Live views: scene.lights[0].color = (1, 0, 0) sets it in the scene.")


def _light(scene, handle):
    return _LiveLight(_LIGHT(scene, handle), lambda: _LIGHT(scene, handle), lambda v: scene.set_light(handle, v))


_light.__doc__ = _LIGHT.__doc__ + " A live view, as scene.lights[i]."
Scene.light = _light


def Points(positions, colors=None, normals=None):
    """A point cloud: a phongvk.Mesh whose every vertex is drawn as a point, a square
    render_settings.point_size pixels wide (docs/DESIGN.md "Points and lines"). positions: (N, 3)
    floats; colors: (N, 3) or (N, 4), uint8 or floats 0..1; normals: (N, 3), without which the
    points are drawn unlit, in their colour (material colour times vertex colour)."""
    return Mesh(positions, colors=colors, normals=normals, points=_np.arange(len(positions), dtype=_np.int64))


def Lines(positions, segments=None, *, strip=False, loop=False, colors=None, normals=None):
    """Line segments: a phongvk.Mesh drawn as lines render_settings.line_width pixels wide.
    positions: (N, 3) floats; segments: (L, 2) vertex indices, or None for consecutive pairs
    (0-1, 2-3, ...: glTF's LINES), a polyline through every vertex (strip=True, LINE_STRIP) or a
    closed one (loop=True, LINE_LOOP); colors and normals as in Points (unlit without normals)."""
    count = len(positions)
    if segments is None:
        if strip or loop:
            first = _np.arange(count - 1 + (1 if loop and count > 2 else 0), dtype=_np.int64)
            segments = _np.stack([first, (first + 1) % count], axis=1)
        else:
            segments = _np.arange(count - count % 2, dtype=_np.int64).reshape(-1, 2)
    elif strip or loop:
        raise ValueError("segments: not given with strip or loop, which make the segments")
    return Mesh(positions, colors=colors, normals=normals, lines=segments)


def _add_points(scene, positions, colors=None, normals=None, *, pose=None, material=None, object_id=None):
    return scene.add(Points(positions, colors=colors, normals=normals), pose=pose, material=material,
                     object_id=object_id)


def _add_lines(scene, positions, segments=None, *, strip=False, loop=False, colors=None, normals=None, pose=None,
               material=None, object_id=None):
    return scene.add(Lines(positions, segments, strip=strip, loop=loop, colors=colors, normals=normals), pose=pose,
                     material=material, object_id=object_id)


# Docstrings led by a signature line, as pybind11's methods have theirs (the stubs test reads it).
_add_points.__doc__ = (
    "add_points(self: Scene, positions: ArrayLike, colors: ArrayLike = None, normals: ArrayLike = None, *, "
    "pose: ArrayLike = None, material: MaterialLike = None, object_id: int = None) -> int\n\n"
    "Adds a point cloud (phongvk.Points: every vertex a point) placed by pose, and returns its handle, as add() does.")
_add_lines.__doc__ = (
    "add_lines(self: Scene, positions: ArrayLike, segments: ArrayLike = None, *, strip: bool = False, "
    "loop: bool = False, colors: ArrayLike = None, normals: ArrayLike = None, pose: ArrayLike = None, "
    "material: MaterialLike = None, object_id: int = None) -> int\n\n"
    "Adds line segments (phongvk.Lines) placed by pose, and returns its handle, as add() does.")
Scene.add_points = _add_points
Scene.add_lines = _add_lines
__all__ += ["Lines", "Points"]
