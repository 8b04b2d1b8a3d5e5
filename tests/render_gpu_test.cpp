// Every committed scene rendered by the Vulkan port and diffed against the reference: the same
// visibility key and the same RGB bytes at every pixel, in both work layouts and both colour
// outputs, on every run, and no validation message.
#include "compute/gpu_renderer.h"
#include "phongvk/compare.h"
#include "reference/render_reference.h"
#include "scene/camera.h"
#include "test_util.h"
#include "vulkan/context.h"
#include "vulkan/float_probe.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>

namespace phongvk {
namespace {

class SceneDiff : public ::testing::TestWithParam<std::string> {
 protected:
  // One context and one float probe for all the scenes.
  static void SetUpTestSuite() {
    context_ = createContext({-1, true});
    exactFloats_ = probeFloatOps(context_).useExact();
  }
  static void TearDownTestSuite() { destroyContext(context_); }
  void TearDown() override {
    ASSERT_TRUE(context_.validation);
    EXPECT_EQ(context_.validation->count(), 0u) << "validation: " << context_.validation->messages().front();
  }
  static VulkanContext context_;
  static bool exactFloats_;
};

VulkanContext SceneDiff::context_;
bool SceneDiff::exactFloats_ = false;

TEST_P(SceneDiff, GpuMatchesReference) {
  const SceneSpec scene = loadSceneSpec(test::sourcePath(GetParam()));
  const SceneData data = buildSceneData(scene);
  const FrameInputs in = makeFrame(data, makeView(scene.camera));
  const RenderOutput reference = renderReference(data, in);

  std::optional<GpuRenderer> gpu(std::in_place, context_, data, GpuRendererOptions{.exactFloats = exactFloats_});
  const RenderOutput first = gpu->render(in, true);
  const RenderOutput second = gpu->render(in, true);
  // Without keys resolve takes other paths (resolve_large shades what large triangles win; with
  // keys resolve_small shades every pixel): the image a user gets must be the same.
  const RenderOutput plain = gpu->render(in);
  // The work layout (resolve tiles, bin pass) and colour output this device does not use by
  // default must give the same bytes (a device without shared memory has only the colour buffer).
  const bool cpu = context_.properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
  const ColorOutput otherOutput = hasSharedMemory(context_) ? ColorOutput::ColorBuffer : ColorOutput::Auto;
  gpu.emplace(context_, data,
              GpuRendererOptions{.layout = cpu ? WorkLayout::Gpu : WorkLayout::Cpu, .output = otherOutput,
                                 .exactFloats = exactFloats_});
  const RenderOutput otherLayout = gpu->render(in, true);
  const RenderOutput otherLayoutPlain = gpu->render(in);
  gpu.reset();

  const DiffStats stats = compareImages(reference.image, first.image, reference.keys, first.keys);
  EXPECT_TRUE(first.keys == reference.keys) << "visibility keys differ from the reference\n" << formatDiff(stats);
  EXPECT_TRUE(first.image.rgb == reference.image.rgb) << "image bytes differ from the reference\n" << formatDiff(stats);
  EXPECT_EQ(first.image.rgb, second.image.rgb) << "GPU image changed between runs";
  EXPECT_EQ(first.keys, second.keys) << "GPU visibility keys changed between runs";
  EXPECT_EQ(first.image.rgb, plain.image.rgb) << "rendering without keys changed the image";
  EXPECT_EQ(first.image.rgb, otherLayout.image.rgb) << "the other work layout changed the image";
  EXPECT_EQ(first.keys, otherLayout.keys) << "the other work layout changed the keys";
  EXPECT_EQ(first.image.rgb, otherLayoutPlain.image.rgb)
      << "the other work layout and colour output, without keys, changed the image";
}

INSTANTIATE_TEST_SUITE_P(Scenes, SceneDiff, ::testing::ValuesIn(test::allScenes()), test::pathTestName);

// The same PNG bytes whatever the number of threads lavapipe runs the workgroups on (LP_NUM_THREADS;
// a GPU ignores it): the atomics' order changes, the smallest key does not. fig1_cube has small
// triangles (atomics) and large ones (binned) on one screen.
TEST(GpuRender, SameBytesOnEveryThreadCount) {
  const std::string dir = test::makeTempDir();
  const std::string scene = test::sourcePath("scenes/paper/fig1_cube.json");
  std::vector<std::string> files;
  for (int threads : {1, 2, 3, 8}) {
    const std::string out = dir + "/threads" + std::to_string(threads) + ".png";
    const auto r = test::runCliWithEnvironment("LP_NUM_THREADS=" + std::to_string(threads), "render " + scene + " -o " + out);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::ifstream in(out, std::ios::binary);
    files.emplace_back(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    ASSERT_FALSE(files.back().empty());
    EXPECT_EQ(files.back(), files.front()) << threads << " threads";
  }
}

// `render --repeat` prints the frame line and, on the compute backend, each pass's median device
// time: three finite, non-negative numbers.
TEST(GpuRender, RepeatPrintsFrameAndPassTimes) {
  const std::string dir = test::makeTempDir();
  const auto r = test::runCli("render " + test::sourcePath("scenes/paper/fig1_cube.json") + " -o " + dir +
                              "/x.png --repeat 3");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  // sscanf, not std::regex: GCC 12's regex warns (maybe-uninitialized) in the sanitizer build.
  double wall = -1, device = -1, low = -1, high = -1, mean = -1, shade = -1, raster = -1, resolve = -1;
  const size_t frame = r.output.find("frame ms: ");
  ASSERT_NE(frame, std::string::npos) << r.output;
  EXPECT_EQ(std::sscanf(r.output.c_str() + frame, "frame ms: median %lf (device %lf, min %lf, max %lf, mean %lf)", &wall,
                        &device, &low, &high, &mean),
            5)
      << r.output;
  EXPECT_TRUE(low <= mean && mean <= high) << r.output;
  const size_t passes = r.output.find("device ms by pass: ");
  ASSERT_NE(passes, std::string::npos) << r.output;
  ASSERT_EQ(std::sscanf(r.output.c_str() + passes, "device ms by pass: shade %lf, raster %lf, resolve %lf (medians)",
                        &shade, &raster, &resolve),
            3)
      << r.output;
  for (double ms : {shade, raster, resolve}) EXPECT_TRUE(std::isfinite(ms) && ms >= 0) << r.output;
}

// Renders `in` with keys: the image and the keys must equal the reference's (`what` names the frame).
void expectFrameMatchesReference(GpuRenderer& gpu, const SceneData& data, const FrameInputs& in,
                                 const std::string& what) {
  const RenderOutput out = gpu.render(in, true);
  const RenderOutput ref = renderReference(data, in);
  EXPECT_EQ(out.image.rgb, ref.image.rgb) << what;
  EXPECT_EQ(out.keys, ref.keys) << what;
}

TEST(GpuRender, SequenceOfFramesSkipsViewIndependentLightingAndStillMatches) {
  // ks = 0 everywhere: moving the camera leaves the lighting bitwise unchanged, so the renderer
  // shades colours once and only transforms afterwards; every frame still equals the reference.
  SceneSpec scene = parseSceneSpec(R"({
    "camera": {"position": [3, 0, 1], "look_at": [0, 0, 0], "width": 160, "height": 120},
    "lights": [{"position": [1, -1, 2]}],
    "objects": [{"shape": "sphere", "radius": 0.6, "material": {"ks": 0}},
                {"shape": "cube", "center": [0, 0, -0.8], "size": 0.8, "material": {"ks": 0, "color": [0.3, 0.3, 1]}}]
  })",
                           "orbit.json", ".");
  VulkanContext context = createContext({-1, true});
  {
    const SceneData data = buildSceneData(scene);
    GpuRenderer gpu(context, data);
    for (int i = 0; i < 4; ++i) {
      const double angle = i * 0.7;
      scene.camera.position = {3 * std::cos(angle), 3 * std::sin(angle), 1};
      scene.camera.direction = -scene.camera.position;
      expectFrameMatchesReference(gpu, data, makeFrame(data, makeView(scene.camera)), "frame " + std::to_string(i));
    }
    EXPECT_EQ(gpu.framesShaded(), 1u);
    EXPECT_EQ(gpu.framesTransformed(), 4u);
  }
  destroyContext(context);
  EXPECT_EQ(context.validation->count(), 0u);
}

TEST(GpuRender, FramesThatOnlyChangeLightingKeepThePositionsAndStillMatch) {
  // The view stays: the shaded positions of the first frame serve the next two (one relit, one
  // unchanged, whose shade pass is skipped altogether); then the camera moves and they are
  // transformed again. Every frame equals the reference, keys included.
  SceneSpec scene = parseSceneSpec(R"({
    "camera": {"position": [3, 0, 1], "look_at": [0, 0, 0], "width": 160, "height": 120},
    "lights": [{"position": [1, -1, 2]}],
    "objects": [{"shape": "sphere", "radius": 0.6, "material": {"ks": 0.5}},
                {"shape": "cylinder", "center": [0, 0, -0.7], "radius": 3, "height": 0.01}]
  })",
                           "relight.json", ".");
  VulkanContext context = createContext({-1, true});
  {
    const SceneData data = buildSceneData(scene);
    GpuRenderer gpu(context, data);
    FrameInputs in = makeFrame(data, makeView(scene.camera));
    expectFrameMatchesReference(gpu, data, in, "first frame");
    in.frame.ambient = glm::vec3(0.3f, 0.1f, 0.2f);
    expectFrameMatchesReference(gpu, data, in, "relit");
    expectFrameMatchesReference(gpu, data, in, "unchanged");
    EXPECT_EQ(gpu.framesTransformed(), 1u);
    EXPECT_EQ(gpu.framesShaded(), 2u);
    scene.camera.position = {0, 3, 1.5};
    scene.camera.direction = -scene.camera.position;
    expectFrameMatchesReference(gpu, data, makeFrame(data, makeView(scene.camera)), "moved");
    EXPECT_EQ(gpu.framesTransformed(), 2u);
  }
  destroyContext(context);
  EXPECT_EQ(context.validation->count(), 0u);
}

