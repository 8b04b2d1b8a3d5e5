// scene_write_test.cpp — Scene::toJson: every scene written back as scene file JSON reads back
// into a scene that renders the same bytes (the reference renderer) and writes the same text; the
// file forms it needs (a rotation matrix, meshes inline) are checked like the rest of the file.
#include "phongvk/phongvk.h"
#include "geometry/transform.h"
#include "base/base64.h"
#include "test_util.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <array>
#include <cstring>
#include <set>
#include <string>
#include <vector>

namespace phongvk {
namespace {

using test::sourcePath;
using test::thrownMessage;

Renderer& reference() {
  static Renderer renderer(Backend::Cpu);
  return renderer;
}

// `scene` written, read back, rendered and written again: the same bytes and the same text.
void expectRoundTrip(const Scene& scene) {
  const std::string text = scene.toJson();
  const Scene back = parseScene(text, "written.json");
  EXPECT_EQ(back.toJson(), text) << "not a fixed point";
  const Image want = reference().render(scene);
  const Image got = reference().render(back);
  ASSERT_EQ(got.width, want.width);
  ASSERT_EQ(got.height, want.height);
  EXPECT_EQ(std::memcmp(got.rgb.data(), want.rgb.data(), want.rgb.size()), 0) << "the written scene renders other bytes";
}

// Pixels of `image` other than its top-left one's colour (the background in these scenes).
size_t drawnPixels(const Image& image) {
  size_t drawn = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) drawn += std::memcmp(image.pixel(x, y), image.pixel(0, 0), 3) != 0;
  return drawn;
}

class EveryScene : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryScene, RoundTripsToTheSameBytesAndText) {
  const Scene scene = loadScene(sourcePath(GetParam()));
  expectRoundTrip(scene);
  if (scene.frameCount() > 1) expectRoundTrip(scene.frame(scene.frameCount() - 1));  // writes that frame
}

INSTANTIATE_TEST_SUITE_P(Scenes, EveryScene, ::testing::ValuesIn(test::allScenes()), test::pathTestName);

TEST(SceneWrite, AModelFileAloneWritesAsAnOrdinaryScene) {
  const Scene model = loadScene(sourcePath("scenes/meshes/torus.obj"));
  expectRoundTrip(model);
  const auto json = nlohmann::json::parse(model.toJson());
  EXPECT_TRUE(json["camera"]["fit"].get<bool>());
  EXPECT_EQ(json["objects"][0]["file"], sourcePath("scenes/meshes/torus.obj"));
}

MeshArrays tetrahedron() {
  MeshArrays mesh;
  mesh.positions = {0.1f, 0.2f, 0.3f, 1.1f, 0.05f, 0.1f, 0.3f, 0.9f, 0.2f, 0.4f, 0.35f, 1.2f};
  mesh.triangles = {0, 2, 1, 0, 1, 3, 1, 2, 3, 2, 0, 3};
  return mesh;
}

// Sheared, scaled unevenly, mirrored and turned: no Euler angles or axis give it.
constexpr Matrix4 kShearedPose = {0.9, 0.35, -0.2, 0.25,  //
                                  -0.1, 1.3, 0.45, -0.4,  //
                                  0.3, -0.2, -0.7, 0.15,  //
                                  0, 0, 0, 1};

