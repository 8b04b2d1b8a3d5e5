// scene_parts_gpu_test.cpp — materials and render settings given as typed values (scene_parts.h):
// a scene built in code renders the bytes of the same scene written as a file, field by field, on
// both backends; a bad value fails with the file's message; the defaults are the file's.
#include "phongvk/phongvk.h"
#include "test_util.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

namespace phongvk {
namespace {

// An octahedron about the origin, as arrays and as the same OBJ file.
MeshArrays octahedron() {
  MeshArrays mesh;
  mesh.positions = {0.5f, 0, 0, -0.5f, 0, 0, 0, 0.5f, 0, 0, -0.5f, 0, 0, 0, 0.5f, 0, 0, -0.5f};
  mesh.triangles = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};
  return mesh;
}

std::string octahedronObj() {
  const MeshArrays mesh = octahedron();
  std::string text;
  for (size_t i = 0; i < mesh.positions.size(); i += 3) {
    text += "v " + std::to_string(mesh.positions[i]) + " " + std::to_string(mesh.positions[i + 1]) + " " +
            std::to_string(mesh.positions[i + 2]) + "\n";
  }
  for (size_t i = 0; i < mesh.triangles.size(); i += 3) {
    text += "f " + std::to_string(mesh.triangles[i] + 1) + " " + std::to_string(mesh.triangles[i + 1] + 1) + " " +
            std::to_string(mesh.triangles[i + 2] + 1) + "\n";
  }
  return text;
}

// The scene Scene(96, 64) starts from, written as a file: the default camera at that size and one
// light at the camera; `more` adds top-level keys and `material` the octahedron's (none: "").
std::string written(const std::string& material, const std::string& more = "") {
  return R"({"camera": {"position": [0, -5, 2], "look_at": [0, 0, 0], "width": 96, "height": 64},
             "lights": [{"position": "camera"}], )" + more + R"("objects": [{"shape": "mesh", "file": "oct.obj")" +
         (material.empty() ? "" : R"(, "material": )" + material) + "}]}";
}

// A material object of a file as Material{} with its fields: the file's without fall-off.
std::string inCode(const std::string& material) {
  if (material.find("attenuation") != std::string::npos) return material;
  return R"({"attenuation": [1, 0, 0])" + (material.size() > 2 ? ", " + material.substr(1) : std::string("}"));
}

// A value set in code, and the same written in the file.
template <typename T>
struct Field {
  std::string json;
  std::function<void(T&)> set;
};

const std::vector<Field<Material>> MATERIAL_FIELDS = {
    {R"({"ka": 0.6})", [](Material& m) { m.ka = 0.6; }},
    {R"({"kd": 0.3})", [](Material& m) { m.kd = 0.3; }},
    {R"({"ks": 0.1})", [](Material& m) { m.ks = 0.1; }},
    {R"({"n": 40})", [](Material& m) { m.n = 40; }},
    {R"({"attenuation": [1, 0.05, 0]})", [](Material& m) { m.attenuation = {1, 0.05, 0}; }},
    {R"({"color": [0.9, 0.3, 0.1]})", [](Material& m) { m.color = {0.9, 0.3, 0.1}; }},
    {R"({"ka": 0.3, "kd": 0.7, "ks": 1, "n": 3, "attenuation": [0.5, 0, 0.01], "color": [0.2, 1, 0.6]})",
     [](Material& m) { m = {0.3, 0.7, 1, 3, {0.5, 0, 0.01}, {0.2, 1, 0.6}}; }},
};

// Render settings: the file's "render" (and "background") keys, and the same set in code.
const std::vector<Field<RenderSettings>> RENDER_FIELDS = {
    {R"("render": {"shading": "flat"}, )", [](RenderSettings& s) { s.shading = Shading::Flat; }},
    {R"("render": {"shading": "phong"}, )", [](RenderSettings& s) { s.shading = Shading::Phong; }},
    {R"("render": {"specular": "blinn"}, )", [](RenderSettings& s) { s.specular = Specular::Blinn; }},
    {R"("render": {"interpolation": "screen"}, )", [](RenderSettings& s) { s.interpolation = Interpolation::Screen; }},
    {R"("render": {"samples": 4}, )", [](RenderSettings& s) { s.samples = 4; }},
    {R"("render": {"samples": 16}, )", [](RenderSettings& s) { s.samples = 16; }},
    {R"("background": [0.25, 0.5, 0.75], )", [](RenderSettings& s) { s.background = {0.25, 0.5, 0.75}; }},
    {R"("render": {"shading": "phong", "specular": "blinn", "samples": 9, "interpolation": "screen"},
        "background": [1, 0.5, 0], )",
     [](RenderSettings& s) { s = {Shading::Phong, Specular::Blinn, Interpolation::Screen, 9, {1, 0.5, 0}}; }},
};

// The message of the SceneError or ArgumentError `call` throws.
std::string failure(const std::function<void()>& call) {
  try {
    call();
  } catch (const SceneError& e) {
    return std::string("SceneError: ") + e.what();
  } catch (const ArgumentError& e) {
    return std::string("ArgumentError: ") + e.what();
  }
  return "(no error)";
}

class SceneParts : public ::testing::Test {
 protected:
  void SetUp() override { test::writeFile(dir_ + "/oct.obj", octahedronObj()); }

