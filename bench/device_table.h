// device_table.h — the compute port on each Vulkan device the machine has, on each key path it
// can take: lavapipe's 64-bit path, lavapipe forced to the 32-bit path (PHONGVK_KEY_PATH=32), and
// SwiftShader (Debian's chromium-common, added to the loader's drivers where installed), each
// scene as the ratio of its frame time to the first column's: docs/BENCHMARKS.md's device table.
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
  std::vector<Timing> times;  // per column: the median of the interleaved rounds
  std::vector<int> maxDiff;   // per column: largest channel difference from the reference (-1: none)
};

struct DeviceTable {
  std::vector<DeviceColumn> columns;
  std::vector<DeviceRow> rows;
};

// Every usable device, and each 64-bit one also forced to the 32-bit path; `scenes` on each, in
// interleaved rounds (every column once per round). Prints one progress line per scene.
DeviceTable runDeviceTable(const std::vector<SuiteScene>& scenes, int repeat, bool withSwiftShader);

// The report's section.
std::string deviceTableSection(const DeviceTable& table, int repeat);

}  // namespace phongvk::bench
