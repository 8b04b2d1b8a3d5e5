// scene_test.cpp — scene loading: a full scene reads back with the right values, and everything
// left out takes its default (docs/DESIGN.md "Scene file").
#include "scene/scene.h"
#include "tests/scene_fixtures.h"
#include "test_util.h"

#include <gtest/gtest.h>

namespace phongvk {
namespace {

using namespace test;
using nlohmann::ordered_json;

// The docs/DESIGN.md example, with the mesh pointing at a file the test creates.
const char* kFullScene = R"({
  "camera": {"position": [-3.5, -2.45, 2.1], "look_at": [0, 0, 0], "fov": 60, "aspect": 1.5, "resolution": 800},
  "background": [0, 0, 0],
  "ambient": [1, 1, 1],
  "lights": [{"position": [-0.7, -0.6, 0.8], "intensity": 1.0, "color": [1, 1, 1]}],
  "materials": {"grey": {"ka": 0.15, "kd": 1.0, "ks": 0.8, "n": 10, "attenuation": [1, 0.2, 0.2], "color": [0.8, 0.8, 0.8]}},
  "objects": [
    {"shape": "sphere", "center": [0, 0, 0], "radius": 0.5, "segments": 32, "material": "grey"},
    {"shape": "cube", "center": [0, 0, 0], "size": 1, "subdivide": 3, "material": "grey"},
    {"shape": "cylinder", "center": [0, 0, 0], "radius": 0.5, "height": 1, "segments": 32, "material": "grey"},
    {"shape": "cone", "center": [0, 0, 0], "radius": 0.5, "height": 1, "segments": 32, "rings": 8, "material": "grey"},
    {"shape": "icosphere", "center": [0, 0, 0], "radius": 0.5, "subdivide": 3, "material": "grey"},
    {"shape": "polyhedron", "points": [[0,0,-0.5],[1,0,-0.5],[0,1,-0.5],[1,1,-0.5],[0,0,0.1],[1,0,0.5],[0.3,0.3,0.4]], "material": "grey"},
    {"shape": "mesh", "file": "meshes/tiny.obj", "scale": 1, "translate": [0, 0, 0], "material": "grey"}
  ],
  "render": {"interpolation": "perspective"}
})";

const char* kTetrahedronObj =
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";

// ---- valid scenes ----

TEST(SceneSpec, FullExampleLoadsWithItsValues) {
  std::string dir = test::makeTempDir();
  test::writeFile(dir + "/meshes/tiny.obj", kTetrahedronObj);
  test::writeFile(dir + "/scene.json", kFullScene);
  SceneSpec scene = loadSceneSpec(dir + "/scene.json");

  EXPECT_EQ(scene.path, dir + "/scene.json");
  // look_at [0,0,0] from position P gives direction -P.
  EXPECT_EQ(scene.camera.position, glm::dvec3(-3.5, -2.45, 2.1));
  EXPECT_EQ(scene.camera.direction, glm::dvec3(3.5, 2.45, -2.1));
  ASSERT_EQ(scene.lights.size(), 1u);
  EXPECT_EQ(scene.lights[0].position, glm::dvec3(-0.7, -0.6, 0.8));
  ASSERT_EQ(scene.materials.size(), 1u);  // every object names "grey": no default added
  EXPECT_EQ(scene.materials[0].attenuation, glm::vec3(1.0f, 0.2f, 0.2f));
  EXPECT_EQ(scene.materials[0].color, glm::vec3(0.8f));

  ASSERT_EQ(scene.objects.size(), 7u);
  const Shape shapes[] = {Shape::Sphere,    Shape::Cube,       Shape::Cylinder, Shape::Cone,
                          Shape::Icosphere, Shape::Polyhedron, Shape::Mesh};
  for (size_t i = 0; i < 7; ++i) {
    EXPECT_EQ(scene.objects[i].shape, shapes[i]) << i;
    EXPECT_EQ(scene.objects[i].jsonPath, "objects[" + std::to_string(i) + "]");
    EXPECT_EQ(scene.objects[i].material, 0);
  }
  EXPECT_EQ(scene.objects[1].subdivide, 3);
  EXPECT_EQ(scene.objects[3].rings, 8);
  ASSERT_EQ(scene.objects[5].points.size(), 7u);
  EXPECT_EQ(scene.objects[5].points[6], glm::dvec3(0.3, 0.3, 0.4));
  // The mesh path resolves against the scene's folder; meshes default to not culled.
  EXPECT_EQ(scene.objects[6].file, dir + "/meshes/tiny.obj");
  EXPECT_FALSE(scene.objects[6].closed);
  EXPECT_TRUE(scene.objects[0].closed);
}

