// normals.cpp — see normals.h. Sums in double: a vertex of many tiny faces keeps its precision.
#include "scene/normals.h"

#include <cassert>

namespace phongvk {

void computeVertexNormals(Mesh& mesh) {
  const size_t vertexCount = mesh.positions.size();
  std::vector<glm::dvec3> sum(vertexCount, glm::dvec3(0.0));
  std::vector<double> weight(vertexCount, 0.0);                    // sum of |n|
  std::vector<glm::dvec3> fallback(vertexCount, glm::dvec3(0.0));  // first face with area
  for (const glm::uvec3& t : mesh.triangles) {
    assert(t.x < vertexCount && t.y < vertexCount && t.z < vertexCount);
    const glm::dvec3 a(mesh.positions[t.x]), b(mesh.positions[t.y]), c(mesh.positions[t.z]);
    const glm::dvec3 n = glm::cross(b - a, c - a);
    if (n == glm::dvec3(0.0)) continue;
    for (uint32_t v : {t.x, t.y, t.z}) {
      sum[v] += n;
      weight[v] += glm::length(n);
      if (fallback[v] == glm::dvec3(0.0)) fallback[v] = n;
    }
  }
  mesh.normals.resize(vertexCount);
  for (size_t v = 0; v < vertexCount; ++v) {
    // Cancelled down to rounding noise: its direction would be noise too.
    glm::dvec3 n = glm::length(sum[v]) > 1e-9 * weight[v] ? sum[v] : fallback[v];
    mesh.normals[v] =
        n == glm::dvec3(0.0) ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(glm::normalize(n));
  }
}

}  // namespace phongvk
