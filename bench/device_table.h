// device_table.h — the compute port on each Vulkan device the machine has, on each key path it
// can take: lavapipe's 64-bit path, lavapipe forced to the 32-bit path (PHONGVK_KEY_PATH=32), and
// SwiftShader (Debian's chromium-common, added to the loader's drivers where installed), each
// scene as the ratio of its frame time to the first column's, and each device's first render on a
// new machine: docs/BENCHMARKS.md's device table.
#pragma once

#include "measure.h"
#include "suite.h"

#include <string>
#include <vector>

namespace phongvk::bench {

struct DeviceColumn {
  std::string device;  // DeviceInfo::name
  std::string keys;    // devices.h keyPathWords
};

struct DeviceRow {
  std::string scene;
  uint64_t triangles = 0;
  int width = 0, height = 0;
  std::vector<Timing> times;   // per column: the median of the interleaved rounds
  std::vector<double> ratios;  // per column: the median over the rounds of its time / the first column's
  std::vector<int> maxDiff;    // per column: largest channel difference from the reference (-1: none)
};

// A column's first render on a new machine: a one-frame `phongvk render` process of the table's
// first-render scene with every cache empty (phongvk's float probe and pipelines, Mesa's).
struct DeviceStartup {
  double seconds = NOT_MEASURED;      // the process's wall time, the median of the rounds
  double pipelinesMs = NOT_MEASURED;  // its pipeline creation as `render` reports it (median)
  double ratio = NOT_MEASURED;        // the median of the rounds' seconds / the first column's
  std::string failure;
};

struct DeviceTable {
  int rounds = 0;
  std::vector<DeviceColumn> columns;
  std::vector<DeviceRow> rows;
  std::string startupScene;             // under scenes/
  int startupRounds = 0;
  std::vector<DeviceStartup> startups;  // per column
};

// What the first-render row runs: the command, the repository root and the scene under scenes/.
struct StartupCommand {
  std::string cli;
  std::string sourceDir;
  std::string scene = "paper/fig1_cube.json";
  int rounds = 3;
};

// The rounds per scene. Each round times every column once, in an order that turns by one column a
// round, and a column's ratio is the median of its rounds' ratios to the first column's time in
// the same round: load that comes and goes then moves both sides of a ratio alike, where medians
// taken apart over 3 rounds scattered a ratio by up to ±0.15 on the 2-core machine. The smoke
// test (--quick) takes SCENE_ROUNDS.
inline constexpr int DEVICE_ROUNDS = 9;

// Every usable device, and each 64-bit one also forced to the 32-bit path; `scenes` on each, in
// `rounds` interleaved rounds, then `startup`'s first render on each, its rounds interleaved too.
// Prints one progress line per scene.
DeviceTable runDeviceTable(const std::vector<SuiteScene>& scenes, int repeat, int rounds, bool withSwiftShader,
                           const StartupCommand& startup);

// The report's section.
std::string deviceTableSection(const DeviceTable& table, int repeat);

}  // namespace phongvk::bench
