// api_gpu_test.cpp — the public API (include/phongvk) through libphongvk.so alone, as an outside
// project links it: scenes and sequences, both renderers giving the same bytes and keys, a renderer
// keeping its meshes across scenes of the same geometry, diff, and the error types.
#include <phongvk/phongvk.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace phongvk {
namespace {

std::string source(const std::string& relative) { return std::string(PHONGVK_SOURCE_DIR) + "/" + relative; }

RendererOptions validatedGpu() { return {Backend::Gpu, -1, true}; }

TEST(Api, BothBackendsGiveTheSameBytesAndKeys) {
  const Scene scene = loadScene(source("scenes/paper/fig1_cube.json"));
  EXPECT_EQ(scene.width(), 1385);
  EXPECT_EQ(scene.height(), 923);
  EXPECT_EQ(scene.objectCount(), 2u);
  Renderer gpu(validatedGpu());
  Renderer cpu(Backend::Cpu);
  const RenderOutput a = gpu.renderWithKeys(scene);
  const RenderOutput b = cpu.renderWithKeys(scene);
  ASSERT_EQ(a.image.width, 1385);
  ASSERT_EQ(a.image.rgb.size(), size_t(1385) * 923 * 3);
  EXPECT_TRUE(a.image.rgb == b.image.rgb);
  EXPECT_TRUE(a.keys == b.keys);
  EXPECT_TRUE(gpu.render(scene).rgb == a.image.rgb);  // without keys: other resolve paths, same image
  EXPECT_EQ(gpu.stats().validationMessages, 0u);
}

// Another size, other materials: the meshes stay; other geometry: built again.
TEST(Api, RendererKeepsItsMeshesWhileTheGeometryStaysTheSame) {
  const Scene scene = loadScene(source("scenes/basic.json"));
  Renderer gpu(validatedGpu());
  Renderer cpu(Backend::Cpu);
  const Scene small = scene.withImageSize(96, 64);
  const Scene relit = parseScene(R"({"camera": {"position": [3, 0, 1], "look_at": [0, 0, 0], "width": 64, "height": 48},
      "lights": [{"position": [1, 1, 2]}], "materials": {"m": {"ks": 0.2}},
      "objects": [{"shape": "sphere", "material": "m"}]})");
  const Scene recoloured = parseScene(R"({"camera": {"position": [3, 0, 1], "look_at": [0, 0, 0], "width": 64, "height": 48},
      "lights": [{"position": [1, 1, 2], "color": [1, 0, 0]}], "materials": {"m": {"ks": 0.9}},
      "objects": [{"shape": "sphere", "material": "m"}]})");
  for (const Scene* s : {&scene, &small, &relit, &recoloured}) {
    EXPECT_TRUE(gpu.render(*s).rgb == cpu.render(*s).rgb) << s->width() << "x" << s->height();
  }
  EXPECT_EQ(gpu.stats().sceneBuilds, 2u);  // basic.json, then the sphere
  EXPECT_EQ(gpu.stats().framesRendered, 4u);
  EXPECT_EQ(cpu.stats().sceneBuilds, 2u);
  EXPECT_EQ(gpu.stats().triangles, 960u);  // a 32-segment sphere
}

