// primitives_test.cpp — the primitive shapes (primitives.h), subdivision on the true surface
// (subdivide.h), vertex normals (normals.h) and the huge-page arrays: counts, watertightness,
// winding, normals, errors.
#include "base/huge_pages.h"
#include "geometry/normals.h"
#include "scene/object_mesh.h"
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

TEST(HugePages, ReserveLargeKeepsTheElementsAndTheRoom) {
  // Subdivision and the scene's flat arrays reserve through reserveLarge: growing must keep what
  // the vector held, and a smaller request must change nothing.
  std::vector<uint32_t> v = {7, 8, 9};
  reserveLarge(v, size_t(3) << 20);  // 12 MiB: whole 2 MiB pages inside, so madvise is asked
  ASSERT_GE(v.capacity(), size_t(3) << 20);
  EXPECT_EQ(v, (std::vector<uint32_t>{7, 8, 9}));
  const uint32_t* data = v.data();
  reserveLarge(v, 10);
  EXPECT_EQ(v.data(), data);
  v.resize(size_t(3) << 20, 5u);  // the advised pages are ordinary memory to write
  EXPECT_EQ(v[2], 9u);
  EXPECT_EQ(v.back(), 5u);
  std::vector<double> empty;
  reserveLarge(empty, 1);  // no whole huge page inside: nothing asked
  EXPECT_GE(empty.capacity(), 1u);
  EXPECT_TRUE(empty.empty());
}

TEST(Cube, HasSharpFacesOfFourVerticesEach) {
  Object object = makeObject(Shape::Cube);
  object.center = {10, 20, 30};
  object.size = 2;
  ObjectMesh m = buildObjectMesh(object);
  EXPECT_EQ(m.origin, glm::dvec3(10, 20, 30));  // built around 0, placed by the origin
  EXPECT_EQ(m.mesh.positions.size(), 24u);
  EXPECT_EQ(m.mesh.triangles.size(), 12u);
  expectClosedConvexShape(m.mesh, {0, 0, 0});
  for (size_t v = 0; v < 24; ++v) {
    // A face normal is an axis, and the vertex lies on that face's plane.
    const glm::vec3 n = m.mesh.normals[v];
    EXPECT_EQ(std::abs(n.x) + std::abs(n.y) + std::abs(n.z), 1.0f);
    EXPECT_EQ(glm::dot(n, m.mesh.positions[v]), 1.0f);
  }
}

TEST(Cube, SubdivideThreeKeepsFacesFlat) {
  Object object = makeObject(Shape::Cube);
  object.subdivide = 3;
  ObjectMesh m = buildObjectMesh(object);
  EXPECT_EQ(m.mesh.triangles.size(), 6u * 2 * 64);  // 6 faces * 2 triangles * 4^3
  EXPECT_EQ(m.mesh.positions.size(), 6u * 9 * 9);   // each face a (2^3 + 1)^2 grid, edges shared
  expectClosedConvexShape(m.mesh, {0, 0, 0});
  for (size_t v = 0; v < m.mesh.positions.size(); ++v)
    EXPECT_EQ(glm::dot(m.mesh.normals[v], m.mesh.positions[v]), 0.5f);  // on its face's plane
}

// ---- spheres ----

void expectOnSphere(const Mesh& mesh, double radius) {
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    const glm::dvec3 p(mesh.positions[v]);
    EXPECT_NEAR(glm::length(p), radius, radius * 1e-6);
    EXPECT_NEAR(glm::length(glm::dvec3(mesh.normals[v]) - p / radius), 0.0,
                1e-6);  // analytic normal
  }
}

TEST(UvSphere, ThirtyTwoSegmentsHasPolesAndNoSeam) {
  Object object = makeObject(Shape::Sphere);
  object.radius = 0.5;
  object.segments = 32;
  ObjectMesh m = buildObjectMesh(object);
  // 16 bands: 15 rings of 32 plus 2 poles; 2 pole fans of 32 + 14 bands of 64 triangles.
  EXPECT_EQ(m.mesh.positions.size(), 2u + 32 * 15);
  EXPECT_EQ(m.mesh.triangles.size(), 2u * 32 * 15);
  expectClosedConvexShape(m.mesh, {0, 0, 0});
  expectOnSphere(m.mesh, 0.5);
}

TEST(UvSphere, ThreeSegmentsStillMakesTwoBands) {
  // segments / 2 = 1 band would be two pole fans meeting at no ring; max(2, s / 2) keeps a ring.
  Object object = makeObject(Shape::Sphere);
  object.segments = 3;
  ObjectMesh m = buildObjectMesh(object);
  EXPECT_EQ(m.mesh.positions.size(), 5u);
  EXPECT_EQ(m.mesh.triangles.size(), 6u);
  expectClosedConvexShape(m.mesh, {0, 0, 0});
}

