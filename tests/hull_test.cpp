// hull_test.cpp — `polyhedron` objects: the convex hull of their points (hull.h), its corners,
// faces and the errors for points that span no volume.
#include "scene/hull.h"
#include "scene/mesh.h"
#include "tests/mesh_checks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace phongvk {
namespace {

using namespace test;

::testing::AssertionResult containsPoints(const ObjectMesh& m,
                                          const std::vector<glm::dvec3>& points) {
  for (const glm::uvec3& t : m.mesh.triangles) {
    const glm::dvec3 n = glm::normalize(faceCross(m.mesh, t)), a(m.mesh.positions[t.x]);
    for (const glm::dvec3& p : points)
      if (glm::dot(n, p - m.origin - a) > 1e-6)
        return ::testing::AssertionFailure() << "a point is outside";
  }
  return ::testing::AssertionSuccess();
}

TEST(Polyhedron, PaperPointsMakeTenTriangles) {
  // The paper's polyhedron. Counting by hand: the base z = -0.5 is the square P0 P1 P3 P2 (2
  // triangles); the side y = 0 is the quad P0 P1 P5 P4 (2); x = 0 is the triangle P0 P2 P4 (1);
  // x = 1 is the triangle P1 P3 P5 (1). Without P6 the top would be two triangles over the
  // diagonal P5-P2 (it is higher than P4-P3); P6 = (.3,.3,.4) lies above both (the plane of P4 P5
  // P2 is z = .1 + .4x - .6y, .04 there; that of P5 P3 P2 is y + z = .5, .7 > .5 there), so the
  // top becomes a fan of 4 triangles from P6 to P4 P5 P3 P2. All 7 points are corners and
  // 2 + 2 + 1 + 1 + 4 = 10 = 2V - 4 triangles; 8 flat faces; E = 13.
  Object object = makeObject(Shape::Polyhedron);
  object.points = {{0, 0, -.5}, {1, 0, -.5}, {0, 1, -.5}, {1, 1, -.5},
                   {0, 0, .1},  {1, 0, .5},  {.3, .3, .4}};
  ObjectMesh m = buildObjectMesh(object);
  EXPECT_NEAR(glm::length(m.origin - glm::dvec3(3.3, 2.3, -1.0) / 7.0), 0.0,
              1e-12);  // the centroid
  EXPECT_EQ(m.mesh.triangles.size(), 10u);
  EXPECT_EQ(m.mesh.positions.size(), 30u);  // flat: each triangle its own three vertices
  EXPECT_TRUE(containsPoints(m, object.points));
  expectClosedConvexShape(m.mesh, {0, 0, 0});  // the centroid is inside
  for (const glm::uvec3& t : m.mesh.triangles) {
    const glm::dvec3 n = glm::normalize(faceCross(m.mesh, t));
    for (uint32_t v : {t.x, t.y, t.z})
      EXPECT_NEAR(glm::length(glm::dvec3(m.mesh.normals[v]) - n), 0.0, 1e-6);
  }
}

TEST(Polyhedron, PointsOnFacesEdgesAndDuplicatesAreNotCorners) {
  // A cube's 8 corners plus its centre, face centres, edge midpoints and repeats. Listed centres
  // first, so the incremental hull meets points on faces before the corners that make them flat:
  // the hull must still be the cube's 12 triangles, without slivers or duplicates.
  Object object = makeObject(Shape::Polyhedron);
  for (int zeros = 3; zeros >= 0; --zeros)  // centre, face centres, edge midpoints, corners
    for (int x = -1; x <= 1; ++x)
      for (int y = -1; y <= 1; ++y)
        for (int z = -1; z <= 1; ++z)
          if ((x == 0) + (y == 0) + (z == 0) == zeros) object.points.push_back({x, y, z});
  object.points.push_back({1, 1, 1});
  object.points.push_back({0, 0, 1});
  ObjectMesh m = buildObjectMesh(object);
  EXPECT_EQ(m.mesh.triangles.size(), 12u);
  EXPECT_TRUE(containsPoints(m, object.points));
  expectClosedConvexShape(m.mesh, {0, 0, 0});
}

TEST(Polyhedron, GridIsACube) {
  // A 10 x 10 x 10 grid: 488 of its points lie on the boundary, only 8 are corners. Rows of
  // collinear and planes of coplanar points are the worst case for an incremental hull.
  Object object = makeObject(Shape::Polyhedron);
  for (int x = 0; x < 10; ++x)
    for (int y = 0; y < 10; ++y)
      for (int z = 0; z < 10; ++z) object.points.push_back({x * 0.1, y * 0.1, z * 0.1});
  ObjectMesh m = buildObjectMesh(object);
  EXPECT_EQ(m.mesh.triangles.size(), 12u);
  EXPECT_TRUE(containsPoints(m, object.points));
  expectClosedConvexShape(m.mesh, {0, 0, 0});
}

TEST(Polyhedron, PointsOnASphereAreAllCorners) {
  // 200 points spread on a sphere (a Fibonacci lattice), far from the origin: every point is a
  // corner, so the hull has 2 * 200 - 4 triangles.
  Object object = makeObject(Shape::Polyhedron);
  const double golden = 3.14159265358979323846 * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < 200; ++i) {
    const double z = 1.0 - 2.0 * (i + 0.5) / 200, r = std::sqrt(1.0 - z * z);
    object.points.push_back(glm::dvec3(1e5, -2e5, 3e4) +
                            glm::dvec3(r * std::cos(golden * i), r * std::sin(golden * i), z));
  }
  ObjectMesh m = buildObjectMesh(object);
  EXPECT_EQ(m.mesh.triangles.size(), 396u);
  EXPECT_TRUE(containsPoints(m, object.points));
  expectClosedConvexShape(m.mesh, {0, 0, 0});
  EXPECT_EQ(buildObjectMesh(object).mesh.positions, m.mesh.positions);  // deterministic
}

TEST(Polyhedron, CoplanarPointsAreAnError) {
  Object object = makeObject(Shape::Polyhedron);
  object.points = {{0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}, {0.5, 0.2, 1}};
  EXPECT_EQ(buildError(object),
            "objects[4].points: the points are coplanar; a polyhedron needs volume");
}

TEST(Polyhedron, CollinearAndTooFewDistinctPointsAreErrors) {
  Object object = makeObject(Shape::Polyhedron);
  object.points = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}};
  EXPECT_EQ(buildError(object),
            "objects[4].points: the points are collinear; a polyhedron needs volume");
  object.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}};  // a repeat does not count
  EXPECT_EQ(buildError(object),
            "objects[4].points: a polyhedron needs at least 4 distinct points, got 3");
}

}  // namespace
}  // namespace phongvk