// A new geometry each frame (a deforming mesh, a dataset of models) reuses the renderer: new
// scene buffers, the same image buffers and pipelines. Every frame gives the reference's bytes and
// keys, whichever geometry came before (more or fewer triangles, other light and material counts,
// other shading), and once every variant has been compiled, new geometry compiles nothing.
TEST(Api, ANewGeometryEachFrameRendersAsTheReferenceAndCompilesNothingAgain) {
  Renderer gpu(validatedGpu());
  Renderer cpu(Backend::Cpu);
  const auto frame = [](int k) {
    Scene s(160, 120);
    s.setCamera({.position = {2, -1.5, 1}, .lookAt = {0, 0, 0}});
    std::vector<Light> lights = {{.position = {2, -3, 3}}};
    if (k % 3 != 0) lights.push_back({.position = {-2, -1, 2}, .color = {1, 0.5, 0}});
    s.setLights(lights);
    s.setRenderSettings({.shading = k % 4 == 1 ? Shading::Phong : Shading::Gouraud});
    MeshArrays mesh;  // a fan of k + 3 triangles around the origin, scaled per frame
    const int n = 3 + 5 * (k % 5);
    mesh.positions = {0, 0, 0.3f};
    for (int i = 0; i <= n; ++i) {
      const float a = float(i) * 6.0f / float(n), r = 0.6f + 0.02f * float(k);
      mesh.positions.insert(mesh.positions.end(), {r * std::cos(a), r * std::sin(a), 0});
    }
    for (int i = 0; i < n; ++i) mesh.triangles.insert(mesh.triangles.end(), {0, i + 1, i + 2});
    s.addMesh(mesh);
    return s;
  };
  double compiled = 0;
  for (int k = 0; k < 24; ++k) {
    const Scene s = frame(k);
    const RenderOutput a = gpu.renderWithKeys(s), b = cpu.renderWithKeys(s);
    EXPECT_TRUE(a.image.rgb == b.image.rgb) << "frame " << k;
    EXPECT_TRUE(a.keys == b.keys) << "frame " << k;
    if (k == 12) compiled = gpu.stats().pipelinesMs;  // every variant the frames use has been seen
  }
  EXPECT_EQ(gpu.stats().sceneBuilds, 24u);
  EXPECT_EQ(gpu.stats().pipelinesMs, compiled);  // frames 13 to 23: new geometry, no pipeline compiled
  EXPECT_EQ(gpu.stats().validationMessages, 0u);
}

TEST(Api, BadSceneIsASceneErrorNamingTheFileAndThePath) {
  try {
    parseScene(R"({"camera": {"position": [0, 0, 0], "direction": [1, 0, 0]},
                   "objects": [{"shape": "sphere", "material": {"ks": -1}}]})",
               "inline.json");
    FAIL() << "no error";
  } catch (const SceneError& e) {
    EXPECT_STREQ(e.what(), "inline.json: objects[0].material.ks: must be >= 0, got -1");
  }
  EXPECT_THROW(loadScene(source("scenes/no_such_scene.json")), SceneError);
  // One catch serves every kind: each derives from phongvk::Error (and so from std::runtime_error).
  const auto kindOf = [](const auto& call) -> std::string {
    try {
      call();
    } catch (const Error& e) {
      const std::runtime_error& base = e;
      return base.what();
    }
    return "(no error)";
  };
  EXPECT_NE(kindOf([&] { loadScene(""); }), "(no error)");
  EXPECT_EQ(kindOf([&] { parseBackend("opengl"); }), "unknown backend 'opengl' (gpu, cpu or graphics)");
  EXPECT_NE(kindOf([&] { loadScene(source("scenes/basic.json")).frame(1); }), "(no error)");
  EXPECT_NE(kindOf([&] { encodePng(Image(), 99); }), "(no error)");
}

TEST(Api, DiffComparesTheReferenceAndTheComputePort) {
  const DiffResult result = diff(loadScene(source("scenes/two_lights.json")).withImageSize(320, 200), validatedGpu());
  EXPECT_EQ(result.stats.pixels, 320u * 200u);
  EXPECT_EQ(result.stats.differing, 0u);
  EXPECT_TRUE(result.stats.keysCompared);
  EXPECT_EQ(result.stats.triangleMismatch, 0u);
  EXPECT_TRUE(std::isinf(result.stats.psnr));
  EXPECT_FALSE(result.deviceName.empty());
}

TEST(Api, AnimationFramesAreScenes) {
  const Scene sequence = loadScene(source("scenes/paper/fig6_orbit_red.json"));
  EXPECT_EQ(sequence.frameCount(), 120);
  const Scene first = sequence.frame(0).withImageSize(120, 80);
  const Scene later = sequence.frame(30).withImageSize(120, 80);
  Renderer cpu(Backend::Cpu);
  EXPECT_FALSE(cpu.render(first).rgb == cpu.render(later).rgb);  // the camera moved
  EXPECT_EQ(cpu.stats().sceneBuilds, 1u);
  EXPECT_THROW(sequence.frame(120), RangeError);
}

