// normals.cpp — see normals.h. Sums in double: a vertex of many tiny faces keeps its precision.
#include "geometry/normals.h"

#include "base/huge_pages.h"

#include <cassert>

namespace phongvk {
namespace {

// What a vertex gathers from its faces, together so that a face touches one place per corner.
struct NormalSum {
  glm::dvec3 sum{0.0};       // the faces' normals, weighted by area
  double weight = 0.0;       // sum of |n|
  glm::dvec3 fallback{0.0};  // first face with area
};

}  // namespace

void computeVertexNormals(Mesh& mesh) {
  const size_t vertexCount = mesh.positions.size();
  std::vector<NormalSum> sums;
  reserveLarge(sums, vertexCount);  // fresh memory on huge pages (a 10M-triangle mesh: 280 MB)
  sums.resize(vertexCount);
  std::vector<bool> used(vertexCount, false);  // by a triangle, with area or without
  for (const glm::uvec3& t : mesh.triangles) {
    assert(t.x < vertexCount && t.y < vertexCount && t.z < vertexCount);
    used[t.x] = used[t.y] = used[t.z] = true;
    const glm::dvec3 a(mesh.positions[t.x]), b(mesh.positions[t.y]), c(mesh.positions[t.z]);
    const glm::dvec3 n = glm::cross(b - a, c - a);
    if (n == glm::dvec3(0.0)) continue;
    const double length = glm::length(n);
    for (uint32_t v : {t.x, t.y, t.z}) {
      NormalSum& s = sums[v];
      s.sum += n;
      s.weight += length;
      if (s.fallback == glm::dvec3(0.0)) s.fallback = n;
    }
  }
  mesh.normals.resize(vertexCount);
  for (size_t v = 0; v < vertexCount; ++v) {
    // Cancelled down to rounding noise: its direction would be noise too.
    const NormalSum& s = sums[v];
    glm::dvec3 n = glm::length(s.sum) > 1e-9 * s.weight ? s.sum : s.fallback;
    if (!used[v])
      mesh.normals[v] = glm::vec3(0.0f);
    else
      mesh.normals[v] = n == glm::dvec3(0.0) ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(glm::normalize(n));
  }
}

}  // namespace phongvk
