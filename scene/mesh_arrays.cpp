#include "scene/mesh_arrays.h"

#include "geometry/normals.h"
#include "scene/scene_json.h"
#include "scene/scene_sections.h"
#include "scene/scene_textures.h"

#include <cfloat>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace phongvk {
namespace {


[[noreturn]] void failRow(const char* array, size_t row, const std::string& what) {
  throw ArgumentError(std::string(array) + ": row " + std::to_string(row) + " " + what);
}

// Appended piece by piece: GCC 12 warns (-Wrestrict, a known false positive) on "[" + a + ...
std::string rowText(const std::vector<float>& xyz, size_t row) {
  std::string text = "[";
  text.append(formatNumber(xyz[3 * row])).append(", ").append(formatNumber(xyz[3 * row + 1]));
  return text.append(", ").append(formatNumber(xyz[3 * row + 2])).append("]");
}

// Texture coordinates: two a vertex, finite (a coordinate far outside [0, 1] wraps).
void checkUvs(const std::vector<float>& uvs, size_t vertices) {
  if (uvs.empty()) return;
  if (uvs.size() != 2 * vertices)
    throw ArgumentError("uvs: expected one row [u, v] per vertex (" + std::to_string(vertices) + "), got " +
                        std::to_string(uvs.size() / 2) + (uvs.size() % 2 ? " and a half" : ""));
  for (size_t i = 0; i < uvs.size(); ++i) {
    if (!std::isfinite(uvs[i])) failRow("uvs", i / 2, "is not finite");
  }
}

// Vertex colours: four bytes a vertex, or none.
void checkColors(const std::vector<uint8_t>& colors, size_t vertices) {
  if (!colors.empty() && colors.size() != 4 * vertices)
    throw ArgumentError("colors: expected one row [r, g, b, a] per vertex (" + std::to_string(vertices) + "), got " +
                        std::to_string(colors.size() / 4) + (colors.size() % 4 ? " and a part" : ""));
}

void checkCounts(const MeshArrays& a) {
  if (a.positions.size() % 3 != 0 || a.triangles.size() % 3 != 0 || a.normals.size() % 3 != 0) {
    throw ArgumentError("vertices, faces and normals hold 3 values a row");
  }
  if (a.lines.size() % 2 != 0) throw ArgumentError("lines hold 2 vertex indices a row");
  if (a.positions.empty()) throw ArgumentError("vertices: the mesh has no vertices");
  if (!a.normals.empty() && a.normals.size() != a.positions.size()) {
    throw ArgumentError("normals: expected one row per vertex (" + std::to_string(a.positions.size() / 3) +
                                "), got " + std::to_string(a.normals.size() / 3));
  }
}

// Finite, and within the coordinates a scene may use (scene.h MAX_COORDINATE).
void checkPositions(const std::vector<float>& p) {
  for (size_t i = 0; i < p.size(); ++i) {
    if (!std::isfinite(p[i])) failRow("vertices", i / 3, "is not finite: " + rowText(p, i / 3));
    if (std::abs(double(p[i])) > MAX_COORDINATE) {
      failRow("vertices", i / 3, "is beyond the " + formatNumber(MAX_COORDINATE) + " m a scene may use: " +
                                     rowText(p, i / 3));
    }
  }
}

// The indices of `array` (rows of `perRow`), each of the vertices.
void checkIndices(const char* array, const std::vector<int64_t>& t, size_t perRow, size_t vertices) {
  for (size_t i = 0; i < t.size(); ++i) {
    if (t[i] < 0 || uint64_t(t[i]) >= vertices) {
      failRow(array, i / perRow, "has index " + std::to_string(t[i]) + ", but there are " + std::to_string(vertices) +
                                     " vertices");
    }
  }
}

// A zero normal says "no normal" (docs/DESIGN.md "Points and lines": drawn unlit), which only a
// vertex that no face uses may have: a face's vertex needs a direction.
void checkZeroNormals(const MeshArrays& a, const Mesh& mesh) {
  if (mesh.normals.empty()) return;
  for (size_t k = 0; k < a.triangles.size(); ++k) {
    const size_t v = size_t(a.triangles[k]);
    if (mesh.normals[v] == glm::vec3(0.0f)) failRow("normals", v, "has no direction: " + rowText(a.normals, v));
  }
}

// The mesh's points and lines; with no faces, lines or points, every vertex a point.
void addPointsAndLines(const MeshArrays& a, Mesh& mesh) {
  for (int64_t p : a.points) mesh.points.push_back(uint32_t(p));
  for (size_t k = 0; k < a.lines.size(); k += 2) mesh.lines.push_back({uint32_t(a.lines[k]), uint32_t(a.lines[k + 1])});
  if (a.triangles.empty() && a.lines.empty() && a.points.empty()) {
    for (uint32_t v = 0; v < mesh.positions.size(); ++v) mesh.points.push_back(v);
  }
}

glm::dvec3 rowOf(const std::vector<float>& xyz, size_t row) { return {xyz[3 * row], xyz[3 * row + 1], xyz[3 * row + 2]}; }

// A normal of unit length as far as a float can say (as built meshes hold them, and as a scene
// written back gives them inline) is kept as given, so that such rows read back unchanged;
// any other is normalised.
glm::vec3 unitNormal(const glm::dvec3& n) {
  if (std::abs(glm::dot(n, n) - 1.0) <= 4.0 * double(FLT_EPSILON)) return glm::vec3(n);
  return glm::vec3(glm::normalize(n));
}

}  // namespace

