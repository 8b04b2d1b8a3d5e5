// mesh_checks.h — what the mesh fuzz targets (mesh_fuzzer.cpp, gltf_fuzzer.cpp) check on every mesh
// that loads: the promises of meshio/mesh_import.h. A broken one aborts, so libFuzzer keeps the input.
#pragma once

#include "geometry/mesh.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace phongvk::fuzz {

[[noreturn]] inline void broken(const std::string& what) {
  std::fprintf(stderr, "broken promise: %s\n", what.c_str());
  std::abort();
}

// Finite positions, one normal a position (unit, or zero for a vertex only points and lines use),
// one colour a position or none, indices in range, something to draw.
inline void checkMesh(const Mesh& mesh) {
  if (mesh.triangles.empty() && mesh.lines.empty() && mesh.points.empty()) broken("a mesh with nothing to draw");
  if (mesh.normals.size() != mesh.positions.size()) broken("normals do not match positions");
  if (!mesh.colors.empty() && mesh.colors.size() != mesh.positions.size()) broken("colours do not match positions");
  for (const glm::vec3& p : mesh.positions)
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) broken("a non-finite position");
  for (const glm::vec3& n : mesh.normals)
    if (!(std::abs(glm::length(n) - 1.0f) < 1e-3f) && n != glm::vec3(0.0f)) broken("a normal neither unit nor zero");
  const size_t count = mesh.positions.size();
  for (const glm::uvec3& t : mesh.triangles)
    if (t.x >= count || t.y >= count || t.z >= count) broken("an index out of range");
  for (const glm::uvec2& l : mesh.lines)
    if (l.x >= count || l.y >= count) broken("a line's index out of range");
  for (uint32_t p : mesh.points)
    if (p >= count) broken("a point's index out of range");
}

}  // namespace phongvk::fuzz
