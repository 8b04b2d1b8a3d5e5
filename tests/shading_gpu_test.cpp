// shading_gpu_test.cpp — flat and per-pixel Phong shading, Blinn's specular model and samples per
// pixel (docs/DESIGN.md "Shading", "Samples"): every committed scene in every mode renders the
// reference's keys and bytes on the compute port, through the public API as users call it, and
// each mode shows what it is for (a highlight inside a large triangle, one colour per triangle,
// anti-aliased edges).
#include "compute/gpu_renderer.h"
#include "phongvk/compare.h"
#include "tools/contact_sheet.h"
#include "phongvk/phongvk.h"
#include "reference/render_reference.h"
#include "scene/camera.h"
#include "scene/scene.h"
#include "test_util.h"
#include "vulkan/context.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace phongvk {
namespace {

// The render options each scene is rendered with, beside its own.
const std::vector<std::string> kModes = {
    R"({"shading": "flat"})",
    R"({"shading": "phong"})",
    R"({"shading": "phong", "specular": "blinn"})",
    R"({"specular": "blinn"})",
    R"({"shading": "phong", "interpolation": "screen"})",
    R"({"samples": 4, "shading": "phong"})",
    R"({"samples": 9})",
};

void expectSame(const RenderOutput& reference, const RenderOutput& gpu, const std::string& what) {
  const DiffStats stats = compareImages(reference.image, gpu.image, reference.keys, gpu.keys);
  EXPECT_TRUE(stats.keysCompared) << what;
  EXPECT_TRUE(gpu.keys == reference.keys) << what << ": visibility keys differ\n" << formatDiff(stats);
  EXPECT_TRUE(gpu.image.rgb == reference.image.rgb) << what << ": image bytes differ\n" << formatDiff(stats);
}

class ShadingModes : public ::testing::TestWithParam<std::string> {
 protected:
  static void SetUpTestSuite() {
    gpu_ = new Renderer(Backend::Gpu);
    cpu_ = new Renderer(Backend::Cpu);
  }
  static void TearDownTestSuite() {
    delete gpu_;
    delete cpu_;
  }
  static Renderer* gpu_;
  static Renderer* cpu_;
};

Renderer* ShadingModes::gpu_ = nullptr;
Renderer* ShadingModes::cpu_ = nullptr;

// At 240x160, so that seven modes of thirty scenes stay short; one renderer of each backend for
// all of them, as a user's program keeps one.
TEST_P(ShadingModes, GpuMatchesReferenceInEveryMode) {
  const Scene scene = loadScene(test::sourcePath(GetParam())).withImageSize(240, 160);
  test::expectTestDevice(gpu_->deviceName());  // where CTest's keys32 and swiftshader entries ask
  for (const std::string& mode : kModes) {
    const Scene moded = test::withRenderOptions(scene, mode);
    const RenderOutput reference = cpu_->renderWithKeys(moded);
    const RenderOutput gpu = gpu_->renderWithKeys(moded);
    expectSame(reference, gpu, GetParam() + " " + mode);
    EXPECT_TRUE(gpu_->render(moded).rgb == reference.image.rgb) << GetParam() << " " << mode << ": without keys";
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, ShadingModes, ::testing::ValuesIn(test::allScenes()), test::pathTestName);

// The most lights a scene may have (scene.h MAX_LIGHTS), on a screen-filling dense mesh whose bins
// hold keys in every tile: every mode renders the reference's bytes, with no loop budget run out
// on lavapipe (2,048 lights ran out with Phong shading and 4 samples).
TEST(ShadingLimits, TheMostLightsRenderTheReferenceBytesInEveryMode) {
  std::string lights;
  for (size_t i = 0; i < MAX_LIGHTS; ++i) {
    lights += std::string(i ? ", " : "") + "{\"position\": [" + std::to_string(0.01 * double(i % 32)) + ", -1, " +
              std::to_string(0.01 * double(i / 32)) + "], \"intensity\": 0.002}";
  }
  const Scene scene = parseScene(R"({"camera": {"position": [0, -1.2, 0], "look_at": [0, 0, 0], "width": 96, "height": 64},
      "lights": [)" + lights + R"(], "objects": [{"shape": "icosphere", "radius": 1, "subdivide": 5}]})");
  Renderer gpu(Backend::Gpu), cpu(Backend::Cpu);
  for (const char* mode : {R"({"shading": "gouraud"})", R"({"shading": "flat", "samples": 4})", R"({"shading": "phong", "samples": 4})"}) {
    const Scene moded = test::withRenderOptions(scene, mode);
    expectSame(cpu.renderWithKeys(moded), gpu.renderWithKeys(moded), mode);
  }
}

// Per-pixel lighting in the GPU renderer's other work layout and colour output (the deferred path
// a GPU takes), on scenes of large and small triangles and one crossing the near plane.
TEST(ShadingLayouts, EveryLayoutAndOutputGivesTheReferenceBytes) {
  VulkanContext context = createContext({-1, true});
  for (const char* file : {"scenes/floor_and_walls.json", "scenes/paper/fig3_two_lights.json", "scenes/stress/near_plane.json"}) {
    for (const char* mode : {R"({"shading": "flat"})", R"({"shading": "phong", "specular": "blinn"})"}) {
      const SceneSpec spec = test::withRenderOptions(loadSceneSpec(test::sourcePath(file)), mode);
      const SceneData data = buildSceneData(spec);
      const FrameInputs in = makeFrame(data, makeView(withImageSize(spec.camera, 320, 240)));
      const RenderOutput reference = renderReference(data, in);
      for (WorkLayout layout : {WorkLayout::Cpu, WorkLayout::Gpu}) {
        for (ColorOutput output : {ColorOutput::Auto, ColorOutput::ColorBuffer}) {
          GpuRenderer renderer(context, data, {.layout = layout, .output = output});
          expectSame(reference, renderer.render(in, true), std::string(file) + " " + mode);
          EXPECT_TRUE(renderer.render(in).image.rgb == reference.image.rgb) << file << " " << mode << ": without keys";
        }
      }
    }
  }
  destroyContext(context);
  EXPECT_EQ(context.validation->count(), 0u);
}

// One shiny sphere of 80 triangles, lit from beside the eye: the highlight falls inside a
// triangle, between its vertices.
Scene coarseShinySphere() {
  return parseScene(R"({"camera": {"position": [0, -2.6, 0], "look_at": [0, 0, 0], "width": 320, "height": 240},
                        "lights": [{"position": [0.6, -3, 0.9]}],
                        "objects": [{"shape": "icosphere", "center": [0, 0, 0], "radius": 1, "subdivide": 1,
                                     "material": {"ks": 1, "n": 60, "kd": 0.5, "color": [0.4, 0.4, 0.9],
                                                  "attenuation": [1, 0, 0]}}]})");
}