// A scene built in code with every typed value set away from its default.
Scene sceneInCode() {
  Scene scene(150, 100);
  const Matrix4 eye = {1, 0, 0, 0.4, 0, 0, 1, -3.1, 0, -1, 0, 1.3, 0, 0, 0, 1};  // OpenCV axes: looks along +y, z up
  Camera camera = cameraFromIntrinsics(131.7, 118.3, 81.25, 43.5, 150, 100, eye, PoseConvention::OpenCV);
  camera.nearPlane = 0.125;
  camera.farPlane = 77.7;
  scene.setCamera(camera);
  scene.setLights({Light{.position = {1.3, -2.2, 2.9}, .intensity = 0.7, .color = {1, 0.9, 0.8}},
                   Light{.intensity = 0.3, .atCamera = true},
                   Light{.intensity = 0.45, .color = {0.2, 0.4, 1}, .directional = true, .direction = {-0.3, 0.6, -1}}});
  scene.setAmbient({0.31, 0.2, 0.17});
  scene.setRenderSettings({Shading::Phong, Specular::Blinn, Interpolation::Screen, 4, {0.05, 0.1, 0.15}});
  scene.add(tetrahedron(), kShearedPose, Material{0.21, 0.7, 0.55, 23.5, {1, 0.1, 0.05}, {0.9, 0.3, 0.2}});
  scene.add(tetrahedron(), {1, 0, 0, -1.2, 0, 1, 0, 0.3, 0, 0, 1, -0.2, 0, 0, 0, 1});  // the default material
  MeshArrays normals = tetrahedron();
  normals.normals = {0.3f, 0.1f, 0.7f, 1, 0, 0, 0, 2, 0, 0.1f, 0.1f, 0.9f};
  scene.add(normals, {0.5, 0, 0, 0.7, 0, 0.5, 0, 0.9, 0, 0, 2, -0.5, 0, 0, 0, 1}, std::nullopt, true);
  return scene;
}

TEST(SceneWrite, ASceneBuiltInCodeRoundTripsEveryTypedValue) {
  const Scene scene = sceneInCode();
  EXPECT_GT(drawnPixels(reference().render(scene)), 1000u);
  expectRoundTrip(scene);
  const Scene back = parseScene(scene.toJson(), "written.json");
  ASSERT_TRUE(back.camera().intrinsics.has_value());
  EXPECT_TRUE(back.camera() == scene.camera());  // every field, the intrinsics too
  ASSERT_EQ(back.lights().size(), 3u);
  EXPECT_TRUE(back.lights() == scene.lights());
  EXPECT_EQ(back.ambient(), scene.ambient());
  EXPECT_EQ(back.renderSettings(), scene.renderSettings());
  EXPECT_EQ(back.objectCount(), 3u);
  // The default material of Scene(width, height) (no fall-off) is written with its values.
  const auto json = nlohmann::json::parse(scene.toJson());
  EXPECT_EQ(json["objects"][1]["material"]["attenuation"], nlohmann::json::array({1.0, 0.0, 0.0}));
}

TEST(SceneWrite, AMeshPlacedByAShearedPoseRoundTripsToTheSameBytes) {
  Scene scene(120, 90);
  scene.setCamera(Camera{.position = {2.5, -3, 2}, .lookAt = {0.3, 0.2, 0.3}});
  scene.add(tetrahedron(), kShearedPose, Material{}, true);
  const ObjectId moved = scene.add(tetrahedron());
  scene.setPose(moved, {0.2, -1.1, 0.05, 0.5, 0.9, 0.3, 0.1, 0.2, -0.1, 0.4, 1.7, -0.3, 0, 0, 0, 1});
  EXPECT_GT(drawnPixels(reference().render(scene)), 200u);
  expectRoundTrip(scene);
  const auto json = nlohmann::json::parse(scene.toJson());
  const auto rows = json["objects"][0]["pose"];  // the pose itself, for the object to read back posed
  EXPECT_FALSE(json["objects"][0].contains("rotate"));
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) EXPECT_EQ(rows[r][c].get<double>(), kShearedPose[size_t(4 * r + c)]);
}

TEST(SceneWrite, NamedMaterialsStayNamedAndTheFileDefaultResolvesToItsValues) {
  const Scene scene = parseScene(R"({"camera": {"position": [3, -4, 2], "look_at": [0, 0, 0], "width": 80, "height": 60},
    "lights": [{"position": [2, -3, 3]}],
    "materials": {"red": {"color": [0.9, 0.1, 0.1], "ks": 0.3}, "unused": {"n": 3}},
    "objects": [{"shape": "sphere", "material": "red", "rotate": {"axis": [1, 2, 3], "angle": 33}},
                {"shape": "cube", "center": [1, 0, 0], "size": 0.5, "rotate": [10, 20, 30]},
                {"shape": "cone", "center": [-1, 0, 0], "scale": [1, -0.5, 2], "subdivide": 1, "closed": false}]})",
                                 "named.json");
  expectRoundTrip(scene);
  const auto json = nlohmann::json::parse(scene.toJson());
  EXPECT_EQ(json["objects"][0]["material"], "red");
  EXPECT_TRUE(json["materials"].contains("unused"));
  EXPECT_EQ(json["objects"][1]["material"]["attenuation"][1].get<double>(), double(0.2f));
}

