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

// Finite positions, one unit normal a position, one colour a position or none, indices in range,
// at least one triangle.
inline void checkMesh(const Mesh& mesh) {
  if (mesh.triangles.empty()) broken("a mesh without triangles");
  if (mesh.normals.size() != mesh.positions.size()) broken("normals do not match positions");
  if (!mesh.colors.empty() && mesh.colors.size() != mesh.positions.size()) broken("colours do not match positions");
  for (const glm::vec3& p : mesh.positions)
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) broken("a non-finite position");
  for (const glm::vec3& n : mesh.normals)
    if (!(std::abs(glm::length(n) - 1.0f) < 1e-3f)) broken("a normal that is not unit length");
  for (const glm::uvec3& t : mesh.triangles)
    if (t.x >= mesh.positions.size() || t.y >= mesh.positions.size() || t.z >= mesh.positions.size())
      broken("an index out of range");
}

}  // namespace phongvk::fuzz