// A mesh added to an animated scene is in every frame, built once: each frame renders on both
// backends the bytes of the same frame with the mesh in its file, and the renderer builds the
// added mesh's geometry once for frames whose geometry stays the same.
TEST(Api, AddedMeshesFollowTheSceneIntoItsFrames) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "phongvk_api_added_meshes";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "tri.obj") << "v 0 0 0.5\nv 0.8 0 0.5\nv 0 0.8 0.5\nf 1 2 3\n";
  const std::string animated = R"j({"camera": {"position": [2, -1.5, 1], "look_at": [0, 0, 0], "width": 96, "height": 64},
      "lights": [{"position": [2, -3, 3]}], "materials": {"red": {"color": [1, 0.2, 0.2]}},
      "objects": [{"shape": "sphere", "radius": 0.4}%s],
      "animate": {"frames": 4, "tracks": [{"path": "camera.position", "expression": ["2*cos(i)", "2*sin(i)", 1]}]}})j";
  const auto withObjects = [&](const std::string& more) {
    std::string text = animated;
    text.replace(text.find("%s"), 2, more);
    return text;
  };
  Scene added = parseScene(withObjects(""), "a.json", dir.string());
  MeshArrays mesh;
  mesh.positions = {0, 0, 0.5f, 0.8f, 0, 0.5f, 0, 0.8f, 0.5f};
  mesh.triangles = {0, 1, 2};
  added.addMesh(mesh, "red");
  const Scene inFile =
      parseScene(withObjects(R"(, {"shape": "mesh", "file": "tri.obj", "material": "red"})"), "a.json", dir.string());
  ASSERT_EQ(added.frameCount(), 4);
  Renderer gpu(validatedGpu()), cpu(Backend::Cpu);
  for (int i = 0; i < added.frameCount(); ++i) {
    EXPECT_EQ(added.frame(i).objectCount(), 2u) << "frame " << i;
    const Image fromFile = cpu.render(inFile.frame(i));
    EXPECT_TRUE(cpu.render(added.frame(i)).rgb == fromFile.rgb) << "frame " << i;
    EXPECT_TRUE(gpu.render(added.frame(i)).rgb == fromFile.rgb) << "frame " << i;
  }
}