TEST(GpuRender, ScenesDrawnUnlitKeepTheirColoursWhenTheLightingMoves) {
  // Points and lines without normals are drawn unlit (docs/DESIGN.md "Points and lines"): their
  // colours are the materials' times the vertices', so a moved eye (with a specular material), a
  // new ambient or a moved light reshades nothing, while a material's new colour does. The shade
  // pass of such a scene lights no vertex (everyVertexUnlit). Every frame equals the reference.
  SceneSpec scene = parseSceneSpec(R"({
    "camera": {"position": [3, 0, 1], "look_at": [0, 0, 0], "width": 160, "height": 120},
    "lights": [{"position": [1, -1, 2]}],
    "render": {"point_size": 4, "line_width": 2},
    "objects": [{"shape": "mesh", "vertices": [[0, 0, 0], [0.5, 0.2, 0.3], [-0.4, 0.5, -0.2], [0.1, -0.6, 0.4]],
                 "colors": [[255, 0, 0, 255], [0, 255, 0, 255], [0, 0, 255, 255], [255, 255, 0, 255]],
                 "material": {"ks": 0.5, "color": [0.9, 0.8, 0.7]}},
                {"shape": "mesh", "vertices": [[-1, -1, -0.5], [1, -1, -0.5], [1, 1, -0.5]], "lines": [[0, 1], [1, 2]],
                 "material": {"ks": 0.3}}]
  })",
                           "unlit.json", ".");
  VulkanContext context = createContext({-1, true});
  {
    const SceneData data = buildSceneData(scene);
    ASSERT_TRUE(everyVertexUnlit(data));
    GpuRenderer gpu(context, data);
    FrameInputs in = makeFrame(data, makeView(scene.camera));
    expectFrameMatchesReference(gpu, data, in, "first frame");
    scene.camera.position = {0, 3, 1.5};
    scene.camera.direction = -scene.camera.position;
    in = makeFrame(data, makeView(scene.camera));
    expectFrameMatchesReference(gpu, data, in, "moved");
    in.frame.ambient = glm::vec3(0.3f, 0.1f, 0.2f);
    in.lights[0].position = glm::vec3(-2.0f, 1.0f, 3.0f);
    expectFrameMatchesReference(gpu, data, in, "relit");
    EXPECT_EQ(gpu.framesShaded(), 1u);
    EXPECT_EQ(gpu.framesTransformed(), 2u);
    in.materials[0].color = glm::vec3(0.2f, 0.9f, 0.4f);
    expectFrameMatchesReference(gpu, data, in, "recoloured");
    EXPECT_EQ(gpu.framesShaded(), 2u);
  }
  destroyContext(context);
  EXPECT_EQ(context.validation->count(), 0u);
}