// One triangle of base colour green.
std::string greenTriangleGltf() {
  const float p[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0.5f};
  const std::string buffer(reinterpret_cast<const char*>(p), sizeof p);
  return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
    "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.2, 0.9, 0.3, 1]}}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "material": 0}]}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0.5]}],
    "bufferViews": [{"buffer": 0, "byteLength": 36}],
    "buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,)" +
         base64Encoded(buffer) + R"("}]})";
}

TEST(SceneWrite, AGltfMeshKeepsItsBaseColoursAndAFittedCameraStaysFitted) {
  const std::string dir = test::makeTempDir();
  test::writeFile(dir + "/green.gltf", greenTriangleGltf());
  const Scene scene = parseScene(R"({"camera": {"fit": true, "width": 90, "height": 70, "fov": 35},
    "lights": [{"position": "camera"}],
    "objects": [{"shape": "mesh", "file": "green.gltf"},
                {"shape": "mesh", "file": "green.gltf", "translate": [1, 0, 0], "material": {"ks": 0.1}},
                {"shape": "mesh", "file": "green.gltf", "translate": [0, 1, 0], "up": "y", "material": {"color": [1, 0, 1]}}]})",
                                 "gltf.json", dir);
  expectRoundTrip(scene);
  const auto json = nlohmann::json::parse(scene.toJson());
  EXPECT_TRUE(json["camera"]["fit"].get<bool>());
  EXPECT_FALSE(json["camera"].contains("position"));
  EXPECT_FALSE(json["objects"][0]["material"].contains("color"));
  EXPECT_FALSE(json["objects"][1]["material"].contains("color"));
  EXPECT_TRUE(json["objects"][2]["material"].contains("color"));
}

TEST(SceneWrite, InlineArraysReadAsAddedArraysDo) {
  Scene added(100, 80);
  MeshArrays mesh = tetrahedron();
  added.add(mesh);
  const Scene inline_ = parseScene(R"({"camera": {"position": [0, -5, 2], "look_at": [0, 0, 0], "width": 100, "height": 80},
    "lights": [{"position": "camera"}],
    "objects": [{"shape": "mesh", "vertices": [[0.1, 0.2, 0.3], [1.1, 0.05, 0.1], [0.3, 0.9, 0.2], [0.4, 0.35, 1.2]],
                 "faces": [[0, 2, 1], [0, 1, 3], [1, 2, 3], [2, 0, 3]], "material": {"attenuation": [1, 0, 0]}}]})",
                                   "inline.json");
  const Image a = reference().render(added), b = reference().render(inline_);
  EXPECT_EQ(a.rgb, b.rgb);
  expectRoundTrip(inline_);
}

// The distinct colours of `image`'s pixels.
size_t colourCount(const Image& image) {
  std::set<std::array<uint8_t, 3>> colours;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) colours.insert({image.pixel(x, y)[0], image.pixel(x, y)[1], image.pixel(x, y)[2]});
  return colours.size();
}

