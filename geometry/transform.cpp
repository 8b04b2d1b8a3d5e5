// transform.cpp — see transform.h.
#include "geometry/transform.h"

#include "base/number_text.h"
#include "phongvk/errors.h"

#include <cmath>
#include <utility>

namespace phongvk {

glm::dmat3 rotationAxisAngle(glm::dvec3 axis, double degrees) {
  const glm::dvec3 u = glm::normalize(axis);
  const double a = glm::radians(degrees), c = std::cos(a), s = std::sin(a), k = 1.0 - c;
  // Rodrigues' formula; glm matrices are column-major: m[column][row].
  glm::dmat3 m;
  m[0] = {c + u.x * u.x * k, u.y * u.x * k + u.z * s, u.z * u.x * k - u.y * s};
  m[1] = {u.x * u.y * k - u.z * s, c + u.y * u.y * k, u.z * u.y * k + u.x * s};
  m[2] = {u.x * u.z * k + u.y * s, u.y * u.z * k - u.x * s, c + u.z * u.z * k};
  return m;
}

glm::dmat3 rotationXYZ(glm::dvec3 degrees) {
  return rotationAxisAngle({0, 0, 1}, degrees.z) * rotationAxisAngle({0, 1, 0}, degrees.y) *
         rotationAxisAngle({1, 0, 0}, degrees.x);
}

glm::dvec3 transformPoint(const LinearTransform& t, glm::vec3 p) { return t.matrix * glm::dvec3(p); }

glm::vec3 transformNormal(const LinearTransform& t, glm::vec3 n) {
  const glm::dvec3 d = t.keepsDirections ? glm::dvec3(n) : t.normalMatrix * glm::dvec3(n);
  return d == glm::dvec3(0.0) ? glm::vec3(0.0f) : glm::vec3(glm::normalize(d));  // no normal stays none
}

void transformPositions(Mesh& mesh, const LinearTransform& t, const std::string& where) {
  if (t.identity) return;
  for (glm::vec3& p : mesh.positions) {
    const glm::dvec3 q = transformPoint(t, p);
    for (int axis = 0; axis < 3; ++axis) {
      if (!(std::abs(q[axis]) <= MAX_COORDINATE))
        throw SceneError(where + ": a vertex coordinate after the object's scale and rotation is " +
                         formatNumber(q[axis]) + ", beyond the " + formatNumber(MAX_COORDINATE) +
                         " m a scene may use");
    }
    p = glm::vec3(q);
  }
  if (t.mirrors) {
    for (glm::uvec3& tri : mesh.triangles) std::swap(tri.y, tri.z);
  }
}

void transformMesh(Mesh& mesh, const LinearTransform& t, const std::string& where) {
  transformPositions(mesh, t, where);
  if (t.keepsDirections) return;
  for (glm::vec3& n : mesh.normals) n = transformNormal(t, n);
}

}  // namespace phongvk
