// phongvk_bench — the benchmark (docs/BENCHMARKS.md). main parses arguments and calls bench/bench.h.
// The documented way to run it is scripts/bench.sh, which builds in Release first.
#include "bench.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>

int main(int argc, char** argv) {
  CLI::App app{"phongvk_bench: reference vs Vulkan compute vs graphics pipeline, and run time against error"};
  phongvk::bench::BenchOptions options;
  options.sourceDir = PHONGVK_SOURCE_DIR;
  options.cli = PHONGVK_CLI;
  app.add_flag("--quick", options.quick, "A few small scenes, one timed frame (the smoke test)");
  auto* repeat = app.add_option("--repeat", options.repeat, "Timed frames per measurement, after a warm-up (default 5)")
                     ->check(CLI::Range(1, 1000));
  auto* out = app.add_option("--out", options.out,
                             "Markdown report (default docs/BENCHMARKS.md; docs/BENCHMARK_DEVICES.md with --devices-only)");
  app.add_option("--plot", options.plot, "Run time against error plot, PNG (default docs/bench_error.png)");
  app.add_option("--source", options.sourceDir, "Repository root, where scenes/ is (default: this build's)");
  app.add_option("--revision", options.revision, "Source revision to show in the report");
  app.add_option("--only", options.only, "Only the suite, mesh setup and end-to-end scenes whose name contains this (a partial run)");
  app.add_option("--cli", options.cli, "The phongvk command timed end to end (default: this build's)");
  app.add_option("--device", options.device, "Vulkan device index (see 'phongvk devices')")->check(CLI::NonNegativeNumber);
  app.add_flag("--moving-only", options.movingOnly,
               "Only a moving object against a moving camera (printed, no report written)");
  app.add_flag("--shadows-only", options.shadowsOnly,
               "Only shadowed frames against unshadowed ones and the tree's build (printed, no report written)");
  app.add_flag("--points-only", options.pointsOnly,
               "Only point clouds against grids of as many triangles (printed, no report written)");
  app.add_flag("--devices-only", options.devicesOnly,
               "Only the device table (each Vulkan device and key path), in a report of its own");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  if (options.quick && repeat->count() == 0) options.repeat = 1;
  if (options.devicesOnly && out->count() == 0) options.out = "docs/BENCHMARK_DEVICES.md";
  try {
    phongvk::bench::runBench(options);
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
}
