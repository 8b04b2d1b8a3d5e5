// module.cpp — phongvk's Python extension (_phongvk), on the public C++ API (include/phongvk) alone:
// numpy arrays in and out, the GIL released while rendering, C++ errors as Python exceptions. What
// users import is the package around it (python/phongvk/__init__.py); the docstrings here are what
// help() shows.
#include <phongvk/phongvk.h>

#include "json_writer.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace py = pybind11;

namespace phongvk::python {
// A file path as Python gives one: a str or any os.PathLike (pathlib.Path) naming text.
struct FsPath {
  std::string text;
};
}  // namespace phongvk::python

namespace pybind11::detail {
template <>
struct type_caster<phongvk::python::FsPath> {
  PYBIND11_TYPE_CASTER(phongvk::python::FsPath, const_name("str | os.PathLike[str]"));
  bool load(handle source, bool) {
    if (!isinstance<str>(source) && !hasattr(source, "__fspath__")) return false;
    const object text = module_::import("os").attr("fspath")(source);
    if (!isinstance<str>(text)) return false;  // a bytes path
    value.text = text.cast<std::string>();
    return true;
  }
  static handle cast(const phongvk::python::FsPath& path, return_value_policy, handle) {
    return str(path.text).release();
  }
};

// Three numbers (a position, a colour) read back as a tuple, not a list: a list would take an item
// assignment (camera.position[0] = 1) and change nothing; a tuple refuses it. Any sequence of
// three numbers is taken.
template <>
struct type_caster<phongvk::Vec3> : array_caster<phongvk::Vec3, double, false, 3> {
  template <typename T>
  static handle cast(T&& src, return_value_policy policy, handle parent) {
    const object items = reinterpret_steal<object>(
        array_caster<phongvk::Vec3, double, false, 3>::cast(std::forward<T>(src), policy, parent));
    return items ? tuple(items).release() : handle();
  }
};
}  // namespace pybind11::detail