Mesh meshFromArrays(const MeshArrays& a) {
  checkCounts(a);
  checkPositions(a.positions);
  const size_t vertices = a.positions.size() / 3;
  checkIndices("faces", a.triangles, 3, vertices);
  checkIndices("lines", a.lines, 2, vertices);
  checkIndices("points", a.points, 1, vertices);
  checkUvs(a.uvs, vertices);
  checkColors(a.colors, vertices);
  Mesh mesh;
  for (size_t v = 0; v < a.colors.size() / 4; ++v) {
    const uint8_t* c = &a.colors[4 * v];
    mesh.colors.push_back(uint32_t(c[0]) | uint32_t(c[1]) << 8 | uint32_t(c[2]) << 16 | uint32_t(c[3]) << 24);
  }
  for (size_t v = 0; v < a.uvs.size() / 2; ++v) mesh.uvs.push_back(glm::vec2(a.uvs[2 * v], a.uvs[2 * v + 1]));
  if (!mesh.uvs.empty()) mesh.textureIds.assign(vertices, gpu::TEXTURE_NONE);  // the material's texture
  for (size_t v = 0; v < vertices; ++v) mesh.positions.push_back(glm::vec3(rowOf(a.positions, v)));
  for (size_t v = 0; v < a.normals.size() / 3; ++v) {
    const glm::dvec3 n = rowOf(a.normals, v);
    if (!std::isfinite(glm::length(n))) failRow("normals", v, "has no direction: " + rowText(a.normals, v));
    mesh.normals.push_back(n == glm::dvec3(0.0) ? glm::vec3(0.0f) : unitNormal(n));  // zero: unlit, checked below
  }
  for (size_t k = 0; k < a.triangles.size(); k += 3) {
    const glm::uvec3 t(uint32_t(a.triangles[k]), uint32_t(a.triangles[k + 1]), uint32_t(a.triangles[k + 2]));
    const glm::dvec3 p0(mesh.positions[t.x]), p1(mesh.positions[t.y]), p2(mesh.positions[t.z]);
    if (glm::cross(p1 - p0, p2 - p0) == glm::dvec3(0.0)) continue;  // zero area: draws nothing, as from a file
    mesh.triangles.push_back(t);
  }
  checkZeroNormals(a, mesh);
  addPointsAndLines(a, mesh);
  if (mesh.triangles.empty() && mesh.lines.empty() && mesh.points.empty()) {
    throw ArgumentError("faces: every triangle is degenerate (zero area)");
  }
  if (mesh.normals.empty()) computeVertexNormals(mesh);
  return mesh;
}

