// measure.h — timing one frame of a scene on each backend: the CPU reference, the Vulkan compute
// port (GpuRenderer) and the graphics-pipeline baseline (GraphicsRenderer); plus device memory and
// host memory. Every time is the median of `repeat` frames after one warm-up (api/timing.h).
#pragma once

#include "compute/gpu_renderer.h"
#include "phongvk/image.h"
#include "prepare/scene_data.h"
#include "vulkan/context.h"

#include <cstdint>
#include <limits>
#include <memory>
#include <string>

namespace phongvk::bench {

inline constexpr double NOT_MEASURED = std::numeric_limits<double>::quiet_NaN();

struct Timing {
  double wallMs = NOT_MEASURED;    // around the render call: per-frame upload, dispatch, wait, readback
  double deviceMs = NOT_MEASURED;  // the device's own timestamps (NaN for the reference)
  std::string failure;             // non-empty when the backend could not render the scene
  bool ok() const { return failure.empty(); }
  // "does not fit" (a device limit, named in failure) or "failed" (anything else); for tables.
  std::string failureKind() const { return failure.rfind("does not fit", 0) == 0 ? "does not fit" : "failed"; }
};

struct BackendRun {
  Timing time;
  Image image;                   // the first frame, for checking the picture
};

struct ComputeRun : BackendRun {
  PassTimes passes;              // median device ms per pass
  uint64_t sceneBytes = 0;       // device memory after constructing the renderer
  uint64_t imageBytes = 0;       // what the first frame added (per-pixel buffers)
  bool shadedEveryFrame = true;  // each timed frame re-lit every vertex (see runCompute)
};

// Two frame inputs that differ only in the last bit of the ambient light's red channel. Frames
// alternate between them so the compute port re-lights every vertex each frame, as a real frame
// and the baseline's vertex shader do; rendering one input again it would skip lighting
// (GpuRenderer::framesShaded). The images differ by at most one rounding step in rare pixels.
struct FramePair {
  FrameInputs a, b;
  const FrameInputs& operator[](uint64_t i) const { return i % 2 ? b : a; }
};
FramePair makeFramePair(const SceneData& data, const View& view);

BackendRun runReference(const SceneData& data, const FramePair& frames, int repeat);

// Failures to construct the renderer (a scene past a device limit) come back in time.failure.
// `pipelines`: compiled ones to take and keep (none: the renderer compiles its own).
ComputeRun runCompute(const VulkanContext& context, const SceneData& data, const FramePair& frames, int repeat,
                      std::shared_ptr<GpuPipelineSet> pipelines = nullptr);
BackendRun runGraphics(const VulkanContext& context, const SceneData& data, const FramePair& frames, int repeat);

// The process's peak resident memory so far (getrusage maxrss), in bytes.
uint64_t peakHostBytes();

}  // namespace phongvk::bench
