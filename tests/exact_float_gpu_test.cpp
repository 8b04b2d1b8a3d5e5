// The float probe on the device the tests run on (vulkan/float_probe.h): its own division and square
// root are exact (lavapipe), or the corrected ones are (a GPU with a fused fma), so the renderer can
// give the reference's bits; and the passes' `_exact` builds compile and render on any device.
#include "compute/gpu_renderer.h"
#include "phongvk/compare.h"
#include "prepare/scene_data.h"
#include "reference/render_reference.h"
#include "scene/camera.h"
#include "scene/scene.h"
#include "test_util.h"
#include "vulkan/context.h"
#include "vulkan/float_probe.h"

#include <gtest/gtest.h>

namespace phongvk {
namespace {

// The device the tests run on: its own operations are exact (lavapipe), or the corrected ones are
// (a GPU with a fused fma), so the renderer can give the reference's bits.
TEST(FloatProbe, DeviceIsExactOrCorrectable) {
  VulkanContext context = createContext({.deviceIndex = -1, .validate = true});
  const FloatReport f = probeFloatOps(context);
  const std::string name = context.info.name;
  const size_t messages = context.validation->count();
  destroyContext(context);
  EXPECT_EQ(messages, 0u);
  EXPECT_GT(f.probes, 4000u);
  EXPECT_TRUE(f.nativeExact() || f.correctionExact())
      << name << ": a / b off on " << f.divideOff << ", sqrt on " << f.sqrtOff << ", fma on " << f.fmaOff
      << ", corrected quotient on " << f.exactDivideOff << ", corrected root on " << f.exactSqrtOff << " of "
      << f.probes << " probes";
}

// The passes' `_exact` builds compile and render on any device. They give the reference's bits
// only with a fused fma (the H100 ran every test with them); lavapipe's fma is not fused, so here
// the image need only be within one level of the reference's.
TEST(FloatProbe, ExactBuildsRenderOnAnyDevice) {
  VulkanContext context = createContext({.deviceIndex = -1, .validate = true});
  {
    const SceneSpec scene = loadSceneSpec(test::sourcePath("scenes/paper/fig1_cube.json"));
    const SceneData data = buildSceneData(scene);
    const FrameInputs in = makeFrame(data, makeView(scene.camera));
    for (WorkLayout layout : {WorkLayout::Cpu, WorkLayout::Gpu}) {
      // The same device, told its division is off and correctable.
      GpuRenderer gpu(context, data, {.layout = layout, .exactFloats = true});
      const RenderOutput out = gpu.render(in, true);
      const RenderOutput ref = renderReference(data, in);
      const DiffStats stats = compareImages(ref.image, out.image, ref.keys, out.keys);
      EXPECT_LE(stats.maxChannelDiff(), 1) << formatDiff(stats);
      EXPECT_GE(stats.identicalFraction(), 0.999) << formatDiff(stats);
    }
  }
  const size_t messages = context.validation->count();
  destroyContext(context);
  EXPECT_EQ(messages, 0u);
}

}  // namespace
}  // namespace phongvk