int brightest(const Image& image) { return *std::max_element(image.rgb.begin(), image.rgb.end()); }

// Gouraud interpolates the vertices' colours, and none of them is near the highlight; Phong lights
// every pixel and shows it. Both backends agree on each.
TEST(ShadingModesShow, PhongShowsTheHighlightGouraudMisses) {
  const Scene sphere = coarseShinySphere();
  Renderer gpu(Backend::Gpu), cpu(Backend::Cpu);
  const Image gouraud = gpu.render(sphere);
  const Image phong = gpu.render(sphere.withRender({.shading = Shading::Phong}));
  EXPECT_EQ(gouraud.rgb, cpu.render(sphere).rgb);
  EXPECT_EQ(phong.rgb, cpu.render(sphere.withRender({.shading = Shading::Phong})).rgb);
  EXPECT_EQ(brightest(phong), 255) << "the highlight saturates";
  EXPECT_LT(brightest(gouraud), 160) << "no vertex sits on the highlight";
  const Image blinn = gpu.render(sphere.withRender({.shading = Shading::Phong, .specular = Specular::Blinn}));
  EXPECT_NE(blinn.rgb, phong.rgb) << "Blinn's half vector makes another highlight";
}

// Flat shading gives every pixel a triangle wins the same colour; Gouraud does not.
TEST(ShadingModesShow, FlatShadingGivesEachTriangleOneColour) {
  const Scene sphere = coarseShinySphere();
  Renderer gpu(Backend::Gpu);
  auto coloursPerTriangle = [](const RenderOutput& out) {
    std::map<uint32_t, std::vector<uint8_t>> first;
    size_t mismatched = 0;
    for (size_t i = 0; i < out.keys.size(); ++i) {
      if (out.keys[i] == ~0ull) continue;
      const std::vector<uint8_t> rgb(out.image.rgb.begin() + 3 * i, out.image.rgb.begin() + 3 * i + 3);
      auto [it, inserted] = first.emplace(uint32_t(out.keys[i]), rgb);
      mismatched += !inserted && it->second != rgb;
    }
    return std::make_pair(first.size(), mismatched);
  };
  const auto [flatTriangles, flatMismatched] = coloursPerTriangle(gpu.renderWithKeys(sphere.withRender({.shading = Shading::Flat})));
  EXPECT_GT(flatTriangles, 20u) << "triangles seen";
  EXPECT_EQ(flatMismatched, 0u) << "pixels of a flat triangle with another colour";
  EXPECT_GT(coloursPerTriangle(gpu.renderWithKeys(sphere)).second, 10000u) << "Gouraud varies within triangles";
}

