// limits_gpu_test.cpp — the device's limits: the largest image its buffers hold renders like the
// reference, and anything past a limit (image size, vertices, any of the scene's arrays) is a
// clear error naming the array, the amount and the limit, in process and from the CLI (exit 4,
// nothing written).
#include "tests/stress_fixture.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <limits>
#include <string>

namespace phongvk {
namespace {

using namespace test;

// The largest square image the device's storage buffers hold (keys: 8 bytes a pixel), capped at
// 4096 (lavapipe's exact limit) to keep CI short.
int largestSquareSide(const VulkanContext& context) {
  const double pixels = double(context.properties.limits.maxStorageBufferRange) / sizeof(uint64_t);
  return std::min(4096, int(std::sqrt(pixels)));
}

TEST_F(StressTest, LargestImageTheDeviceHolds) {
  const int side = largestSquareSide(context_);
  const StressResult r = renderScene("near_plane.json", side, side);
  EXPECT_EQ(r.diff.width, side);
}

// One row more than the key buffer holds: a clear error before anything is allocated, never a
// device loss, and the renderer still renders afterwards.
TEST_F(StressTest, ImageLargerThanTheDeviceHoldsIsAClearError) {
  const VkDeviceSize range = context_.properties.limits.maxStorageBufferRange;
  const int side = largestSquareSide(context_);
  if (VkDeviceSize(side) * (side + 1) * sizeof(uint64_t) <= range) {
    GTEST_SKIP() << "this device's maxStorageBufferRange (" << range << ") holds keys past " << side << "x" << side
                 << "; the case needs a smaller limit, such as lavapipe's 128 MiB";
  }
  const SceneSpec scene = loadSceneSpec(test::sourcePath("scenes/stress/one_pixel.json"));
  const SceneData data = buildSceneData(scene);
  GpuRenderer renderer(context_, data);
  const FrameInputs tooLarge = makeFrame(data, makeView(withImageSize(scene.camera, side, side + 1)));
  try {
    renderer.render(tooLarge);
    FAIL() << "no error for a " << side << "x" << side + 1 << " image";
  } catch (const std::runtime_error& e) {
    const std::string bytes = std::to_string(VkDeviceSize(side) * (side + 1) * sizeof(uint64_t));
    EXPECT_EQ(std::string(e.what()), "scene too large for " + context_.info.name +
                                         ": the per-pixel depth keys need " + bytes +
                                         " bytes, more than maxStorageBufferRange (" + std::to_string(range) + ")");
  }
  const FrameInputs small = makeFrame(data, makeView(withImageSize(scene.camera, 8, 8)));
  const RenderOutput out = renderer.render(small, true);
  EXPECT_EQ(out.keys, renderReference(data, small).keys) << "the renderer is still usable after the error";
}

// The CLI meets the device's real limits: exit code 4, the limit named, and no file written. Where
// the device holds more than the case can ask for (the CLI's 16384-pixel sides; a scene of more than
// 16 big icospheres would take minutes to build), the case is skipped: the in-process tests above
// and below reach every limit on any device.
class CliLimit : public StressTest {
 protected:
  void expectRefused(const std::string& args, const std::string& message) {
    const std::string out = test::makeTempDir();
    const test::CommandResult r = test::runCli(args + " -o " + out + "/x.png");
    EXPECT_EQ(r.exitCode, 4) << args << "\n" << r.output;
    EXPECT_NE(r.output.find(message), std::string::npos) << args << "\n" << r.output;
    EXPECT_TRUE(std::filesystem::is_empty(out)) << args << ": a file was left behind";
  }
  std::string limitMessage(const std::string& what, uint64_t need) const {
    return what + " need " + std::to_string(need) + " bytes, more than maxStorageBufferRange (" +
           std::to_string(context_.properties.limits.maxStorageBufferRange) + ")";
  }
};

// 4096 pixels wide, one row more than the key buffer holds (4097 rows on lavapipe's 128 MiB).
TEST_F(CliLimit, ImageLargerThanTheDeviceHolds) {
  const uint64_t range = context_.properties.limits.maxStorageBufferRange;
  const uint64_t rows = range / (4096 * sizeof(uint64_t)) + 1;
  if (rows > MAX_IMAGE_SIDE) GTEST_SKIP() << "this device's maxStorageBufferRange (" << range << ") holds keys past "
                                          << "4096x" << MAX_IMAGE_SIDE << ", the largest image the CLI takes";
  expectRefused("render " + test::sourcePath("scenes/stress/one_pixel.json") + " --width 4096 --height " +
                    std::to_string(rows),
                limitMessage("the per-pixel depth keys", 4096 * rows * sizeof(uint64_t)));
}

// Icospheres of 655,362 vertices, one more than their shaded positions (16 bytes each) fit in
// maxStorageBufferRange (13 on lavapipe). The vertices themselves are read as texels (2 GiB there).
TEST_F(CliLimit, MoreVerticesThanTheDeviceHolds) {
  const uint64_t range = context_.properties.limits.maxStorageBufferRange;
  const uint64_t sphereBytes = 16 * 655362;
  const uint64_t spheres = range / sphereBytes + 1;
  if (spheres > 16) GTEST_SKIP() << "this device's maxStorageBufferRange (" << range << ") holds " << spheres - 1
                                 << " icospheres of subdivide 8; the case builds at most 16";
  std::string objects;
  for (uint64_t i = 0; i < spheres; ++i) {
    objects += std::string(i ? ", " : "") + R"({"shape": "icosphere", "center": [)" + std::to_string(i) +
               R"(, 0, 0], "subdivide": 8})";
  }
  const std::string dir = test::makeTempDir();
  test::writeFile(dir + "/big.json", R"({"camera": {"position": [0, -30, 0], "look_at": [0, 0, 0]}, "objects": [)" +
                                         objects + "]}");
  expectRefused("render " + dir + "/big.json --width 8 --height 8",
                limitMessage("the shaded vertex positions", spheres * sphereBytes));
}

// ---- scene sizes ----

// The message GpuRenderer's constructor throws for `data`.
std::string uploadError(const VulkanContext& context, const SceneData& data) {
  try {
    GpuRenderer renderer(context, data);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "(no error)";
}

// SceneSpec arrays past a device limit: a clear error naming the array, the amount and the limit,
// thrown before anything is allocated. The limits are lowered on a copy of the context, so a small
// scene reaches each of them (CliLimit.MoreVerticesThanTheDeviceHolds meets the real one).
TEST_F(StressTest, MoreGeometryThanTheDeviceHoldsIsAClearError) {
  SceneData data = buildSceneData(loadSceneSpec(test::sourcePath("scenes/stress/one_pixel.json")));
  const uint64_t vertices = data.vertices.size();
  data.triangles.resize(4 * vertices + 1, data.triangles[0]);  // more than the vertices need, in both units
  const uint64_t triangles = data.triangles.size();
  const std::string prefix = "scene too large for " + context_.info.name + ": ";
  auto limited = [&](uint32_t texels, uint32_t bytes) {
    VulkanContext context = context_;
    context.properties.limits.maxTexelBufferElements = texels;
    context.properties.limits.maxStorageBufferRange = bytes;
    return uploadError(context, data);
  };
  auto message = [&](const std::string& what, uint64_t need, const char* unit, const char* limit, uint64_t value) {
    return prefix + what + " need " + std::to_string(need) + " " + unit + ", more than " + limit + " (" +
           std::to_string(value) + ")";
  };
  const uint32_t big = std::numeric_limits<uint32_t>::max();
  // VertexIn is two texels; a triangle one; a shaded position one texel and 16 bytes; the clip
  // list a 32-byte header and 4 bytes per triangle.
  EXPECT_EQ(limited(2 * vertices - 1, big), message("the vertices", 2 * vertices, "texels", "maxTexelBufferElements", 2 * vertices - 1));
  EXPECT_EQ(limited(triangles - 1, big), message("the triangles", triangles, "texels", "maxTexelBufferElements", triangles - 1));
  EXPECT_EQ(limited(big, 16 * vertices - 1),
            message("the shaded vertex positions", 16 * vertices, "bytes", "maxStorageBufferRange", 16 * vertices - 1));
  const uint64_t clipBytes = sizeof(gpu::IdList) + 4 * triangles;
  EXPECT_EQ(limited(big, clipBytes - 1), message("the clip list", clipBytes, "bytes", "maxStorageBufferRange", clipBytes - 1));
  EXPECT_EQ(limited(big, big), "(no error)");
}

}  // namespace
}  // namespace phongvk