  Scene file(const std::string& text) const { return parseScene(text, "", dir_); }

  // The octahedron added in code with `material`, in the empty scene of that size.
  static Scene built(const Material& material) {
    Scene scene(96, 64);
    scene.add(octahedron(), IDENTITY_POSE, material);
    return scene;
  }

  // Both backends render `code` as the reference renders `file`.
  void expectSame(const Scene& code, const Scene& file, const std::string& what) {
    const Image expected = cpu_.render(file);
    EXPECT_TRUE(cpu_.render(code).rgb == expected.rgb) << what << ": cpu";
    EXPECT_TRUE(gpu_.render(code).rgb == expected.rgb) << what << ": gpu";
  }

  std::string dir_ = test::makeTempDir();
  Renderer cpu_{Backend::Cpu};
  Renderer gpu_{RendererOptions{Backend::Gpu, -1, true}};
};

TEST_F(SceneParts, EveryMaterialFieldRendersAsTheFileSaysIt) {
  expectSame(built(Material{}), file(written(inCode("{}"))), "the default material");
  for (const Field<Material>& field : MATERIAL_FIELDS) {
    Material material;
    field.set(material);
    expectSame(built(material), file(written(inCode(field.json))), field.json);
  }
}

TEST_F(SceneParts, EveryRenderSettingRendersAsTheFileSaysIt) {
  const Scene plain = built(Material{});
  for (const Field<RenderSettings>& field : RENDER_FIELDS) {
    RenderSettings settings;
    field.set(settings);
    Scene assigned = plain;
    assigned.setRenderSettings(settings);
    EXPECT_EQ(assigned.renderSettings(), settings) << field.json;
    EXPECT_EQ(file(written("", field.json)).renderSettings(), settings) << field.json;
    expectSame(assigned, file(written(inCode("{}"), field.json)), field.json);
    expectSame(plain.withRender(settings), file(written(inCode("{}"), field.json)), field.json);
  }
}

TEST_F(SceneParts, TheAmbientLightRendersAsTheFileSaysIt) {
  Scene scene = built(Material{.ka = 0.8});
  scene.setAmbient({0.5, 0.25, 0});
  EXPECT_EQ(scene.ambient(), (Vec3{0.5, 0.25, 0}));
  expectSame(scene, file(written(inCode(R"({"ka": 0.8})"), R"("ambient": [0.5, 0.25, 0], )")), "ambient");
  const std::string expected = failure([&] { file(written("", R"("ambient": [1, -1, 0], )")); });
  EXPECT_EQ(expected, "SceneError: ambient[1]: must be >= 0, got -1");
  EXPECT_EQ(failure([&] { scene.setAmbient({1, -1, 0}); }), expected);
  EXPECT_EQ(failure([&] { scene.setAmbient({1, NAN, 0}); }), "ArgumentError: ambient[1]: must be finite, got nan");
  EXPECT_EQ(scene.ambient(), (Vec3{0.5, 0.25, 0})) << "a failed assignment changes nothing";
}

TEST_F(SceneParts, DefaultsAreTheFilesButTheFallOff) {
  const Scene empty(96, 64);
  EXPECT_EQ(empty.renderSettings(), RenderSettings{});
  EXPECT_EQ(empty.ambient(), (Vec3{1, 1, 1}));
  EXPECT_EQ(file(written("")).renderSettings(), RenderSettings{});
  EXPECT_EQ(empty.objectCount(), 0u);
  EXPECT_EQ(empty.lightCount(), 1u);
  EXPECT_TRUE(empty.lights()[0].atCamera);
  EXPECT_EQ(empty.camera().position, Camera{}.position);
  EXPECT_EQ((std::pair{empty.width(), empty.height()}), (std::pair{96, 64}));
  // Material{} is the material an object of a scene file that names none gets, without fall-off,
  // and the one a mesh added in code without a material gets, as a model file alone has.
  expectSame(built(Material{}), file(written(inCode("{}"))), "Material{}");
  expectSame(built(Material{.attenuation = {1, 0.2, 0.2}}), file(written("")), "the file's default");
  Scene defaulted(96, 64);
  defaulted.addMesh(octahedron());
  expectSame(defaulted, file(written(R"({"attenuation": [1, 0, 0]})")), "addMesh without a material");
  Scene added(96, 64);
  added.add(octahedron());
  expectSame(added, file(written(R"({"attenuation": [1, 0, 0]})")), "add without a material");
  EXPECT_EQ(test::thrownMessage<SceneError>([&] { cpu_.render(empty); }), "objects: scene has no objects");
}

TEST_F(SceneParts, BadMaterialsFailWithTheFilesMessage) {
  for (const Field<Material>& bad : std::vector<Field<Material>>{
           {R"({"ka": -0.5})", [](Material& m) { m.ka = -0.5; }},
           {R"({"kd": -1})", [](Material& m) { m.kd = -1; }},
           {R"({"ks": -1})", [](Material& m) { m.ks = -1; }},
           {R"({"n": -2})", [](Material& m) { m.n = -2; }},
           {R"({"ks": 1e39})", [](Material& m) { m.ks = 1e39; }},
           {R"({"attenuation": [0, 0, 0]})", [](Material& m) { m.attenuation = {0, 0, 0}; }},
           {R"({"attenuation": [1, -3, 1]})", [](Material& m) { m.attenuation = {1, -3, 1}; }},
           {R"({"color": [0.5, -0.1, 0]})", [](Material& m) { m.color = {0.5, -0.1, 0}; }}}) {
    Material material;
    bad.set(material);
    Scene scene(96, 64);
    const std::string expected = failure([&] { file(written(bad.json)); });
    EXPECT_NE(expected.find("objects[0].material."), std::string::npos) << expected;
    EXPECT_EQ(failure([&] { scene.add(octahedron(), IDENTITY_POSE, material); }), expected);
    EXPECT_EQ(scene.objectCount(), 0u) << "a failed add changes nothing";
  }
  Scene scene(96, 64);
  EXPECT_EQ(failure([&] { scene.addMesh(octahedron(), Material{.ka = NAN}); }),
            "ArgumentError: material.ka: must be finite, got nan");
  EXPECT_EQ(failure([&] { scene.addMesh(octahedron(), Material{.color = {0, INFINITY, 0}}); }),
            "ArgumentError: material.color[1]: must be finite, got inf");
  EXPECT_EQ(failure([&] { scene.addMesh(octahedron(), "gold"); }),
            "SceneError: objects[0].material: unknown material 'gold' (no named materials are defined)");
}

TEST_F(SceneParts, BadRenderSettingsFailWithTheFilesMessage) {
  for (const Field<RenderSettings>& bad : std::vector<Field<RenderSettings>>{
           {R"("render": {"samples": 3}, )", [](RenderSettings& s) { s.samples = 3; }},
           {R"("render": {"samples": 25}, )", [](RenderSettings& s) { s.samples = 25; }},
           {R"("background": [1.5, 0, 0], )", [](RenderSettings& s) { s.background = {1.5, 0, 0}; }},
           {R"("background": [0, 0, -1], )", [](RenderSettings& s) { s.background = {0, 0, -1}; }}}) {
    RenderSettings settings;
    bad.set(settings);
    Scene scene = built(Material{});
    const std::string expected = failure([&] { file(written("", bad.json)); });
    EXPECT_EQ(failure([&] { scene.setRenderSettings(settings); }), expected);
    EXPECT_EQ(failure([&] { scene.withRender(settings); }), expected);
    EXPECT_EQ(scene.renderSettings(), RenderSettings{}) << "a failed assignment changes nothing";
  }
  EXPECT_EQ(failure([] { parseShading("smooth"); }),
            "SceneError: render.shading: must be one of gouraud, flat, phong, got 'smooth'");
  EXPECT_EQ(failure([] { parseSpecular("cook-torrance"); }),
            "SceneError: render.specular: must be one of phong, blinn, got 'cook-torrance'");
  EXPECT_EQ(failure([] { parseInterpolation("linear"); }),
            "SceneError: render.interpolation: must be one of perspective, screen, got 'linear'");
  EXPECT_EQ(failure([&] { built(Material{}).withRender({.shading = Shading(7)}); }),
            "SceneError: render.shading: must be one of gouraud, flat, phong, got ''");
  EXPECT_EQ(failure([&] { built(Material{}).withRender({.background = {NAN, 0, 0}}); }),
            "ArgumentError: background[0]: must be finite, got nan");
}

// Each pixel's object id in a frame of `scene`, on both backends (which must agree).
std::vector<int32_t> objectIdsOf(const Scene& scene) {
  const RenderedFrame cpu = Renderer(Backend::Cpu).renderOutputs(scene, {.objectIds = true});
  const RenderedFrame gpu = Renderer(Backend::Gpu).renderOutputs(scene, {.objectIds = true});
  EXPECT_EQ(cpu.objectIds, gpu.objectIds);
  std::vector<int32_t> ids = cpu.objectIds;
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  return ids;
}

Matrix4 translated(double x) {
  Matrix4 pose = IDENTITY_POSE;
  pose[3] = x;
  return pose;
}

TEST(SceneHandles, ObjectIdsStayWithTheirObjectsAndTravelWithTheText) {
  Scene scene(96, 64);
  MeshArrays small = octahedron();
  for (float& p : small.positions) p *= 0.5f;
  const ObjectId a = scene.add(small, translated(-1)), b = scene.add(small), c = scene.add(small, translated(1));
  EXPECT_EQ(scene.objectId(a), 0);
  EXPECT_EQ(scene.objectId(c), 2);
  scene.remove(b);
  const ObjectId d = scene.add(small, translated(0.2));
  EXPECT_EQ(scene.objectId(d), 3);
  EXPECT_EQ(objectIdsOf(scene), (std::vector<int32_t>{-1, 0, 2, 3}));
  scene.setObjectId(c, 9);
  EXPECT_EQ(objectIdsOf(scene), (std::vector<int32_t>{-1, 0, 3, 9}));
  EXPECT_EQ(objectIdsOf(parseScene(scene.toJson())), (std::vector<int32_t>{-1, 0, 3, 9}));
  EXPECT_THROW(scene.setObjectId(a, -1), ArgumentError);
  EXPECT_THROW(scene.objectId(b), RangeError);
}

TEST(SceneHandles, SetMeshKeepsTheObjectsPlaceAndId) {
  Scene swapped(96, 64), direct(96, 64);
  MeshArrays small = octahedron();
  for (float& p : small.positions) p *= 0.5f;
  const ObjectId id = swapped.add(small, translated(0.5));
  swapped.setMesh(id, TriangleMesh(octahedron()));
  direct.add(octahedron(), translated(0.5));
  EXPECT_EQ(Renderer(Backend::Cpu).render(swapped).rgb, Renderer(Backend::Gpu).render(direct).rgb);
  EXPECT_EQ(swapped.objectId(id), 0);
}

TEST(SceneHandles, LightsAddedByHandleAreChangedAndRemovedByIt) {
  Scene scene(96, 64);
  scene.add(octahedron());
  const LightId red = scene.addLight({.position = {2, -3, 2}, .color = {1, 0, 0}});
  const LightId blue = scene.addLight({.position = {-2, -3, 2}, .color = {0, 0, 1}});
  EXPECT_EQ(scene.lightCount(), 3u);
  scene.removeLight(red);
  EXPECT_EQ(scene.light(blue).color, (Vec3{0, 0, 1}));
  scene.setLight(blue, {.position = {-2, -3, 2}, .intensity = 2});
  EXPECT_EQ(scene.lights()[1].intensity, 2);
  scene.setLightAt(0, {.position = {0, -4, 0}});
  EXPECT_EQ(scene.light(blue).intensity, 2);  // the handle's light kept its place
  EXPECT_THROW(scene.light(red), RangeError);
  EXPECT_THROW(scene.setLightAt(5, {}), RangeError);
  EXPECT_THROW(scene.addLight({.intensity = NAN}), ArgumentError);
  EXPECT_EQ(scene.lightCount(), 2u);
  Scene written = parseScene(scene.toJson());
  EXPECT_EQ(Renderer(Backend::Cpu).render(scene).rgb, Renderer(Backend::Gpu).render(written).rgb);
  scene.setLights({Light{}});
  EXPECT_THROW(scene.light(blue), RangeError);  // setLights retires every handle
  EXPECT_NO_THROW(scene.setLights({{.position = {NAN, 0, 0}, .atCamera = true}}));  // at the camera: position unused
}

TEST(SceneHandles, VertexColoursFromArraysMultiplyTheMaterial) {
  MeshArrays coloured = octahedron();
  for (int v = 0; v < 6; ++v) coloured.colors.insert(coloured.colors.end(), {255, uint8_t(40 * v), 0, 255});
  Scene scene(96, 64), white(96, 64);
  scene.add(coloured);
  white.add(octahedron());
  const Image image = Renderer(Backend::Cpu).render(scene);
  EXPECT_EQ(image.rgb, Renderer(Backend::Gpu).render(scene).rgb);
  EXPECT_NE(image.rgb, Renderer(Backend::Cpu).render(white).rgb);
  EXPECT_EQ(Renderer(Backend::Cpu).render(parseScene(scene.toJson())).rgb, image.rgb);
  coloured.colors.pop_back();
  EXPECT_THROW(TriangleMesh{coloured}, ArgumentError);
}

// A turn by `angle` about z, scaled along x by `scale`, then shifted by `x`.
Matrix4 turned(double angle, double x, double scale = 1) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * scale, -s, 0, x, s * scale, c, 0, 0.1, 0, 0, 1, -0.2, 0, 0, 0, 1};
}