TEST(UvSphere, SubdividedVerticesLieOnTheSphere) {
  Object object = makeObject(Shape::Sphere);
  object.radius = 2;
  object.segments = 8;
  object.subdivide = 3;
  ObjectMesh m = buildObjectMesh(object);
  EXPECT_EQ(m.mesh.triangles.size(), 2u * 8 * 3 * 64);
  expectClosedConvexShape(m.mesh, {0, 0, 0});
  expectOnSphere(m.mesh, 2);
}

TEST(Icosphere, CountsPerLevel) {
  for (int k = 0; k <= 3; ++k) {
    SCOPED_TRACE("subdivide " + std::to_string(k));
    Object object = makeObject(Shape::Icosphere);
    object.radius = 1.5;
    object.subdivide = k;
    ObjectMesh m = buildObjectMesh(object);
    const size_t pow4 = size_t(1) << (2 * k);
    EXPECT_EQ(m.mesh.positions.size(), 10 * pow4 + 2);  // a midpoint per edge, shared
    EXPECT_EQ(m.mesh.triangles.size(), 20 * pow4);
    expectClosedConvexShape(m.mesh, {0, 0, 0});
    expectOnSphere(m.mesh, 1.5);
  }
}

// ---- cylinder ----

void expectCylinderNormals(const Mesh& mesh, double radius, double height) {
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    const glm::vec3 p = mesh.positions[v], n = mesh.normals[v];
    if (n.z == 0.0f) {  // side: on the surface, normal radial
      const glm::dvec2 xy(p.x, p.y);
      EXPECT_NEAR(glm::length(xy), radius, 1e-6);
      EXPECT_NEAR(glm::length(glm::dvec2(n.x, n.y) - xy / radius), 0.0, 1e-6);
    } else {  // cap: flat, normal +-z exactly
      EXPECT_EQ(std::abs(n.z), 1.0f);
      EXPECT_EQ(p.z, float(n.z * height / 2));
      EXPECT_LE(glm::length(glm::dvec2(p.x, p.y)), radius * (1 + 1e-6));
    }
  }
}

TEST(Cylinder, SidesAndCapsWithSharpRims) {
  Object object = makeObject(Shape::Cylinder);
  object.radius = 0.5;
  object.height = 1;
  object.segments = 32;
  ObjectMesh m = buildObjectMesh(object);
  EXPECT_EQ(m.mesh.positions.size(), 4u * 32 + 2);  // 2 side rings, 2 cap rims, 2 cap centres
  EXPECT_EQ(m.mesh.triangles.size(), 4u * 32);      // side band 2s, two fans of s
  expectClosedConvexShape(m.mesh, {0, 0, 0});
  expectCylinderNormals(m.mesh, 0.5, 1);
}

TEST(Cylinder, SubdividedOnceHasNoCrackAtTheRim) {
  // The rim edge belongs to the side and to the cap with different vertex indices. Each computes
  // its own midpoint and both must project it onto the rim circle to the same bits, or the weld by
  // position leaves an open edge.
  Object object = makeObject(Shape::Cylinder);
  object.radius = 0.5;
  object.height = 1;
  object.segments = 32;
  object.subdivide = 1;
  ObjectMesh m = buildObjectMesh(object);
  // 8 s edges (side: s vertical, s diagonal, 2 s rim; caps: 2 s spokes, 2 s rim) add a vertex each.
  EXPECT_EQ(m.mesh.positions.size(), 4u * 32 + 2 + 8 * 32);
  EXPECT_EQ(m.mesh.triangles.size(), 16u * 32);
  expectClosedConvexShape(m.mesh, {0, 0, 0});
  expectCylinderNormals(m.mesh, 0.5, 1);
}

TEST(Cylinder, FewSegmentsManyLevelsStayWatertight) {
  // Three segments: the rim chords are far inside the circle, so projection moves midpoints a lot.
  Object object = makeObject(Shape::Cylinder);
  object.radius = 3;
  object.height = 0.25;
  object.segments = 3;
  object.subdivide = 4;
  ObjectMesh m = buildObjectMesh(object);
  EXPECT_EQ(m.mesh.triangles.size(), 4u * 3 * 256);
  expectClosedConvexShape(m.mesh, {0, 0, 0});
  expectCylinderNormals(m.mesh, 3, 0.25);
}

// ---- cone ----

