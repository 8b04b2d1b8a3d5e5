#include "bench.h"

#include "plot.h"
#include "report.h"
#include "vulkan/context.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace phongvk::bench {

namespace {

namespace fs = std::filesystem;

// Through a temporary file and a rename, so an interrupted run never leaves half a report.
void writeText(const std::string& path, const std::string& text) {
  const std::string temp = path + ".tmp";
  {
    std::ofstream file(temp, std::ios::binary);
    file << text;
    if (!file.flush()) throw OutputError("cannot write '" + temp + "'");
  }
  fs::rename(temp, path);
}

bool selected(const SuiteScene& scene, const BenchOptions& options) {
  return scene.name.find(options.only) != std::string::npos;
}

std::vector<SceneResult> runSuite(const VulkanContext& context, const BenchOptions& options) {
  std::vector<SceneResult> results;
  for (const SuiteScene& scene : makeSuite(options.sourceDir, options.quick)) {
    if (selected(scene, options)) results.push_back(measureScene(context, scene, options.repeat));
  }
  return results;
}

std::vector<SetupResult> runSetup(const BenchOptions& options) {
  std::vector<SetupResult> results;
  for (const SuiteScene& scene : makeSetupScenes(options.quick)) {
    if (selected(scene, options)) results.push_back(measureSetup(scene, options.repeat));
  }
  return results;
}

std::vector<SuiteScene> deviceScenes(const BenchOptions& options) {
  std::vector<SuiteScene> scenes = makeDeviceScenes(options.sourceDir, options.quick);
  std::erase_if(scenes, [&](const SuiteScene& s) { return !selected(s, options); });
  return scenes;
}

// The smoke test (--quick) leaves SwiftShader out (its compiler takes tens of seconds a pass) and
// takes the scene table's rounds.
DeviceTable measureDevices(const BenchOptions& options) {
  const StartupCommand startup{.cli = options.cli, .sourceDir = options.sourceDir, .rounds = options.quick ? 1 : 3};
  return runDeviceTable(deviceScenes(options), options.repeat, options.quick ? SCENE_ROUNDS : DEVICE_ROUNDS,
                        !options.quick, startup);
}

// The device table alone, as a report of its own (`--devices-only`).
void runDevicesOnly(const BenchOptions& options) {
  checkWritable(options.out);
  const DeviceTable table = measureDevices(options);
  writeText(options.out, "# phongvk devices and key paths\n\nMade by `phongvk_bench --devices-only`.\n\n" +
                             deviceTableSection(table, options.repeat));
  std::printf("wrote %s\n", options.out.c_str());
}

}  // namespace

void runBench(const BenchOptions& options) {
  if (options.devicesOnly) return runDevicesOnly(options);
  if (options.movingOnly) {  // printed only: a quick look at one section
    runMovingObjects(options.quick);
    return;
  }
  if (options.pointsOnly) {
    runPoints(options.quick);
    return;
  }
  if (options.shadowsOnly) {
    runShadows(options.sourceDir, options.quick);
    timeShadowBuild(options.quick);
    return;
  }
  checkWritable(options.out);
  checkWritable(options.plot);
  // The context; each backend makes its own renderer per scene.
  ScopedContext gpu({options.device, false});
  {
    Report report;
    report.command = options.quick ? "phongvk_bench --quick" : "bash scripts/bench.sh";
    report.quick = options.quick;
    report.only = options.only;
    report.repeat = options.repeat;
    report.revision = options.revision;
    report.machine = describeMachine(gpu.context);
    std::printf("phongvk_bench on %s, %d timed frames per measurement\n", report.machine.device.c_str(), options.repeat);
    report.scenes = runSuite(gpu.context, options);
    std::printf("devices and key paths:\n");
    report.devices = measureDevices(options);
    report.setups = runSetup(options);
    report.sweep = runErrorSweep(gpu.context, options.quick, options.repeat);
    report.plotNote = plotErrorSweep(report.sweep, options.plot, gpu.context.info.name);
    std::printf("end to end (%s):\n", options.cli.c_str());
    report.endToEnd = runEndToEnd(options.cli, options.sourceDir, options.quick, options.only);
    std::printf("mesh files:\n");
    report.meshLoads = runMeshLoads(options.quick);
    std::printf("a new mesh each frame:\n");
    report.geometryChanges = runGeometryChanges(options.quick);
    std::printf("a moving object:\n");
    report.movingObjects = runMovingObjects(options.quick);
    std::printf("shadows:\n");
    report.shadows = runShadows(options.sourceDir, options.quick);
    report.shadowBuild = timeShadowBuild(options.quick);
    std::printf("point clouds:\n");
    report.points = runPoints(options.quick);
    if (report.plotNote.empty()) {
      report.plotLink = fs::relative(fs::absolute(options.plot), fs::absolute(options.out).parent_path()).string();
    }
    writeText(options.out, formatReport(report));
    std::printf("wrote %s%s\n", options.out.c_str(), report.plotNote.empty() ? (" and " + options.plot).c_str() : "");
  }
}

}  // namespace phongvk::bench
