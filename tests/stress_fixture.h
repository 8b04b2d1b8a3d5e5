// stress_fixture.h — what the stress suites share (stress_gpu_test: scenes nobody planned for,
// limits_gpu_test: the device's limits): one validated context per test, rendering a scene with
// both renderers and checking the stress contract (finite vertices, the same keys and bytes).
#pragma once

#include "compute/gpu_renderer.h"
#include "phongvk/compare.h"
#include "prepare/scene_data.h"
#include "reference/render_reference.h"
#include "scene/camera.h"
#include "scene/scene.h"
#include "shaders/depth.h"
#include "tests/test_util.h"
#include "vulkan/context.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace phongvk::test {

// What one stress render measured, beyond the diff itself.
struct StressResult {
  SceneData data;
  FrameInputs in;
  RenderOutput reference;
  RenderOutput gpu;
  DiffStats diff;
};

inline uint32_t objectOf(const SceneData& data, uint64_t key) { return data.triangles[uint32_t(key)].w; }

// Pixels won by each object (index = object), from a renderer's keys.
inline std::vector<size_t> pixelsPerObject(const SceneData& data, const std::vector<uint64_t>& keys) {
  std::vector<size_t> pixels(data.objects.size(), 0);
  for (uint64_t key : keys) {
    if (key != gpu::KEY_CLEAR) ++pixels[objectOf(data, key)];
  }
  return pixels;
}

inline size_t coveredPixels(const std::vector<uint64_t>& keys) {
  size_t covered = 0;
  for (uint64_t key : keys) covered += key != gpu::KEY_CLEAR;
  return covered;
}

inline void expectFinite(const std::vector<gpu::ShadedVertex>& shaded) {
  size_t bad = 0;
  for (size_t i = 0; i < shaded.size(); ++i) {
    const gpu::ShadedVertex& v = shaded[i];
    const bool finite = std::isfinite(v.hpos.x) && std::isfinite(v.hpos.y) && std::isfinite(v.hpos.z) &&
                        std::isfinite(v.color.x) && std::isfinite(v.color.y) && std::isfinite(v.color.z);
    if (!finite && ++bad <= 3) {
      ADD_FAILURE() << "vertex " << i << " is not finite: hpos (" << v.hpos.x << ", " << v.hpos.y << ", " << v.hpos.z
                    << "), colour (" << v.color.x << ", " << v.color.y << ", " << v.color.z << ")";
    }
  }
  EXPECT_EQ(bad, 0u) << "vertices with NaN or Inf in their shaded position or colour";
}

// One validated context per test. TearDown destroys it before reading the log, so objects left
// alive (reported at vkDestroyDevice) fail the test too.
class StressTest : public ::testing::Test {
 protected:
  void SetUp() override { openContext(); }
  void TearDown() override { closeContext(); }

  // Makes context_ again as on a device whose maxStorageBufferRange is `bytes` (where the device's
  // own is larger), through PHONGVK_MAX_STORAGE_BUFFER_RANGE, set while the context is made.
  void limitStorageBufferRange(uint64_t bytes) {
    closeContext();
    const ScopedEnv range("PHONGVK_MAX_STORAGE_BUFFER_RANGE", std::to_string(bytes));
    openContext();
  }

  void openContext() {
    context_ = createContext({.deviceIndex = -1, .validate = true});
    log_ = context_.validation;
    ASSERT_NE(log_, nullptr);
  }

  void closeContext() {
    destroyContext(context_);
    if (!log_) return;
    std::string text;
    for (const std::string& message : log_->messages()) text += message + "\n";
    EXPECT_EQ(log_->count(), 0u) << "validation messages:\n" << text;
    log_.reset();
  }

  // Renders `data` as seen in `in` with both backends and checks the stress contract.
  StressResult renderBoth(SceneData data, const FrameInputs& in, const std::string& name) {
    StressResult r{std::move(data), in, {}, {}, {}};
    expectFinite(shadeVertices(r.data, r.in));
    r.reference = renderReference(r.data, r.in);
    GpuRenderer renderer(context_, r.data);
    r.gpu = renderer.render(r.in, true);
    r.diff = compareImages(r.reference.image, r.gpu.image, r.reference.keys, r.gpu.keys);
    expectIdentical(r, name);
    std::printf("stress: %-22s %5dx%-5d %8zu triangles, %7zu px covered: %llu px differ, max channel diff %d, "
                "%llu triangle mismatches\n",
                name.c_str(), r.diff.width, r.diff.height, r.data.triangles.size(), coveredPixels(r.reference.keys),
                static_cast<unsigned long long>(r.diff.differing), r.diff.maxChannelDiff(),
                static_cast<unsigned long long>(r.diff.triangleMismatch));
    return r;
  }

  // A scene file of scenes/stress/, optionally at another image size (as --width/--height).
  StressResult renderScene(const std::string& file, int width = 0, int height = 0) {
    const SceneSpec scene = loadSceneSpec(test::sourcePath("scenes/stress/" + file));
    const CameraSpec camera = width > 0 ? withImageSize(scene.camera, width, height) : scene.camera;
    SceneData data = buildSceneData(scene);
    const FrameInputs in = makeFrame(data, makeView(camera));
    return renderBoth(std::move(data), in, file);
  }

  static void expectIdentical(const StressResult& r, const std::string& name) {
    EXPECT_TRUE(r.diff.keysCompared) << name;
    EXPECT_EQ(r.diff.triangleMismatch, 0u) << name << ": pixels whose winning triangle differs from the reference";
    EXPECT_TRUE(r.gpu.keys == r.reference.keys) << name << ": visibility keys differ from the reference";
    EXPECT_TRUE(r.gpu.image.rgb == r.reference.image.rgb) << name << ": image bytes differ\n" << formatDiff(r.diff);
  }

  VulkanContext context_;
  std::shared_ptr<ValidationLog> log_;
};

}  // namespace phongvk::test