TEST(SceneWrite, AModelFilesTexturesTravelInlineAsPngDataUris) {
  Scene scene(120, 90);
  scene.add(TriangleMesh::fromFile(sourcePath("scenes/meshes/textured_cube.obj")));
  Camera camera;
  camera.position = {2.2, -3.1, 2.4};
  scene.setCamera(camera);
  expectRoundTrip(scene);
  const auto json = nlohmann::json::parse(scene.toJson());
  const auto& mesh = json["objects"][0];
  ASSERT_EQ(mesh["textures"].size(), 1u);
  EXPECT_EQ(mesh["textures"][0]["image"].get<std::string>().rfind("data:image/png;base64,", 0), 0u);
  EXPECT_EQ(mesh["textures"][0]["wrap"], nlohmann::json::array({"repeat", "repeat"}));
  EXPECT_EQ(mesh["texture_ids"].size(), mesh["vertices"].size());
  EXPECT_GT(colourCount(reference().render(parseScene(scene.toJson(), "back.json"))), 100u);
}

// A 2 x 2 texture of four colours, held in memory.
Texture fourColours() {
  const uint8_t rgba[16] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 0, 255};
  return Texture::fromRows(2, 2, [&](int y, uint8_t* row) { std::memcpy(row, rgba + 8 * y, 8); });
}

TEST(SceneWrite, ATextureHeldInMemoryRendersAndTravelsAsADataUri) {
  Scene scene(64, 64);
  Camera camera;
  camera.position = {0, -3, 0};
  scene.setCamera(camera);
  MeshArrays quad;
  quad.positions = {-1, 0, -1, 1, 0, -1, 1, 0, 1, -1, 0, 1};
  quad.triangles = {0, 1, 2, 0, 2, 3};
  quad.uvs = {0, 1, 1, 1, 1, 0, 0, 0};
  Material material;
  material.textureImage = fourColours();
  scene.add(quad, IDENTITY_POSE, material);
  EXPECT_GT(colourCount(reference().render(scene)), 4u);
  expectRoundTrip(scene);
  const auto json = nlohmann::json::parse(scene.toJson());
  EXPECT_EQ(json["objects"][0]["material"]["texture"].get<std::string>().rfind("data:image/png;base64,", 0), 0u);
  material.texture = "checker.png";
  EXPECT_EQ(thrownMessage<ArgumentError>([&] { scene.add(quad, IDENTITY_POSE, material); }),
            "material: a texture file (texture) or one held in memory (textureImage), not both");
  EXPECT_EQ(thrownMessage<SceneError>([] { Texture::fromRows(0, 4, [](int, uint8_t*) {}, "pixels"); }),
            "pixels: the image is 0x4 pixels; a texture's sides are 1 to 16384");
}

// A quad whose coordinates run from -1 to 2, sampling checker.png with the wrap modes `wrap`.
std::string wrappedQuad(const std::string& wrap) {
  return R"({"camera": {"position": [0, -3, 0], "look_at": [0, 0, 0], "width": 96, "height": 96},
    "lights": [{"position": "camera"}],
    "objects": [{"shape": "mesh", "vertices": [[-1, 0, -1], [1, 0, -1], [1, 0, 1], [-1, 0, 1]],
                 "faces": [[0, 1, 2], [0, 2, 3]], "uvs": [[-1, 2], [2, 2], [2, -1], [-1, -1]],
                 "textures": [{"image": ")" + sourcePath("scenes/meshes/checker.png") + R"(", "wrap": )" + wrap + R"(}],
                 "texture_ids": [0, 0, 0, 0]}]})";
}

TEST(SceneWrite, AnInlineMeshsOwnTexturesKeepTheirWrapModes) {
  const Scene repeat = parseScene(wrappedQuad(R"(["repeat", "repeat"])"), "repeat.json");
  const Scene clamp = parseScene(wrappedQuad(R"(["clamp_to_edge", "mirrored_repeat"])"), "clamp.json");
  expectRoundTrip(clamp);
  EXPECT_EQ(nlohmann::json::parse(clamp.toJson())["objects"][0]["textures"][0]["wrap"],
            nlohmann::json::array({"clamp_to_edge", "mirrored_repeat"}));
  EXPECT_NE(reference().render(repeat).rgb, reference().render(clamp).rgb);
}

// The SceneError message of a scene whose only object is `object`.
std::string objectError(const std::string& object) {
  return thrownMessage<SceneError>([&] {
    parseScene(R"({"camera": {"position": [0, -5, 2], "look_at": [0, 0, 0]}, "objects": [)" + object + "]}", "bad.json");
  });
}