// A scene driven from code: a typed camera and lights, and a mesh placed, moved and removed by
// handle, render the bytes of the same scene written as JSON, on both backends.
TEST(Api, TypedCameraLightsAndPosesRenderAsTheSameSceneWritten) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "phongvk_api_typed";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "tri.obj") << "v 0 0 0\nv 0.8 0 0\nv 0 0.8 0.3\nf 1 2 3\n";
  const auto written = [&](const std::string& objects) {
    return parseScene(R"({"camera": {"position": [2, -3, 1.5], "look_at": [0, 0, 0.3], "fov": 45, "width": 96,
        "height": 64}, "lights": [{"position": [2, -3, 3], "intensity": 0.9}, {"position": "camera", "color": [1, 0.5, 0]}],
        "objects": [{"shape": "cube", "size": 0.5})" + objects + "]}", "w.json", dir.string());
  };
  Scene built = parseScene(R"({"camera": {"position": [9, 0, 0], "look_at": [0, 0, 0]}, "objects": [{"shape": "cube", "size": 0.5}]})");
  built.setCamera(Camera{{2, -3, 1.5}, {0, 0, 0.3}, {0, 0, 1}, 45, 96, 64});
  built.setLights({Light{{2, -3, 3}, 0.9, {1, 1, 1}, false}, Light{{0, 0, 0}, 1, {1, 0.5, 0}, true}});
  MeshArrays tri;
  tri.positions = {0, 0, 0, 0.8f, 0, 0, 0, 0.8f, 0.3f};
  tri.triangles = {0, 1, 2};
  Matrix4 pose = IDENTITY_POSE;
  pose[3] = 0.5;  // translate x
  const ObjectId id = built.add(tri, pose);
  Renderer gpu(validatedGpu()), cpu(Backend::Cpu);
  const auto expectSame = [&](const Scene& a, const Scene& b) {
    const Image expected = cpu.render(b);
    EXPECT_TRUE(cpu.render(a).rgb == expected.rgb);
    EXPECT_TRUE(gpu.render(a).rgb == expected.rgb);
  };
  expectSame(built, written(R"(, {"shape": "mesh", "file": "tri.obj", "translate": [0.5, 0, 0]})"));
  pose[3] = -0.25;
  pose[11] = 0.5;  // translate z
  built.setPose(id, pose);
  expectSame(built, written(R"(, {"shape": "mesh", "file": "tri.obj", "translate": [-0.25, 0, 0.5]})"));
  built.remove(id);
  EXPECT_EQ(built.objectCount(), 1u);
  expectSame(built, written(""));
  EXPECT_THROW(built.setPose(id, pose), RangeError);
  EXPECT_EQ(built.camera().fov, 45);
  EXPECT_EQ(built.lights().size(), 2u);
  EXPECT_THROW(built.setCamera(Camera{{0, 0, 3}, {0, 0, 0}, {0, 0, 1}, 45, 96, 64}), SceneError);  // up along the view
  EXPECT_THROW(cameraFromIntrinsics(0, 120, 47.5, 31.5, 96, 64, IDENTITY_POSE), ArgumentError);
  const Camera fromIntrinsics = cameraFromIntrinsics(100, 120, 40.25, 35, 96, 64, IDENTITY_POSE, PoseConvention::OpenCV);
  EXPECT_EQ(fromIntrinsics.intrinsics, (Intrinsics{100, 120, 40.25, 35}));
  EXPECT_EQ(fromIntrinsics.lookAt, (Vec3{0, 0, 1}));  // OpenCV: the camera looks down its +z
  EXPECT_EQ(fromIntrinsics.up, (Vec3{0, -1, 0}));     // and its y points down
  built.setCamera(fromIntrinsics);
  EXPECT_EQ(built.camera().intrinsics, fromIntrinsics.intrinsics);
  Camera outside = fromIntrinsics;
  outside.intrinsics->cx = -20000;
  EXPECT_THROW(built.setCamera(outside), SceneError);  // beyond one largest image side
}

// A mesh built once and placed twice renders as the same arrays added twice; one from a file as
// the scene file's mesh object of that file; and bad input is the usual errors.
TEST(Api, TriangleMeshesAreSharedAndRenderAsTheirSources) {
  MeshArrays tri;
  tri.positions = {0, 0, 0, 1, 0, 0, 0, 0, 1};
  tri.triangles = {0, 1, 2};
  const TriangleMesh shared(tri);
  EXPECT_EQ(shared.vertexCount(), 3u);
  EXPECT_EQ(shared.triangleCount(), 1u);
  Scene once(96, 64), twice(96, 64);
  Matrix4 pose = IDENTITY_POSE;
  for (const double x : {-0.75, 0.25}) {
    pose[3] = x;
    once.add(shared, pose);
    twice.add(tri, pose);
  }
  Renderer cpu(Backend::Cpu), gpu(validatedGpu());
  EXPECT_TRUE(cpu.render(once).rgb == cpu.render(twice).rgb);
  EXPECT_TRUE(gpu.render(once).rgb == cpu.render(twice).rgb);

  const std::string torus = source("scenes/meshes/torus.obj");
  const TriangleMesh fromFile = TriangleMesh::fromFile(torus, ModelUp::Z);
  Scene built(96, 64), written = parseScene(R"({"camera": {"position": [0, -4, 2], "look_at": [0, 0, 0],
      "width": 96, "height": 64}, "lights": [{"position": "camera"}],
      "objects": [{"shape": "mesh", "file": ")" + torus + R"(", "up": "z", "material": {"attenuation": [1, 0, 0]}}]})",
                                                     "", ".");
  built.setCamera(written.camera());
  built.add(fromFile);
  EXPECT_GT(fromFile.triangleCount(), 100u);
  EXPECT_TRUE(cpu.render(built).rgb == cpu.render(written).rgb);
  EXPECT_THROW(TriangleMesh::fromFile(source("scenes/basic.json")), ArgumentError);
  const std::filesystem::path bad = std::filesystem::temp_directory_path() / "phongvk_bad_mesh.obj";
  std::ofstream(bad) << "v 0 0 0\nv 1 0 0\nf 1 2 7\n";
  try {
    TriangleMesh::fromFile(bad.string());
    ADD_FAILURE() << "no error";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find(bad.string() + ": "), std::string::npos) << e.what();
  }
  std::filesystem::remove(bad);
}

