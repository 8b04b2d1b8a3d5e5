// bindings.h — what the Python module's files share (module.cpp registers them): the type
// casters for paths and three numbers, the array, mesh, material and rendering helpers, and one
// binding function per class. Internal to python/.
#pragma once

#include <phongvk/phongvk.h>

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

// What the PNG coder takes from Python: an (H, W, 3) or (H, W, 4) uint8 array (RGB, RGBA) or an
// (H, W) uint16 array (16-bit grey), copied.
using PngImage = std::variant<Image, ImageRGBA, ImageGrey16, ImageGrey8>;

constexpr const char* PNG_ARRAYS = "a uint8 array of shape (height, width, 3) or (height, width, 4), or a uint16 array "
                                   "of shape (height, width)";

// write_png and encode_png take grey masks too.
constexpr const char* PNG_WRITE_ARRAYS = "a uint8 array of shape (height, width, 3) or (height, width, 4), or a uint8, "
                                         "uint16 or bool array of shape (height, width)";

py::array_t<uint8_t> imageArray(Image&& image);

// read_png: the file's pixels in the form `mode` names.
py::array pngArray(const FsPath& file, const std::string& mode);

// MemoryError with `message`, which names the argument that found no memory.
[[noreturn]] void raiseMemoryError(const std::string& message);

std::string shapeText(const py::array& a);

std::string typeName(const py::handle& value);

// `value` as a numpy array of numbers (integers or floating point) for the argument `name`, whose
// form `expected` describes: an array as it is, anything else (nested lists or tuples, an
// array-like) through numpy.asarray. ValueError naming `name` for anything else: ragged rows,
// strings, objects, a dict, booleans, complex numbers (a cast would drop their imaginary part).
py::array numberArray(const py::handle& value, const char* name, const std::string& expected);

// A 2-D uint8 or bool array (bool as 0 and 255): an 8-bit grey image; else nothing.
std::optional<ImageGrey8> grey8FromArray(const py::array& array, const char* name);

// ValueError naming `name` for an array that is not an image PNG_ARRAYS describes, or is empty.
void checkPngArray(const py::array& array, const char* name, const char* expected = PNG_ARRAYS);

// `array`, the argument `name`, as the image it holds (ValueError where checkPngArray refuses it).
PngImage pngImageFromArray(const py::array& array, const char* name);

// The PNG of `pixels` (the argument `name`) at `level`, encoded without the GIL; MemoryError naming
// the argument where its encoding finds no memory.
std::vector<uint8_t> encodedPng(const PngImage& pixels, int level, const char* name);

Scene sceneFromDict(const py::dict& d, std::optional<std::string> baseDir);

// `value` (the argument `name`) as rows of 3 numbers: an array as it is (rowsOf3 checks its dtype),
// anything else (nested lists or tuples, an array-like) as float64 where `floats`.
py::array asArray(const py::handle& value, const char* name, bool floats);

// Texture coordinates: an (N, 2) array (or rows of 2 numbers), as floats, flattened.
std::vector<float> uvRows(const py::object& uvs);

// Vertex colours: an (N, 3) or (N, 4) array, of integers 0..255 (uint8, say) or of floats 0..1
// (rounded to the nearest of 256 steps), as RGBA8 rows (alpha 255 where not given). ValueError
// naming "colors" and the first bad row.
std::vector<uint8_t> colorRows(const py::object& colors, py::ssize_t vertices);

// A trimesh-like object's vertex colours and texture coordinates, where its `visual` has them:
// visual.kind "vertex" with visual.vertex_colors, or visual.uv (trimesh's v runs up from the
// bottom; phongvk's from the top, so v becomes 1 - v).
void visualArrays(const py::object& object, MeshArrays& mesh, bool uvsGiven, bool colorsGiven);

// The arrays of a mesh: vertices with faces, lines (N, 2) and points (N,) where given (vertices
// alone: a point cloud), or (faces None and vertices no array) one object with .vertices and .faces
// arrays (a trimesh.Trimesh, say, whose visual's vertex colours and uvs come too); texture
// coordinates and vertex colours if given.
MeshArrays meshArrays(const py::object& vertices, const py::object& faces, const py::object& normals,
                      const py::object& uvs = py::none(), const py::object& colors = py::none(),
                      const py::object& lines = py::none(), const py::object& points = py::none());

// A (4, 4) array (or rows of 4 numbers) as a row-major Matrix4; None is the identity.
Matrix4 matrix4(const py::object& value, const char* name);

PoseConvention convention(const std::string& name);

std::string floatText(double x);

std::string vec3Text(const Vec3& v);

// ", fov=60.0", ", ortho_height=2.0" for an orthographic camera, or ", intrinsics=(fx, fy, cx, cy)"
// for a camera that has them.
std::string fieldOfViewText(const Camera& c);

// `fields` (a dict or kwargs: attribute names to values) set on `value`, a phongvk.Material or
// RenderSettings, as its keyword constructor sets them; SceneError "<what>: unknown key 'x'
// (allowed: ...)" for a name it does not have, as a scene file's section says it.
void setFields(py::object& value, const py::dict& fields, const std::string& what);

