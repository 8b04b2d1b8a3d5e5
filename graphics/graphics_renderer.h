// graphics_renderer.h — the Vulkan *graphics* pipeline baseline (`--backend raster`): the same
// per-vertex Phong in a vertex shader, fixed-function rasterization with a depth buffer, Gouraud
// interpolation by the hardware's varyings. It is the speed baseline of the benchmark and a second,
// independent check of the compute port's images (its raster rules and depth are the device's own,
// so it agrees with the reference closely but not bit for bit).
#pragma once

#include "phongvk/image.h"
#include "prepare/scene_data.h"
#include "vulkan/context.h"

#include <memory>

namespace phongvk {

class GraphicsRenderer {
 public:
  // Uploads the scene once. Throws DeviceError naming the device limit a scene exceeds,
  // VulkanError otherwise.
  GraphicsRenderer(const VulkanContext& context, const SceneData& data);
  ~GraphicsRenderer();
  GraphicsRenderer(const GraphicsRenderer&) = delete;
  GraphicsRenderer& operator=(const GraphicsRenderer&) = delete;

  // Renders one frame and reads the image back. RenderOutput::keys stays empty.
  RenderOutput render(const FrameInputs& in);

  // Device time of the last frame's draw (clear to resolve), in milliseconds; NaN without
  // timestamps.
  double lastDeviceMs() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace phongvk
