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
    devices,
    diff,
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
    "devices", "diff", "encode_png", "load_scene", "read_png", "scene_from_dict", "write_png",
]


class Image(_np.ndarray):
    """An RGB image: a C-contiguous uint8 numpy array of shape (height, width, 3), row 0 at the
    top, that shows itself as a picture in Jupyter. Everything numpy does with arrays works."""

    def _repr_png_(self):
        return encode_png(_np.asarray(self))


class NoticeWarning(UserWarning):
    """What a user may not expect of a picture (Renderer.stats["notice"]): a fitted camera that
    sees only the back of every triangle, so the model is drawn dark."""


class Renderer(_phongvk.Renderer):
    __doc__ = _phongvk.Renderer.__doc__

    def render(self, scene, width=None, height=None, outputs=None):
        """One frame of `scene` as an Image (a uint8 array of shape (height, width, 3)); at
        width x height pixels when both are given (the vertical field of view is kept).

        With outputs (names among "color", "rgba", "alpha", "depth", "object_id", "triangle_id",
        "normal"), a dict of arrays by name instead: color an Image, rgba a (height, width, 4) uint8
        array with alpha where triangles cover the pixel (255: every sample), alpha that
        (height, width) uint8 coverage alone, depth float32 metres along the camera's axis (inf
        where empty), object_id (the index in the scene's objects) and triangle_id int32 (-1 where
        empty), normal a (height, width, 3) float32 array of unit shading normals in camera space,
        x right, y up, z forward along the depth's axis (a surface facing the camera has z < 0;
        0, 0, 0 where empty): the face normal with flat shading, the vertex normals interpolated at
        the pixel and normalized with Gouraud and Phong, as stored on a back face (not flipped).
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