TEST(SceneWrite, BadInlineArraysNameTheirJsonPath) {
  const std::string tri = R"("vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]])";
  EXPECT_EQ(objectError(R"({"shape": "mesh", )" + tri + R"(, "faces": [[0, 1, 3]]})"),
            "bad.json: objects[0].faces: row 0 has index 3, but there are 3 vertices");
  EXPECT_EQ(objectError(R"({"shape": "mesh", )" + tri + R"(, "faces": [[0, 1, 2]], "normals": [[0, 0, 1], [0, 0, 0], [0, 0, 1]]})"),
            "bad.json: objects[0].normals: row 1 has no direction: [0, 0, 0]");
  EXPECT_EQ(objectError(R"({"shape": "mesh", )" + tri + R"(, "faces": [[0, 1, 2]], "normals": [[0, 0, 1]]})"),
            "bad.json: objects[0].normals: expected one row per vertex (3), got 1");
  EXPECT_EQ(objectError(R"({"shape": "mesh", "vertices": [[0, 0, 0], [1, 0]], "faces": [[0, 1, 1]]})"),
            "bad.json: objects[0].vertices[1]: must be an array of 3 numbers, got 2 elements");
  EXPECT_EQ(objectError(R"({"shape": "mesh", "vertices": [], "faces": []})"),
            "bad.json: objects[0].vertices: the mesh has no vertices");
  EXPECT_EQ(objectError(R"({"shape": "mesh", )" + tri + R"(, "faces": [[0, 1, 1]]})"),
            "bad.json: objects[0].faces: every triangle is degenerate (zero area)");
  EXPECT_EQ(objectError(R"({"shape": "mesh", )" + tri + R"(, "faces": [[0, 1.5, 2]]})"),
            "bad.json: objects[0].faces[0][1]: must be an integer, got 1.5");
  EXPECT_EQ(objectError(R"({"shape": "mesh", )" + tri + R"(, "faces": [[0, 1, 2]], "colors": [[1, 2, 3, 4]]})"),
            "bad.json: objects[0].colors: expected one row per vertex (3), got 1");
  EXPECT_EQ(objectError(R"({"shape": "mesh", )" + tri + R"(, "faces": [[0, 1, 2]], "colors": [[1, 2, 3, 4], [0, 0, 0, 0], [9, 256, 0, 0]]})"),
            "bad.json: objects[0].colors[2][1]: must be between 0 and 255, got 256");
  EXPECT_EQ(objectError(R"({"shape": "mesh", )" + tri + R"(, "faces": [[0, 1, 2]], "file": "x.obj"})"),
            "bad.json: objects[0].file: cannot be given with 'vertices': a mesh is a file or arrays");
  EXPECT_EQ(objectError(R"({"shape": "mesh", "faces": [[0, 1, 2]]})"),
            "bad.json: objects[0].faces: needs 'vertices' (a mesh given inline)");
  EXPECT_EQ(objectError(R"({"shape": "cube", "faces": [[0, 1, 2]]})").find("not used by shape 'cube'") != std::string::npos,
            true);
}