namespace phongvk::python {
namespace {

// ---- arrays ----

// A vector's bytes as an array of `shape` that owns them (no copy).
template <typename T>
py::array_t<T> ownedArray(std::vector<T>&& values, std::vector<py::ssize_t> shape) {
  auto* owned = new std::vector<T>(std::move(values));
  py::capsule owner(owned, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  return py::array_t<T>(shape, owned->data(), owner);
}

py::array_t<uint8_t> imageArray(Image&& image) {
  const py::ssize_t h = image.height, w = image.width;
  return ownedArray(std::move(image.rgb), {h, w, 3});
}

// read_png: the file's pixels in the form `mode` names.
py::array pngArray(const FsPath& file, const std::string& mode) {
  const std::string& path = file.text;
  if (mode == "rgb") return imageArray(readPng(path));
  if (mode == "rgba") {
    ImageRGBA image = readPngRGBA(path);
    return ownedArray(std::move(image.rgba), {image.height, image.width, 4});
  }
  if (mode == "grey16") {
    ImageGrey16 image = readPngGrey16(path);
    return ownedArray(std::move(image.grey), {image.height, image.width});
  }
  throw ArgumentError("mode: expected 'rgb', 'rgba' or 'grey16', got '" + mode + "'");
}

// MemoryError with `message`, which names the argument that found no memory.
[[noreturn]] void raiseMemoryError(const std::string& message) {
  PyErr_SetString(PyExc_MemoryError, message.c_str());
  throw py::error_already_set();
}

std::string shapeText(const py::array& a) {
  std::string text = "(";
  for (py::ssize_t i = 0; i < a.ndim(); ++i) text += (i ? ", " : "") + std::to_string(a.shape(i));
  return text + (a.ndim() == 1 ? ",)" : ")");
}

std::string typeName(const py::handle& value) { return py::str(py::type::of(value).attr("__name__")); }

// `value` as a numpy array of numbers (integers or floating point) for the argument `name`, whose
// form `expected` describes: an array as it is, anything else (nested lists or tuples, an
// array-like) through numpy.asarray. ValueError naming `name` for anything else: ragged rows,
// strings, objects, a dict, booleans, complex numbers (a cast would drop their imaginary part).
py::array numberArray(const py::handle& value, const char* name, const std::string& expected) {
  py::array a;
  if (py::isinstance<py::array>(value)) {
    a = py::reinterpret_borrow<py::array>(value);
  } else {
    try {
      a = py::module_::import("numpy").attr("asarray")(value);
    } catch (py::error_already_set& e) {
      if (e.matches(PyExc_MemoryError)) throw;
      throw py::value_error(std::string(name) + ": expected " + expected + ", got " + typeName(value) + " (" +
                            e.what() + ")");
    }
  }
  const char kind = a.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u') {
    throw py::value_error(std::string(name) + ": expected " + expected + ", got " + typeName(value) + " of dtype " +
                          std::string(py::str(a.dtype())));
  }
  return a;
}

// The values of `a` (numbers: numberArray) converted to T, row-major, in a vector of their own:
// numpy copies them once, whatever their strides, straight into it (MemoryError where there is no
// room, never a half-made copy read).
template <typename T>
std::vector<T> valuesOf(const py::array& a, const char* name) {
  std::vector<T> values;
  try {
    values.resize(size_t(a.size()));
  } catch (const std::bad_alloc&) {
    raiseMemoryError(std::string(name) + ": no memory for a copy of its " + shapeText(a) + " values (" +
                     std::to_string(size_t(a.size()) * sizeof(T)) + " bytes)");
  }
  if (values.empty()) return values;
  // A writable view of the vector (the capsule, owning nothing, tells numpy not to copy).
  const py::array_t<T> view(std::vector<py::ssize_t>(a.shape(), a.shape() + a.ndim()), values.data(),
                            py::capsule(values.data(), [](void*) {}));
  py::module_::import("numpy").attr("copyto")(view, a, py::arg("casting") = "unsafe");
  return values;
}

// What the PNG coder takes from Python: an (H, W, 3) or (H, W, 4) uint8 array (RGB, RGBA) or an
// (H, W) uint16 array (16-bit grey), copied.
using PngImage = std::variant<Image, ImageRGBA, ImageGrey16, ImageGrey8>;

constexpr const char* PNG_ARRAYS = "a uint8 array of shape (height, width, 3) or (height, width, 4), or a uint16 array "
                                   "of shape (height, width)";
// write_png and encode_png take grey masks too.
constexpr const char* PNG_WRITE_ARRAYS = "a uint8 array of shape (height, width, 3) or (height, width, 4), or a uint8, "
                                         "uint16 or bool array of shape (height, width)";

// A 2-D uint8 or bool array (bool as 0 and 255): an 8-bit grey image; else nothing.
std::optional<ImageGrey8> grey8FromArray(const py::array& array, const char* name) {
  const bool bools = array.dtype().kind() == 'b';
  if (array.ndim() != 2 || !(bools || py::isinstance<py::array_t<uint8_t>>(array))) return std::nullopt;
  if (array.shape(0) == 0 || array.shape(1) == 0)
    throw py::value_error(std::string(name) + ": expected a non-empty array, got shape " + shapeText(array));
  ImageGrey8 image{int(array.shape(1)), int(array.shape(0)), valuesOf<uint8_t>(array, name)};
  if (bools) {
    for (uint8_t& v : image.grey) v = v ? 255 : 0;
  }
  return image;
}

// ValueError naming `name` for an array that is not an image PNG_ARRAYS describes, or is empty.
void checkPngArray(const py::array& array, const char* name, const char* expected = PNG_ARRAYS) {
  const std::string shape = shapeText(array);
  const bool bytes = py::isinstance<py::array_t<uint8_t>>(array), words = py::isinstance<py::array_t<uint16_t>>(array);
  const py::ssize_t channels = array.ndim() == 3 ? array.shape(2) : 0;
  if (!(bytes && (channels == 3 || channels == 4)) && !(words && array.ndim() == 2)) {
    throw py::value_error(std::string(name) + ": expected " + expected + ", got " +
                          std::string(py::str(array.dtype())) + " of shape " + shape);
  }
  if (array.shape(0) == 0 || array.shape(1) == 0) {
    throw py::value_error(std::string(name) + ": expected a non-empty array, got shape " + shape);
  }
}

// `array`, the argument `name`, as the image it holds (ValueError where checkPngArray refuses it).
PngImage pngImageFromArray(const py::array& array, const char* name) {
  if (std::optional<ImageGrey8> grey = grey8FromArray(array, name)) return std::move(*grey);
  checkPngArray(array, name, PNG_WRITE_ARRAYS);
  const int w = int(array.shape(1)), h = int(array.shape(0));
  if (array.ndim() == 2) return ImageGrey16{w, h, valuesOf<uint16_t>(array, name)};
  if (array.shape(2) == 4) return ImageRGBA{w, h, valuesOf<uint8_t>(array, name)};
  Image image;
  image.width = w;
  image.height = h;
  image.rgb = valuesOf<uint8_t>(array, name);
  return image;
}

// The PNG of `pixels` (the argument `name`) at `level`, encoded without the GIL; MemoryError naming
// the argument where its encoding finds no memory.
std::vector<uint8_t> encodedPng(const PngImage& pixels, int level, const char* name) {
  std::vector<uint8_t> png;
  bool noMemory = false;
  {
    const py::gil_scoped_release release;
    try {
      png = std::visit([&](const auto& any) { return encodePng(any, level); }, pixels);
    } catch (const std::bad_alloc&) {
      noMemory = true;
    }
  }
  if (noMemory) {
    const auto [w, h] = std::visit([](const auto& any) { return std::pair(any.width, any.height); }, pixels);
    raiseMemoryError(std::string(name) + ": no memory to encode its " + std::to_string(w) + " x " + std::to_string(h) + " PNG");
  }
  return png;
}

// `name` as an (N, 3) array of `kind` ('f': floating point, 'i': integer), flattened row-major.
template <typename T>
std::vector<T> rowsOf3(const py::array& a, const char* name, char kind) {
  const char have = a.dtype().kind();
  const bool kindOk = kind == 'f' ? have == 'f' : (have == 'i' || have == 'u');
  if (!kindOk) {
    throw py::value_error(std::string(name) + ": expected " + (kind == 'f' ? "a floating-point" : "an integer") +
                          " array of shape (N, 3), got dtype " + std::string(py::str(a.dtype())));
  }
  if (a.ndim() != 2 || a.shape(1) != 3) {
    throw py::value_error(std::string(name) + ": expected shape (N, 3), got " + shapeText(a));
  }
  return valuesOf<T>(a, name);
}

// ---- scenes ----

Scene sceneFromDict(const py::dict& d, std::optional<std::string> baseDir) {
  const std::string json = JsonWriter("").write(d);
  return parseScene(json, "", baseDir.value_or("."), true);
}

// `value` (the argument `name`) as rows of 3 numbers: an array as it is (rowsOf3 checks its dtype),
// anything else (nested lists or tuples, an array-like) as float64 where `floats`.
py::array asArray(const py::handle& value, const char* name, bool floats) {
  const py::array a = numberArray(value, name, "an array of shape (N, 3) or rows of 3 numbers");
  if (!floats || py::isinstance<py::array>(value)) return a;
  return a.attr("astype")("float64");
}

// Texture coordinates: an (N, 2) array (or rows of 2 numbers), as floats, flattened.
std::vector<float> uvRows(const py::object& uvs) {
  const py::array a = numberArray(uvs, "uvs", "an array of shape (N, 2) or rows of 2 numbers");
  if (a.ndim() != 2 || a.shape(1) != 2) throw py::value_error("uvs: expected shape (N, 2), got " + shapeText(a));
  return valuesOf<float>(a, "uvs");
}

// Vertex colours: an (N, 3) or (N, 4) array, of integers 0..255 (uint8, say) or of floats 0..1
// (rounded to the nearest of 256 steps), as RGBA8 rows (alpha 255 where not given). ValueError
// naming "colors" and the first bad row.
std::vector<uint8_t> colorRows(const py::object& colors, py::ssize_t vertices) {
  const py::array a = numberArray(colors, "colors", "an array of shape (N, 3) or (N, 4)");
  if (a.ndim() != 2 || (a.shape(1) != 3 && a.shape(1) != 4))
    throw py::value_error("colors: expected shape (N, 3) or (N, 4), got " + shapeText(a));
  if (a.shape(0) != vertices)
    throw py::value_error("colors: expected one row per vertex (" + std::to_string(vertices) + "), got " +
                          std::to_string(a.shape(0)));
  const bool floats = a.dtype().kind() == 'f';
  const std::vector<double> values = valuesOf<double>(a, "colors");
  const size_t channels = size_t(a.shape(1));
  std::vector<uint8_t> rgba;
  rgba.reserve(size_t(vertices) * 4);
  for (size_t i = 0; i < values.size(); ++i) {
    const double v = values[i], top = floats ? 1.0 : 255.0;
    if (!(v >= 0 && v <= top))
      throw py::value_error("colors: row " + std::to_string(i / channels) + " has " + std::string(py::str(py::float_(v))) + ", outside 0.." +
                            (floats ? "1 (floats)" : "255 (integers)"));
    rgba.push_back(uint8_t(floats ? std::lround(v * 255.0) : v));
    if (channels == 3 && i % 3 == 2) rgba.push_back(255);
  }
  return rgba;
}

// A trimesh-like object's vertex colours and texture coordinates, where its `visual` has them:
// visual.kind "vertex" with visual.vertex_colors, or visual.uv (trimesh's v runs up from the
// bottom; phongvk's from the top, so v becomes 1 - v).
void visualArrays(const py::object& object, MeshArrays& mesh, bool uvsGiven, bool colorsGiven) {
  if (!py::hasattr(object, "visual")) return;
  const py::object visual = object.attr("visual");
  const py::ssize_t vertices = py::ssize_t(mesh.positions.size() / 3);
  if (!colorsGiven && py::hasattr(visual, "kind") && py::str(visual.attr("kind")).cast<std::string>() == "vertex" &&
      py::hasattr(visual, "vertex_colors"))
    mesh.colors = colorRows(visual.attr("vertex_colors"), vertices);
  if (!uvsGiven && py::hasattr(visual, "uv") && !visual.attr("uv").is_none()) {
    mesh.uvs = uvRows(visual.attr("uv"));
    for (size_t i = 1; i < mesh.uvs.size(); i += 2) mesh.uvs[i] = 1.0f - mesh.uvs[i];
  }
}

// The arrays of a mesh: vertices and faces, or (faces None) one object with .vertices and .faces
// arrays (a trimesh.Trimesh, say, whose visual's vertex colours and uvs come too); texture
// coordinates and vertex colours if given.
MeshArrays meshArrays(const py::object& vertices, const py::object& faces, const py::object& normals,
                      const py::object& uvs = py::none(), const py::object& colors = py::none()) {
  if (faces.is_none()) {
    if (!py::hasattr(vertices, "vertices") || !py::hasattr(vertices, "faces")) {
      throw py::type_error("add_mesh: expected vertices and faces, a phongvk.Mesh, or one object with .vertices "
                           "and .faces arrays (a trimesh.Trimesh, for one), got " +
                           std::string(py::str(py::type::of(vertices).attr("__name__"))));
    }
    MeshArrays mesh = meshArrays(vertices.attr("vertices"), vertices.attr("faces"), normals, uvs, colors);
    visualArrays(vertices, mesh, !uvs.is_none(), !colors.is_none());
    return mesh;
  }
  const py::array vertexArray = asArray(vertices, "vertices", true);
  MeshArrays mesh;
  mesh.positions = rowsOf3<float>(vertexArray, "vertices", 'f');
  mesh.triangles = rowsOf3<int64_t>(asArray(faces, "faces", false), "faces", 'i');
  if (!normals.is_none()) {
    const py::array normalArray = asArray(normals, "normals", true);
    mesh.normals = rowsOf3<float>(normalArray, "normals", 'f');
    if (normalArray.shape(0) != vertexArray.shape(0)) {
      throw py::value_error("normals: expected one row per vertex (" + std::to_string(vertexArray.shape(0)) +
                            "), got " + std::to_string(normalArray.shape(0)));
    }
  }
  if (!uvs.is_none()) mesh.uvs = uvRows(uvs);
  if (!colors.is_none()) mesh.colors = colorRows(colors, vertexArray.shape(0));
  return mesh;
}

// A (4, 4) array (or rows of 4 numbers) as a row-major Matrix4; None is the identity.
Matrix4 matrix4(const py::object& value, const char* name) {
  if (value.is_none()) return IDENTITY_POSE;
  const py::array a = numberArray(value, name, "a 4x4 matrix of numbers");
  if (a.ndim() != 2 || a.shape(0) != 4 || a.shape(1) != 4) {
    throw py::value_error(std::string(name) + ": expected a 4x4 matrix, got shape " + shapeText(a));
  }
  const std::vector<double> values = valuesOf<double>(a, name);
  Matrix4 m{};
  std::copy(values.begin(), values.end(), m.begin());
  return m;
}

PoseConvention convention(const std::string& name) {
  if (name == "opengl") return PoseConvention::OpenGL;
  if (name == "opencv") return PoseConvention::OpenCV;
  throw ArgumentError("convention: expected 'opengl' or 'opencv', got '" + name + "'");
}

std::string floatText(double x) { return py::str(py::float_(x)); }

std::string vec3Text(const Vec3& v) { return "(" + floatText(v[0]) + ", " + floatText(v[1]) + ", " + floatText(v[2]) + ")"; }

// ", fov=60.0", ", ortho_height=2.0" for an orthographic camera, or ", intrinsics=(fx, fy, cx, cy)"
// for a camera that has them.
std::string fieldOfViewText(const Camera& c) {
  if (c.orthoHeight) return ", ortho_height=" + floatText(*c.orthoHeight);
  if (!c.intrinsics) return ", fov=" + floatText(c.fov);
  const Intrinsics& k = *c.intrinsics;
  return ", intrinsics=(" + floatText(k.fx) + ", " + floatText(k.fy) + ", " + floatText(k.cx) + ", " + floatText(k.cy) + ")";
}

// ---- materials and render settings ----

// `fields` (a dict or kwargs: attribute names to values) set on `value`, a phongvk.Material or
// RenderSettings, as its keyword constructor sets them; SceneError "<what>: unknown key 'x'
// (allowed: ...)" for a name it does not have, as a scene file's section says it.
void setFields(py::object& value, const py::dict& fields, const std::string& what) {
  for (const auto& [key, field] : fields) {
    const std::string name = py::str(key);
    if (name.empty() || name[0] == '_' || !py::hasattr(value, name.c_str())) {
      std::string allowed;
      for (const py::handle attribute : py::module_::import("builtins").attr("dir")(value)) {
        const std::string a = py::str(attribute);
        if (a[0] != '_') allowed += (allowed.empty() ? "" : ", ") + a;
      }
      throw SceneError(what + ": unknown key '" + name + "' (allowed: " + allowed + ")");
    }
    value.attr(name.c_str()) = field;
  }
}

// The texels of an image array textureOfArray has checked, row by row from its strides.
Texture texelsOfArray(const py::array& array, const char* name) {
  const int width = int(array.shape(1)), height = int(array.shape(0));
  const auto* base = static_cast<const uint8_t*>(array.data());
  const py::ssize_t rowStride = array.strides(0), pixelStride = array.strides(1);
  if (array.ndim() == 2) {  // 16-bit grey
    return Texture::fromRows(width, height, [&](int y, uint8_t* rgba) {
      for (int x = 0; x < width; ++x, rgba += 4) {
        uint16_t grey;
        std::memcpy(&grey, base + y * rowStride + x * pixelStride, sizeof grey);
        rgba[0] = rgba[1] = rgba[2] = uint8_t(grey >> 8);
        rgba[3] = 255;
      }
    }, name);
  }
  const py::ssize_t channelStride = array.strides(2);
  const bool alpha = array.shape(2) == 4;
  return Texture::fromRows(width, height, [&](int y, uint8_t* rgba) {
    for (int x = 0; x < width; ++x, rgba += 4) {
      const uint8_t* pixel = base + y * rowStride + x * pixelStride;
      for (int c = 0; c < 3; ++c) rgba[c] = pixel[c * channelStride];
      rgba[3] = alpha ? pixel[3 * channelStride] : 255;
    }
  }, name);
}

// An image array ((height, width, 3 or 4) uint8, or (height, width) uint16 grey: PNG_ARRAYS) as a
// texture held in memory: its texels written row by row straight from the array, whatever its
// strides, without a copy of the array or a PNG of it. RGB gets alpha 255, grey is replicated and
// 16-bit samples keep their high byte, as a PNG of the array decodes. Its size is checked against
// what a texture may be before anything is allocated.
Texture textureOfArray(const py::array& array, const char* name) {
  checkPngArray(array, name);
  checkTextureSize(array.shape(1), array.shape(0), name);
  try {
    return texelsOfArray(array, name);
  } catch (const std::bad_alloc&) {
    raiseMemoryError(std::string(name) + ": no memory for its " + std::to_string(array.shape(1)) + " x " +
                     std::to_string(array.shape(0)) + " texels (" + std::to_string(array.shape(0) * array.shape(1) * 4) +
                     " bytes)");
  }
}

std::string textureRepr(const Texture& texture) {
  return "<phongvk.Texture " + std::to_string(texture.width()) + " x " + std::to_string(texture.height()) + ">";
}

// Sets a material's texture from what Material.texture takes: None for none, a path (text or
// os.PathLike) for a file, a phongvk.Texture as it is, an image array as a Texture of its pixels.
void setTexture(Material& material, const py::object& texture) {
  material.texture.clear();
  material.textureImage.reset();
  if (texture.is_none()) return;
  if (py::isinstance<py::str>(texture) || py::hasattr(texture, "__fspath__")) {
    material.texture = py::str(py::module_::import("os").attr("fspath")(texture));
  } else if (py::isinstance<Texture>(texture)) {
    material.textureImage = texture.cast<Texture>();
  } else {
    material.textureImage = textureOfArray(numberArray(texture, "texture", PNG_ARRAYS), "texture");
  }
}

// A material given to add or add_mesh: a phongvk.Material, a dict of its fields, or None (the
// scene's default material).
std::optional<Material> materialOf(const py::object& material) {
  if (material.is_none()) return std::nullopt;
  if (py::isinstance<Material>(material)) return material.cast<Material>();
  if (!py::isinstance<py::dict>(material)) {
    throw py::type_error("material: expected a phongvk.Material, a dict of its fields, a material name or None, got " +
                         std::string(py::str(py::type::of(material).attr("__name__"))));
  }
  py::object value = py::cast(Material{});
  setFields(value, material.cast<py::dict>(), "material");
  return value.cast<Material>();
}

// What add and add_mesh place: a phongvk.Mesh as it is (shared, built once), or arrays built now.
TriangleMesh meshOf(const py::object& vertices, const py::object& faces, const py::object& normals,
                    const py::object& uvs = py::none(), const py::object& colors = py::none()) {
  if (!py::isinstance<TriangleMesh>(vertices)) return TriangleMesh(meshArrays(vertices, faces, normals, uvs, colors));
  if (!faces.is_none() || !normals.is_none() || !uvs.is_none() || !colors.is_none())
    throw py::type_error("faces, normals, uvs and colors: not given with a phongvk.Mesh, which has its own");
  return vertices.cast<TriangleMesh>();
}

// A trimesh-like object's texture image (visual.material.image, or a PBR material's
// baseColorTexture: a PIL image or an array), as the material of an object added without one.
std::optional<Material> visualMaterial(const py::object& object) {
  if (!py::hasattr(object, "visual") || !py::hasattr(object.attr("visual"), "material")) return std::nullopt;
  const py::object material = object.attr("visual").attr("material");
  for (const char* name : {"image", "baseColorTexture"}) {
    if (!py::hasattr(material, name) || material.attr(name).is_none()) continue;
    Material textured;
    textured.textureImage = textureOfArray(numberArray(material.attr(name), "visual.material.image", PNG_ARRAYS),
                                           "visual.material.image");
    return textured;
  }
  return std::nullopt;
}

// Adds `mesh` at `pose`; `object` is what the caller gave (a trimesh-like object's texture serves
// when no material is given), `objectId` the object_id output's number if given.
unsigned long long addPlaced(Scene& scene, const TriangleMesh& mesh, const py::object& object, const Matrix4& pose,
                             const py::object& material, bool closed, std::optional<int32_t> objectId) {
  ObjectId id;
  if (py::isinstance<py::str>(material)) {
    id = scene.add(mesh, pose, material.cast<std::string>(), closed);
  } else {
    const std::optional<Material> given = materialOf(material);
    id = scene.add(mesh, pose, given ? given : visualMaterial(object), closed);
  }
  if (objectId) {
    try {
      scene.setObjectId(id, *objectId);
    } catch (...) {
      scene.remove(id);  // the scene as it was
      throw;
    }
  }
  return id.value;
}

void addMesh(Scene& scene, const py::object& vertices, const py::object& faces, const py::object& normals,
             const py::object& material, bool closed, const py::object& uvs, const py::object& colors,
             std::optional<int32_t> objectId) {
  addPlaced(scene, meshOf(vertices, faces, normals, uvs, colors), vertices, IDENTITY_POSE, material, closed, objectId);
}

unsigned long long addObject(Scene& scene, const py::object& object, const py::object& faces, const py::object& pose,
                             const py::object& material, bool closed, const py::object& normals, const py::object& uvs,
                             const py::object& colors, std::optional<int32_t> objectId) {
  const TriangleMesh mesh = meshOf(object, faces, normals, uvs, colors);
  return addPlaced(scene, mesh, object, matrix4(pose, "pose"), material, closed, objectId);
}

// A handle as the scene's object or light handle it is (Scene.remove takes either).
bool isLightHandle(unsigned long long handle) { return handle & (1ull << 31); }

TriangleMesh meshFromFile(const FsPath& path, const std::optional<std::string>& up) {
  const ModelUp axis = up ? parseModelUp(*up) : ModelUp::Usual;
  py::gil_scoped_release release;
  return TriangleMesh::fromFile(path.text, axis);
}

// `scene` with_render(settings, **options): `settings` (a phongvk.RenderSettings, a dict of its
// fields, or None for the scene's own), then the options over it.
Scene withRender(const Scene& scene, const py::object& settings, const py::kwargs& options) {
  py::object value = py::cast(scene.renderSettings());
  if (py::isinstance<RenderSettings>(settings)) {
    value = py::cast(settings.cast<RenderSettings>());
  } else if (py::isinstance<py::dict>(settings)) {
    setFields(value, settings.cast<py::dict>(), "render");
  } else if (!settings.is_none()) {
    throw py::type_error("settings: expected a phongvk.RenderSettings, a dict of its fields or None, got " +
                         std::string(py::str(py::type::of(settings).attr("__name__"))));
  }
  setFields(value, options, "render");
  return scene.withRender(value.cast<RenderSettings>());
}

// ---- rendering ----

// The scene at width x height when both are given, else as its camera says.
Scene sized(const Scene& scene, std::optional<int> width, std::optional<int> height) {
  if (width.has_value() != height.has_value()) throw py::value_error("width and height go together");
  return width ? scene.withImageSize(*width, *height) : scene;
}

// `call` (a Renderer method) on `scene` at the asked size, with the GIL released meanwhile.
template <typename Result>
Result released(Renderer& renderer, const Scene& scene, std::optional<int> width, std::optional<int> height,
                Result (Renderer::*call)(const Scene&)) {
  const Scene s = sized(scene, width, height);
  py::gil_scoped_release release;
  return (renderer.*call)(s);
}

// One frame of `scene` at the asked size with `outputs`, the GIL released meanwhile.
RenderedFrame renderedFrame(Renderer& renderer, const Scene& scene, std::optional<int> width, std::optional<int> height,
                            const Outputs& outputs) {
  const Scene s = sized(scene, width, height);
  py::gil_scoped_release release;
  return renderer.renderOutputs(s, outputs);
}

// The output names render(outputs=...) takes, as the library's Outputs. Each name once: the dict
// has one array a name, and outputsDict moves each output out of the frame once.
Outputs outputsNamed(const std::vector<std::string>& names) {
  Outputs outputs;
  for (auto name = names.begin(); name != names.end(); ++name) {
    if (std::find(names.begin(), name, *name) != name)
      throw ArgumentError("outputs: '" + *name + "' is asked for more than once");
  }
  for (const std::string& name : names) {
    if (name == "alpha" || name == "rgba") outputs.alpha = true;
    else if (name == "depth") outputs.depth = true;
    else if (name == "object_id") outputs.objectIds = true;
    else if (name == "triangle_id") outputs.triangleIds = true;
    else if (name == "normal") outputs.normals = true;
    else if (name != "color")
      throw ArgumentError("outputs: unknown output '" + name +
                          "' (color, rgba, alpha, depth, object_id, triangle_id, normal)");
  }
  return outputs;
}

// The frame's outputs by name: color (height, width, 3) and rgba (height, width, 4) uint8, alpha
// uint8, depth float32, object_id and triangle_id int32, each (height, width), and normal
// (height, width, 3) float32.
py::dict outputsDict(RenderedFrame&& frame, const std::vector<std::string>& names) {
  const py::ssize_t h = frame.image.height, w = frame.image.width;
  const size_t pixels = size_t(h) * size_t(w);
  py::dict d;
  for (const std::string& name : names) {
    if (name == "rgba") {
      std::vector<uint8_t> rgba(pixels * 4);
      for (size_t i = 0; i < pixels; ++i) {
        std::memcpy(&rgba[4 * i], &frame.image.rgb[3 * i], 3);
        rgba[4 * i + 3] = frame.alpha[i];
      }
      d["rgba"] = ownedArray(std::move(rgba), {h, w, 4});
    } else if (name == "alpha") {
      d["alpha"] = ownedArray(std::vector<uint8_t>(frame.alpha), {h, w});
    } else if (name == "depth") {
      d["depth"] = ownedArray(std::move(frame.depth), {h, w});
    } else if (name == "object_id") {
      d["object_id"] = ownedArray(std::move(frame.objectIds), {h, w});
    } else if (name == "triangle_id") {
      d["triangle_id"] = ownedArray(std::move(frame.triangleIds), {h, w});
    } else if (name == "normal") {
      d["normal"] = ownedArray(std::move(frame.normals), {h, w, 3});
    }
  }
  // The colour last: rgba above copied from the image this moves.
  if (std::find(names.begin(), names.end(), "color") != names.end()) d["color"] = imageArray(std::move(frame.image));
  return d;
}

py::dict statsDict(const RendererStats& s) {
  py::dict d;
  d["scene_builds"] = s.sceneBuilds;
  d["frames_rendered"] = s.framesRendered;
  d["frames_shaded"] = s.framesShaded;
  d["frames_repeated"] = s.framesRepeated;
  d["triangles"] = s.triangles;
  d["build_ms"] = s.buildMs;
  d["texture_bytes"] = s.textureBytes;
  d["device_bytes"] = s.deviceBytes;
  d["validation_messages"] = s.validationMessages;
  d["startup_vulkan_ms"] = s.contextMs;
  d["startup_probe_ms"] = s.probeMs;
  d["startup_pipelines_ms"] = s.pipelinesMs;
  d["first_frame_ms"] = s.firstFrameMs;
  d["notice"] = s.notice;
  return d;
}

py::dict diffDict(const DiffResult& r) {
  const DiffStats& s = r.stats;
  py::dict d;
  d["width"] = s.width;
  d["height"] = s.height;
  d["pixels"] = s.pixels;
  d["differing"] = s.differing;
  d["max_abs"] = py::make_tuple(s.maxAbs[0], s.maxAbs[1], s.maxAbs[2]);
  d["mean_abs"] = py::make_tuple(s.meanAbs[0], s.meanAbs[1], s.meanAbs[2]);
  d["psnr"] = s.psnr;
  d["triangle_mismatch"] = s.triangleMismatch;
  d["identical_fraction"] = s.identicalFraction();
  d["device"] = r.deviceName;
  d["report"] = formatDiff(s);
  return d;
}

py::dict deviceDict(const DeviceInfo& info) {
  py::dict d;
  d["index"] = info.index;
  d["name"] = info.name;
  d["type"] = info.type;
  d["api_version"] = info.apiVersion;
  d["usable"] = info.suitable;
  d["missing"] = info.missing;
  d["keys"] = keyPathWords(info);  // "64-bit atomics" or "32-bit atomics, two passes (...)"
  return d;
}

RendererOptions rendererOptions(const std::string& backend, std::optional<int> device, bool validate) {
  return {parseBackend(backend), device.value_or(-1), validate};
}

}  // namespace
}  // namespace phongvk::python