// Scene::triangles: the built geometry in world coordinates, each triangle with its object.
TEST(Api, TrianglesAreTheBuiltGeometryInWorldCoordinates) {
  Scene scene = parseScene(R"({"camera": {"position": [0, -8, 1], "look_at": [0, 0, 0], "width": 64, "height": 48},
    "lights": [{"position": [1, -4, 3]}],
    "objects": [{"shape": "cube", "size": 2, "center": [10, 0, 0]},
                {"shape": "mesh", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "faces": [[0, 1, 2]]}]})");
  MeshArrays tri;
  tri.positions = {0, 0, 0, 1, 0, 0, 0, 0, 1};
  tri.triangles = {0, 1, 2};
  Matrix4 pose = IDENTITY_POSE;
  pose[3] = -5;  // moved 5 along -x
  scene.add(tri, pose);
  const SceneTriangles t = scene.triangles();
  ASSERT_EQ(t.objects.size(), 14u) << "a cube's 12, the inline mesh's 1 and the added one's 1";
  ASSERT_EQ(t.mesh.triangles.size(), 3 * t.objects.size());
  ASSERT_EQ(t.mesh.normals.size(), t.mesh.positions.size());
  for (size_t k = 0; k < t.objects.size(); ++k) EXPECT_EQ(t.objects[k], k < 12 ? 0 : int32_t(k) - 11);
  const auto vertex = [&](int64_t i) { return std::array<float, 3>{t.mesh.positions[3 * i], t.mesh.positions[3 * i + 1], t.mesh.positions[3 * i + 2]}; };
  for (size_t k = 0; k < 12; ++k) {
    for (int c = 0; c < 3; ++c) {
      const std::array<float, 3> p = vertex(t.mesh.triangles[3 * k + c]);
      EXPECT_TRUE(std::abs(p[0] - 10.0f) == 1.0f && std::abs(p[1]) == 1.0f && std::abs(p[2]) == 1.0f) << k;
    }
  }
  EXPECT_EQ(vertex(t.mesh.triangles[3 * 12 + 1]), (std::array<float, 3>{1, 0, 0}));
  EXPECT_EQ(vertex(t.mesh.triangles[3 * 13 + 2]), (std::array<float, 3>{-5, 0, 1}));
  for (size_t i = 0; i < t.mesh.normals.size(); i += 3) {
    const double length = std::hypot(t.mesh.normals[i], t.mesh.normals[i + 1], t.mesh.normals[i + 2]);
    EXPECT_NEAR(length, 1.0, 1e-6);
  }
  const std::array<Vec3, 2> box = scene.bounds();
  EXPECT_EQ(box[0], (Vec3{-5, -1, -1}));
  EXPECT_EQ(box[1], (Vec3{11, 1, 1}));
}