TEST(SceneHandles, AMovedObjectBuildsNothingAndRendersAsOneBuiltWhereItStands) {
  Renderer cpu(Backend::Cpu), gpu(Backend::Gpu);
  setenv("PHONGVK_KEY_PATH", "32", 1);  // the 32-bit key path's passes turn posed vertices too
  Renderer gpu32(Backend::Gpu);
  unsetenv("PHONGVK_KEY_PATH");
  Scene scene(96, 64);
  scene.setRenderSettings({.shading = Shading::Phong});
  const ObjectId id = scene.add(octahedron(), turned(0.2, 0));
  for (const Matrix4& pose : {turned(0.9, 0.3, 1.4), IDENTITY_POSE, turned(-0.4, -0.2)}) {
    scene.setPose(id, pose);
    Scene fresh(96, 64);
    fresh.setRenderSettings({.shading = Shading::Phong});
    fresh.add(octahedron(), pose);
    const Outputs outputs{.depth = true, .normals = true};
    const RenderedFrame expected = Renderer(Backend::Cpu).renderOutputs(fresh, outputs);
    for (Renderer* r : {&cpu, &gpu, &gpu32}) {
      const RenderedFrame moved = r->renderOutputs(scene, outputs);
      EXPECT_EQ(moved.image.rgb, expected.image.rgb) << r->deviceName();
      EXPECT_EQ(moved.depth, expected.depth) << r->deviceName();
      EXPECT_EQ(moved.normals, expected.normals) << r->deviceName();
    }
  }
  for (Renderer* r : {&cpu, &gpu, &gpu32}) EXPECT_EQ(r->stats().sceneBuilds, 1u) << r->deviceName();
}

TEST(SceneHandles, AClosedRendererRefusesToRender) {
  Renderer renderer(Backend::Gpu);
  Scene scene(32, 24);
  scene.add(octahedron());
  EXPECT_EQ(renderer.render(scene).width, 32);
  renderer.close();
  EXPECT_THROW(renderer.render(scene), ArgumentError);
  EXPECT_THROW(renderer.stats(), ArgumentError);
  renderer.close();
}

TEST(SceneNames, EveryChoiceHasTheFilesNameBothWays) {
  for (Shading s : {Shading::Gouraud, Shading::Flat, Shading::Phong}) EXPECT_EQ(parseShading(shadingName(s)), s);
  for (Specular s : {Specular::Phong, Specular::Blinn}) EXPECT_EQ(parseSpecular(specularName(s)), s);
  for (Interpolation i : {Interpolation::Perspective, Interpolation::Screen})
    EXPECT_EQ(parseInterpolation(interpolationName(i)), i);
  EXPECT_STREQ(shadingName(Shading::Phong), "phong");
  EXPECT_STREQ(specularName(Specular::Blinn), "blinn");
  EXPECT_STREQ(interpolationName(Interpolation::Screen), "screen");
}

}  // namespace
}  // namespace phongvk
