// long_lists_gpu_test.cpp — scenes whose bins thousands of large triangles reach: more work for one
// bin than one lavapipe invocation's loop budget (65535 iterations) even with the most workgroups.
// Each must still render on the compute port, the same keys and bytes as the reference, in both
// work layouts: the frame is rendered again with the bins' lists taken a chunk at a time
// (gpu_layout.h LIST_CHUNK_FIRST), in rounds. The scenes are generated here, not committed.
#include "tests/stress_fixture.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

namespace phongvk {
namespace {

using namespace test;

// A scene of one mesh file (or any objects) seen straight down the z axis at 320x240.
std::string sceneLookingDown(const std::string& objects) {
  return R"({"camera": {"position": [0, 0, 3], "look_at": [0, 0, 0], "up": [0, 1, 0], "width": 320, "height": 240},
             "lights": [{"position": [0.5, 0.7, 4]}], "objects": [)" +
         objects + "]}";
}

// `count` triangles that each fill the whole view, at depths in a scrambled order, so the nearest
// (which wins every pixel) is neither first nor last in any bin's list.
std::string overlappingTrianglesObj(int count) {
  std::string obj;
  for (int i = 0; i < count; ++i) {
    const std::string z = std::to_string(-0.001 * ((i * 7919) % count));
    obj += "v -50 -50 " + z + "\nv 50 -50 " + z + "\nv 0 50 " + z + "\n";
  }
  for (int i = 0; i < count; ++i) {
    obj += "f " + std::to_string(3 * i + 1) + " " + std::to_string(3 * i + 2) + " " + std::to_string(3 * i + 3) + "\n";
  }
  return obj;
}

// One face of `corners` corners on the unit circle: cut into a fan, every triangle of which starts
// at the first corner, so the bins there hold nearly all of them.
std::string circlePolygonObj(int corners) {
  std::string obj;
  char line[96];
  for (int i = 0; i < corners; ++i) {
    const double a = 2 * M_PI * i / corners;
    std::snprintf(line, sizeof line, "v %.9f %.9f 0\n", std::cos(a), std::sin(a));
    obj += line;
  }
  obj += "f";
  for (int i = 1; i <= corners; ++i) obj += " " + std::to_string(i);
  return obj + "\n";
}

class LongLists : public StressTest {
 protected:
  // Writes `obj` (if any) and the scene into a temporary folder and loads it.
  SceneData load(const std::string& objects, const std::string& obj = "") {
    const std::string dir = makeTempDir();
    if (!obj.empty()) writeFile(dir + "/mesh.obj", obj);
    writeFile(dir + "/scene.json", sceneLookingDown(objects));
    spec_ = loadSceneSpec(dir + "/scene.json");
    return buildSceneData(spec_);
  }

  // Renders `data` in the given layout and checks it against the reference; on a CPU device the
  // frame must have been rendered again with the lists taken in chunks (else the case tests nothing).
  void expectRendered(const SceneData& data, WorkLayout layout, const char* name) {
    const FrameInputs in = makeFrame(data, makeView(spec_.camera));
    const RenderOutput reference = renderReference(data, in);
    GpuRenderer renderer(context_, data, {.layout = layout});
    const RenderOutput gpu = renderer.render(in, true);
    EXPECT_TRUE(gpu.keys == reference.keys) << name << ": visibility keys differ from the reference";
    EXPECT_TRUE(gpu.image.rgb == reference.image.rgb) << name << ": image bytes differ";
    EXPECT_GT(coveredPixels(reference.keys), 0u) << name;
    if (context_.properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU && layout == WorkLayout::Cpu) {
      EXPECT_NE(renderer.listChunk(), 0u) << name << ": expected to need the lists in chunks on lavapipe";
    }
    // The next frame keeps the chunks (no retries) and is still right.
    const uint64_t repeated = renderer.framesRepeated();
    EXPECT_TRUE(renderer.render(in).image.rgb == reference.image.rgb) << name << ": second frame";
    EXPECT_EQ(renderer.framesRepeated(), repeated) << name << ": the second frame was rendered again";
  }

