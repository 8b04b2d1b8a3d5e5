// mesh_import.h — the one path from a loaded mesh (an OBJ, PLY, STL or glTF file, or arrays) to the
// mesh an object renders: the object's transform, zero-area triangles dropped, vertices that no
// triangle, point or line uses removed, normals normalised or, where the source has none,
// area-weighted (normals.h).
#pragma once

#include "geometry/mesh.h"
#include "geometry/transform.h"

#include <string>

namespace phongvk {

// `loaded` holds the source's positions (finite), its triangles, points and lines (indices in
// range), normals only where it has one per position (any non-zero finite length; (0, 0, 0) at a
// vertex no triangle uses, which stays so: drawn unlit) and colours only where it has one per
// position. Zero-length lines are kept (a point's worth of pixels). Throws SceneError
// "<where>: ..." for a position the transform takes out of range, for a mesh with nothing to draw
// and for one whose triangles all have zero area and that has no points or lines.
Mesh finishLoadedMesh(Mesh loaded, const LinearTransform& transform, const std::string& where);

// One mesh of a file as an importer reads it (a glTF primitive, a PLY or STL file): positions with the
// file's node transform applied, normals (transformed, any non-zero length; (0, 0, 0) allowed at a
// vertex no triangle uses) or none, RGBA8 colours or none, triangles, points and lines indexing
// this part's positions.
struct MeshPart {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;
  std::vector<uint32_t> colors;
  std::vector<glm::uvec3> triangles;
  std::vector<uint32_t> points;
  std::vector<glm::uvec2> lines;
  // Texture coordinates (one per position) and the base-colour texture they sample, or none.
  std::vector<glm::vec2> uvs;
  std::shared_ptr<const TextureImage> texture;
};

// A texture file a model names (OBJ's map_Kd, PLY's TextureFile, a glTF image's URI) as a path:
// relative to the model's folder, Windows separators (".\\wood.jpg", as some exporters write) read
// as '/'.
std::string texturePathBeside(const std::string& name, const std::string& modelPath);

// Mesh::notice for a model whose materials have maps phongvk does not render ("normal",
// "map_Ks", ...): "<path>: its normal and emissive maps are not rendered (...)"; "" for none.
std::string ignoredMapsNotice(const std::string& path, const std::vector<std::string>& maps);

// The parts as one loaded mesh: normals where every part with triangles has them, (0, 0, 0) for the
// parts of points and lines alone that have none (drawn unlit: glTF's rule); where a part with
// triangles has none, no normals at all (computed: the vertices of points and lines only then get
// (0, 0, 0), whatever their part gave), and with `flatWithoutNormals` each triangle gets vertices of
// its own, so that the computed normals are the face normals (STL's facets, glTF's rule for
// primitives without normals). Colours where any part has them (white for the others), texture
// coordinates where any part has them with a texture ((0, 0) and no texture for the others).
// Throws SceneError "<where>: nothing to draw (no triangles, lines or points)" for none.
Mesh joinParts(std::vector<MeshPart>& parts, bool flatWithoutNormals, const std::string& where);

// The message for a mesh with nothing to draw: "nothing to draw (no triangles, lines or points)".
inline constexpr const char* NOTHING_TO_DRAW = "nothing to draw (no triangles, lines or points)";

}  // namespace phongvk