// The texels of an image array textureOfArray has checked, row by row from its strides.
Texture texelsOfArray(const py::array& array, const char* name);

// An image array ((height, width, 3 or 4) uint8, or (height, width) uint16 grey: PNG_ARRAYS) as a
// texture held in memory: its texels written row by row straight from the array, whatever its
// strides, without a copy of the array or a PNG of it. RGB gets alpha 255, grey is replicated and
// 16-bit samples keep their high byte, as a PNG of the array decodes. Its size is checked against
// what a texture may be before anything is allocated.
Texture textureOfArray(const py::array& array, const char* name);

std::string textureRepr(const Texture& texture);

// Sets a material's texture from what Material.texture takes: None for none, a path (text or
// os.PathLike) for a file, a phongvk.Texture as it is, an image array as a Texture of its pixels.
void setTexture(Material& material, const py::object& texture);

// A material given to add or add_mesh: a phongvk.Material, a dict of its fields, or None (the
// scene's default material).
std::optional<Material> materialOf(const py::object& material);

// What add and add_mesh place: a phongvk.Mesh as it is (shared, built once), or arrays built now.
TriangleMesh meshOf(const py::object& vertices, const py::object& faces, const py::object& normals,
                    const py::object& uvs = py::none(), const py::object& colors = py::none());

// A trimesh-like object's texture image (visual.material.image, or a PBR material's
// baseColorTexture: a PIL image or an array), as the material of an object added without one.
std::optional<Material> visualMaterial(const py::object& object);

// Adds `mesh` at `pose`; `object` is what the caller gave (a trimesh-like object's texture serves
// when no material is given), `objectId` the object_id output's number if given.
unsigned long long addPlaced(Scene& scene, const TriangleMesh& mesh, const py::object& object, const Matrix4& pose,
                             const py::object& material, bool closed, std::optional<int32_t> objectId);

void addMesh(Scene& scene, const py::object& vertices, const py::object& faces, const py::object& normals,
             const py::object& material, bool closed, const py::object& uvs, const py::object& colors,
             std::optional<int32_t> objectId);

unsigned long long addObject(Scene& scene, const py::object& object, const py::object& faces, const py::object& pose,
                             const py::object& material, bool closed, const py::object& normals, const py::object& uvs,
                             const py::object& colors, std::optional<int32_t> objectId);

// A handle as the scene's object or light handle it is (Scene.remove takes either).
bool isLightHandle(unsigned long long handle);

TriangleMesh meshFromFile(const FsPath& path, const std::optional<std::string>& up);

// `scene` with_render(settings, **options): `settings` (a phongvk.RenderSettings, a dict of its
// fields, or None for the scene's own), then the options over it.
Scene withRender(const Scene& scene, const py::object& settings, const py::kwargs& options);

// The scene at width x height when both are given, else as its camera says.
Scene sized(const Scene& scene, std::optional<int> width, std::optional<int> height);

// One frame of `scene` at the asked size with `outputs`, the GIL released meanwhile.
RenderedFrame renderedFrame(Renderer& renderer, const Scene& scene, std::optional<int> width, std::optional<int> height,
                            const Outputs& outputs);

// The output names render(outputs=...) takes, as the library's Outputs. Each name once: the dict
// has one array a name, and outputsDict moves each output out of the frame once.
Outputs outputsNamed(const std::vector<std::string>& names);

// The frame's outputs by name: color (height, width, 3) and rgba (height, width, 4) uint8, alpha
// uint8, depth float32, object_id and triangle_id int32, each (height, width), and normal
// (height, width, 3) float32.
py::dict outputsDict(RenderedFrame&& frame, const std::vector<std::string>& names);

py::dict statsDict(const RendererStats& s);

py::dict diffDict(const DiffResult& r);

py::dict deviceDict(const DeviceInfo& info);

RendererOptions rendererOptions(const std::string& backend, std::optional<int> device, bool validate);

// A vector's bytes as an array of `shape` that owns them (no copy).
template <typename T>
py::array_t<T> ownedArray(std::vector<T>&& values, std::vector<py::ssize_t> shape) {
  auto* owned = new std::vector<T>(std::move(values));
  py::capsule owner(owned, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  return py::array_t<T>(shape, owned->data(), owner);
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

// `call` (a Renderer method) on `scene` at the asked size, with the GIL released meanwhile.
template <typename Result>
Result released(Renderer& renderer, const Scene& scene, std::optional<int> width, std::optional<int> height,
                Result (Renderer::*call)(const Scene&)) {
  const Scene s = sized(scene, width, height);
  py::gil_scoped_release release;
  return (renderer.*call)(s);
}

// The bindings, one a class (bind_*.cpp), in the order module.cpp registers them.
void bindCamera(py::module_& m);
void bindLight(py::module_& m);
void bindTexture(py::module_& m);
void bindMaterial(py::module_& m);
void bindRenderSettings(py::module_& m);
void bindMesh(py::module_& m);
void bindScene(py::module_& m);
void bindRenderer(py::module_& m);
void bindPng(py::module_& m);

}  // namespace phongvk::python