TEST(SceneSpec, DefaultsFillEverythingLeftOut) {
  SceneSpec scene = parse(kMinimalScene);
  EXPECT_EQ(scene.path, "a.json");
  EXPECT_EQ(scene.camera.up, glm::dvec3(0, 0, 1));
  EXPECT_EQ(scene.camera.fov, 60);
  EXPECT_EQ(scene.camera.aspect, 1.5);
  EXPECT_EQ(scene.camera.resolution, 800);
  EXPECT_EQ(scene.camera.width, 0);
  EXPECT_EQ(scene.camera.nearPlane, 0.05);
  EXPECT_EQ(scene.camera.farPlane, 1000);
  EXPECT_EQ(scene.background, glm::vec3(0));
  EXPECT_EQ(scene.ambient, glm::vec3(1));
  EXPECT_TRUE(scene.lights.empty());
  EXPECT_EQ(scene.interpolation, Interpolation::Perspective);

  const Object& sphere = scene.objects.at(0);
  EXPECT_EQ(sphere.radius, 0.5);
  EXPECT_EQ(sphere.segments, 32);
  EXPECT_EQ(sphere.subdivide, 0);
  EXPECT_TRUE(sphere.closed);
  // No material named: one default material is appended for it.
  ASSERT_EQ(scene.materials.size(), 1u);
  EXPECT_EQ(sphere.material, 0);
  EXPECT_EQ(scene.materials[0].ks, 0.8f);
  EXPECT_EQ(scene.materials[0].n, 10.0f);
}

TEST(SceneSpec, LightDefaults) {
  SceneSpec scene = parse(minimalWith([](ordered_json& s) {
                        s["lights"] = {{{"position", {1, 2, 3}}}};
                      }).dump());
  ASSERT_EQ(scene.lights.size(), 1u);
  EXPECT_EQ(scene.lights[0].intensity, 1.0f);
  EXPECT_EQ(scene.lights[0].color, glm::vec3(1));
}

// Named materials keep file order (not sorted by name); inline ones follow, each its own entry;
// all objects without a material share one default.
TEST(SceneSpec, MaterialIndicesNamedFirstThenInline) {
  SceneSpec scene = parse(R"({
    "camera": {"position": [0, 0, 0], "direction": [1, 0, 0]},
    "materials": {"zeta": {"ks": 0.1}, "alpha": {"ks": 0.2}},
    "objects": [
      {"shape": "sphere", "material": {"ks": 0.3}},
      {"shape": "cube", "material": "alpha"},
      {"shape": "cube"},
      {"shape": "cone", "material": {"ks": 0.4}},
      {"shape": "cube"},
      {"shape": "sphere", "material": "zeta"}
    ]})");
  std::vector<int> indices;
  for (const Object& object : scene.objects) indices.push_back(object.material);
  EXPECT_EQ(indices, (std::vector<int>{2, 1, 3, 4, 3, 0}));
  ASSERT_EQ(scene.materials.size(), 5u);
  EXPECT_EQ(scene.materials[0].ks, 0.1f);
  EXPECT_EQ(scene.materials[1].ks, 0.2f);
  EXPECT_EQ(scene.materials[2].ks, 0.3f);
  EXPECT_EQ(scene.materials[3].ks, MaterialSpec{}.ks);
  EXPECT_EQ(scene.materials[4].ks, 0.4f);
}

TEST(SceneSpec, WidthAndHeightSetTheAspect) {
  SceneSpec scene = parse(minimalWith([](ordered_json& s) {
                        s["camera"]["width"] = 640;
                        s["camera"]["height"] = 480.0;  // integral, though written as a real
                      }).dump());
  EXPECT_EQ(scene.camera.width, 640);
  EXPECT_EQ(scene.camera.height, 480);
  EXPECT_DOUBLE_EQ(scene.camera.aspect, 640.0 / 480.0);
}

TEST(SceneSpec, RenderModesDefaultToThePapersAndCanBeChanged) {
  const SceneSpec plain = parse(minimalWith([](ordered_json&) {}).dump());
  EXPECT_EQ(plain.shading, Shading::Gouraud);
  EXPECT_EQ(plain.specular, Specular::Phong);
  EXPECT_EQ(plain.samples, 1);
  const SceneSpec scene = parse(minimalWith([](ordered_json& s) {
                                  s["render"] = {{"shading", "phong"}, {"specular", "blinn"}, {"samples", 9}};
                                }).dump());
  EXPECT_EQ(scene.shading, Shading::Phong);
  EXPECT_EQ(scene.specular, Specular::Blinn);
  EXPECT_EQ(scene.samples, 9);
  const SceneSpec flat = test::withRenderOptions(scene, R"({"shading": "flat", "samples": 1})");
  EXPECT_EQ(flat.shading, Shading::Flat);
  EXPECT_EQ(flat.specular, Specular::Blinn) << "options not named keep the scene's";
  EXPECT_EQ(flat.samples, 1);
}

TEST(SceneSpec, ClosedAndInterpolationCanBeChanged) {
  SceneSpec scene = parse(minimalWith([](ordered_json& s) {
                        s["objects"][0]["closed"] = false;
                        s["render"]["interpolation"] = "screen";
                      }).dump());
  EXPECT_FALSE(scene.objects[0].closed);
  EXPECT_EQ(scene.interpolation, Interpolation::Screen);
}

// A negative linear term is fine while the quadratic has no positive root: 1 - d + d^2 > 0.
TEST(SceneSpec, AttenuationWithNegativeLinearTermAccepted) {
  SceneSpec scene = parse(minimalWith([](ordered_json& s) {
                        s["materials"]["m"]["attenuation"] = {1, -1, 1};
                      }).dump());
  EXPECT_EQ(scene.materials[0].attenuation, glm::vec3(1, -1, 1));
}

// ---- files and syntax ----

}  // namespace
}  // namespace phongvk
