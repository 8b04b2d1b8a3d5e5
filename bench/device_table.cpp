#include "device_table.h"

#include "process.h"
#include "scene_bench.h"
#include "text.h"

#include "phongvk/compare.h"
#include "phongvk/devices.h"
#include "scene/camera.h"
#include "tools/statistics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>

namespace phongvk::bench {

namespace {

constexpr const char* SWIFTSHADER_ICD = "/usr/lib/chromium/vk_swiftshader_icd.json";

// An environment variable set (or, with no value, unset) while the object lives, then put back.
class ScopedVariable {
 public:
  ScopedVariable(const char* name, std::optional<std::string> value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    if (value) setenv(name, value->c_str(), 1);
    else unsetenv(name);
  }
  ~ScopedVariable() {
    if (old_) setenv(name_, old_->c_str(), 1);
    else unsetenv(name_);
  }
  ScopedVariable(const ScopedVariable&) = delete;
  ScopedVariable& operator=(const ScopedVariable&) = delete;

 private:
  const char* name_;
  std::optional<std::string> old_;
};

// A column's device: its own context (each made while its key path's variable held) and the
// pipelines compiled on it, kept across the scenes (SwiftShader compiles some for tens of seconds).
struct Column {
  DeviceColumn description;
  std::string environment;  // what a `phongvk` process on this column runs under: its drivers and key path
  uint32_t deviceIndex = 0;  // its --device
  std::unique_ptr<ScopedContext> context;
  std::shared_ptr<GpuPipelineSet> pipelines;

