// hull_test.cpp — `polyhedron` objects: the convex hull of their points (hull.h), its corners,
// faces and the errors for points that span no volume.
#include "geometry/hull.h"
#include "scene/object_mesh.h"
#include "tests/mesh_checks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <ctime>
#include <random>
#include <string>
#include <vector>

namespace phongvk {
namespace {

using namespace test;

// Processor seconds that mean a hang (the code before took from seconds to hours on these
// inputs), not a speed claim. The sanitizer build (scripts/sanitize.sh) runs several times slower.
#ifdef __SANITIZE_ADDRESS__
constexpr double kHangSeconds = 10;
#else
constexpr double kHangSeconds = 2;
#endif

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

// Closed (every directed edge once, and its reverse once) and convex at every edge: the two
// triangles at an edge do not both have the other's far corner above their plane (by more than
// the hull's tolerance; one of them may, where that corner is far from the edge and the fold is
// within tolerance at the near one). For a closed surface, convex.
::testing::AssertionResult isClosedAndConvex(const std::vector<glm::dvec3>& p,
                                             const std::vector<glm::uvec3>& triangles) {
  std::vector<std::array<uint32_t, 3>> edges;  // from, to, the triangle's third corner
  for (const glm::uvec3& t : triangles)
    for (int k = 0; k < 3; ++k) edges.push_back({t[k], t[(k + 1) % 3], t[(k + 2) % 3]});
  std::sort(edges.begin(), edges.end());
  auto height = [&](uint32_t a, uint32_t b, uint32_t c, uint32_t q) {  // of q above triangle (a, b, c)
    return glm::dot(glm::normalize(glm::cross(p[b] - p[a], p[c] - p[a])), p[q] - p[a]);
  };
  for (size_t k = 0; k < edges.size(); ++k) {
    const auto [from, to, third] = edges[k];
    if (k > 0 && from == edges[k - 1][0] && to == edges[k - 1][1])
      return ::testing::AssertionFailure() << "edge " << from << "->" << to << " twice";
    auto reverse = std::lower_bound(edges.begin(), edges.end(), std::array<uint32_t, 3>{to, from, 0});
    if (reverse == edges.end() || (*reverse)[0] != to || (*reverse)[1] != from)
      return ::testing::AssertionFailure() << "edge " << from << "->" << to << " has no reverse";
    const uint32_t across = (*reverse)[2];
    if (std::min(height(from, to, third, across), height(to, from, across, third)) > 1e-9)
      return ::testing::AssertionFailure() << "the hull folds outward at edge " << from << "->" << to;
  }
  return ::testing::AssertionSuccess();
}

TEST(Polyhedron, HundredThousandPointsOnASphereAreAllCorners) {
  // Every point is a corner, so the hull has 2n - 4 triangles. Testing every face for every
  // point, the hull took minutes. The points are sorted by height, an order that costs an
  // incremental hull following it about five times as much as a shuffled one.
  std::mt19937 random(11);
  std::normal_distribution<double> normal;
  std::vector<glm::dvec3> points;
  for (int i = 0; i < 100000; ++i) {
    const double x = normal(random), y = normal(random), z = normal(random);
    points.push_back(glm::normalize(glm::dvec3(x, y, z)));
  }
  std::sort(points.begin(), points.end(), [](const glm::dvec3& a, const glm::dvec3& b) { return a.z < b.z; });
  const std::clock_t start = std::clock();
  const Hull hull = convexHull(points);
  EXPECT_LT(double(std::clock() - start) / CLOCKS_PER_SEC, kHangSeconds);
  EXPECT_EQ(hull.error, "");
  EXPECT_EQ(hull.triangles.size(), 2 * points.size() - 4);
  EXPECT_TRUE(isClosedAndConvex(points, hull.triangles));
}

TEST(Polyhedron, PointsInsideACubeLeaveItsTwelveTriangles) {
  // 20,000 points inside and the 8 corners: more points than are added in the order given, so
  // they go in a shuffled order, and hulls of inside points come and go before the corners
  // arrive. None of them, and no sliver, may be left.
  std::mt19937 random(5);
  std::uniform_real_distribution<double> inside(-0.999, 0.999);
  Object object = makeObject(Shape::Polyhedron);
  for (int i = 0; i < 20000; ++i) object.points.push_back({inside(random), inside(random), inside(random)});
  for (int k = 0; k < 8; ++k) object.points.push_back({k & 1 ? 1.0 : -1.0, k & 2 ? 1.0 : -1.0, k & 4 ? 1.0 : -1.0});
  ObjectMesh m = buildObjectMesh(object);
  EXPECT_EQ(m.mesh.triangles.size(), 12u);
  for (const glm::vec3& p : m.mesh.positions)  // only the corners are used
    EXPECT_NEAR(glm::length(glm::abs(glm::dvec3(p) + m.origin) - glm::dvec3(1.0)), 0.0, 1e-6);
  EXPECT_TRUE(containsPoints(m, object.points));
  expectClosedConvexShape(m.mesh, {0, 0, 0});
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
