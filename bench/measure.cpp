#include "measure.h"

#include "api/timing.h"
#include "graphics/graphics_renderer.h"
#include "reference/render_reference.h"
#include "tools/statistics.h"

#include <sys/resource.h>

#include <cmath>
#include <functional>
#include <memory>
#include <stdexcept>

namespace phongvk::bench {

namespace {

using RenderFn = std::function<RenderOutput(const FrameInputs&)>;

// One warm-up and `repeat` timed frames over the alternating inputs, keeping the first image.
// `deviceMs` is asked after each frame for the device time the backend measured.
BackendRun timeRenders(const FramePair& frames, int repeat, const RenderFn& render,
                       const std::function<double()>& deviceMs) {
  BackendRun run;
  uint64_t calls = 0;
  const FrameTimes times = timeFrames(repeat, [&] {
    RenderOutput out = render(frames[calls]);
    if (calls++ == 0) run.image = std::move(out.image);
    return deviceMs();
  });
  run.time.wallMs = median(times.wallMs);
  run.time.deviceMs = median(times.deviceMs);
  return run;
}

// The renderers throw a std::runtime_error naming the device limit a scene exceeds, and a
// VulkanError (also a runtime_error) for anything else; either becomes the row's failure.
template <typename Run, typename Body>
Run orFailure(const Body& body) {
  try {
    return body();
  } catch (const VulkanError& e) {
    Run run;
    run.time.failure = std::string("failed: ") + e.what();
    return run;
  } catch (const std::runtime_error& e) {
    Run run;
    run.time.failure = std::string("does not fit: ") + e.what();
    return run;
  }
}

PassTimes medianPasses(const std::vector<PassTimes>& frames) {
  auto field = [&](double PassTimes::*member) {
    std::vector<double> values;
    for (const PassTimes& p : frames) values.push_back(p.*member);
    return median(values);
  };
  return {field(&PassTimes::shade), field(&PassTimes::raster), field(&PassTimes::resolve), field(&PassTimes::total)};
}

}  // namespace

FramePair makeFramePair(const SceneData& data, const View& view) {
  FramePair pair{makeFrame(data, view), {}};
  pair.b = pair.a;
  pair.b.frame.ambient.x = std::nextafter(pair.a.frame.ambient.x, 2.0f);
  return pair;
}

BackendRun runReference(const SceneData& data, const FramePair& frames, int repeat) {
  return timeRenders(frames, repeat, [&](const FrameInputs& in) { return renderReference(data, in); },
                     [] { return NOT_MEASURED; });
}

ComputeRun runCompute(const VulkanContext& context, const SceneData& data, const FramePair& frames, int repeat,
                      std::shared_ptr<GpuPipelineSet> pipelines) {
  return orFailure<ComputeRun>([&] {
    ComputeRun run;
    const uint64_t before = deviceBytes(context);
    GpuRendererOptions options;
    options.pipelines = std::move(pipelines);
    GpuRenderer renderer(context, data, options);
    run.sceneBytes = deviceBytes(context) - before;
    std::vector<PassTimes> passes;
    static_cast<BackendRun&>(run) = timeRenders(
        frames, repeat, [&](const FrameInputs& in) { return renderer.render(in); },
        [&] {
          passes.push_back(renderer.lastPassTimes());
          return passes.back().total;
        });
    run.imageBytes = deviceBytes(context) - before - run.sceneBytes;
    passes.erase(passes.begin());  // the warm-up
    run.passes = medianPasses(passes);
    run.shadedEveryFrame = renderer.framesShaded() == uint64_t(repeat) + 1;
    return run;
  });
}

BackendRun runGraphics(const VulkanContext& context, const SceneData& data, const FramePair& frames, int repeat) {
  return orFailure<BackendRun>([&] {
    GraphicsRenderer renderer(context, data);
    return timeRenders(frames, repeat, [&](const FrameInputs& in) { return renderer.render(in); },
                       [&] { return renderer.lastDeviceMs(); });
  });
}

uint64_t peakHostBytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return uint64_t(usage.ru_maxrss) * 1024;  // Linux reports kilobytes
}

}  // namespace phongvk::bench