// Non-square pixels and a principal point off centre, then outside the image (the frustum's side
// planes, the guard band and the near plane's clipping about it), with 16 samples a pixel: the
// same bytes on both backends.
TEST(Api, IntrinsicsRenderTheSameOnBothBackends) {
  Scene scene = loadScene(source("scenes/intrinsics.json")).withImageSize(96, 72).withRender({.samples = 16});
  Renderer gpu(validatedGpu()), cpu(Backend::Cpu);
  const Outputs keys{.depth = true, .triangleIds = true};
  for (const double cx : {60.0, -30.5, 140.0}) {
    Camera camera = scene.camera();
    ASSERT_TRUE(camera.intrinsics);
    camera.intrinsics->cx = cx;
    camera.intrinsics->cy = 20 - cx / 4;
    scene.setCamera(camera);
    const RenderedFrame a = gpu.renderOutputs(scene, keys), b = cpu.renderOutputs(scene, keys);
    EXPECT_TRUE(a.image.rgb == b.image.rgb) << "cx " << cx;
    EXPECT_TRUE(a.triangleIds == b.triangleIds) << "cx " << cx;
    EXPECT_EQ(std::memcmp(a.depth.data(), b.depth.data(), a.depth.size() * sizeof(float)), 0) << "cx " << cx;
    EXPECT_GT(std::count_if(a.triangleIds.begin(), a.triangleIds.end(), [](int32_t t) { return t >= 0; }), 100);
  }
}

// Alpha, depth and ids come from the keys: the same bytes on both backends, with samples too.
TEST(Api, FrameOutputsAreTheSameOnBothBackends) {
  const Scene scene = loadScene(source("scenes/basic.json")).withImageSize(120, 80).withRender({.samples = 4});
  const Outputs all{.alpha = true, .depth = true, .objectIds = true, .triangleIds = true};
  Renderer gpu(validatedGpu()), cpu(Backend::Cpu);
  const RenderedFrame a = gpu.renderOutputs(scene, all), b = cpu.renderOutputs(scene, all);
  EXPECT_TRUE(a.image.rgb == b.image.rgb);
  EXPECT_TRUE(a.alpha == b.alpha);
  EXPECT_EQ(a.depth.size(), size_t(120 * 80));
  EXPECT_EQ(std::memcmp(a.depth.data(), b.depth.data(), a.depth.size() * sizeof(float)), 0);
  EXPECT_TRUE(a.objectIds == b.objectIds);
  EXPECT_TRUE(a.triangleIds == b.triangleIds);
  EXPECT_TRUE(a.image.rgb == cpu.render(scene).rgb);
  const RenderedFrame colourOnly = gpu.renderOutputs(scene, {});
  EXPECT_TRUE(colourOnly.depth.empty() && colourOnly.alpha.empty());
  Renderer graphics(Backend::Graphics);
  EXPECT_THROW(graphics.renderOutputs(scene, all), ArgumentError);
}

TEST(Api, BackendsByName) {
  EXPECT_EQ(parseBackend("gpu"), Backend::Gpu);
  EXPECT_EQ(parseBackend("cpu"), Backend::Cpu);
  EXPECT_EQ(parseBackend("graphics"), Backend::Graphics);
  EXPECT_EQ(parseBackend("raster"), Backend::Graphics);  // the graphics baseline's older name
  EXPECT_THROW(parseBackend("opengl"), ArgumentError);
  EXPECT_STREQ(backendName(Backend::Graphics), "graphics");
  Renderer graphics(Backend::Graphics);
  EXPECT_THROW(graphics.renderWithKeys(loadScene(source("scenes/basic.json"))), ArgumentError);
}

TEST(Api, VersionAndRevision) {
  EXPECT_STREQ(version(), PHONGVK_VERSION_STRING);
  EXPECT_GT(std::string(revision()).size(), 0u);
}

TEST(Api, TimedFramesHaveWallAndDeviceTimes) {
  const Scene scene = loadScene(source("scenes/basic.json")).withImageSize(160, 100);
  Renderer gpu(validatedGpu());
  const std::vector<FrameTime> frames = gpu.timeFrames(scene, 3);
  ASSERT_EQ(frames.size(), 3u);
  for (const FrameTime& f : frames) {
    EXPECT_GT(f.wallMs, 0.0);
    EXPECT_TRUE(std::isnan(f.deviceMs) || f.deviceMs >= 0.0);
  }
  EXPECT_EQ(gpu.stats().framesRendered, 4u);  // one warm-up
}

}  // namespace
}  // namespace phongvk
