// mesh_import.cpp — see mesh_import.h.
#include "meshio/mesh_import.h"

#include "phongvk/errors.h"

#include "geometry/normals.h"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <utility>

namespace phongvk {
namespace {

void dropZeroArea(Mesh& mesh) {
  size_t kept = 0;
  for (const glm::uvec3& t : mesh.triangles) {
    const glm::dvec3 a(mesh.positions[t.x]), b(mesh.positions[t.y]), c(mesh.positions[t.z]);
    if (glm::cross(b - a, c - a) != glm::dvec3(0.0)) mesh.triangles[kept++] = t;  // zero area draws nothing
  }
  mesh.triangles.resize(kept);
}

template <typename T>
void keepUsed(std::vector<T>& values, const std::vector<uint32_t>& newIndex) {
  size_t kept = 0;
  for (size_t i = 0; i < values.size(); ++i) {
    if (newIndex[i] != UINT32_MAX) values[kept++] = values[i];
  }
  values.resize(kept);
}

// Vertices no triangle, point or line uses are dropped (in order), so that nothing shades them.
void removeUnused(Mesh& mesh) {
  std::vector<uint32_t> newIndex(mesh.positions.size(), UINT32_MAX);
  for (const glm::uvec3& t : mesh.triangles) newIndex[t.x] = newIndex[t.y] = newIndex[t.z] = 0;
  for (uint32_t p : mesh.points) newIndex[p] = 0;
  for (const glm::uvec2& l : mesh.lines) newIndex[l.x] = newIndex[l.y] = 0;
  uint32_t next = 0;
  for (uint32_t& index : newIndex) {
    if (index != UINT32_MAX) index = next++;
  }
  if (next == mesh.positions.size()) return;
  for (glm::uvec3& t : mesh.triangles) t = {newIndex[t.x], newIndex[t.y], newIndex[t.z]};
  for (uint32_t& p : mesh.points) p = newIndex[p];
  for (glm::uvec2& l : mesh.lines) l = {newIndex[l.x], newIndex[l.y]};
  keepUsed(mesh.positions, newIndex);
  if (!mesh.normals.empty()) keepUsed(mesh.normals, newIndex);
  if (!mesh.colors.empty()) keepUsed(mesh.colors, newIndex);
  if (!mesh.uvs.empty()) keepUsed(mesh.uvs, newIndex);
  if (!mesh.textureIds.empty()) keepUsed(mesh.textureIds, newIndex);
}

}  // namespace

Mesh finishLoadedMesh(Mesh mesh, const LinearTransform& transform, const std::string& where) {
  const bool givenNormals = !mesh.normals.empty();
  const bool anyTriangles = !mesh.triangles.empty();
  transformPositions(mesh, transform, where);
  for (glm::vec3& n : mesh.normals) {
    if (n != glm::vec3(0.0f)) n = transformNormal(transform, n);  // (0, 0, 0): unlit, and stays so
  }
  dropZeroArea(mesh);
  if (mesh.triangles.empty() && mesh.points.empty() && mesh.lines.empty())
    throw SceneError(where + ": " + (anyTriangles ? "every triangle is degenerate (zero area)" : NOTHING_TO_DRAW));
  removeUnused(mesh);
  if (!givenNormals) computeVertexNormals(mesh);
  return mesh;
}

namespace {

// Vertex v of `from` appended to `to`'s arrays; its index there.
uint32_t copyVertex(const Mesh& from, uint32_t v, Mesh& to) {
  to.positions.push_back(from.positions[v]);
  if (!from.colors.empty()) to.colors.push_back(from.colors[v]);
  if (!from.uvs.empty()) to.uvs.push_back(from.uvs[v]);
  if (!from.textureIds.empty()) to.textureIds.push_back(from.textureIds[v]);
  return uint32_t(to.positions.size() - 1);
}

// Each triangle with vertices of its own; after them, the vertices points and lines use, once each.
void unshareVertices(Mesh& mesh) {
  Mesh flat;
  flat.positions.reserve(3 * mesh.triangles.size());
  flat.textures = std::move(mesh.textures);
  for (const glm::uvec3& t : mesh.triangles) {
    const uint32_t first = uint32_t(flat.positions.size());
    for (uint32_t v : {t.x, t.y, t.z}) copyVertex(mesh, v, flat);
    flat.triangles.push_back({first, first + 1, first + 2});
  }
  std::vector<uint32_t> copied(mesh.points.empty() && mesh.lines.empty() ? 0 : mesh.positions.size(), UINT32_MAX);
  const auto vertex = [&](uint32_t v) {
    if (copied[v] == UINT32_MAX) copied[v] = copyVertex(mesh, v, flat);
    return copied[v];
  };
  for (uint32_t p : mesh.points) flat.points.push_back(vertex(p));
  for (const glm::uvec2& l : mesh.lines) flat.lines.push_back({vertex(l.x), vertex(l.y)});
  mesh = std::move(flat);
}

// Part `part`'s texture as an index into mesh.textures (added there the first time a part names
// it), or gpu::TEXTURE_NONE.
uint32_t textureIndex(Mesh& mesh, const std::shared_ptr<const TextureImage>& texture) {
  if (!texture) return gpu::TEXTURE_NONE;
  for (size_t i = 0; i < mesh.textures.size(); ++i) {
    if (mesh.textures[i] == texture) return uint32_t(i);
  }
  mesh.textures.push_back(texture);
  return uint32_t(mesh.textures.size() - 1);
}

// The part's texture coordinates and texture appended to the mesh's: (0, 0) and none for a part
// without coordinates when another part has them.
void appendTexturing(Mesh& mesh, MeshPart& part) {
  const uint32_t texture = part.uvs.empty() ? gpu::TEXTURE_NONE : textureIndex(mesh, part.texture);
  if (part.uvs.empty()) part.uvs.assign(part.positions.size(), glm::vec2(0.0f));
  mesh.uvs.insert(mesh.uvs.end(), part.uvs.begin(), part.uvs.end());
  mesh.textureIds.insert(mesh.textureIds.end(), part.positions.size(), texture);
}

}  // namespace

std::string ignoredMapsNotice(const std::string& path, const std::vector<std::string>& maps) {
  if (maps.empty()) return "";
  std::string names;
  for (size_t i = 0; i < maps.size(); ++i) names += (i == 0 ? "" : i + 1 == maps.size() ? " and " : ", ") + maps[i];
  return path + ": its " + names + " maps are not rendered (phongvk samples base-colour textures only)";
}

std::string texturePathBeside(const std::string& name, const std::string& modelPath) {
  std::string file = name;
  std::replace(file.begin(), file.end(), '\\', '/');
  const std::filesystem::path p(file);
  return p.is_absolute() ? file : (std::filesystem::path(modelPath).parent_path() / p).string();
}

namespace {

// Whether the joined mesh takes its parts' normals (mesh_import.h joinParts): every part has them
// but those of points and lines alone, and some part has them.
bool partsHaveNormals(const std::vector<MeshPart>& parts) {
  bool every = true, some = false;
  for (const MeshPart& part : parts) {
    const bool has = part.normals.size() == part.positions.size();
    const bool pointsAndLinesOnly = part.triangles.empty() && (!part.points.empty() || !part.lines.empty());
    if (!pointsAndLinesOnly) every = every && has;
    some = some || (has && !part.positions.empty());
  }
  return every && some;
}

// The part's triangles, points and lines, indexing the mesh's vertices from `first`.
void appendElements(Mesh& mesh, const MeshPart& part, uint32_t first) {
  for (const glm::uvec3& t : part.triangles) mesh.triangles.push_back(t + glm::uvec3(first));
  for (uint32_t p : part.points) mesh.points.push_back(p + first);
  for (const glm::uvec2& l : part.lines) mesh.lines.push_back(l + glm::uvec2(first));
}

}  // namespace

Mesh joinParts(std::vector<MeshPart>& parts, bool flatWithoutNormals, const std::string& where) {
  const bool normals = partsHaveNormals(parts);
  bool colors = false, textured = false, triangles = false;
  for (const MeshPart& part : parts) {
    colors = colors || !part.colors.empty();
    textured = textured || (!part.uvs.empty() && part.texture);
    triangles = triangles || !part.triangles.empty();
  }
  const bool flat = !normals && flatWithoutNormals && triangles;
  Mesh mesh;
  if (parts.size() == 1 && !textured && (normals || parts[0].normals.empty()) && !flat) {
    mesh.positions = std::move(parts[0].positions);  // one part: its arrays, not a copy
    mesh.normals = std::move(parts[0].normals);
    mesh.colors = std::move(parts[0].colors);
    mesh.triangles = std::move(parts[0].triangles);
    mesh.points = std::move(parts[0].points);
    mesh.lines = std::move(parts[0].lines);
    parts[0] = {};
  }
  for (MeshPart& part : parts) {
    appendElements(mesh, part, uint32_t(mesh.positions.size()));
    if (textured) appendTexturing(mesh, part);
    if (normals && part.normals.size() != part.positions.size()) part.normals.assign(part.positions.size(), glm::vec3(0.0f));
    mesh.positions.insert(mesh.positions.end(), part.positions.begin(), part.positions.end());
    if (normals) mesh.normals.insert(mesh.normals.end(), part.normals.begin(), part.normals.end());
    if (colors && part.colors.empty()) part.colors.assign(part.positions.size(), 0xFFFFFFFFu);
    if (colors) mesh.colors.insert(mesh.colors.end(), part.colors.begin(), part.colors.end());
    part = {};
  }
  if (mesh.triangles.empty() && mesh.points.empty() && mesh.lines.empty()) throw SceneError(where + ": " + NOTHING_TO_DRAW);
  if (flat) unshareVertices(mesh);
  return mesh;
}

}  // namespace phongvk
