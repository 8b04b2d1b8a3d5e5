// mesh_checks.h — the facts every object mesh must satisfy, as gtest assertions shared by the mesh
// suites (primitives_test, hull_test, obj_import_test): watertight, wound outward, unit normals.
#pragma once

#include "scene/object_mesh.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <string>
#include <vector>

namespace phongvk::test {

inline Object makeObject(Shape shape) {
  Object object;
  object.shape = shape;
  object.jsonPath = "objects[4]";
  return object;
}

inline std::array<uint32_t, 3> bitsOf(glm::vec3 p) {
  std::array<uint32_t, 3> bits;
  std::memcpy(bits.data(), &p, sizeof bits);
  return bits;
}

// Watertight with consistent orientation: after welding vertices whose positions are bitwise
// equal, every directed edge appears exactly once and its reverse exactly once. A crack (two
// midpoints a rounding apart), a hole, a flipped triangle or a duplicated one all fail this.
inline ::testing::AssertionResult isWatertight(const Mesh& mesh) {
  std::map<std::array<uint32_t, 3>, uint32_t> weld;
  std::vector<uint32_t> id(mesh.positions.size());
  for (size_t v = 0; v < mesh.positions.size(); ++v)
    id[v] = weld.try_emplace(bitsOf(mesh.positions[v]), uint32_t(weld.size())).first->second;
  std::map<std::pair<uint32_t, uint32_t>, int> directed;
  for (const glm::uvec3& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) directed[{id[t[k]], id[t[(k + 1) % 3]]}]++;
  for (const auto& [edge, count] : directed) {
    auto reverse = directed.find({edge.second, edge.first});
    if (count != 1 || reverse == directed.end() || reverse->second != 1)
      return ::testing::AssertionFailure()
             << "edge " << edge.first << "->" << edge.second << " appears " << count
             << " times, its reverse " << (reverse == directed.end() ? 0 : reverse->second)
             << " times";
  }
  return ::testing::AssertionSuccess();
}

inline glm::dvec3 faceCross(const Mesh& mesh, const glm::uvec3& t) {
  const glm::dvec3 a(mesh.positions[t.x]), b(mesh.positions[t.y]), c(mesh.positions[t.z]);
  return glm::cross(b - a, c - a);
}

// Every triangle has area and winds the way its vertices' normals point.
inline ::testing::AssertionResult windsOutward(const Mesh& mesh) {
  for (size_t i = 0; i < mesh.triangles.size(); ++i) {
    const glm::uvec3& t = mesh.triangles[i];
    const glm::dvec3 n = faceCross(mesh, t);
    if (!(glm::length(n) > 0.0))
      return ::testing::AssertionFailure() << "triangle " << i << " has no area";
    for (uint32_t v : {t.x, t.y, t.z})
      if (!(glm::dot(n, glm::dvec3(mesh.normals[v])) > 0.0))
        return ::testing::AssertionFailure()
               << "triangle " << i << " winds against vertex " << v << "'s normal";
  }
  return ::testing::AssertionSuccess();
}

// Unit normals pointing away from `inside` (the shapes tested this way are convex).
inline ::testing::AssertionResult normalsPointOut(const Mesh& mesh, glm::dvec3 inside) {
  if (mesh.normals.size() != mesh.positions.size())
    return ::testing::AssertionFailure() << "normal count";
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    const glm::dvec3 n(mesh.normals[v]);
    if (std::abs(glm::length(n) - 1.0) > 1e-6)
      return ::testing::AssertionFailure() << "normal " << v << " not unit";
    if (!(glm::dot(n, glm::dvec3(mesh.positions[v]) - inside) > 0.0))
      return ::testing::AssertionFailure() << "normal " << v << " points inward";
  }
  return ::testing::AssertionSuccess();
}

// The message of the SceneError that building `object` throws.
inline std::string buildError(const Object& object) {
  try {
    buildObjectMesh(object);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "no error";
}

inline void expectClosedConvexShape(const Mesh& mesh, glm::dvec3 inside) {
  EXPECT_TRUE(isWatertight(mesh));
  EXPECT_TRUE(windsOutward(mesh));
  EXPECT_TRUE(normalsPointOut(mesh, inside));
}

}  // namespace phongvk::test