TEST(GpuRender, RelitFramesCompileNothingNew) {
  // lavapipe (Mesa 22.3) compiles a pipeline anew at every bind when inlining the uniform values
  // that decide its branches and loop ends halves it, and keeps every copy (bindings.glsl
  // loadFrame). Relit frames of fig1_cube, whose shade pass did that, must not add code mappings
  // to the process once the first frames are done (on any device: none should).
  const int before = test::executableMappings();
  if (before < 0) GTEST_SKIP() << "no /proc/self/maps";
  SceneSpec scene = loadSceneSpec(test::sourcePath("scenes/paper/fig1_cube.json"));
  VulkanContext context = createContext({-1, false});
  {
    const SceneData data = buildSceneData(scene);
    GpuRenderer gpu(context, data);
    const FrameInputs in = makeFrame(data, makeView(scene.camera));
    EXPECT_EQ(test::mappingsAddedByRelitFrames(in, [&](const FrameInputs& f) { gpu.render(f); }), 0)
        << "code mappings before the first frame: " << before;
    EXPECT_EQ(gpu.framesShaded(), 24u);
  }
  destroyContext(context);
}

// Frames without keys, one after another, in either colour output: where the key slots hold the
// colours, the host must reset every slot it read, or a pixel an object left keeps last frame's
// colour. The cube slides across the view (a frame with keys in between switches output and back).
TEST(GpuRender, FramesLeaveNoColourBehindInEitherOutput) {
  SceneSpec scene = parseSceneSpec(R"({
    "camera": {"position": [0, -3, 0], "look_at": [0, 0, 0], "up": [0, 0, 1], "width": 160, "height": 120},
    "lights": [{"position": [1, -2, 2]}],
    "objects": [{"shape": "cube", "size": 0.8, "material": {"color": [1, 0.5, 0.2]}},
                {"shape": "sphere", "radius": 0.3, "center": [0, 1, 0], "subdivide": 2}]
  })",
                           "slide.json", ".");
  VulkanContext context = createContext({-1, true});
  for (ColorOutput output : {ColorOutput::InKeySlots, ColorOutput::ColorBuffer}) {
    if (output == ColorOutput::InKeySlots && !hasSharedMemory(context)) continue;  // a discrete GPU has the other only
    SceneData data = buildSceneData(scene);
    GpuRenderer gpu(context, data, {.output = output});
    for (int i = 0; i < 5; ++i) {
      scene.camera.position = {-1.2 + 0.6 * i, -3, 0};  // the view slides, so every object moves on screen
      scene.camera.direction = {0, 1, 0};
      const FrameInputs in = makeFrame(data, makeView(scene.camera));
      const RenderOutput out = gpu.render(in, i == 2);
      EXPECT_EQ(out.image.rgb, renderReference(data, in).image.rgb) << "frame " << i << ", output " << int(output);
    }
  }
  destroyContext(context);
  EXPECT_EQ(context.validation->count(), 0u);
}

