// meshes.cpp — scenes from dicts, meshes from arrays and trimesh-like objects, poses, and value texts (see bindings.h).
#include "bindings.h"
#include "json_writer.h"

namespace phongvk::python {

Scene sceneFromDict(const py::dict& d, std::optional<std::string> baseDir) {
  const std::string json = JsonWriter("").write(d);
  return parseScene(json, "", baseDir.value_or("."), true);
}

py::array asArray(const py::handle& value, const char* name, bool floats) {
  const py::array a = numberArray(value, name, "an array of shape (N, 3) or rows of 3 numbers");
  if (!floats || py::isinstance<py::array>(value)) return a;
  return a.attr("astype")("float64");
}

std::vector<float> uvRows(const py::object& uvs) {
  const py::array a = numberArray(uvs, "uvs", "an array of shape (N, 2) or rows of 2 numbers");
  if (a.ndim() != 2 || a.shape(1) != 2) throw py::value_error("uvs: expected shape (N, 2), got " + shapeText(a));
  return valuesOf<float>(a, "uvs");
}

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

// Lines (N, 2) or points (N,) (columns 1): integer vertex indices, flattened.
std::vector<int64_t> indexRows(const py::object& value, const char* name, py::ssize_t columns) {
  const std::string shape = columns == 1 ? "(N,)" : "(N, " + std::to_string(columns) + ")";
  const py::array a = numberArray(value, name, ("an integer array of shape " + shape).c_str());
  const char kind = a.dtype().kind();
  if (kind != 'i' && kind != 'u') {
    throw py::value_error(std::string(name) + ": expected an integer array of shape " + shape + ", got dtype " +
                          std::string(py::str(a.dtype())));
  }
  if (columns == 1 ? a.ndim() != 1 : (a.ndim() != 2 || a.shape(1) != columns)) {
    throw py::value_error(std::string(name) + ": expected shape " + shape + ", got " + shapeText(a));
  }
  return valuesOf<int64_t>(a, name);
}

// Whether `value` is one mesh object with .vertices and .faces (a trimesh.Trimesh), not arrays.
bool isMeshObject(const py::object& value) { return py::hasattr(value, "vertices") && py::hasattr(value, "faces"); }

MeshArrays meshArrays(const py::object& vertices, const py::object& faces, const py::object& normals,
                      const py::object& uvs, const py::object& colors, const py::object& lines, const py::object& points) {
  if (faces.is_none() && isMeshObject(vertices)) {
    MeshArrays mesh = meshArrays(vertices.attr("vertices"), vertices.attr("faces"), normals, uvs, colors);
    visualArrays(vertices, mesh, !uvs.is_none(), !colors.is_none());
    return mesh;
  }
  if (faces.is_none() && lines.is_none() && points.is_none() && !py::isinstance<py::array>(vertices) &&
      !py::isinstance<py::sequence>(vertices)) {
    throw py::type_error("add_mesh: expected vertices and faces, a phongvk.Mesh, or one object with .vertices "
                         "and .faces arrays (a trimesh.Trimesh, for one), got " +
                         std::string(py::str(py::type::of(vertices).attr("__name__"))));
  }
  const py::array vertexArray = asArray(vertices, "vertices", true);
  MeshArrays mesh;
  mesh.positions = rowsOf3<float>(vertexArray, "vertices", 'f');
  if (!faces.is_none()) mesh.triangles = rowsOf3<int64_t>(asArray(faces, "faces", false), "faces", 'i');
  if (!lines.is_none()) mesh.lines = indexRows(lines, "lines", 2);
  if (!points.is_none()) mesh.points = indexRows(points, "points", 1);
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

std::string fieldOfViewText(const Camera& c) {
  if (c.orthoHeight) return ", ortho_height=" + floatText(*c.orthoHeight);
  if (!c.intrinsics) return ", fov=" + floatText(c.fov);
  const Intrinsics& k = *c.intrinsics;
  return ", intrinsics=(" + floatText(k.fx) + ", " + floatText(k.fy) + ", " + floatText(k.cx) + ", " + floatText(k.cy) + ")";
}

}  // namespace phongvk::python