// A lit triangle filling part of the view: with one sample every pixel is background or the
// triangle's colour; with 16, pixels on its edges fall between. The 16-sample image is exactly the
// 4x larger one-sample image averaged over 4x4 blocks (a regular grid, box filter).
TEST(ShadingModesShow, SamplesAntiAliasEdges) {
  const Scene triangle = parseScene(R"({"camera": {"position": [0, -3, 0], "look_at": [0, 0, 0], "width": 96, "height": 64},
       "ambient": [1, 1, 1],
       "objects": [{"shape": "polyhedron", "points": [[-1, 0, -0.8], [1.1, 0, -0.5], [0.1, 0, 0.9], [0, 0.2, 0]],
                    "material": {"ka": 1, "kd": 0, "ks": 0, "color": [1, 1, 1]}}]})");
  Renderer gpu(Backend::Gpu), cpu(Backend::Cpu);
  auto levels = [](const Image& image) {
    std::vector<bool> seen(256, false);
    for (uint8_t v : image.rgb) seen[v] = true;
    return std::count(seen.begin(), seen.end(), true);
  };
  const Image one = gpu.render(triangle);
  EXPECT_EQ(levels(one), 2) << "background and the triangle only";
  const Scene sixteen = triangle.withRender({.samples = 16});
  const RenderOutput aa = gpu.renderWithKeys(sixteen);
  EXPECT_EQ(aa.image.width, 96);
  EXPECT_EQ(aa.keys.size(), 96u * 64u * 16u) << "a key per sample";
  EXPECT_GT(levels(aa.image), 10) << "edge pixels between background and triangle";
  EXPECT_EQ(aa.image.rgb, cpu.render(sixteen).rgb);
  const Image large = gpu.render(triangle.withImageSize(384, 256));
  EXPECT_EQ(aa.image.rgb, downscale(large, 96, 64).rgb);
  EXPECT_EQ(diff(sixteen, gpu).stats.triangleMismatch, 0u);
}

// The graphics pipeline is the benchmark's Gouraud baseline: other modes are refused, not faked.
TEST(ShadingModesShow, GraphicsBackendRefusesOtherShading) {
  Renderer graphics(Backend::Graphics);
  try {
    graphics.render(coarseShinySphere().withRender({.shading = Shading::Phong}));
    FAIL() << "no error";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("renders Gouraud shading"), std::string::npos) << e.what();
  }
}

// The command line's options override the scene's render block, and diff holds the modes to the
// reference too.
TEST(ShadingModesShow, CommandLineOptionsOverrideTheScene) {
  const std::string dir = test::makeTempDir();
  const std::string fig = test::sourcePath("scenes/paper/fig1_cube.json");
  test::writeFile(dir + "/phong.json", R"({"camera": {"position": [-3.5, -2.45, 2.1], "look_at": [0, 0, 0], "width": 200, "height": 150},
      "lights": [{"position": [-0.7, -0.6, 0.8]}], "objects": [{"shape": "cube", "center": [0, 0, 0], "size": 1}],
      "render": {"shading": "phong", "samples": 4}})");
  test::writeFile(dir + "/plain.json", R"({"camera": {"position": [-3.5, -2.45, 2.1], "look_at": [0, 0, 0], "width": 200, "height": 150},
      "lights": [{"position": [-0.7, -0.6, 0.8]}], "objects": [{"shape": "cube", "center": [0, 0, 0], "size": 1}]})");
  ASSERT_EQ(test::runCli("render " + dir + "/phong.json -o " + dir + "/a.png").exitCode, 0);
  ASSERT_EQ(test::runCli("render " + dir + "/plain.json --shading phong --samples 4 -o " + dir + "/b.png").exitCode, 0);
  EXPECT_EQ(test::readBytes(dir + "/a.png"), test::readBytes(dir + "/b.png"));
  const test::CommandResult diffed = test::runCli("diff " + dir + "/plain.json --shading flat --specular blinn --samples 9");
  EXPECT_EQ(diffed.exitCode, 0) << diffed.output;
  EXPECT_NE(diffed.output.find("winning triangle differs: 0 pixels"), std::string::npos) << diffed.output;
  const test::CommandResult bad = test::runCli("render " + fig + " --samples 8 -o " + dir + "/c.png");
  EXPECT_EQ(bad.exitCode, 2) << bad.output;
  EXPECT_FALSE(std::filesystem::exists(dir + "/c.png"));
}

}  // namespace
}  // namespace phongvk