TEST(SceneWrite, BadInlineTexturesNameTheirJsonPath) {
  const std::string quad = R"("vertices": [[0, 0, 0], [1, 0, 0], [0, 0, 1], [1, 0, 1]], "faces": [[0, 1, 2], [1, 3, 2]])";
  const std::string uvs = R"(, "uvs": [[0, 0], [1, 0], [0, 1], [1, 1]])";
  const std::string checker = R"("textures": [{"image": ")" + sourcePath("scenes/meshes/checker.png") + R"("}])";
  EXPECT_EQ(objectError(R"({"shape": "mesh", )" + quad + uvs + ", " + checker + "}"),
            "bad.json: objects[0].textures: needs 'texture_ids' (which texture each vertex samples)");
  EXPECT_EQ(objectError(R"({"shape": "mesh", )" + quad + ", " + checker + R"(, "texture_ids": [0, 0, 0, 0]})"),
            "bad.json: objects[0].textures: needs 'uvs' (the coordinates the textures are sampled at)");
  EXPECT_EQ(objectError(R"({"shape": "mesh", )" + quad + uvs + ", " + checker + R"(, "texture_ids": [0, 0, 0, 1]})"),
            "bad.json: objects[0].texture_ids[3]: must be between -1 and 0, got 1");
  EXPECT_EQ(objectError(R"({"shape": "mesh", )" + quad + uvs + ", " + checker + R"(, "texture_ids": [0, 0, 0, -1]})"),
            "bad.json: objects[0].texture_ids: vertices 1, 3 and 2 make a triangle but sample different textures");
  EXPECT_EQ(objectError(R"({"shape": "mesh", )" + quad + uvs + ", " + checker + R"(, "texture_ids": [0, 0, 0]})"),
            "bad.json: objects[0].texture_ids: expected one texture index per vertex (4), got 3");
  EXPECT_EQ(objectError(R"({"shape": "mesh", )" + quad + uvs +
                        R"(, "textures": [{"image": "data:image/png;base64,AAAA", "wrap": ["repeat", "around"]}], "texture_ids": [0, 0, 0, 0]})"),
            "bad.json: objects[0].textures[0].image: the data URI: not a PNG or JPEG image (it starts 00 00 00)");
  EXPECT_EQ(objectError(R"({"shape": "mesh", )" + quad + uvs + R"(, "textures": [{"image": ")" +
                        sourcePath("scenes/meshes/checker.png") + R"(", "wrap": ["repeat", "around"]}], "texture_ids": [0, 0, 0, 0]})"),
            "bad.json: objects[0].textures[0].wrap[1]: must be one of repeat, clamp_to_edge, mirrored_repeat, got 'around'");
}

TEST(SceneWrite, BadRotateMatrixNamesItsJsonPath) {
  EXPECT_EQ(objectError(R"({"shape": "cube", "rotate": {"matrix": [[1, 0, 0], [0, 1, 0], [1, 1, 0]]}})"),
            "bad.json: objects[0].rotate.matrix: must be invertible, got determinant 0");
  EXPECT_EQ(objectError(R"({"shape": "cube", "rotate": {"matrix": [[1, 0, 0], [0, 1, 0]]}})"),
            "bad.json: objects[0].rotate.matrix: must be an array of 3 rows, got 2");
  EXPECT_EQ(objectError(R"({"shape": "cube", "rotate": {"matrix": [[1, 0, 0], [0, 1, 0], [0, 0, "1"]]}})"),
            "bad.json: objects[0].rotate.matrix[2][2]: must be a number, got string");
  EXPECT_EQ(objectError(R"({"shape": "cube", "rotate": {"matrix": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "angle": 3}})"),
            "bad.json: objects[0].rotate.angle: cannot be given with 'matrix'");
}

TEST(SceneWrite, ARotateMatrixIsTheLinearMapEulerAnglesGive) {
  const std::string camera = R"("camera": {"position": [2, -4, 3], "look_at": [0, 0, 0], "width": 90, "height": 60},
    "lights": [{"position": [1, -3, 4]}])";
  const glm::dmat3 m = rotationXYZ({10, 20, 30});
  nlohmann::json rows = nlohmann::json::array();
  for (int r = 0; r < 3; ++r) rows.push_back({m[0][r], m[1][r], m[2][r]});
  const Scene euler = parseScene("{" + camera + R"(, "objects": [{"shape": "cube", "rotate": [10, 20, 30]}]})", "a.json");
  const Scene matrix = parseScene(
      "{" + camera + R"(, "objects": [{"shape": "cube", "rotate": {"matrix": )" + rows.dump() + "}}]}", "b.json");
  const Image a = reference().render(euler);
  EXPECT_GT(drawnPixels(a), 100u);
  EXPECT_EQ(a.rgb, reference().render(matrix).rgb);
}

}  // namespace
}  // namespace phongvk
