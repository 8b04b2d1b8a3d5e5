// scene_objects.cpp — the scene file's "objects": each shape's keys, its geometry values and its
// material. Meshes are only checked for a readable file here; object_mesh.cpp builds them.
#include "scene/scene_sections.h"

#include "geometry/transform.h"
#include "meshio/mesh_file.h"
#include "scene/object_pose.h"
#include "scene/scene_checks.h"

#include <cmath>
#include <filesystem>
#include <limits>

namespace phongvk::scenejson {
namespace {

const Keys kObjectKeys = {"shape", "material", "subdivide", "closed", "scale", "rotate", "object_id",
                           "cast_shadows"};  // every shape

struct ShapeInfo {
  Shape shape;
  std::string_view name;
  Keys keys;  // on top of kObjectKeys
};

const std::vector<ShapeInfo> kShapes = {
    {Shape::Sphere, "sphere", {"center", "radius", "segments"}},
    {Shape::Cube, "cube", {"center", "size"}},
    {Shape::Cylinder, "cylinder", {"center", "radius", "height", "segments"}},
    {Shape::Cone, "cone", {"center", "radius", "height", "segments", "rings"}},
    {Shape::Icosphere, "icosphere", {"center", "radius"}},
    {Shape::Polyhedron, "polyhedron", {"points"}},
    {Shape::Mesh, "mesh", {"file", "vertices", "faces", "lines", "point_indices", "normals", "colors", "uvs", "textures",
                           "texture_ids", "translate", "up", "pose", "file_lights", "file_light_shadows", "point_size", "line_width"}},
};


const ShapeInfo& readShape(const Node& node) {
  std::string name = string(node);
  for (const ShapeInfo& info : kShapes) {
    if (info.name == name) return info;
  }
  std::string allowed;
  for (const ShapeInfo& info : kShapes) {
    allowed += (allowed.empty() ? "" : ", ") + std::string(info.name);
  }
  node.fail("unknown shape '" + name + "' (allowed: " + allowed + ")");
}

void checkObjectKeys(const Node& node, const ShapeInfo& info) {
  Keys allowed = kObjectKeys;
  allowed.insert(allowed.end(), info.keys.begin(), info.keys.end());
  Keys anyShape;
  for (const ShapeInfo& other : kShapes) {
    anyShape.insert(anyShape.end(), other.keys.begin(), other.keys.end());
  }
  checkKeys(node, allowed, anyShape, "not used by shape '" + std::string(info.name) + "'");
}

std::vector<glm::dvec3> readPoints(const Node& node) {
  requireArray(node);
  size_t count = node.json().size();
  if (count < 4) node.fail("needs at least 4 points, got " + std::to_string(count));
  std::vector<glm::dvec3> points;
  for (size_t i = 0; i < count; ++i) points.push_back(point(node.element(i)));
  return points;
}



// The file's path (resolved against baseDir) into `object.file`, its version, and the triangles it
// will build (mesh_file.h meshFileTriangles).
void resolveMeshFile(const Node& node, const std::string& baseDir, Object& object) {
  std::string file = string(node);
  if (file.empty()) node.fail("must name a file, got an empty string");
  // An absolute `file` replaces baseDir here.
  object.file = (std::filesystem::path(baseDir) / file).string();
  if (auto reason = unreadableReason(object.file)) node.fail("cannot read '" + file + "': " + *reason);
  const DetectedFormat format = detectMeshFormat(object.file);
  if (!format.format) node.fail(format.problem);
  object.fileVersion = fileVersion(object.file);
  object.fileTriangles = meshFileTriangles(object.file, *format.format, object.fileVersion.bytes);
}

// A mesh's "file", or its arrays inline ("vertices", "faces", and "normals", "colors", "uvs",
// "textures", "texture_ids" if any).
void readMeshSource(const Node& node, const std::string& baseDir, Object& object) {
  const std::optional<Node> file = node.find("file");
  if (!node.find("vertices")) {
    for (std::string_view key : {"faces", "lines", "point_indices", "normals", "colors", "uvs", "textures", "texture_ids"}) {
      if (node.find(key)) node.failAt(key, "needs 'vertices' (a mesh given inline)");
    }
    resolveMeshFile(node.require("file"), baseDir, object);
    if (auto lights = node.find("file_lights")) object.fileLights = boolean(*lights);
    if (auto shadows = node.find("file_light_shadows")) object.fileLightShadows = boolean(*shadows);
    if (object.fileLightShadows && !object.fileLights)
      node.failAt("file_light_shadows", "needs the file's lights, which \"file_lights\": false leaves out");
    return;
  }
  if (file) file->fail("cannot be given with 'vertices': a mesh is a file or arrays");
  for (std::string_view key : {"file_lights", "file_light_shadows"}) {
    if (node.find(key)) node.failAt(key, "needs 'file' (the lights of a mesh file)");
  }
  object.arrays = readMeshArrays(node, baseDir);
}

// Each geometry key means the same for every shape that takes it, and checkObjectKeys has
// already rejected the keys this shape does not take, so one reader serves all shapes.
void readGeometry(const Node& node, Object& object, const std::string& baseDir) {
  if (auto center = node.find("center")) object.center = point(*center);
  if (auto radius = node.find("radius")) object.radius = length(*radius);
  if (auto size = node.find("size")) object.size = length(*size);
  if (auto height = node.find("height")) object.height = length(*height);
  if (auto segments = node.find("segments")) object.segments = integer(*segments, 3, 4096);
  if (auto rings = node.find("rings")) object.rings = integer(*rings, 1, 4096);
  if (auto translate = node.find("translate")) object.translate = point(*translate);
  if (auto size = node.find("point_size")) object.pointSize = quadWidth(number(*size), size->where());
  if (auto width = node.find("line_width")) object.lineWidth = quadWidth(number(*width), width->where());
  if (object.shape == Shape::Polyhedron) object.points = readPoints(node.require("points"));
  if (object.shape == Shape::Mesh) readMeshSource(node, baseDir, object);
}

// A scale factor: non-zero (a negative one mirrors), within the coordinates a scene may use.
double scaleFactor(const Node& node) {
  const double s = inRange(node, -MAX_COORDINATE, MAX_COORDINATE);
  if (s == 0.0) node.fail("must not be 0");
  return s;
}

glm::dvec3 readScale(const Node& node) {
  if (node.json().is_number()) return glm::dvec3(length(node));
  return vec3(node, scaleFactor);
}

double angle(const Node& node) { return inRange(node, -1e6, 1e6); }

// {"matrix": [[a, b, c], [d, e, f], [g, h, i]]}: any invertible linear map, row-major, as a
// pose's upper 3x3 block (api/scene_parts.cpp placeObject) takes it.
glm::dmat3 readMatrix(const Node& node) {
  requireArray(node);
  if (node.json().size() != 3) node.fail("must be an array of 3 rows, got " + std::to_string(node.json().size()));
  glm::dmat3 m;
  for (int r = 0; r < 3; ++r) {
    const glm::dvec3 row = vec3(node.element(size_t(r)));
    for (int c = 0; c < 3; ++c) m[c][r] = row[c];  // glm: m[column][row]
  }
  const double det = glm::determinant(m);
  if (!(std::abs(det) > 0)) node.fail("must be invertible, got determinant " + formatNumber(det));
  return m;
}

// [x, y, z] degrees (about x first, then y, then z), {"axis": [x, y, z], "angle": degrees}, or
// {"matrix": rows}.
glm::dmat3 readRotation(const Node& node) {
  if (!node.json().is_object()) return rotationXYZ(vec3(node, angle));
  checkKeys(node, {"axis", "angle", "matrix"});
  if (const std::optional<Node> matrix = node.find("matrix")) {
    for (std::string_view key : {"axis", "angle"}) {
      if (node.find(key)) node.failAt(key, "cannot be given with 'matrix'");
    }
    return readMatrix(*matrix);
  }
  const Node axis = node.require("axis");
  return rotationAxisAngle(usableDirection(axis, vec3(axis)), angle(node.require("angle")));
}

UpAxis readUp(const Node& node) {
  const std::string up = string(node);
  if (up != "y" && up != "z") node.fail("must be \"y\" or \"z\", got '" + up + "'");
  return up == "y" ? UpAxis::Y : UpAxis::Z;
}

// A mesh's "pose": 4 rows of 4 numbers placing it as Scene::add does (object_pose.h), in place of
// "translate", "scale" and "rotate".
void readPose(const Node& node, Object& object) {
  const std::optional<Node> pose = node.find("pose");
  if (!pose) return;
  for (std::string_view key : {"translate", "scale", "rotate"}) {
    if (node.find(key)) node.failAt(key, "cannot be given with 'pose'");
  }
  requireArray(*pose);
  if (pose->json().size() != 4) pose->fail("must be 4 rows of 4 numbers, got " + std::to_string(pose->json().size()) + " rows");
  Matrix4 m{};
  for (size_t r = 0; r < 4; ++r) {
    const Node row = pose->element(r);
    requireArray(row);
    if (row.json().size() != 4) row.fail("must be 4 numbers, got " + std::to_string(row.json().size()));
    for (size_t c = 0; c < 4; ++c) m[4 * r + c] = number(row.element(c));
  }
  if (const std::string problem = poseProblem(m); !problem.empty()) pose->fail(problem);
  placeObject(object, m);
}

void readTransform(const Node& node, Object& object) {
  if (auto scale = node.find("scale")) object.scale = readScale(*scale);
  if (auto rotate = node.find("rotate")) object.rotation = readRotation(*rotate);
  if (auto up = node.find("up")) object.up = readUp(*up);
  readPose(node, object);
}

// A glTF file's base colours are its objects' colours unless the scene sets one: a named material,
// or an inline one with a "color". The object's material is then white, for them to multiply.
bool takesBaseColors(const Node& node, const Object& object) {
  if (object.shape != Shape::Mesh || object.arrays) return false;
  const MeshFormat format = meshFormat(object.file, object.jsonPath + ".file");
  if (format != MeshFormat::Gltf && format != MeshFormat::Glb) return false;
  const std::optional<Node> material = node.find("material");
  return !material || (material->json().is_object() && !material->find("color"));
}

int objectMaterial(const Node& node, const Object& object, MaterialTable& materials) {
  if (!object.baseColors) return materials.forObject(node.find("material"));
  const std::optional<Node> inline_ = node.find("material");
  MaterialSpec white = inline_ ? readMaterial(*inline_, materials.baseDir()) : MaterialSpec{};
  white.color = glm::vec3(1.0f);
  return materials.add(white);
}

Object readObject(const Node& node, const std::string& baseDir, MaterialTable& materials) {
  requireObject(node);
  const ShapeInfo& info = readShape(node.require("shape"));
  checkObjectKeys(node, info);
  Object object;
  object.shape = info.shape;
  object.jsonPath = node.path();
  object.closed = info.shape != Shape::Mesh;  // imported meshes are often open or mis-wound
  readGeometry(node, object, baseDir);
  readTransform(node, object);
  if (auto subdivide = node.find("subdivide")) object.subdivide = integer(*subdivide, 0, 10);
  if (auto closed = node.find("closed")) object.closed = boolean(*closed);
  if (auto casts = node.find("cast_shadows")) object.castShadows = boolean(*casts);
  if (auto label = node.find("object_id")) object.label = integer(*label, 0, std::numeric_limits<int32_t>::max());
  object.baseColors = takesBaseColors(node, object);
  object.material = objectMaterial(node, object, materials);
  return object;
}

}  // namespace

std::vector<Object> readObjects(const Node& node, const std::string& baseDir, MaterialTable& materials,
                                bool mayBeEmpty) {
  requireArray(node);
  if (node.json().empty() && !mayBeEmpty) node.fail("scene has no objects");
  std::vector<Object> objects;
  for (size_t i = 0; i < node.json().size(); ++i) {
    objects.push_back(readObject(node.element(i), baseDir, materials));
  }
  return objects;
}

}  // namespace phongvk::scenejson

namespace phongvk {

std::string_view shapeName(Shape shape) {
  for (const scenejson::ShapeInfo& info : scenejson::kShapes) {
    if (info.shape == shape) return info.name;
  }
  throw std::logic_error("shapeName: a shape without a name");
}

}  // namespace phongvk