// One workgroup per pass: on lavapipe, resolving a 4K frame of large triangles in one invocation
// runs out of loop iterations (65535 per invocation), which cut the frame short without a word.
// The frame must be noticed and rendered again with more workgroups, and equal the reference.
TEST(GpuRender, FrameOutOfLoopIterationsIsRenderedAgainWithMoreWorkgroups) {
  SceneSpec scene = loadSceneSpec(test::sourcePath("scenes/floor_and_walls.json"));
  scene.camera.width = 3840;
  scene.camera.height = 2160;
  const SceneData data = buildSceneData(scene);
  const FrameInputs in = makeFrame(data, makeView(scene.camera));
  VulkanContext context = createContext({-1, true});
  {
    GpuRenderer gpu(context, data, {.firstGroupCap = 1});
    const RenderOutput out = gpu.render(in);
    EXPECT_EQ(out.image.rgb, renderReference(data, in).image.rgb);
    if (context.properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU) {
      EXPECT_GT(gpu.framesRepeated(), 0u) << "one workgroup was expected to run out of loop iterations on lavapipe";
    }
  }
  destroyContext(context);
  EXPECT_EQ(context.validation->count(), 0u);
}

// The clip pass carries the clipper only in frames whose scene box reaches outside the clip volume
// (FrameInputs::clip), and from the first frame whose clip pass met a triangle to clip without it
// (that frame rendered again with it). Every frame gives the reference's bytes.
TEST(GpuRender, ClipperOnlyWhereAFrameMayNeedIt) {
  const SceneSpec insideSpec = loadSceneSpec(test::sourcePath("scenes/basic.json"));
  const SceneSpec crossingSpec = loadSceneSpec(test::sourcePath("scenes/stress/near_plane.json"));
  const SceneSpec hugeSpec = loadSceneSpec(test::sourcePath("scenes/stress/huge_triangles.json"));
  const SceneData inside = buildSceneData(insideSpec), crossing = buildSceneData(crossingSpec),
                  huge = buildSceneData(hugeSpec);
  const FrameInputs insideFrame = makeFrame(inside, makeView(insideSpec.camera));
  FrameInputs crossingFrame = makeFrame(crossing, makeView(crossingSpec.camera));
  FrameInputs hugeFrame = makeFrame(huge, makeView(hugeSpec.camera));
  EXPECT_EQ(insideFrame.clip, gpu::CLIP_NONE) << "basic.json's box lies in front of the camera";
  EXPECT_EQ(crossingFrame.clip, gpu::CLIP_ALL) << "near_plane.json crosses the near plane";
  EXPECT_EQ(hugeFrame.clip, gpu::CLIP_ALL) << "huge_triangles.json reaches past the guard band";
  VulkanContext context = createContext({-1, true});
  {
    GpuRenderer gpu(context, crossing);
    EXPECT_EQ(gpu.render(crossingFrame).image.rgb, renderReference(crossing, crossingFrame).image.rgb);
    EXPECT_EQ(gpu.framesRepeated(), 0u) << "foreseen: the first attempt clips";
    EXPECT_EQ(gpu.clipFloor(), gpu::CLIP_NONE);
    // Unforeseen (a frame told that nothing crosses): the clip pass asks for the next clipper.
    crossingFrame.clip = gpu::CLIP_NONE;
    EXPECT_EQ(gpu.render(crossingFrame).image.rgb, renderReference(crossing, crossingFrame).image.rgb);
    EXPECT_EQ(gpu.framesRepeated(), 1u);
    EXPECT_EQ(gpu.clipFloor(), gpu::CLIP_ALL) << "kept for the later frames";
    // Polygons past the guard band on every side, with the clipper kept.
    gpu.replaceScene(huge);
    hugeFrame.clip = gpu::CLIP_NONE;
    EXPECT_EQ(gpu.render(hugeFrame).image.rgb, renderReference(huge, hugeFrame).image.rgb);
    EXPECT_EQ(gpu.framesRepeated(), 1u);
    gpu.replaceScene(inside);
    EXPECT_EQ(gpu.render(insideFrame).image.rgb, renderReference(inside, insideFrame).image.rgb);
    EXPECT_EQ(gpu.framesRepeated(), 1u);
  }
  {
    GpuRenderer gpu(context, inside);
    EXPECT_EQ(gpu.render(insideFrame).image.rgb, renderReference(inside, insideFrame).image.rgb);
    EXPECT_EQ(gpu.framesRepeated(), 0u);
    EXPECT_EQ(gpu.clipFloor(), gpu::CLIP_NONE);
  }
  destroyContext(context);
  EXPECT_EQ(context.validation->count(), 0u);
}

