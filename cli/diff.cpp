// diff.cpp — `phongvk diff`: the scene on the reference and on the compute port, compared pixel by
// pixel and key by key; exit 1 above the tolerance, so it works as a CI gate. With --devices, on
// several Vulkan devices, each compared with the one reference render: a user with a GPU and
// lavapipe proves in one command that both give the reference's bytes.
#include "cli/cli_support.h"

#include <cstdio>

namespace phongvk::cli {
namespace {

bool withinTolerance(const DiffStats& stats, double tolerance) { return stats.maxChannelDiff() <= tolerance; }

void printResult(bool pass, double tolerance) {
  std::printf("result:              %s (tolerance %g of 255 per channel)\n", pass ? "PASS" : "FAIL", tolerance);
}

int diffOneDevice(const DiffOptions& options, const Scene& scene) {
  const DiffResult result = diff(scene, rendererOptions(options, "gpu"));
  std::printf("scene:               %s\ndevice:              %s\n%s", options.scene.c_str(), result.deviceName.c_str(),
              formatDiff(result.stats).c_str());
  if (!options.heatmap.empty()) {
    writePng(options.heatmap, diffHeatmap(result.reference.image, result.gpu.image, result.reference.keys, result.gpu.keys),
             options.pngLevel);
    std::printf("heatmap:             %s\n", options.heatmap.c_str());
  }
  const bool pass = withinTolerance(result.stats, options.tolerance);
  printResult(pass, options.tolerance);
  return int(pass ? EXIT_OK : EXIT_DIFF_ABOVE_TOLERANCE);
}

// Each device of --devices against one reference render, then whether the devices agree with each
// other byte for byte (image and keys).
int diffDevices(const DiffOptions& options, const Scene& scene) {
  const RenderOutput reference = Renderer(Backend::Cpu).renderWithKeys(scene);
  std::printf("scene:               %s\n", options.scene.c_str());
  bool pass = true;
  std::vector<RenderOutput> renders;
  for (int device : options.devices) {
    RendererOptions gpuOptions = rendererOptions(options, "gpu");
    gpuOptions.device = device;
    Renderer gpu(gpuOptions);
    renders.push_back(gpu.renderWithKeys(scene));
    const DiffStats stats = compareImages(reference.image, renders.back().image, reference.keys, renders.back().keys);
    std::printf("\ndevice %d:%*s%s\n%s", device, int(12 - std::to_string(device).size()), "", gpu.deviceName().c_str(),
                formatDiff(stats).c_str());
    const bool devicePass = withinTolerance(stats, options.tolerance);
    printResult(devicePass, options.tolerance);
    pass = pass && devicePass;
  }
  bool same = true;
  for (const RenderOutput& r : renders) same = same && r.image.rgb == renders[0].image.rgb && r.keys == renders[0].keys;
  std::printf("\ndevices:             %s\n", same ? "every device gave the same bytes and keys"
                                                   : "the devices' bytes or keys differ");
  printResult(pass, options.tolerance);
  return int(pass ? EXIT_OK : EXIT_DIFF_ABOVE_TOLERANCE);
}

}  // namespace

int runDiff(const DiffOptions& options) {
  return guarded([&] {
    checkWritable(options.heatmap);
    const Scene scene = loadEveryFrameValidated(options);
    return options.devices.empty() ? diffOneDevice(options, scene) : diffDevices(options, scene);
  });
}

}  // namespace phongvk::cli
