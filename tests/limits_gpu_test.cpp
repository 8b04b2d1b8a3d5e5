// limits_gpu_test.cpp — the device's limits: the largest image its buffers hold renders like the
// reference, and anything past a limit (image size, vertices, any of the scene's arrays) is a
// clear error naming the array, the amount and the limit, in process and from the CLI (exit 4,
// nothing written). A device whose maxStorageBufferRange is larger than a case can reach (a GPU's
// 4 GiB) runs that case as on lavapipe, through PHONGVK_MAX_STORAGE_BUFFER_RANGE.
#include "tests/stress_fixture.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <limits>
#include <string>

namespace phongvk {
namespace {

using namespace test;

// lavapipe's maxStorageBufferRange, the least Vulkan allows (2^27 bytes): the cases past that limit
// run with it on every device.
constexpr uint64_t kLeastStorageRange = uint64_t(1) << 27;
constexpr const char* kStorageRangeVariable = "PHONGVK_MAX_STORAGE_BUFFER_RANGE";

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
// device loss, and the renderer still renders afterwards. A device that holds keys past 4096x4097
// meets the limit lowered to lavapipe's.
TEST_F(StressTest, ImageLargerThanTheDeviceHoldsIsAClearError) {
  if (context_.properties.limits.maxStorageBufferRange > kLeastStorageRange)
    limitStorageBufferRange(kLeastStorageRange);
  const VkDeviceSize range = context_.properties.limits.maxStorageBufferRange;
  const int side = largestSquareSide(context_);
  ASSERT_GT(VkDeviceSize(side) * (side + 1) * sizeof(uint64_t), range);
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

// The CLI meets the device's limits: exit code 4, the limit named, and no file written. A device
// that holds more than the cases can ask for (keys past the CLI's 16384-pixel sides; more than 16
// big icospheres, minutes to build) runs the CLI with its limit lowered to lavapipe's, as on the
// least device Vulkan allows; lavapipe meets its real limit.
class CliLimit : public StressTest {
 protected:
  // The maxStorageBufferRange the CLI runs under.
  uint64_t range() const {
    return std::min<uint64_t>(context_.properties.limits.maxStorageBufferRange, kLeastStorageRange);
  }
  // The environment that gives the CLI range(): nothing where it is the device's own.
  std::string environment() const {
    if (range() == context_.properties.limits.maxStorageBufferRange) return "";
    return std::string(kStorageRangeVariable) + "=" + std::to_string(range());
  }
  void expectRefused(const std::string& args, const std::string& message) {
    const std::string out = test::makeTempDir();
    const test::CommandResult r = test::runCliWithEnvironment(environment(), args + " -o " + out + "/x.png");
    EXPECT_EQ(r.exitCode, 4) << args << "\n" << r.output;
    EXPECT_NE(r.output.find(message), std::string::npos) << args << "\n" << r.output;
    EXPECT_TRUE(std::filesystem::is_empty(out)) << args << ": a file was left behind";
  }
  std::string limitMessage(const std::string& what, uint64_t need) const {
    return what + " need " + std::to_string(need) + " bytes, more than maxStorageBufferRange (" +
           std::to_string(range()) + ")";
  }
};

// 4096 pixels wide, one row more than the key buffer holds (4097 rows at 128 MiB).
TEST_F(CliLimit, ImageLargerThanTheDeviceHolds) {
  const uint64_t rows = range() / (4096 * sizeof(uint64_t)) + 1;
  ASSERT_LE(rows, uint64_t(MAX_IMAGE_SIDE));
  expectRefused("render " + test::sourcePath("scenes/stress/one_pixel.json") + " --width 4096 --height " +
                    std::to_string(rows),
                limitMessage("the per-pixel depth keys", 4096 * rows * sizeof(uint64_t)));
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
// scene reaches each of them (CliLimit.MoreVerticesThanTheDeviceHolds meets the renderer's own).
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
  // list a 48-byte header, 4 bytes per triangle and on the 32-bit key path a word of kept bits per
  // 32 triangles and, in a scene this small, the kept triangles' list (4 bytes per triangle).
  EXPECT_EQ(limited(2 * vertices - 1, big), message("the vertices", 2 * vertices, "texels", "maxTexelBufferElements", 2 * vertices - 1));
  EXPECT_EQ(limited(triangles - 1, big), message("the triangles", triangles, "texels", "maxTexelBufferElements", triangles - 1));
  const bool keys32 = context_.info.keys32;
  ASSERT_LT(triangles, gpu::KEPT_LIST_BELOW);
  const uint64_t clipBytes = sizeof(gpu::IdList) + 4 * triangles + (keys32 ? 4 * ((triangles + 31) / 32) + 4 * triangles : 0);
  EXPECT_EQ(limited(big, clipBytes - 1), message("the clip list", clipBytes, "bytes", "maxStorageBufferRange", clipBytes - 1));
  // The shaded positions (16 bytes a vertex) are written a binding's worth at a time (gpu_layout.h
  // ShadeChunk) and read as texels: one binding must hold them all only where the passes read
  // them as storage buffers (VulkanContext::storageArrays), and there the vertices (32 bytes each) meet it first.
  ASSERT_LT(16 * vertices, clipBytes);
  EXPECT_EQ(limited(big, 16 * vertices - 1),
            context_.storageArrays
                ? message("the vertices", 32 * vertices, "bytes", "maxStorageBufferRange", 16 * vertices - 1)
                : message("the clip list", clipBytes, "bytes", "maxStorageBufferRange", 16 * vertices - 1));
  EXPECT_EQ(limited(big, big), "(no error)");
}

// A scene whose shaded positions pass one storage-buffer binding is shaded in chunks, each dispatch
// writing through bindings at its chunk (gpu_layout.h ShadeChunk), and renders with the reference's
// keys and bytes: 1,800 separate triangles (three vertices each) and 2,400 points, half of them
// lit, 7,800 vertices (124,800 bytes of shaded positions), on a device whose maxStorageBufferRange
// is 70,000 bytes (4,368 vertices a chunk: two chunks, the second short). The first chunk holds
// most of the triangles' vertices, the second the rest of them and every point.
TEST_F(StressTest, VerticesPastOneBindingAreShadedInChunks) {
  const uint64_t range = 70000;
  std::string soup = R"({"shape": "mesh", "material": {"color": [0.9, 0.6, 0.3], "ks": 0.4}, "vertices": [)", faces;
  for (int t = 0; t < 1800; ++t) {
    const double x = -1.0 + 0.05 * (t % 40), y = -1.0 + 0.045 * (t / 40), z = 0.1 * std::sin(0.7 * t);
    soup += std::string(t ? ", " : "") + "[" + std::to_string(x) + ", " + std::to_string(y) + ", " + std::to_string(z) +
            "], [" + std::to_string(x + 0.12) + ", " + std::to_string(y) + ", " + std::to_string(z + 0.02) + "], [" +
            std::to_string(x) + ", " + std::to_string(y + 0.1) + ", " + std::to_string(z - 0.03) + "]";
    faces += std::string(t ? ", " : "") + "[" + std::to_string(3 * t) + ", " + std::to_string(3 * t + 1) + ", " +
             std::to_string(3 * t + 2) + "]";
  }
  soup += "], \"faces\": [" + faces + "]}";
  auto cloud = [](int first, bool normals) {
    std::string points = R"({"shape": "mesh", "point_size": 3, "vertices": [)", normalRows;
    for (int p = first; p < first + 1200; ++p) {
      points += std::string(p > first ? ", " : "") + "[" + std::to_string(-1.0 + 0.00083 * p) + ", " +
                std::to_string(0.8 * std::cos(0.01 * p)) + ", " + std::to_string(0.2 + 0.1 * std::sin(0.05 * p)) + "]";
      normalRows += std::string(p > first ? ", " : "") + "[0, -1, 1]";
    }
    return points + "]" + (normals ? ", \"normals\": [" + normalRows + "]" : std::string()) + "}";
  };
  const std::string dir = makeTempDir();
  writeFile(dir + "/chunks.json", R"({"camera": {"position": [0, -3, 2], "look_at": [0, 0, 0], "width": 64, "height": 48},
    "lights": [{"position": [1, -2, 3]}], "objects": [)" + soup + ", " + cloud(0, true) + ", " + cloud(1200, false) + "]}");
  limitStorageBufferRange(range);
  const SceneSpec scene = loadSceneSpec(dir + "/chunks.json");
  SceneData data = buildSceneData(scene);
  ASSERT_EQ(data.vertices.size(), 7800u);
  ASSERT_GT(data.vertices.size() * 16, range);
  const FrameInputs in = makeFrame(data, makeView(scene.camera));
  const StressResult r = renderBoth(std::move(data), in, "chunks.json");
  const std::vector<size_t> won = pixelsPerObject(r.data, r.reference.keys);  // the soup, then the clouds
  for (size_t object = 0; object < won.size(); ++object) EXPECT_GT(won[object], 100u) << "object " << object;
}

// ---- PHONGVK_MAX_STORAGE_BUFFER_RANGE ----

// The device's maxStorageBufferRange, as a context made with the variable set to `value` reads it.
uint64_t storageRangeWith(const std::string& value) {
  const ScopedEnv range(kStorageRangeVariable, value);
  VulkanContext context = createContext({.deviceIndex = -1});
  const uint64_t limit = context.properties.limits.maxStorageBufferRange;
  destroyContext(context);
  return limit;
}

uint64_t deviceStorageRange() {
  VulkanContext context = createContext({.deviceIndex = -1});
  const uint64_t limit = context.properties.limits.maxStorageBufferRange;
  destroyContext(context);
  return limit;
}

// A smaller value lowers the limit; the device's own, a larger one or one past 64 bits leaves it.
TEST(StorageRangeVariable, LowersTheLimitAndNeverRaisesIt) {
  const uint64_t device = deviceStorageRange();
  EXPECT_EQ(storageRangeWith("1000"), 1000u);
  EXPECT_EQ(storageRangeWith(std::to_string(device - 1)), device - 1);
  EXPECT_EQ(storageRangeWith(std::to_string(device)), device);
  EXPECT_EQ(storageRangeWith(std::to_string(device + 1)), device);
  EXPECT_EQ(storageRangeWith("99999999999999999999999"), device);
}

// Anything but a decimal number of bytes, at least 1, is an error naming the variable and the value,
// in process (ArgumentError) and from the CLI (exit 2, nothing rendered).
TEST(StorageRangeVariable, AnInvalidValueIsAClearError) {
  for (const char* bad : {"", "abc", "0", "-1", "+5", " 5", "5 ", "12x", "1e6", "0x100", "1.5"}) {
    const ScopedEnv range(kStorageRangeVariable, bad);
    EXPECT_EQ(thrownMessage<ArgumentError>([] { createContext({.deviceIndex = -1}); }),
              std::string(kStorageRangeVariable) + " is '" + bad +
                  "': expected a number of bytes, at least 1 (e.g. 134217728)");
  }
  const std::string out = makeTempDir();
  const CommandResult r = runCliWithEnvironment(std::string(kStorageRangeVariable) + "=abc",
                                                "render " + sourcePath("scenes/basic.json") + " -o " + out + "/x.png");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find(std::string("error: ") + kStorageRangeVariable + " is 'abc'"), std::string::npos) << r.output;
  EXPECT_TRUE(std::filesystem::is_empty(out)) << "a file was left behind";
}

}  // namespace
}  // namespace phongvk
