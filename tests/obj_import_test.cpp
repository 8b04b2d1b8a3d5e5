// obj_import_test.cpp — `mesh` objects from OBJ files (obj_import.h): normals kept or computed,
// subdivision, numbers in every form, and errors naming the JSON path, the file and the line.
#include "scene/object_mesh.h"
#include "tests/mesh_checks.h"
#include "tests/test_util.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace phongvk {
namespace {

using namespace test;

Object objObject(const std::string& file) {
  Object object = makeObject(Shape::Mesh);
  object.jsonPath = "objects[6]";
  object.file = file;
  object.closed = false;
  return object;
}

TEST(ObjMesh, FileNormalsAreKept) {
  Object object = objObject(test::sourcePath("tests/data/meshes/tetrahedron_normals.obj"));
  object.scale = glm::dvec3(2);
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
  expectObjError("this is not\nan OBJ file \x01\x02\n", "nothing to draw (no 'f', 'l', 'p' or 'v' lines)");
  expectObjError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n",
                 "line 4: face corner '9': vertex index 9 is out of range (the file has 3 vertices)");
  expectObjError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -7\n",
                 "line 4: face corner '-7': vertex index -7 is out of range (the file has 3 vertices)");
  expectObjError("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3 9\n",
                 "line 5: face corner '9': vertex index 9 is out of range (the file has 4 vertices)");
  // A texture coordinate index out of range, positive or negative (tinyobjloader leaves a bad
  // negative one as "none").
  expectObjError("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/-100 2/2 3/3\n",
                 "line 7: face corner '1/-100': texture coordinate index -100 is out of range (the file has 3 'vt' lines)");
  expectObjError("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/-4 2/2 3/3\n",
                 "line 7: face corner '1/-4': texture coordinate index -4 is out of range (the file has 3 'vt' lines)");
  expectObjError("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//-2 2//1 3//1\n",
                 "line 5: face corner '1//-2': normal index -2 is out of range (the file has 1 normals)");
  expectObjError("v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\nf 1 1 2\n",
                 "every triangle is degenerate (zero area)");
  // tinyobjloader reads these as 0; they must not become a vertex at the origin.
  expectObjError("v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n", "line 2: 'nan' in a 'v' line is not a number");
  expectObjError("v 0 0 0\nv 1 0 0\nv 0 -inf 0\nf 1 2 3\n", "line 3: '-inf' in a 'v' line is not a number");
  expectObjError("v 0 0 0\nv 0x1p3 0 0\nv 0 1 0\nf 1 2 3\n", "line 2: '0x1p3' in a 'v' line is not a number");
  expectObjError("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1e\nf 1//1 2//1 3//1\n",
                 "line 4: '1e' in a 'vn' line is not a number");
  expectObjError("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt . 0\nf 1 2 3\n", "line 4: '.' in a 'vt' line is not a number");
  // Silent wrong geometry once: an index that wrapped to 3 or to the last vertex, a missing z read as 0.
  const std::string three = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  expectObjError(three + "f 1 2 4294967299\n",
                 "line 4: '4294967299' is not a face corner (v, v/vt, v//vn or v/vt/vn, indices 32-bit and not 0)");
  expectObjError(three + "f 1 2 99999999999999999999\n",
                 "line 4: '99999999999999999999' is not a face corner (v, v/vt, v//vn or v/vt/vn, indices 32-bit and not 0)");
  expectObjError("v 0 0 0\nv 1 0\nv 0 1 0\nf 1 2 3\n", "line 2: a 'v' line needs x, y and z, got 2 numbers");
  expectObjError(three + "f 1 2\n", "line 4: a face needs 3 corners or more, got 2");
  expectObjError(three + "f 1 0 2\n", "line 4: '0' is not a face corner (v, v/vt, v//vn or v/vt/vn, indices 32-bit and not 0)");
  expectObjError(std::string("\xff\xfev\0 \0""0\0", 8), "not a text file (it holds NUL bytes: binary, or UTF-16 text, which OBJ is not)");
}

// A thin ring as one concave polygon (as some exporters write it): ear clipping keeps the hole
// open where a fan from the first corner would fill it.
TEST(ObjMesh, ConcavePolygonsAreNotFanned) {
  std::string obj;
  const int n = 33;  // corners on each circle: outer counter-clockwise, then inner back, joined by a slit
  for (int i = 0; i <= n; ++i) {
    const double a = 2 * M_PI * i / n;
    obj += "v " + std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " 0\n";
  }
  for (int i = n; i >= 0; --i) {
    const double a = 2 * M_PI * i / n;
    obj += "v " + std::to_string(0.8 * std::cos(a)) + " " + std::to_string(0.8 * std::sin(a)) + " 0\n";
  }
  obj += "f";
  for (int i = 1; i <= 2 * (n + 1); ++i) obj.append(" ").append(std::to_string(i));  // not " " + ...: GCC 12 -Wrestrict
  const std::string path = test::makeTempDir() + "/ring.obj";
  test::writeFile(path, obj + "\n");
  const ObjectMesh m = buildObjectMesh(objObject(path));
  for (const glm::uvec3& t : m.mesh.triangles) {
    const glm::vec3 c = (m.mesh.positions[t.x] + m.mesh.positions[t.y] + m.mesh.positions[t.z]) / 3.0f;
    EXPECT_GT(glm::length(glm::vec2(c)), 0.75f) << "a triangle over the hole";
  }
  EXPECT_GE(m.mesh.triangles.size(), size_t(2 * n));
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
  EXPECT_EQ(buildError(objObject(path)), "objects[6].file: " + path + ": cannot open the file: No such file or directory");
}

}  // namespace
}  // namespace phongvk