TEST(GpuRender, OverflowingTheLargeTriangleListStillMatchesEveryRun) {
  // 40 open cubes stacked in front of the camera, every face filling much of the 640x480 view:
  // about 40 * 8 large triangles each reserving a bin entry for most of the 300 bins, far more
  // than the large list first holds (640*480/64 entries), so the first frame overflows and is
  // rendered again with larger lists. The image must equal the reference, run after run. (Large
  // triangles that overflowed used to be drawn in place, one invocation each, and on lavapipe a
  // screen-filling one ran out of loop iterations at row 123: about 1 run in 40 was wrong.)
  std::string objects;
  for (int i = 0; i < 40; ++i) {
    objects += std::string(i ? "," : "") + R"({"shape": "cube", "closed": false, "size": 40, "center": [0, )" +
               std::to_string(25 + i) + R"(, 0], "material": {"ks": 0, "color": [)" + std::to_string(0.02 * i) +
               ", 0.5, 0.5]}}";
  }
  const SceneSpec scene = parseSceneSpec(R"({"camera": {"position": [0, 0, 0], "direction": [0, 1, 0], "width": 640, "height": 480},
                                     "lights": [{"position": [0, 1, 0]}], "objects": [)" +
                                     objects + "]}",
                                 "stack.json", ".");
  const SceneData data = buildSceneData(scene);
  const FrameInputs in = makeFrame(data, makeView(scene.camera));
  const RenderOutput ref = renderReference(data, in);
  // Between test frames, a frame from an oblique pose sets up more large triangles, so stale
  // list entries from it would point at set-up records this frame never wrote.
  CameraSpec oblique = scene.camera;
  oblique.position = {6, 0, 4};
  oblique.direction = {-0.3, 1, -0.2};
  const FrameInputs other = makeFrame(data, makeView(oblique));
  VulkanContext context = createContext({-1, true});
  {
    GpuRenderer gpu(context, data);
    for (int run = 0; run < 4; ++run) {
      gpu.render(other);
      const RenderOutput out = gpu.render(in, true);
      EXPECT_EQ(out.keys, ref.keys) << "run " << run;
      EXPECT_EQ(out.image.rgb, ref.image.rgb) << "run " << run;
    }
    EXPECT_GT(gpu.framesRepeated(), 0u) << "the lists were expected to overflow at first";
  }
  destroyContext(context);
  EXPECT_EQ(context.validation->count(), 0u);
}

TEST(GpuRender, SpecularSceneReshadesWhenTheEyeMoves) {
  SceneSpec scene = parseSceneSpec(R"({
    "camera": {"position": [3, 0, 1], "look_at": [0, 0, 0], "width": 96, "height": 64},
    "lights": [{"position": [1, -1, 2]}],
    "objects": [{"shape": "sphere", "radius": 0.6, "material": {"ks": 0.8}}]
  })",
                           "spec.json", ".");
  VulkanContext context = createContext({-1, true});
  {
    const SceneData data = buildSceneData(scene);
    GpuRenderer gpu(context, data);
    gpu.render(makeFrame(data, makeView(scene.camera)));
    scene.camera.position = {0, 3, 1};
    scene.camera.direction = -scene.camera.position;
    const FrameInputs in = makeFrame(data, makeView(scene.camera));
    EXPECT_EQ(gpu.render(in).image.rgb, renderReference(data, in).image.rgb);
    EXPECT_EQ(gpu.framesShaded(), 2u);
  }
  destroyContext(context);
  EXPECT_EQ(context.validation->count(), 0u);
}

}  // namespace
}  // namespace phongvk
