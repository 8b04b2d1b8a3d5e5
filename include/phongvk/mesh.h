// mesh.h — a triangle mesh given as arrays (Scene::addMesh), the way numpy users hold one, and a
// mesh built once (from arrays or a file) that many objects share (TriangleMesh, Scene::add).
#pragma once

#include "phongvk/export.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace phongvk {

// N vertices and M triangles, row-major: positions x0 y0 z0 x1 ... (3N floats, world metres),
// triangles a0 b0 c0 a1 ... (3M vertex indices, counter-clockwise seen from outside), and either
// no normals (they are then area-weighted face normals, as for an OBJ file without any; a vertex
// only points and lines use has none and is drawn unlit) or one per vertex (3N floats, any length
// but zero). Points and line segments (docs/DESIGN.md "Points and lines") index the same vertices;
// arrays with vertices alone are a point cloud: every vertex a point. The messages of a bad mesh
// name these as "vertices", "faces", "lines", "points" and "normals", with the first bad row.
struct MeshArrays {
  std::vector<float> positions;
  std::vector<int64_t> triangles;
  std::vector<int64_t> lines;   // segments a0 b0 a1 b1 ... (vertex index pairs)
  std::vector<int64_t> points;  // vertex indices, each drawn as a point
  std::vector<float> normals;
  // Texture coordinates u0 v0 u1 v1 ... (2N finite floats; (0, 0) the texture's top-left corner,
  // docs/DESIGN.md "Textures"), or none: what a material's texture is sampled with ("uvs").
  std::vector<float> uvs;
  // Vertex colours r0 g0 b0 a0 r1 ... (4N bytes, 0..255), or none (white): each multiplies the
  // material's colour at its vertex, as a PLY's or glTF's vertex colours do ("colors"). Alpha is
  // kept with the mesh (a scene written out holds it) and not drawn.
  std::vector<uint8_t> colors;
};

// How a model file loaded alone (no scene file: loadScene("model.ply"), TriangleMesh::fromFile) is
// stood up: with the up axis its format usually has (y for glTF and OBJ, z for PLY and STL), or the
// one given, for a model whose exporter used the other convention.
enum class ModelUp { Usual, Y, Z };

struct Mesh;  // the built mesh (positions, unit normals, triangles, colours)

// A mesh built once and shared: every object that adds it (Scene::add) renders the same built
// vertices, held once in memory however many objects place it, and a renderer's meshes are built
// from it without reading or checking anything again. Cheap to copy (copies share the mesh).
class PHONGVK_API TriangleMesh {
 public:
  // Built from arrays as Scene::addMesh builds them; ArgumentError naming the array ("vertices",
  // "faces", "normals") and its first bad row.
  explicit TriangleMesh(const MeshArrays& arrays);
  // A mesh file (OBJ, PLY, STL, glTF 2.0, GLB) read as a model rendered alone reads it: stood up
  // by `up`, a glTF's base colours as vertex colours, in the file's own coordinates (the pose of
  // each object that adds it places it). SceneError naming the file and its line for a bad file,
  // ArgumentError for a path that does not name a mesh file.
  static TriangleMesh fromFile(const std::string& path, ModelUp up = ModelUp::Usual);

  size_t vertexCount() const;
  size_t triangleCount() const;
  size_t lineCount() const;
  size_t pointCount() const;

 private:
  explicit TriangleMesh(std::shared_ptr<const Mesh> mesh);
  std::shared_ptr<const Mesh> mesh_;
  friend struct TriangleMeshAccess;
};

}  // namespace phongvk
