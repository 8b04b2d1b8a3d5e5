// render.cpp — `phongvk render`: one still on the chosen backend, optionally timed (--repeat).
#include "cli/cli_support.h"
#include "cli/render_outputs.h"
#include "tools/statistics.h"

#include <algorithm>
#include <cstdio>

namespace phongvk::cli {
namespace {

// --repeat: N timed frames after one warm-up: wall clock per frame and device time, and on the
// compute backend the median device time of each pass, so a user sees where a frame goes.
void printRepeatTiming(const std::vector<FrameTime>& frames, Backend backend, FILE* out) {
  std::vector<double> wall, device, shade, raster, resolve;
  for (const FrameTime& f : frames) {
    wall.push_back(f.wallMs);
    device.push_back(f.deviceMs);
    shade.push_back(f.shadeMs);
    raster.push_back(f.rasterMs);
    resolve.push_back(f.resolveMs);
  }
  double sum = 0;
  for (double ms : wall) sum += ms;
  std::fprintf(out, "frame ms: median %.3f (device %.3f, min %.3f, max %.3f, mean %.3f)\n", median(wall), median(device),
              *std::min_element(wall.begin(), wall.end()), *std::max_element(wall.begin(), wall.end()),
              sum / double(wall.size()));
  if (backend != Backend::Gpu) return;
  std::fprintf(out, "device ms by pass: shade %.3f, raster %.3f, resolve %.3f (medians)\n", median(shade), median(raster),
              median(resolve));
}

// "gpu (Vulkan compute, llvmpipe ...)", "cpu (reference)", "graphics (Vulkan graphics pipeline, ...)".
std::string describeBackend(const Renderer& renderer) {
  switch (renderer.backend()) {
    case Backend::Cpu: return "cpu (reference)";
    case Backend::Graphics: return "graphics (Vulkan graphics pipeline, " + renderer.deviceName() + ")";
    case Backend::Gpu: break;
  }
  return "gpu (Vulkan compute, " + renderer.deviceName() + ")";
}

// " (start-up: Vulkan 95.1 ms, float probe cached, pipelines 180.2 ms, first frame 13.2 ms on the
// device)": where a Vulkan backend's first render went; empty for the reference. The first frame
// on the device holds the driver's code generation where it happens then (lavapipe on a new machine).
// ", 6 lines, 2 points" where the scene draws any (docs/DESIGN.md "Points and lines").
std::string primitivesText(const RendererStats& stats) {
  return (stats.lines ? ", " + std::to_string(stats.lines) + " lines" : "") +
         (stats.points ? ", " + std::to_string(stats.points) + " points" : "");
}

std::string startupText(const RendererStats& stats, Backend backend) {
  if (backend == Backend::Cpu) return "";
  char text[200];
  const std::string probe = backend != Backend::Gpu ? ""
                            : stats.probeCached  ? ", float probe cached"
                                                 : ", float probe " + std::to_string(int(stats.probeMs + 0.5)) + " ms";
  std::snprintf(text, sizeof text, " (start-up: Vulkan %.1f ms%s, pipelines %.1f ms, first frame %.1f ms on the device)",
                stats.contextMs, probe.c_str(), stats.pipelinesMs, stats.firstFrameMs);
  return text;
}

}  // namespace

int runRender(const RenderOptions& options) {
  if (options.mpi) {
    // A --depth, --ids or --normals file of another kind is refused before MPI starts (outputsAsked).
    const int refused = guarded([&] {
      outputsAsked(options);
      return int(EXIT_OK);
    });
    return refused != EXIT_OK ? refused : runRenderMpi(options);
  }
  return guarded([&] {
    const Outputs outputs = outputsAsked(options);
    checkWritable(options.output);
    FILE* out = options.output == "-" ? stderr : stdout;  // standard output carries the PNG then
    const auto start = Clock::now();
    const Scene scene = loadEveryFrameValidated(options);
    checkOutputFiles(options, scene);
    const double loadMs = msSince(start);
    const auto renderStart = Clock::now();
    Renderer renderer(rendererOptions(options, options.backend));
    if (options.repeat > 0) printRepeatTiming(renderer.timeFrames(scene, options.repeat), renderer.backend(), out);
    const RenderedFrame frame = renderer.renderOutputs(scene, outputs);
    const Image& image = frame.image;
    const RendererStats stats = renderer.stats();
    // Building the meshes counts as loading the scene, as the summary has always said.
    const double renderMs = msSince(renderStart) - stats.buildMs;
    writeRenderedFiles(options, frame);
    std::fprintf(out, "rendered %s: %dx%d, %zu objects, %zu triangles%s, %zu lights, %s backend: scene %.1f ms, render %.1f ms%s"
                " -> %s\n",
                options.scene.c_str(), image.width, image.height, scene.objectCount(), stats.triangles,
                primitivesText(stats).c_str(), stats.lights, describeBackend(renderer).c_str(), loadMs + stats.buildMs, renderMs,
                startupText(stats, renderer.backend()).c_str(), options.output.c_str());
    if (!stats.notice.empty()) std::fprintf(stderr, "phongvk: notice: %s\n", stats.notice.c_str());
    return int(EXIT_OK);
  });
}

}  // namespace phongvk::cli
