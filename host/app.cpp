#include "app.h"

#include "host/cli_support.h"
#include "host/context.h"
#include "host/gpu_renderer.h"
#include "host/raster_renderer.h"
#include "host/timing.h"
#include "reference/camera.h"
#include "reference/compare.h"
#include "reference/render_reference.h"
#include "reference/scene_data.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>

namespace phongvk {

namespace {

// A scene loaded and flattened, with the view the options ask for.
struct Prepared {
  Scene scene;
  SceneData data;
  View view;
  FrameInputs frame;
  double loadMs = 0;
};

Prepared prepare(const ViewOptions& options) {
  const auto start = Clock::now();
  Prepared p;
  p.scene = loadScene(options.scene);
  CameraSpec camera = p.scene.camera;
  if (options.width > 0 || options.height > 0) camera = withImageSize(camera, options.width, options.height);
  p.view = makeView(camera);
  p.data = buildSceneData(p.scene);
  p.frame = makeFrame(p.data, p.view);
  p.loadMs = msSince(start);
  return p;
}

// --repeat: N timed frames after one warm-up, wall clock per frame and device time.
void printRepeatTiming(int repeat, const std::function<double()>& frame) {
  const FrameTimes t = timeFrames(repeat, frame);
  std::printf("frame ms: median %.3f (device %.3f, min %.3f, max %.3f)\n", median(t.wallMs), median(t.deviceMs),
              *std::min_element(t.wallMs.begin(), t.wallMs.end()), *std::max_element(t.wallMs.begin(), t.wallMs.end()));
}

// --repeat on the compute backend: the median device time of each pass over the timed frames
// (`frames` holds the warm-up first, which is left out), so a user sees where a frame goes.
void printPassTiming(const std::vector<PassTimes>& frames) {
  std::vector<double> shade, raster, resolve;
  for (size_t i = 1; i < frames.size(); ++i) {
    shade.push_back(frames[i].shade);
    raster.push_back(frames[i].raster);
    resolve.push_back(frames[i].resolve);
  }
  std::printf("device ms by pass: shade %.3f, raster %.3f, resolve %.3f (medians)\n", median(shade), median(raster),
              median(resolve));
}

void printSummary(const RenderOptions& options, const Prepared& p, const std::string& backend, double renderMs) {
  std::printf("rendered %s: %dx%d, %zu objects, %zu triangles, %zu lights, %s backend: scene %.1f ms, render %.1f ms -> %s\n",
              options.scene.c_str(), p.view.width, p.view.height, p.scene.objects.size(), p.data.triangles.size(),
              p.scene.lights.size(), backend.c_str(), p.loadMs, renderMs, options.output.c_str());
}

}  // namespace

namespace {

// One frame on the chosen backend, optionally timed with --repeat. Returns the image and a
// description of the backend for the summary line.
RenderOutput renderOnBackend(const RenderOptions& options, const Prepared& p, std::string& backend) {
  if (options.backend == "cpu") {
    backend = "cpu (reference)";
    if (options.repeat > 0) {
      printRepeatTiming(options.repeat, [&] {
        const auto t = Clock::now();
        renderReference(p.data, p.frame);
        return msSince(t);
      });
    }
    return renderReference(p.data, p.frame);
  }
  GpuSession gpu(options);
  if (options.backend == "raster") {
    backend = "raster (Vulkan graphics pipeline, " + gpu.context.report.name + ")";
    RasterRenderer raster(gpu.context, p.data);
    if (options.repeat > 0) {
      printRepeatTiming(options.repeat, [&] {
        raster.render(p.frame);
        return raster.lastDeviceMs();
      });
    }
    return raster.render(p.frame);
  }
  backend = "gpu (Vulkan compute, " + gpu.context.report.name + ")";
  gpu.load(p.data);
  if (options.repeat > 0) {
    std::vector<PassTimes> frames;
    printRepeatTiming(options.repeat, [&] {
      gpu.renderer->render(p.frame);
      frames.push_back(gpu.renderer->lastPassTimes());
      return frames.back().total;
    });
    printPassTiming(frames);
  }
  return gpu.renderer->render(p.frame);
}

}  // namespace

int runRender(const RenderOptions& options) {
  return guarded([&] {
    checkWritable(options.output);
    const Prepared p = prepare(options);
    const auto start = Clock::now();
    std::string backend;
    const RenderOutput out = renderOnBackend(options, p, backend);
    const double renderMs = msSince(start);
    writePng(options.output, out.image);
    printSummary(options, p, backend, renderMs);
    return int(EXIT_OK);
  });
}

int runDiff(const DiffOptions& options) {
  return guarded([&] {
    checkWritable(options.heatmap);
    const Prepared p = prepare(options);
    const RenderOutput reference = renderReference(p.data, p.frame);
    GpuSession gpu(options, p.data);
    const RenderOutput port = gpu.renderer->render(p.frame, true);
    const DiffStats stats = compareImages(reference.image, port.image, reference.keys, port.keys);
    std::printf("scene:               %s\ndevice:              %s\n%s", options.scene.c_str(),
                gpu.context.report.name.c_str(), formatDiff(stats).c_str());
    if (!options.heatmap.empty()) {
      writePng(options.heatmap, diffHeatmap(reference.image, port.image, reference.keys, port.keys));
      std::printf("heatmap:             %s\n", options.heatmap.c_str());
    }
    const bool pass = stats.maxChannelDiff() <= options.tolerance;
    std::printf("result:              %s (tolerance %g of 255 per channel)\n", pass ? "PASS" : "FAIL", options.tolerance);
    return int(pass ? EXIT_OK : EXIT_DIFF_ABOVE_TOLERANCE);
  });
}

int runDevices() {
  return guarded([] {
    std::printf("%s", formatDeviceList(listDevices()).c_str());
    return int(EXIT_OK);
  });
}

}  // namespace phongvk
