// mesh_test.cpp — the facts every object mesh must satisfy (mesh.h, primitives.h, hull.h,
// subdivide.h, obj_import.h, normals.h): counts, watertightness, winding, normals, errors.
#include "scene/mesh.h"
#include "scene/huge_pages.h"
#include "scene/hull.h"
#include "scene/normals.h"
#include "tests/test_util.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <string>

namespace phongvk {
namespace {

// ---- helpers ----

Object makeObject(Shape shape) {
  Object object;
  object.shape = shape;
  object.jsonPath = "objects[4]";
  return object;
}

std::array<uint32_t, 3> bitsOf(glm::vec3 p) {
  std::array<uint32_t, 3> bits;
  std::memcpy(bits.data(), &p, sizeof bits);
  return bits;
}

// Watertight with consistent orientation: after welding vertices whose positions are bitwise
// equal, every directed edge appears exactly once and its reverse exactly once. A crack (two
// midpoints a rounding apart), a hole, a flipped triangle or a duplicated one all fail this.
::testing::AssertionResult isWatertight(const Mesh& mesh) {
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

glm::dvec3 faceCross(const Mesh& mesh, const glm::uvec3& t) {
  const glm::dvec3 a(mesh.positions[t.x]), b(mesh.positions[t.y]), c(mesh.positions[t.z]);
  return glm::cross(b - a, c - a);
}

// Every triangle has area and winds the way its vertices' normals point.
::testing::AssertionResult windsOutward(const Mesh& mesh) {
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
::testing::AssertionResult normalsPointOut(const Mesh& mesh, glm::dvec3 inside) {
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
std::string buildError(const Object& object) {
  try {
    buildObjectMesh(object);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "no error";
}

void expectClosedConvexShape(const Mesh& mesh, glm::dvec3 inside) {
  EXPECT_TRUE(isWatertight(mesh));
  EXPECT_TRUE(windsOutward(mesh));
  EXPECT_TRUE(normalsPointOut(mesh, inside));
}

// ---- cube ----

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

// ---- polyhedron (convex hull) ----

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

// ---- OBJ import ----

Object objObject(const std::string& file) {
  Object object = makeObject(Shape::Mesh);
  object.jsonPath = "objects[6]";
  object.file = file;
  object.closed = false;
  return object;
}

TEST(ObjMesh, FileNormalsAreKept) {
  Object object = objObject(test::sourcePath("tests/data/meshes/tetrahedron_normals.obj"));
  object.scale = 2;
  object.translate = {5, 6, 7};
  ObjectMesh m = buildObjectMesh(object);
  EXPECT_EQ(m.origin, glm::dvec3(5, 6, 7));
  EXPECT_FALSE(m.closed);  // passed through from the object
  EXPECT_EQ(m.mesh.triangles.size(), 4u);
  EXPECT_EQ(m.mesh.positions.size(), 12u);  // 4 corners x 3 faces, one normal each
  expectClosedConvexShape(m.mesh, {0.5, 0.5, 0.5});
  for (const glm::uvec3& t : m.mesh.triangles) {  // flat: the file's face normals, normalised
    const glm::dvec3 n = glm::normalize(faceCross(m.mesh, t));
    for (uint32_t v : {t.x, t.y, t.z})
      EXPECT_NEAR(glm::length(glm::dvec3(m.mesh.normals[v]) - n), 0.0, 1e-6);
  }
  float largest = 0;
  for (const glm::vec3& p : m.mesh.positions) largest = std::max({largest, p.x, p.y, p.z});
  EXPECT_EQ(largest, 2.0f);  // scaled, local to the translation
}

TEST(ObjMesh, MissingNormalsAreComputedOnSharedVertices) {
  Object object = objObject(test::sourcePath("tests/data/meshes/cube_quads.obj"));
  object.closed = true;
  ObjectMesh m = buildObjectMesh(object);
  EXPECT_TRUE(m.closed);
  EXPECT_EQ(m.mesh.triangles.size(), 12u);  // 6 quads, triangulated
  EXPECT_EQ(m.mesh.positions.size(), 8u);   // welded by the file's position index
  expectClosedConvexShape(m.mesh, {0.5, 0.5, 0.5});
}

TEST(ObjMesh, SubdividesFlat) {
  Object object = objObject(test::sourcePath("tests/data/meshes/cube_quads.obj"));
  object.subdivide = 2;
  ObjectMesh m = buildObjectMesh(object);
  EXPECT_EQ(m.mesh.triangles.size(), 12u * 16);
  EXPECT_TRUE(isWatertight(m.mesh));
  EXPECT_TRUE(normalsPointOut(m.mesh, {0.5, 0.5, 0.5}));
  for (const glm::vec3& p : m.mesh.positions)  // still on the cube's surface
    EXPECT_TRUE(p.x == 0 || p.x == 1 || p.y == 0 || p.y == 1 || p.z == 0 || p.z == 1);
}

void expectObjError(const std::string& text, const std::string& why) {
  const std::string path = test::makeTempDir() + "/bad.obj";
  test::writeFile(path, text);
  EXPECT_EQ(buildError(objObject(path)), "objects[6].file: " + path + ": " + why);
}

TEST(ObjMesh, BadFilesNameTheJsonPathAndTheFile) {
  expectObjError("this is not\nan OBJ file \x01\x02\n", "no triangles (no 'f' lines)");
  expectObjError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n",
                 "a face's vertex index is out of range (the file has 3 vertices)");
  expectObjError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -7\n",
                 "a face's vertex index is out of range (the file has 3 vertices)");
  expectObjError("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3 9\n",
                 "a face's vertex index is out of range");
  expectObjError("v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\nf 1 1 2\n",
                 "every triangle is degenerate (zero area)");
  // tinyobjloader reads these as 0; they must not become a vertex at the origin.
  expectObjError("v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n", "line 2: 'nan' in a 'v' line is not a number");
  expectObjError("v 0 0 0\nv 1 0 0\nv 0 -inf 0\nf 1 2 3\n", "line 3: '-inf' in a 'v' line is not a number");
  expectObjError("v 0 0 0\nv 0x1p3 0 0\nv 0 1 0\nf 1 2 3\n", "line 2: '0x1p3' in a 'v' line is not a number");
  expectObjError("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1e\nf 1//1 2//1 3//1\n",
                 "line 4: '1e' in a 'vn' line is not a number");
  expectObjError("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt . 0\nf 1 2 3\n", "line 4: '.' in a 'vt' line is not a number");
}

TEST(ObjMesh, PlainNumbersInEveryFormAreRead) {
  // Signs, no digits before or after the point, exponents.
  const std::string path = test::makeTempDir() + "/numbers.obj";
  test::writeFile(path, "v +0 -0. .0\nv 1.5E+0 0 0\nv 0 2e-0 0\nf 1 2 3\n");
  ObjectMesh m = buildObjectMesh(objObject(path));
  ASSERT_EQ(m.mesh.triangles.size(), 1u);
  EXPECT_EQ(m.mesh.positions[1].x - m.mesh.positions[0].x, 1.5f);
  EXPECT_EQ(m.mesh.positions[2].y - m.mesh.positions[0].y, 2.0f);
}

TEST(ObjMesh, MissingFileIsAnError) {
  const std::string path = test::makeTempDir() + "/missing.obj";
  EXPECT_EQ(buildError(objObject(path)), "objects[6].file: " + path + ": cannot open the file");
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