void expectConeSurface(const Mesh& mesh, double radius, double height) {
  const double slant = std::sqrt(radius * radius + height * height);
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    const glm::vec3 p = mesh.positions[v], n = mesh.normals[v];
    if (n == glm::vec3(0, 0, -1)) {  // base
      EXPECT_EQ(p.z, float(-height / 2));
      continue;
    }
    const glm::dvec2 xy(p.x, p.y);
    EXPECT_NEAR(glm::length(xy), radius * (height / 2 - p.z) / height, 1e-6);  // on the slant
    EXPECT_NEAR(n.z, radius / slant, 1e-6);  // the true cone normal's elevation
    if (glm::length(xy) > 1e-3) {            // and its azimuth (the apex copies have their own)
      const glm::dvec2 expected = xy / glm::length(xy) * (height / slant);
      EXPECT_NEAR(glm::length(glm::dvec2(n.x, n.y) - expected), 0.0, 1e-6);
    }
  }
}

TEST(Cone, EightRingsWithApexCopies) {
  Object object = makeObject(Shape::Cone);
  object.radius = 0.5;
  object.height = 1;
  object.segments = 32;
  object.rings = 8;
  ObjectMesh m = buildObjectMesh(object);
  // Side: 8 rings of 32 (the base rim is ring 0) + 32 apex copies; base: 32 rim + 1 centre.
  EXPECT_EQ(m.mesh.positions.size(), 32u * 10 + 1);
  // 7 quad bands of 64, the apex fan of 32, the base fan of 32.
  EXPECT_EQ(m.mesh.triangles.size(), 2u * 32 * 8);
  expectClosedConvexShape(m.mesh, {0, 0, -0.25});
  expectConeSurface(m.mesh, 0.5, 1);
}

TEST(Cone, SubdividedStaysOnTheConeAndWatertight) {
  // Also tests the apex: the copies share a position, so their edges' midpoints must be equal too.
  Object object = makeObject(Shape::Cone);
  object.radius = 0.7;
  object.height = 1.3;
  object.segments = 5;
  object.rings = 2;
  object.subdivide = 3;
  ObjectMesh m = buildObjectMesh(object);
  EXPECT_EQ(m.mesh.triangles.size(), 2u * 5 * 2 * 64);
  expectClosedConvexShape(m.mesh, {0, 0, -0.3});
  expectConeSurface(m.mesh, 0.7, 1.3);
}


// ---- vertex normals ----

TEST(VertexNormals, WeighFacesByArea) {
  // Vertex 0 joins a triangle of area 2 facing +z and one of area 0.5 facing +x: its normal leans
  // four to one towards +z (an unweighted average would give 45 degrees).
  Mesh mesh;
  mesh.positions = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0, 1, 0}, {0, 0, 1}};
  mesh.triangles = {{0, 1, 2}, {0, 3, 4}};
  computeVertexNormals(mesh);
  ASSERT_EQ(mesh.normals.size(), 5u);
  EXPECT_NEAR(glm::length(glm::dvec3(mesh.normals[0]) - glm::normalize(glm::dvec3(1, 0, 4))), 0.0,
              1e-7);
  EXPECT_EQ(mesh.normals[1], glm::vec3(0, 0, 1));
  EXPECT_EQ(mesh.normals[4], glm::vec3(1, 0, 0));
}

TEST(VertexNormals, CancelledSumFallsBackToAFace) {
  // A two-sided sheet: the two faces cancel at every vertex; a unit normal is still required.
  Mesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 1}};
  computeVertexNormals(mesh);
  for (const glm::vec3& n : mesh.normals) EXPECT_EQ(n, glm::vec3(0, 0, 1));
}

// ---- limits and size ----

TEST(Subdivide, TooManyTrianglesIsAnError) {
  Object object = makeObject(Shape::Sphere);
  object.segments = 4096;
  object.subdivide = 10;
  EXPECT_EQ(buildError(object),
            "objects[4].subdivide: the mesh would have more than 67108864 triangles");
}

TEST(Subdivide, FiveMillionTriangles) {
  // Icosphere level 9: 20 * 4^9 = 5,242,880 triangles. Timing is not asserted here (it is
  // measured in the benchmark); this proves the size builds and keeps its invariants.
  Object object = makeObject(Shape::Icosphere);
  object.radius = 1;
  object.subdivide = 9;
  ObjectMesh m = buildObjectMesh(object);
  EXPECT_EQ(m.mesh.triangles.size(), 20u << 18);
  EXPECT_EQ(m.mesh.positions.size(), (10u << 18) + 2);
  for (size_t v = 0; v < m.mesh.positions.size(); v += 997)
    EXPECT_NEAR(glm::length(m.mesh.positions[v]), 1.0f, 1e-6f);
}

}  // namespace
}  // namespace phongvk