  SceneSpec spec_;
};

TEST_F(LongLists, TwoThousandOverlappingScreenFillingTriangles) {
  const SceneData data = load(R"({"shape": "mesh", "file": "mesh.obj", "material": {"ks": 0.5}})",
                              overlappingTrianglesObj(2000));
  ASSERT_EQ(data.triangles.size(), 2000u);
  for (WorkLayout layout : {WorkLayout::Cpu, WorkLayout::Gpu}) expectRendered(data, layout, "2000 triangles");
}

TEST_F(LongLists, HundredThousandCornerPolygon) {
  const SceneData data = load(R"({"shape": "mesh", "file": "mesh.obj"})", circlePolygonObj(100000));
  ASSERT_EQ(data.triangles.size(), 99998u);
  expectRendered(data, WorkLayout::Cpu, "100k-corner polygon");
}

// A 4096-segment cylinder and cone seen end-on: thousands of thin triangles meet at the axis.
TEST_F(LongLists, CylinderAndConeOf4096SegmentsEndOn) {
  for (const char* shape : {"cylinder", "cone"}) {
    const SceneData data = load(std::string(R"({"shape": ")") + shape +
                                R"(", "center": [0, 0, 0], "radius": 1, "height": 1, "segments": 4096})");
    const FrameInputs in = makeFrame(data, makeView(spec_.camera));
    const RenderOutput reference = renderReference(data, in);
    GpuRenderer renderer(context_, data);
    const RenderOutput gpu = renderer.render(in, true);
    EXPECT_TRUE(gpu.keys == reference.keys) << shape;
    EXPECT_TRUE(gpu.image.rgb == reference.image.rgb) << shape;
  }
}

// Lists taken a few entries a round from the first frame, on scenes of large and small triangles
// (the floor, walls and objects; the paper's cube and two lights; triangles crossing the near
// plane), in both layouts, with and without keys (colours in the key slots or the colour buffer):
// the rounds leave the reference's keys and bytes.
TEST_F(LongLists, ListsTakenInRoundsGiveTheReferenceImage) {
  for (const char* file : {"scenes/floor_and_walls.json", "scenes/paper/fig3_two_lights.json", "scenes/stress/near_plane.json"}) {
    spec_ = loadSceneSpec(sourcePath(file));
    const SceneData data = buildSceneData(spec_);
    const FrameInputs in = makeFrame(data, makeView(withImageSize(spec_.camera, 320, 240)));
    const RenderOutput reference = renderReference(data, in);
    for (WorkLayout layout : {WorkLayout::Cpu, WorkLayout::Gpu}) {
      for (ColorOutput output : {ColorOutput::Auto, ColorOutput::ColorBuffer}) {
        GpuRenderer renderer(context_, data, {.layout = layout, .output = output, .firstListChunk = 2});
        const RenderOutput withKeys = renderer.render(in, true);
        EXPECT_TRUE(withKeys.keys == reference.keys) << file;
        EXPECT_TRUE(withKeys.image.rgb == reference.image.rgb) << file;
        EXPECT_TRUE(renderer.render(in).image.rgb == reference.image.rgb) << file << ", without keys";
        EXPECT_EQ(renderer.listChunk(), 2u);
      }
    }
  }
}

// From the command line: exit 0 and the reference's PNG, where the same scene used to exit 4 with
// "scene too large for llvmpipe".
TEST_F(LongLists, TheCommandRendersWhatItUsedToRefuse) {
  const std::string dir = makeTempDir();
  writeFile(dir + "/mesh.obj", overlappingTrianglesObj(2000));
  writeFile(dir + "/scene.json", sceneLookingDown(R"({"shape": "mesh", "file": "mesh.obj"})"));
  const CommandResult gpu = runCli("render " + dir + "/scene.json -o " + dir + "/gpu.png");
  ASSERT_EQ(gpu.exitCode, 0) << gpu.output;
  const CommandResult cpu = runCli("render " + dir + "/scene.json --backend cpu -o " + dir + "/cpu.png");
  ASSERT_EQ(cpu.exitCode, 0) << cpu.output;
  const CommandResult diff = runCli("diff " + dir + "/scene.json");
  EXPECT_EQ(diff.exitCode, 0) << diff.output;
  EXPECT_EQ(readBytes(dir + "/gpu.png"), readBytes(dir + "/cpu.png"));
}

}  // namespace
}  // namespace phongvk
