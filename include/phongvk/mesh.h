// mesh.h — a triangle mesh given as arrays (Scene::addMesh), the way numpy users hold one.
#pragma once

#include <cstdint>
#include <vector>

namespace phongvk {

// N vertices and M triangles, row-major: positions x0 y0 z0 x1 ... (3N floats, world metres),
// triangles a0 b0 c0 a1 ... (3M vertex indices, counter-clockwise seen from outside), and either
// no normals (they are then area-weighted face normals, as for an OBJ file without any) or one
// per vertex (3N floats, any length but zero). The messages of a bad mesh name these as
// "vertices", "faces" and "normals", with the first bad row.
struct MeshArrays {
  std::vector<float> positions;
  std::vector<int64_t> triangles;
  std::vector<float> normals;
};

}  // namespace phongvk