  Column() = default;
  Column(Column&&) = default;
  Column& operator=(Column&&) = default;
  // The pipelines go through their own context's functions (volk holds the newest context's).
  ~Column() {
    if (!context) return;
    const ContextLock lock(context->context);
    pipelines.reset();
  }
};

void addColumn(std::vector<Column>& columns, const DeviceInfo& device, const char* keyPath, const std::string& drivers) {
  const ScopedVariable path("PHONGVK_KEY_PATH", keyPath ? std::optional<std::string>(keyPath) : std::nullopt);
  Column c;
  c.environment = "env -u PHONGVK_KEY_PATH -u VK_ADD_DRIVER_FILES " + drivers +
                  (keyPath ? std::string("PHONGVK_KEY_PATH=") + keyPath + " " : "");
  c.deviceIndex = device.index;
  c.context = std::make_unique<ScopedContext>(ContextOptions{int(device.index)});
  c.description = {device.name, keyPathWords(c.context->context.info)};
  c.pipelines = std::make_shared<GpuPipelineSet>(c.context->context);
  columns.push_back(std::move(c));
}

// Every usable device on its own path, a 64-bit one also on the 32-bit path; a CPU device first
// (lavapipe: the column the ratios are to), then as the loader lists them.
std::vector<Column> makeColumns(bool withSwiftShader) {
  const bool addSwiftShader = withSwiftShader && std::filesystem::exists(SWIFTSHADER_ICD);
  // The loader reads the variable when an instance is made: every context below sees SwiftShader.
  const ScopedVariable drivers("VK_ADD_DRIVER_FILES",
                               addSwiftShader ? std::optional<std::string>(SWIFTSHADER_ICD) : std::nullopt);
  const ScopedVariable natural("PHONGVK_KEY_PATH", std::nullopt);
  std::vector<DeviceInfo> devices = listDevices();
  std::stable_sort(devices.begin(), devices.end(), [](const DeviceInfo& a, const DeviceInfo& b) {
    return a.name.rfind("llvmpipe", 0) == 0 && b.name.rfind("llvmpipe", 0) != 0;
  });
  std::vector<Column> columns;
  const std::string driverFiles = addSwiftShader ? std::string("VK_ADD_DRIVER_FILES=") + SWIFTSHADER_ICD + " " : "";
  for (const DeviceInfo& device : devices) {
    if (!device.suitable) continue;
    addColumn(columns, device, nullptr, driverFiles);
    if (!device.keys32) addColumn(columns, device, "32", driverFiles);
  }
  return columns;
}

// The median over the rounds of a column's time over the first column's in the same round (NaN
// when a round of either failed).
double medianRatio(const std::vector<double>& column, const std::vector<double>& first) {
  std::vector<double> ratios;
  for (size_t r = 0; r < column.size(); ++r) {
    if (!std::isfinite(column[r]) || !std::isfinite(first[r]) || !(first[r] > 0)) return NOT_MEASURED;
    ratios.push_back(column[r] / first[r]);
  }
  return median(ratios);
}

std::vector<double> wallTimes(const std::vector<ComputeRun>& runs) {
  std::vector<double> times;
  for (const ComputeRun& run : runs) times.push_back(run.time.ok() ? run.time.wallMs : NOT_MEASURED);
  return times;
}

DeviceRow measureRow(std::vector<Column>& columns, const SuiteScene& scene, int repeat, int rounds) {
  DeviceRow row;
  row.scene = scene.name;
  const SceneSpec loaded = scene.load();
  const View view = makeView(loaded.camera);
  const SceneData data = buildSceneData(loaded);
  row.triangles = data.triangles.size();
  row.width = view.width;
  row.height = view.height;
  const FramePair frames = makeFramePair(data, view);
  const BackendRun reference = runReference(data, frames, 1);
  std::vector<std::vector<ComputeRun>> runs(columns.size());
  for (int round = 0; round < rounds; ++round) {
    for (size_t i = 0; i < columns.size(); ++i) {
      const size_t c = (i + size_t(round)) % columns.size();
      const ContextLock lock(columns[c].context->context);
      runs[c].push_back(runCompute(columns[c].context->context, data, frames, repeat, columns[c].pipelines));
    }
  }
  for (size_t c = 0; c < columns.size(); ++c) {
    const ComputeRun run = medianRound(runs[c]);
    row.times.push_back(run.time);
    row.ratios.push_back(medianRatio(wallTimes(runs[c]), wallTimes(runs[0])));
    row.maxDiff.push_back(run.time.ok() && reference.time.ok() ? compareImages(reference.image, run.image).maxChannelDiff() : -1);
  }
  return row;
}

// One first render of `command.scene` on column c, every cache in the new folder `cache`.
Process firstRender(const Column& c, const StartupCommand& command, const Scratch& scratch, const std::string& cache) {
  std::filesystem::create_directories(cache);
  return run(c.environment + cachesIn(cache) +
             quoted(command.cli) + " render " + quoted(command.sourceDir + "/scenes/" + command.scene) + " -o " +
             quoted((scratch.dir / "first.png").string()) + " --device " + std::to_string(c.deviceIndex));
}

// Each column's first render, `command.rounds` rounds interleaved as the scenes' are.
std::vector<DeviceStartup> measureStartups(const std::vector<Column>& columns, const StartupCommand& command) {
  const Scratch scratch;
  std::vector<std::vector<double>> seconds(columns.size()), pipelines(columns.size());
  std::vector<DeviceStartup> result(columns.size());
  for (int round = 0; round < command.rounds; ++round) {
    for (size_t i = 0; i < columns.size(); ++i) {
      const size_t c = (i + size_t(round)) % columns.size();
      const std::string cache = (scratch.dir / ("cache-" + std::to_string(round) + "-" + std::to_string(c))).string();
      const Process p = firstRender(columns[c], command, scratch, cache);
      if (p.status != 0) result[c].failure = "exit status " + std::to_string(p.status);
      seconds[c].push_back(p.status == 0 ? p.seconds : NOT_MEASURED);
      const double pipelineMs = after(p.out, ", pipelines ");
      if (std::isfinite(pipelineMs)) pipelines[c].push_back(pipelineMs);
    }
  }
  for (size_t c = 0; c < columns.size(); ++c) {
    if (!result[c].failure.empty()) continue;
    result[c].seconds = median(seconds[c]);
    if (!pipelines[c].empty()) result[c].pipelinesMs = median(pipelines[c]);
    result[c].ratio = medianRatio(seconds[c], seconds[0]);
  }
  return result;
}

std::string startupCell(const DeviceStartup& s) {
  if (!s.failure.empty()) return s.failure;
  std::string text = number(s.seconds, 2) + " s";
  if (std::isfinite(s.pipelinesMs)) text += ", pipelines " + number(s.pipelinesMs / 1000.0, 2) + " s";
  if (std::isfinite(s.ratio)) text += " (" + number(s.ratio, 2) + "x)";
  return text;
}

std::string cell(const Timing& t, double ratio) {
  if (!t.ok()) return t.failureKind();
  std::string text = number(t.wallMs, 2) + " ms";
  if (std::isfinite(ratio)) text += " (" + number(ratio, 2) + "x)";
  return text;
}

}  // namespace

DeviceTable runDeviceTable(const std::vector<SuiteScene>& scenes, int repeat, int rounds, bool withSwiftShader,
                           const StartupCommand& startup) {
  std::vector<Column> columns = makeColumns(withSwiftShader);
  DeviceTable table;
  table.rounds = rounds;
  table.startupScene = startup.scene;
  table.startupRounds = startup.rounds;
  for (const Column& c : columns) table.columns.push_back(c.description);
  for (const SuiteScene& scene : scenes) {
    table.rows.push_back(measureRow(columns, scene, repeat, rounds));
    std::string line = "devices " + scene.name + ":";
    for (size_t c = 0; c < columns.size(); ++c) line += " " + cell(table.rows.back().times[c], table.rows.back().ratios[c]);
    std::printf("%s\n", line.c_str());
    std::fflush(stdout);
  }
  table.startups = measureStartups(columns, startup);
  std::string line = "devices, first render of " + startup.scene + ":";
  for (const DeviceStartup& s : table.startups) line += " " + startupCell(s);
  std::printf("%s\n", line.c_str());
  return table;
}

std::string deviceTableSection(const DeviceTable& table, int repeat) {
  std::string s = "## Devices and key paths\n\nThe compute port on every Vulkan device of this machine and on each key "
                  "path it can take (docs/DESIGN.md \"Visibility\"): a device with 64-bit atomics also forced to the "
                  "32-bit path (`PHONGVK_KEY_PATH=32`), and SwiftShader (Debian's `chromium-common`) where installed. "
                  "Each cell is the median frame wall time (" + std::to_string(repeat) + " frame(s) after a warm-up, the "
                  "median of " + std::to_string(table.rounds) + " rounds interleaved across the columns, in an order that "
                  "turns by one column a round; pipelines compiled before the timed frames) and its ratio to the first "
                  "column, the median of the rounds' ratios, each taken within one round. Every image is compared with "
                  "the reference's: the last column gives the largest channel difference over all devices.\n\n";
  std::vector<std::string> head = {"scene", "triangles"};
  for (const DeviceColumn& c : table.columns) head.push_back(c.device + ", " + c.keys);
  head.push_back("max diff");
  s += header(head);
  for (const DeviceRow& r : table.rows) {
    std::vector<std::string> cells = {r.scene + " (" + std::to_string(r.width) + "x" + std::to_string(r.height) + ")",
                                      formatText("%llu", static_cast<unsigned long long>(r.triangles))};
    int worst = -1;
    for (size_t c = 0; c < r.times.size(); ++c) {
      cells.push_back(cell(r.times[c], r.ratios[c]));
      worst = std::max(worst, r.maxDiff[c]);
    }
    cells.push_back(worst < 0 ? "–" : std::to_string(worst));
    s += row(cells);
  }
  std::vector<std::string> cells = {"first render of " + table.startupScene + " (process, empty caches)", "–"};
  for (const DeviceStartup& startup : table.startups) cells.push_back(startupCell(startup));
  cells.push_back("–");
  s += row(cells);
  s += "\nThe last row is what a user waits for on a new machine: one `phongvk render` process (`--device` the column's, "
       "its key path's variable set) with every cache in a new empty folder (`XDG_CACHE_HOME`: phongvk's float probe "
       "and pipeline cache, Mesa's), the median wall time of " + std::to_string(table.startupRounds) +
       " interleaved rounds, the pipelines' creation as `render` reports it, and the median of the rounds' ratios to "
       "the first column.\n";
  return s + "\n";
}

}  // namespace phongvk::bench
