// bench.h — the benchmark run: the suite, mesh setup, the error sweep, whole commands end to end,
// then the report and plot.
#pragma once

#include <string>

namespace phongvk::bench {

struct BenchOptions {
  bool quick = false;                        // a few small scenes: the CTest smoke test
  int repeat = 5;                            // timed frames per measurement, after one warm-up
  std::string out = "docs/BENCHMARKS.md";
  std::string plot = "docs/bench_error.png";
  std::string sourceDir;                     // repository root, for scenes/
  std::string revision;                      // shown in the report when given
  std::string only;                          // non-empty: only the suite and setup scenes whose name has it
  int device = -1;                           // Vulkan device index, -1 = best
  std::string cli;                           // the phongvk command the end-to-end section runs
  bool devicesOnly = false;                  // only the device table (device_table.h)
  bool pointsOnly = false;                   // only the point clouds against grids (points.h), printed
  bool shadowsOnly = false;                  // only the shadow runs (shadows.h), printed
  bool movingOnly = false;                   // only the moving-object runs (moving_object.h), printed
};

// Runs everything and writes the report and the plot. Throws on failure (a bad output path, no
// usable device).
void runBench(const BenchOptions& options);

}  // namespace phongvk::bench