PYBIND11_MODULE(_phongvk, m) {
  using namespace phongvk;
  using namespace phongvk::python;
  m.doc() = "phongvk's compiled core; import phongvk, not this module.";

  // C++ failures as Python exceptions, all under phongvk.Error: a bad scene is also a ValueError,
  // a bad argument a ValueError (an index past the end an IndexError), an unwritable file an
  // OSError, a missing Vulkan device or a device limit a RuntimeError. Subclasses are registered
  // after their bases: pybind11 tries the last registered translator first.
  const py::object error = py::register_exception<Error>(m, "Error", PyExc_RuntimeError);
  const auto under = [&](PyObject* python) { return py::make_tuple(error, py::handle(python)); };
  py::register_exception<SceneError>(m, "SceneError", under(PyExc_ValueError));
  const py::object argument = py::register_exception<ArgumentError>(m, "ArgumentError", under(PyExc_ValueError));
  py::register_exception<RangeError>(m, "RangeError", py::make_tuple(argument, py::handle(PyExc_IndexError)));
  py::register_exception<OutputError>(m, "OutputError", under(PyExc_OSError));
  py::register_exception<NoDeviceError>(m, "NoDeviceError", under(PyExc_RuntimeError));
  py::register_exception<DeviceError>(m, "DeviceError", under(PyExc_RuntimeError));

  m.attr("__version__") = version();
  m.attr("__revision__") = revision();

  py::class_<Camera>(m, "Camera", R"(A camera: position, look_at, up (world coordinates, z up by
default), and its view: fov (vertical, degrees), or intrinsics (fx, fy, cx, cy in pixels) of a
pinhole camera, or ortho_height (metres from the image's top to its bottom) of an orthographic
one; width x height (0 x 0: the scene's own size), near and far.
Camera.from_pose and Camera.from_intrinsics make one from a camera-to-world matrix. Assigned to
Scene.camera, it is checked like a scene file's "camera".)")
      .def(py::init([](Vec3 position, Vec3 lookAt, Vec3 up, double fov, int width, int height, double nearPlane,
                       double farPlane, std::optional<std::array<double, 4>> k, std::optional<double> orthoHeight) {
             Camera camera{position, lookAt, up, fov, width, height, nearPlane, farPlane};
             if (k) camera.intrinsics = Intrinsics{(*k)[0], (*k)[1], (*k)[2], (*k)[3]};
             camera.orthoHeight = orthoHeight;
             return camera;
           }),
           py::kw_only(), py::arg("position") = Camera{}.position, py::arg("look_at") = Camera{}.lookAt,
           py::arg("up") = Camera{}.up, py::arg("fov") = Camera{}.fov, py::arg("width") = 0, py::arg("height") = 0,
           py::arg("near") = Camera{}.nearPlane, py::arg("far") = Camera{}.farPlane, py::arg("intrinsics") = py::none(),
           py::arg("ortho_height") = py::none())
      .def_readwrite("position", &Camera::position)
      .def_readwrite("look_at", &Camera::lookAt)
      .def_readwrite("up", &Camera::up)
      .def_readwrite("fov", &Camera::fov)
      .def_readwrite("width", &Camera::width)
      .def_readwrite("height", &Camera::height)
      .def_readwrite("near", &Camera::nearPlane)
      .def_readwrite("far", &Camera::farPlane)
      .def_property(
          "intrinsics",
          [](const Camera& c) -> py::object {
            if (!c.intrinsics) return py::none();
            return py::make_tuple(c.intrinsics->fx, c.intrinsics->fy, c.intrinsics->cx, c.intrinsics->cy);
          },
          [](Camera& c, const py::object& value) {
            if (value.is_none()) return c.intrinsics.reset();
            const auto k = value.cast<std::array<double, 4>>();
            c.intrinsics = Intrinsics{k[0], k[1], k[2], k[3]};
          },
          R"((fx, fy, cx, cy) in pixels, OpenCV's convention (pixel centres at integer coordinates), or
None: the field of view is fov. With intrinsics the camera needs a width and height.)")
      .def_readwrite("ortho_height", &Camera::orthoHeight,
                     R"(Metres the image spans from top to bottom (and ortho_height * width / height
across) for an orthographic camera, whose pixels all look along the view direction; None for a
perspective one. An orthographic camera needs a width and height, and no intrinsics.)")
      .def_static(
          "from_pose",
          [](const py::object& pose, const std::string& conventionName, double fov, int width, int height,
             std::optional<double> orthoHeight) {
            Camera camera = cameraFromPose(matrix4(pose, "pose"), convention(conventionName), fov, width, height);
            camera.orthoHeight = orthoHeight;
            return camera;
          },
          py::arg("pose"), py::kw_only(), py::arg("convention") = "opengl", py::arg("fov") = 60.0,
          py::arg("width") = 0, py::arg("height") = 0, py::arg("ortho_height") = py::none(),
          R"(The camera a (4, 4) camera-to-world pose describes. convention: "opengl" (the camera looks
down its -z, y up: Blender, three.js, NeRF) or "opencv" (looks down +z, y down: COLMAP, most
datasets). A pose whose rotation block is not a rotation raises ValueError. ortho_height (metres
from the image's top to its bottom) makes it an orthographic camera, fov then unused.)")
      .def_static(
          "from_intrinsics",
          [](double fx, double fy, double cx, double cy, int width, int height, const py::object& pose,
             const std::string& conventionName) {
            return cameraFromIntrinsics(fx, fy, cx, cy, width, height, matrix4(pose, "pose"), convention(conventionName));
          },
          py::arg("fx"), py::arg("fy"), py::arg("cx"), py::arg("cy"), py::arg("width"), py::arg("height"),
          py::arg("pose") = py::none(), py::arg("convention") = "opengl",
          R"(The camera of pinhole intrinsics (pixels, OpenCV's convention: pixel centres at integer
coordinates, so the centre is ((width - 1) / 2, (height - 1) / 2)) and a (4, 4) camera-to-world pose
(identity when None) in the convention every pose-taking call defaults to, "opengl" (as from_pose;
datasets with intrinsics often give "opencv" poses: say so). fx and fy may differ; the principal point (cx, cy) may lie off centre, or
outside the image within 16384 pixels of it. A focal length that is not positive raises ValueError.)")
      .def("__eq__", [](const Camera& a, const Camera& b) { return a == b; }, py::is_operator())
      .def("__repr__", [](const Camera& c) {
        return "phongvk.Camera(position=" + vec3Text(c.position) + ", look_at=" + vec3Text(c.lookAt) + ", up=" +
               vec3Text(c.up) + fieldOfViewText(c) + ", width=" + std::to_string(c.width) +
               ", height=" + std::to_string(c.height) + ")";
      });

  py::class_<Light>(m, "Light", R"(A light: a point light at position (or at_camera=True: at the eye,
wherever the camera is), or a directional light (direction=(x, y, z): its light travels that way
and reaches every point alike, without fall-off, as the sun's); intensity, color. Assigned to
Scene.lights, checked like a scene file's "lights".)")
      .def(py::init([](Vec3 position, std::optional<Vec3> direction, double intensity, Vec3 color, bool atCamera) {
             Light light{position, intensity, color, atCamera};
             if (direction) {
               light.directional = true;
               light.direction = *direction;
             }
             return light;
           }),
           py::kw_only(), py::arg("position") = Vec3{0, 0, 0}, py::arg("direction") = py::none(),
           py::arg("intensity") = 1.0, py::arg("color") = Vec3{1, 1, 1}, py::arg("at_camera") = false)
      .def_readwrite("position", &Light::position)
      .def_property(
          "direction",
          [](const Light& l) { return l.directional ? std::optional<Vec3>(l.direction) : std::nullopt; },
          [](Light& l, std::optional<Vec3> direction) {
            l.directional = direction.has_value();
            if (direction) l.direction = *direction;
          },
          "The direction a directional light's light travels, or None for a point light.")
      .def_readwrite("intensity", &Light::intensity)
      .def_readwrite("color", &Light::color)
      .def_readwrite("at_camera", &Light::atCamera)
      .def("__repr__", [](const Light& l) {
        const std::string where = l.directional ? "direction=" + vec3Text(l.direction)
                                  : l.atCamera  ? std::string("at_camera=True")
                                                : "position=" + vec3Text(l.position);
        return "phongvk.Light(" + where + ", intensity=" + std::string(py::str(py::float_(l.intensity))) +
               ", color=" + vec3Text(l.color) + ")";
      });

  py::class_<Texture>(m, "Texture", R"(A texture held in memory, made once from an image array ((height, width, 3 or
4) uint8 RGB or RGBA, or (height, width) uint16 grey; row 0 at the top) and shared by every material
that takes it: Material(texture=...) makes one of an array, or takes one made before. Its texels are
written from the array directly, whatever its strides: no copy of the array, no PNG. A scene's
to_json() writes it as a data URI of its PNG.)")
      .def(py::init([](const py::object& image) { return textureOfArray(numberArray(image, "image", PNG_ARRAYS), "image"); }),
           py::arg("image"))
      .def_property_readonly("width", &Texture::width)
      .def_property_readonly("height", &Texture::height)
      .def("__eq__", [](const Texture& a, const Texture& b) { return a == b; }, py::is_operator())
      .def("__repr__", textureRepr);

  const Material material;
  py::class_<Material>(m, "Material", R"(A material, as a scene file's material object: ka, kd, ks (the
ambient, diffuse and specular coefficients), n (the specular exponent, the shininess), attenuation
(a, b, c of the fall-off 1 / (a + b d + c d^2)) and color (RGB). The defaults are the scene file's
but the fall-off: 0.15, 1.0, 0.8, 10, (1, 0, 0), grey 0.8; no fall-off, as a model file rendered
alone has, so a scene built in code is well exposed at any distance (a scene file's default
attenuation is the paper's (1, 0.2, 0.2)). Given to Scene.add or add_mesh, it is checked like a
scene file's material (SceneError naming objects[N].material.KEY). texture: a base-colour texture
that multiplies color where the object's mesh has texture coordinates (uvs): a PNG or JPEG file's
path, a phongvk.Texture, or an image array ((height, width, 3 or 4) uint8, row 0 at the top), held
as a phongvk.Texture of its pixels (a scene's to_json() writes it as a data URI of its PNG); None
for none.)")
      .def(py::init([](double ka, double kd, double ks, double n, Vec3 attenuation, Vec3 color, const py::object& texture) {
             Material material{ka, kd, ks, n, attenuation, color};
             setTexture(material, texture);
             return material;
           }),
           py::kw_only(), py::arg("ka") = material.ka, py::arg("kd") = material.kd, py::arg("ks") = material.ks,
           py::arg("n") = material.n, py::arg("attenuation") = material.attenuation, py::arg("color") = material.color,
           py::arg("texture") = py::none())
      .def_readwrite("ka", &Material::ka, "Ambient coefficient (>= 0).")
      .def_readwrite("kd", &Material::kd, "Diffuse coefficient (>= 0).")
      .def_readwrite("ks", &Material::ks, "Specular coefficient (>= 0).")
      .def_readwrite("n", &Material::n, "Specular exponent, the shininess (>= 0).")
      .def_readwrite("attenuation", &Material::attenuation,
                     "(a, b, c) of the fall-off 1 / (a + b d + c d^2), positive at every distance d > 0.")
      .def_readwrite("color", &Material::color, "RGB (>= 0).")
      .def_property(
          "texture",
          [](const Material& x) {
            if (x.textureImage) return py::cast(*x.textureImage);
            return x.texture.empty() ? py::object(py::none()) : py::object(py::str(x.texture));
          },
          setTexture, "The texture's file (or data URI), or the phongvk.Texture an array became; None for none.")
      .def("__eq__", [](const Material& a, const Material& b) { return a == b; }, py::is_operator())
      .def("__repr__", [](const Material& x) {
        return "phongvk.Material(ka=" + floatText(x.ka) + ", kd=" + floatText(x.kd) + ", ks=" + floatText(x.ks) +
               ", n=" + floatText(x.n) + ", attenuation=" + vec3Text(x.attenuation) + ", color=" + vec3Text(x.color) +
               (x.textureImage                        ? ", texture=" + textureRepr(*x.textureImage)
                : x.texture.empty()                   ? std::string()
                : x.texture.rfind("data:", 0) == 0    ? ", texture=<PNG data URI, " + std::to_string(x.texture.size()) + " characters>"
                                                      : ", texture='" + x.texture + "'") +
               ")";
      });

  const RenderSettings settings;
  py::class_<RenderSettings>(m, "RenderSettings", R"(How a scene is rendered: its scene file's "render" options
and background. shading: "gouraud" (lit at the vertices), "flat" (once per triangle) or "phong" (at
every pixel); specular: "phong" or "blinn" (the highlight's base); interpolation: "perspective" or
"screen"; samples per pixel: 1, 4, 9 or 16; background: RGB in [0, 1]; texture_filter: "bilinear" or
"nearest" (how a model's base-colour texture is sampled). The defaults are the scene file's. A name that is none of the choices raises SceneError at once; the rest is checked when a
scene takes the settings (Scene.render_settings, with_render), like a scene file's "render".)")
      .def(py::init([](const std::string& shading, const std::string& specular, const std::string& interpolation,
                       int samples, Vec3 background, const std::string& textureFilter) {
             return RenderSettings{parseShading(shading), parseSpecular(specular), parseInterpolation(interpolation),
                                   samples, background, parseTextureFilter(textureFilter)};
           }),
           py::kw_only(), py::arg("shading") = shadingName(settings.shading),
           py::arg("specular") = specularName(settings.specular),
           py::arg("interpolation") = interpolationName(settings.interpolation), py::arg("samples") = settings.samples,
           py::arg("background") = settings.background, py::arg("texture_filter") = textureFilterName(settings.textureFilter))
      .def_property(
          "shading", [](const RenderSettings& s) { return shadingName(s.shading); },
          [](RenderSettings& s, const std::string& name) { s.shading = parseShading(name); },
          "\"gouraud\", \"flat\" or \"phong\".")
      .def_property(
          "specular", [](const RenderSettings& s) { return specularName(s.specular); },
          [](RenderSettings& s, const std::string& name) { s.specular = parseSpecular(name); }, "\"phong\" or \"blinn\".")
      .def_property(
          "interpolation", [](const RenderSettings& s) { return interpolationName(s.interpolation); },
          [](RenderSettings& s, const std::string& name) { s.interpolation = parseInterpolation(name); },
          "\"perspective\" or \"screen\".")
      .def_property(
          "texture_filter", [](const RenderSettings& s) { return textureFilterName(s.textureFilter); },
          [](RenderSettings& s, const std::string& name) { s.textureFilter = parseTextureFilter(name); },
          "\"bilinear\" or \"nearest\".")
      .def_readwrite("samples", &RenderSettings::samples, "Samples per pixel: 1, 4, 9 or 16 (a regular grid).")
      .def_readwrite("background", &RenderSettings::background, "RGB in [0, 1] where nothing is drawn.")
      .def("__eq__", [](const RenderSettings& a, const RenderSettings& b) { return a == b; }, py::is_operator())
      .def("__repr__", [](const RenderSettings& s) {
        return std::string("phongvk.RenderSettings(shading='") + shadingName(s.shading) + "', specular='" +
               specularName(s.specular) + "', interpolation='" + interpolationName(s.interpolation) +
               "', samples=" + std::to_string(s.samples) + ", background=" + vec3Text(s.background) +
               ", texture_filter='" + textureFilterName(s.textureFilter) + "')";
      });

  py::class_<TriangleMesh>(m, "Mesh", R"(A triangle mesh built once, which Scene.add and add_mesh place as many
times as asked without building or holding it again: Mesh(vertices, faces, normals=None, uvs=None,
colors=None) from arrays (or one object with .vertices and .faces, a trimesh.Trimesh, whose
visual's vertex colours and uvs come with it), checked as add_mesh checks them, or
Mesh.from_file(path, up=None) from an OBJ, PLY, STL, glTF or GLB file.)")
      .def(py::init([](const py::object& vertices, const py::object& faces, const py::object& normals, const py::object& uvs,
                       const py::object& colors) { return TriangleMesh(meshArrays(vertices, faces, normals, uvs, colors)); }),
           py::arg("vertices"), py::arg("faces") = py::none(), py::arg("normals") = py::none(), py::arg("uvs") = py::none(),
           py::arg("colors") = py::none())
      .def_static("from_file", &meshFromFile, py::arg("path"), py::arg("up") = py::none(),
                  R"(A mesh file read as a model rendered alone reads it: stood up by up ("y" or "z"; None: the
format's usual axis, y for glTF and OBJ, z for PLY and STL), a glTF's base colours as vertex colours,
in the file's coordinates (the pose it is added with places it). SceneError naming the file and its
line for a bad file.)")
      .def_property_readonly("vertex_count", &TriangleMesh::vertexCount)
      .def_property_readonly("triangle_count", &TriangleMesh::triangleCount)
      .def("__repr__", [](const TriangleMesh& mesh) {
        return "<phongvk.Mesh: " + std::to_string(mesh.vertexCount()) + " vertices, " +
               std::to_string(mesh.triangleCount()) + " triangles>";
      });

  py::class_<Scene>(m, "Scene", R"(A validated scene: camera, lights, materials, objects.

Made by Scene(width, height) (an empty scene to build in code: the default Camera at that size,
one white light at the camera, no objects yet), load_scene(path) or scene_from_dict(d); meshes are
added as numpy arrays with add() or add_mesh(). A scene file with an "animate" block is frame 0 of
its sequence; frame(i) gives the others.)")
      .def(py::init<int, int>(), py::arg("width"), py::arg("height"),
           "An empty scene rendered at width x height pixels (1..16384 each); SceneError for a size out of range.")
      .def_property_readonly("path", &Scene::path, "The file the scene came from ('' for one made in code or from a dict).")
      .def_property_readonly("width", &Scene::width, "Width in pixels of the image the scene's camera renders.")
      .def_property_readonly("height", &Scene::height, "Height in pixels of the image the scene's camera renders.")
      .def_property_readonly("object_count", &Scene::objectCount, "How many objects the scene has.")
      .def_property_readonly("light_count", &Scene::lightCount, "How many lights the scene has.")
      .def_property_readonly("frame_count", &Scene::frameCount,
                             "Frames of the scene's animation (1 for a scene without an \"animate\" block).")
      .def("frame", &Scene::frame, py::arg("index"),
           "Frame `index` of the scene's animation, validated like a scene file (IndexError when out of range).")
      .def("with_render", &withRender, py::arg("settings") = py::none(),
           R"(The same scene rendered with other settings: a phongvk.RenderSettings, or the scene's own
with some replaced, by a dict or by keywords: with_render(shading="phong", samples=4). The keys are
RenderSettings' (shading, specular, interpolation, samples, background). Checked like a scene file's
"render"; a bad value raises SceneError naming render.KEY.)")
      .def_property("render_settings", &Scene::renderSettings, &Scene::setRenderSettings,
                    "The render settings (a phongvk.RenderSettings); assigning some checks them like a scene "
                    "file's \"render\" and \"background\".")
      .def("add_mesh", &addMesh, py::arg("vertices"), py::arg("faces") = py::none(), py::arg("normals") = py::none(),
           py::arg("material") = py::none(), py::arg("closed") = false, py::arg("uvs") = py::none(),
           py::arg("colors") = py::none(), py::arg("object_id") = py::none(),
           R"(Adds a triangle mesh object; it follows the scene into its other frames (frame(i)).

vertices: (N, 3) floating-point array of world positions (or rows of 3 numbers), or, with
    faces left out, a phongvk.Mesh (built once, shared by every object that adds it) or one mesh
    object with .vertices and .faces arrays (a trimesh.Trimesh works without phongvk importing
    trimesh).
faces: (M, 3) integer array of vertex indices (or rows of 3 integers), counter-clockwise seen
    from outside.
normals: optional (N, 3) floating-point array of vertex normals; computed from the faces
    (area-weighted) when not given.
material: None (the scene's default material: Material() in a Scene(width, height), the file's
    default in a scene from a file or dict), a phongvk.Material, a dict of its fields ({"ks": 0.2,
    "color": [1, 0, 0]}), or the name of one of the scene's materials; checked like a scene file's.
closed: True if the mesh is a closed surface whose back faces may be culled.
uvs: optional (N, 2) array of texture coordinates, (0, 0) the texture's top-left corner and
    (1, 1) its bottom-right: what the material's texture (Material(texture=...)) is sampled with.
colors: optional (N, 3) or (N, 4) vertex colours, integers 0..255 (uint8) or floats 0..1, that
    multiply the material's colour (alpha is kept, not drawn). A trimesh-like object brings its
    own: visual.vertex_colors where visual.kind is "vertex", visual.uv (v flipped: trimesh's v
    runs up) and, with no material given, visual.material's image as the texture.
object_id: the object's number in the object_id output (0..2^31-1, shared by several objects
    if wanted); by default the next of the scene's ids, kept for the scene's life.

A wrong shape or dtype, a non-finite value or an index out of range raises ValueError naming the
argument and the first bad row; a bad material raises SceneError.)")
      .def("add", &addObject, py::arg("mesh"), py::arg("faces") = py::none(), py::kw_only(),
           py::arg("pose") = py::none(), py::arg("material") = py::none(), py::arg("closed") = false,
           py::arg("normals") = py::none(), py::arg("uvs") = py::none(), py::arg("colors") = py::none(),
           py::arg("object_id") = py::none(),
           R"(Adds a mesh placed by a (4, 4) local-to-world pose (identity when None) and returns its
handle, for set_pose, set_mesh, object_id and remove. mesh: a phongvk.Mesh (built once: placing it
many times builds and holds it once), one object with .vertices and .faces arrays (a
trimesh.Trimesh works, with its vertex colours, uvs and texture), or vertices with faces;
material, closed, normals, uvs, colors and object_id as in add_mesh.)")
      .def(
          "set_pose", [](Scene& s, unsigned long long id, const py::object& pose) { s.setPose(ObjectId{id}, matrix4(pose, "pose")); },
          py::arg("object"), py::arg("pose"),
          "Moves an object added with add(). IndexError for a handle this scene does not hold: one removed, or "
          "one another scene gave (handles are unique to the scene that gave them).")
      .def(
          "set_mesh",
          [](Scene& s, unsigned long long id, const py::object& mesh, const py::object& faces, const py::object& normals,
             const py::object& uvs, const py::object& colors) {
            s.setMesh(ObjectId{id}, meshOf(mesh, faces, normals, uvs, colors));
          },
          py::arg("object"), py::arg("mesh"), py::arg("faces") = py::none(), py::kw_only(), py::arg("normals") = py::none(),
          py::arg("uvs") = py::none(), py::arg("colors") = py::none(),
          "Replaces an added object's geometry (what add() takes as mesh) in place: its handle, object_id, pose, "
          "material and closed stay.")
      .def(
          "object_id", [](const Scene& s, unsigned long long id) { return s.objectId(ObjectId{id}); }, py::arg("object"),
          "The number an object added with add() has in the object_id output: stable for the scene's life, "
          "whatever is removed or added after it.")
      .def(
          "set_object_id", [](Scene& s, unsigned long long id, int32_t value) { s.setObjectId(ObjectId{id}, value); },
          py::arg("object"), py::arg("object_id"),
          "Gives an added object your own number in the object_id output (0..2^31-1; objects may share one).")
      .def(
          "add_light", [](Scene& s, const Light& light) { return s.addLight(light).value; }, py::arg("light"),
          "Adds a light (a phongvk.Light, checked like a scene file's) after the scene's lights and returns its "
          "handle, for light, set_light and remove. It follows the scene into its other frames.")
      .def(
          "light", [](const Scene& s, unsigned long long id) { return s.light(LightId{id}); }, py::arg("light"),
          "The light a handle from add_light names (IndexError for one this scene does not hold).")
      .def(
          "set_light", [](Scene& s, unsigned long long id, const Light& light) { s.setLight(LightId{id}, light); },
          py::arg("light"), py::arg("value"), "Replaces the light a handle from add_light names.")
      .def(
          "_set_light_at", [](Scene& s, size_t index, const Light& light) { s.setLightAt(index, light); },
          py::arg("index"), py::arg("value"), "The light at `index` of lights replaced, its handle kept.")
      .def(
          "remove",
          [](Scene& s, unsigned long long id) {
            if (isLightHandle(id)) return s.removeLight(LightId{id});
            s.remove(ObjectId{id});
          },
          py::arg("handle"),
          "Takes out an object added with add() or a light added with add_light() (IndexError for a handle this "
          "scene does not hold, as set_pose).")
      .def_property_readonly("bounds", &Scene::bounds,
                             "The world box around every object's vertices, as built: (min, max), each (x, y, z). "
                             "Builds the meshes to know; SceneError first for a scene beyond the memory limit, as rendering it.")
      .def(
          "triangles",
          [](const Scene& s) {
            SceneTriangles t = s.triangles();
            const py::ssize_t vertices = py::ssize_t(t.mesh.positions.size() / 3), faces = py::ssize_t(t.objects.size());
            py::dict out;
            out["vertices"] = ownedArray(std::move(t.mesh.positions), {vertices, 3});
            out["normals"] = ownedArray(std::move(t.mesh.normals), {vertices, 3});
            out["faces"] = ownedArray(std::move(t.mesh.triangles), {faces, 3});
            out["objects"] = ownedArray(std::move(t.objects), {faces});
            return out;
          },
          "Every triangle as both renderers draw it (shapes tessellated, meshes subdivided, transforms and "
          "poses applied), in world coordinates: a dict of numpy arrays, vertices (N, 3) float32, normals "
          "(N, 3) float32 (unit), faces (M, 3) int64 (vertex indices) and objects (M,) int32 (each "
          "triangle's object, its index in the scene's objects). For drawing the same geometry with another "
          "renderer, or exporting it. Builds the meshes, as bounds does; SceneError for a scene whose meshes, "
          "or the arrays of them, need more than the memory limit.")
      .def_property("camera", &Scene::camera, &Scene::setCamera,
                    "The camera (a phongvk.Camera); assigning one checks it like a scene file's \"camera\".")
      .def_property("lights", &Scene::lights, &Scene::setLights,
                    "The lights (phongvk.Light); assigning a list checks it like a scene file's \"lights\".")
      .def_property("ambient", &Scene::ambient, &Scene::setAmbient,
                    "The ambient light, RGB (default white); assigning one checks it like a scene file's "
                    "\"ambient\".")
      .def("to_json", &Scene::toJson,
           R"(The scene as scene file JSON text (str): scene_from_dict(json.loads(text)) or load_scene
of the text saved gives a scene that renders the same bytes, and whose to_json() is this text again.
Every value is written: the camera, lights, materials (named ones by name, every other inline),
each object's parameters, scale and rotation (as {"matrix": rows}), mesh files by absolute path,
meshes added with add() or add_mesh() inline as "vertices", "faces" and "normals" at their poses,
and the render settings. An animated scene writes this frame, without its "animate" block.)")
      .def(
          "to_dict", [](const Scene& s) { return py::module_::import("json").attr("loads")(s.toJson()); },
          R"(The scene as a dict with the scene file's schema (to_json() read by json.loads):
phongvk.scene_from_dict(scene.to_dict()) renders the same bytes.)")
      .def("__repr__", [](const Scene& s) {
        return "<phongvk.Scene " + (s.path().empty() ? std::string("(no file)") : s.path()) + ": " +
               std::to_string(s.objectCount()) + " objects, " + std::to_string(s.lightCount()) + " lights, " +
               std::to_string(s.width()) + "x" + std::to_string(s.height()) + ">";
      });

  m.def(
      "load_scene",
      [](const FsPath& path, std::optional<std::string> up, std::optional<std::string> projection) {
        return loadScene(path.text, LoadOptions{up ? parseModelUp(*up) : ModelUp::Usual,
                                           projection ? std::optional<bool>(parseOrthographic(*projection)) : std::nullopt});
      },
      py::arg("path"), py::arg("up") = py::none(), py::arg("projection") = py::none(),
      R"(Reads and validates a scene file (the CLI's schema), or a model file (.obj .ply .stl .gltf
.glb) as a scene of its own: the model in full view, lit from the camera. Raises SceneError naming
the file and the JSON path.

up: None, "y" or "z": the up axis of a model file loaded alone, for one whose exporter used the
    other convention (None: its format's usual one, y for glTF and OBJ, z for PLY and STL).
projection: None, "perspective" or "orthographic": the fitted camera of a model file loaded alone
    (None: perspective); a scene file's camera says its own, and either given with one is an
    error.)");
  m.def("scene_from_dict", &sceneFromDict, py::arg("d"), py::arg("base_dir") = py::none(),
        R"(A scene from a dict with the scene file's schema, validated the same way.

Relative mesh paths resolve against base_dir (the working directory when None). The dict may have
no objects yet ("objects": []) and get them from add() or add_mesh(); rendering a scene without
objects raises SceneError. A scene built in code needs no dict: Scene(width, height).)");

  py::class_<Renderer>(m, "Renderer", R"(Renders scenes on one backend.

backend: "gpu" (the Vulkan compute port, default), "cpu" (the reference) or "graphics" (the Vulkan
    graphics-pipeline baseline). "gpu" and "cpu" give the same bytes; pick by speed. On a
    machine with a GPU, "gpu". On a CPU-only machine (lavapipe), "cpu" is about as fast for
    small models (a 1,280-triangle sphere at 640x480 from a Python loop: 2.4-3.0 ms a frame
    against 2.5-2.6 in two runs) and quicker for single stills (a cold process 0.12-0.14 s
    against 0.26-0.28), "gpu" for many triangles or large images (1.3M triangles at 1920x1080:
    79-89 ms against 259-287; the paper's scenes at 1385x923: 7-10 ms against 18-38);
    bench/peers.py measures it on the machine at hand.
device: a Vulkan device index (see devices()); None for the best usable one.
validate: turn the Vulkan validation layers on.

A renderer keeps what it uploaded: rendering a scene with the same geometry as the last one (another
camera, size, lights or materials, another frame of an orbit) builds and uploads no mesh again
(stats["scene_builds"] counts the builds). The GIL is released while rendering, so renderers in
other threads go on; one renderer used from several threads renders one frame at a time.)")
      .def(py::init([](const std::string& backend, std::optional<int> device, bool validate) {
             return std::make_unique<Renderer>(rendererOptions(backend, device, validate));
           }),
           py::arg("backend") = "gpu", py::arg("device") = py::none(), py::arg("validate") = false)
      .def("__repr__",
           [](const Renderer& r) {
             return "<phongvk.Renderer " + std::string(backendName(r.backend())) + " on " + r.deviceName() + ">";
           })
      .def(
          "render",
          [](Renderer& r, const Scene& scene, std::optional<int> width, std::optional<int> height) {
            return imageArray(released(r, scene, width, height, &Renderer::render));
          },
          py::arg("scene"), py::arg("width") = py::none(), py::arg("height") = py::none(),
          "One frame of `scene` as a C-contiguous uint8 array of shape (height, width, 3), row 0 at the top.")
      .def(
          "render_outputs",
          [](Renderer& r, const Scene& scene, const std::vector<std::string>& names, std::optional<int> width,
             std::optional<int> height) {
            return outputsDict(renderedFrame(r, scene, width, height, outputsNamed(names)), names);
          },
          py::arg("scene"), py::arg("outputs"), py::arg("width") = py::none(), py::arg("height") = py::none(),
          "render(scene, outputs=...) without the package's Image view: a dict of arrays by name.")
      .def(
          "render_visibility",
          [](Renderer& r, const Scene& scene, std::optional<int> width, std::optional<int> height) {
            RenderedFrame frame = renderedFrame(r, scene, width, height, Outputs{.depth = true, .triangleIds = true});
            const py::ssize_t h = frame.image.height, w = frame.image.width;
            std::vector<uint32_t> triangle(frame.triangleIds.size());
            std::memcpy(triangle.data(), frame.triangleIds.data(), triangle.size() * sizeof(uint32_t));  // -1: NO_TRIANGLE
            return py::make_tuple(imageArray(std::move(frame.image)), ownedArray(std::move(triangle), {h, w}),
                                  ownedArray(std::move(frame.depth), {h, w}));
          },
          py::arg("scene"), py::arg("width") = py::none(), py::arg("height") = py::none(),
          R"(One frame with its visibility buffer: (image, triangle, depth).

triangle: (height, width) uint32 array, the winning triangle's index in the scene (objects in order,
    each object's triangles in order), NO_TRIANGLE where nothing covers the pixel.
depth: (height, width) float32 array, the winning fragment's depth along the camera's axis in
    metres, inf where nothing covers it.
With samples per pixel, both are the pixel's nearest sample's. The gpu and cpu backends give the
same buffers; the graphics backend has none (ValueError).)")
      .def(
          "diff",
          [](Renderer& r, const Scene& scene) {
            DiffResult result;
            {
              py::gil_scoped_release release;
              result = diff(scene, r);
            }
            return diffDict(result);
          },
          py::arg("scene"),
          "`scene` rendered by the reference and by this renderer, compared as phongvk.diff() does (a dict "
          "with the numbers `phongvk diff` prints and its text as \"report\").")
      .def_property_readonly("backend", [](const Renderer& r) { return backendName(r.backend()); },
                             "The backend's name.")
      .def("close", &Renderer::close,
           "Frees the renderer's device, buffers and pipelines now (also at the end of a `with` block); "
           "calls after it raise ArgumentError.")
      .def_property_readonly("device_name", &Renderer::deviceName,
                             "The Vulkan device's name, or 'cpu (reference)'.")
      .def_property_readonly("stats", [](const Renderer& r) { return statsDict(r.stats()); },
                             "What the renderer has done: scene_builds, frames_rendered, frames_shaded, "
                             "frames_repeated, triangles, build_ms, texture_bytes (the last scene's textures), device_bytes "
                             "(device memory the renderer's buffers hold; 0 for the reference), validation_messages; and where its "
                             "start-up went (Vulkan backends; 0 for the reference): startup_vulkan_ms "
                             "(instance and device), startup_probe_ms (the float probe; 0 when cached), "
                             "startup_pipelines_ms, first_frame_ms (the first frame on the device: on "
                             "lavapipe with an empty Mesa shader cache, mostly code generation); notice "
                             "(a sentence on what a user may not expect of the last scene's picture, such as "
                             "a fitted camera that sees only the back of every triangle; empty when none).")
      .def_property_readonly("notice", [](const Renderer& r) { return r.stats().notice; },
                             "stats['notice'] alone: Renderer.render warns with it (phongvk.NoticeWarning).");

  m.def(
      "diff",
      [](const Scene& scene, std::optional<int> device) {
        DiffResult result;
        {
          py::gil_scoped_release release;
          result = diff(scene, rendererOptions("gpu", device, false));
        }
        return diffDict(result);
      },
      py::arg("scene"), py::arg("device") = py::none(),
      R"(Renders `scene` with the reference and the compute port and compares them, pixel by pixel and key
by key: the numbers `phongvk diff` prints, as a dict (width, height, pixels, differing, max_abs,
mean_abs, psnr, triangle_mismatch, identical_fraction, device), and its text as "report".)");

  m.def("write_png", [](const FsPath& path, const py::array& image, int level) {
    const PngImage pixels = pngImageFromArray(image, "image");
    const py::gil_scoped_release release;
    std::visit([&](const auto& any) { writePng(path.text, any, level); }, pixels);
  }, py::arg("path"), py::arg("image"), py::arg("level") = PNG_LEVEL_DEFAULT,
        "Writes an image array as a PNG, atomically (no partial file): (height, width, 3) uint8 as RGB, "
        "(height, width, 4) uint8 as RGBA, (height, width) uint16 as 16-bit grey (a depth in millimetres, ids), "
        "(height, width) uint8 as 8-bit grey and bool as 0 and 255 (a mask). path: str or os.PathLike. "
        "level: deflate level, 0 (stored) to 12 (smallest); the same pixels at every level. Raises OutputError, "
        "or ValueError for another array or a level out of range.");
  m.def("read_png", &pngArray, py::arg("path"), py::arg("mode") = "rgb",
        "Reads a PNG as mode says: \"rgb\" a (height, width, 3) uint8 array, \"rgba\" (height, width, 4) "
        "uint8 (alpha 255 where the file has none), \"grey16\" (height, width) uint16 (a depth PNG's "
        "millimetres, an ids PNG's index + 1; 8-bit samples scaled by 257).");
  m.def("encode_png", [](const py::array& image, int level) {
    const std::vector<uint8_t> png = encodedPng(pngImageFromArray(image, "image"), level, "image");
    return py::bytes(reinterpret_cast<const char*>(png.data()), png.size());
  }, py::arg("image"), py::arg("level") = PNG_LEVEL_DEFAULT,
        "An image array as PNG bytes, deflated at `level` (0 to 12): (height, width, 3) uint8 as RGB, "
        "(height, width, 4) uint8 as RGBA, (height, width) uint16 as 16-bit grey, (height, width) uint8 or bool (0 and 255) as 8-bit grey.");
  m.attr("PNG_LEVEL_DEFAULT") = PNG_LEVEL_DEFAULT;
  m.def("devices", [] {
    py::list list;
    for (const DeviceInfo& info : listDevices()) list.append(deviceDict(info));
    return list;
  }, "The Vulkan devices, each a dict: index, name, type, api_version, usable, missing (what it lacks).");
  m.attr("NO_TRIANGLE") = NO_TRIANGLE;
}
