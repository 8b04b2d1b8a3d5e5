// diff.cpp — `phongvk diff`: the scene on the reference and on the compute port, compared pixel by
// pixel and key by key; exit 1 above the tolerance, so it works as a CI gate.
#include "cli/cli_support.h"

#include <cstdio>

namespace phongvk::cli {

int runDiff(const DiffOptions& options) {
  return guarded([&] {
    checkWritable(options.heatmap);
    const Scene scene = loadEveryFrameValidated(options);
    const DiffResult result = diff(scene, rendererOptions(options, "gpu"));
    std::printf("scene:               %s\ndevice:              %s\n%s", options.scene.c_str(), result.deviceName.c_str(),
                formatDiff(result.stats).c_str());
    if (!options.heatmap.empty()) {
      writePng(options.heatmap,
               diffHeatmap(result.reference.image, result.gpu.image, result.reference.keys, result.gpu.keys),
               options.pngLevel);
      std::printf("heatmap:             %s\n", options.heatmap.c_str());
    }
    const bool pass = result.stats.maxChannelDiff() <= options.tolerance;
    std::printf("result:              %s (tolerance %g of 255 per channel)\n", pass ? "PASS" : "FAIL", options.tolerance);
    return int(pass ? EXIT_OK : EXIT_DIFF_ABOVE_TOLERANCE);
  });
}

}  // namespace phongvk::cli