void addMeshObject(SceneSpec& scene, std::shared_ptr<const Mesh> mesh, const scenejson::MaterialChoice& material,
                   bool closed) {
  Object object;
  object.shape = Shape::Mesh;
  object.jsonPath = "objects[" + std::to_string(scene.objects.size()) + "]";
  object.closed = closed;
  object.arrays = std::move(mesh);
  // The material may add an entry before it fails: taken back then, so the scene is as it was
  // (without a copy of the scene, which would make n adds take n^2 time).
  const size_t materials = scene.materials.size();
  const std::optional<int> defaultMaterial = scene.defaultMaterial;
  scenejson::MaterialTable table(scene, "");
  try {
    object.material = table.forObject(material, scenejson::Where(object.jsonPath + ".material", scene.path));
  } catch (...) {
    scene.materials.erase(scene.materials.begin() + ptrdiff_t(materials), scene.materials.end());
    scene.defaultMaterial = defaultMaterial;
    throw;
  }
  scene.objects.push_back(std::move(object));
}

namespace scenejson {
namespace {

// Rows of 3 numbers, each read by `element`, as one flat array of T, as MeshArrays holds them.
template <typename T>
std::vector<T> rowsOf3(const Node& node, ElementReader element) {
  requireArray(node);
  std::vector<T> values;
  values.reserve(3 * node.json().size());
  for (size_t i = 0; i < node.json().size(); ++i) {
    const glm::dvec3 row = vec3(node.element(i), element);
    values.insert(values.end(), {T(row.x), T(row.y), T(row.z)});
  }
  return values;
}

// Positions and normals: 32-bit floats.
std::vector<float> floatRows(const Node& node) { return rowsOf3<float>(node, floatComponent); }

// Rows of 2 numbers, each read by `element`, as one flat array of T; a row of another length
// fails with "must be <shape>, got <its length><unit>".
template <typename T>
std::vector<T> rowsOf2(const Node& node, ElementReader element, const char* shape, const char* unit) {
  requireArray(node);
  std::vector<T> values;
  values.reserve(2 * node.json().size());
  for (size_t i = 0; i < node.json().size(); ++i) {
    const Node row = node.element(i);
    requireArray(row);
    if (row.json().size() != 2) row.fail(std::string("must be ") + shape + ", got " + std::to_string(row.json().size()) + unit);
    for (size_t c = 0; c < 2; ++c) values.push_back(T(element(row.element(c))));
  }
  return values;
}

// Texture coordinates: rows [u, v] of 32-bit floats, flattened.
std::vector<float> uvRows(const Node& node) { return rowsOf2<float>(node, floatComponent, "[u, v]", " numbers"); }

double index(const Node& node) {
  return integer(node, std::numeric_limits<int>::min(), std::numeric_limits<int>::max());
}

// Faces: vertex indices (meshFromArrays checks their range).
std::vector<int64_t> indexRows(const Node& node) { return rowsOf3<int64_t>(node, index); }

// Lines: rows [a, b] of vertex indices, flattened.
std::vector<int64_t> pairRows(const Node& node) { return rowsOf2<int64_t>(node, index, "[a, b], two vertex indices", ""); }

// Points: vertex indices.
std::vector<int64_t> indexList(const Node& node) {
  requireArray(node);
  std::vector<int64_t> values;
  for (size_t i = 0; i < node.json().size(); ++i) values.push_back(int64_t(index(node.element(i))));
  return values;
}

// One [r, g, b, a] row of integers 0..255 per vertex, as RGBA8 (red in the low byte).
std::vector<uint32_t> colorRows(const Node& node, size_t vertices) {
  requireArray(node);
  if (node.json().size() != vertices) {
    node.fail("expected one row per vertex (" + std::to_string(vertices) + "), got " + std::to_string(node.json().size()));
  }
  std::vector<uint32_t> colors;
  for (size_t i = 0; i < vertices; ++i) {
    const Node row = node.element(i);
    requireArray(row);
    if (row.json().size() != 4) row.fail("must be [r, g, b, a], 4 integers 0..255, got " + std::to_string(row.json().size()) + " elements");
    uint32_t rgba = 0;
    for (size_t c = 0; c < 4; ++c) rgba |= uint32_t(integer(row.element(c), 0, 255)) << (8 * c);
    colors.push_back(rgba);
  }
  return colors;
}

const Keys kMeshTextureKeys = {"image", "wrap"};

// One of an inline mesh's own textures: {"image": a PNG or JPEG file or a data URI of one,
// "wrap": [u, v] (default ["repeat", "repeat"])}.
std::shared_ptr<const TextureImage> meshTexture(const Node& node, const std::string& baseDir) {
  requireObject(node);
  checkKeys(node, kMeshTextureKeys);
  const Node image = node.require("image");
  const std::string source = string(image);
  std::shared_ptr<const TextureImage> texture;
  try {
    texture = sceneTexture(source, baseDir);
  } catch (const SceneError& error) {
    image.fail(error.what());
  }
  const std::optional<Node> wrap = node.find("wrap");
  if (!wrap) return texture;
  requireArray(*wrap);
  if (wrap->json().size() != 2) wrap->fail("must be [u, v], two wrap modes, got " + std::to_string(wrap->json().size()));
  return withWrap(texture, choice<uint32_t>(wrap->element(0), TEXTURE_WRAP_NAMES),
                  choice<uint32_t>(wrap->element(1), TEXTURE_WRAP_NAMES));
}

// Which of the mesh's textures each vertex samples: one integer per vertex, -1 (none) up to the
// last texture, the same at a triangle's three vertices (a triangle samples one texture).
std::vector<uint32_t> textureIdRows(const Node& node, const Mesh& mesh, size_t textures) {
  requireArray(node);
  const size_t vertices = mesh.positions.size();
  if (node.json().size() != vertices) {
    node.fail("expected one texture index per vertex (" + std::to_string(vertices) + "), got " + std::to_string(node.json().size()));
  }
  std::vector<uint32_t> ids(vertices);
  for (size_t i = 0; i < vertices; ++i) {
    const int id = integer(node.element(i), -1, int(textures) - 1);
    ids[i] = id < 0 ? gpu::TEXTURE_NONE : uint32_t(id);
  }
  for (const glm::uvec3& t : mesh.triangles) {
    if (ids[t.x] != ids[t.y] || ids[t.x] != ids[t.z]) {
      node.fail("vertices " + std::to_string(t.x) + ", " + std::to_string(t.y) + " and " + std::to_string(t.z) +
                " make a triangle but sample different textures");
    }
  }
  return ids;
}

// The mesh's own textures ("textures" and "texture_ids", given together, with "uvs").
void readMeshTextures(const Node& object, const std::string& baseDir, Mesh& mesh) {
  const std::optional<Node> textures = object.find("textures"), ids = object.find("texture_ids");
  if (!textures && !ids) return;
  if (!textures) object.failAt("texture_ids", "needs 'textures' (the textures it indexes)");
  if (!ids) object.failAt("textures", "needs 'texture_ids' (which texture each vertex samples)");
  if (mesh.uvs.empty()) object.failAt("textures", "needs 'uvs' (the coordinates the textures are sampled at)");
  requireArray(*textures);
  mesh.textures.clear();
  for (size_t i = 0; i < textures->json().size(); ++i) mesh.textures.push_back(meshTexture(textures->element(i), baseDir));
  mesh.textureIds = textureIdRows(*ids, mesh, mesh.textures.size());
}

}  // namespace

std::shared_ptr<const Mesh> readMeshArrays(const Node& object, const std::string& baseDir) {
  MeshArrays arrays;
  arrays.positions = floatRows(object.require("vertices"));
  if (auto faces = object.find("faces")) arrays.triangles = indexRows(*faces);
  if (auto lines = object.find("lines")) arrays.lines = pairRows(*lines);
  if (auto points = object.find("point_indices")) arrays.points = indexList(*points);
  if (auto normals = object.find("normals")) arrays.normals = floatRows(*normals);
  if (auto uvs = object.find("uvs")) arrays.uvs = uvRows(*uvs);
  Mesh mesh;
  try {
    mesh = meshFromArrays(arrays);
  } catch (const ArgumentError& error) {
    // "faces: row 2 has index 9, ..." becomes "objects[0].faces: row 2 has index 9, ...".
    std::string message = error.what();
    if (message.rfind("points: ", 0) == 0) message.replace(0, 6, "point_indices");  // the file's name for them
    const size_t colon = message.find(": ");
    if (colon == std::string::npos) object.fail(message);
    object.failAt(message.substr(0, colon), message.substr(colon + 2));
  }
  if (auto colors = object.find("colors")) mesh.colors = colorRows(*colors, mesh.positions.size());
  readMeshTextures(object, baseDir, mesh);
  return std::make_shared<const Mesh>(std::move(mesh));
}

}  // namespace scenejson
}  // namespace phongvk
