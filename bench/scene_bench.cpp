#include "scene_bench.h"

#include "machine.h"
#include "text.h"

#include "api/timing.h"
#include "scene/camera.h"
#include "phongvk/compare.h"
#include "tools/statistics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace phongvk::bench {

namespace {

// Largest channel difference between two backends' first frames; -1 unless both rendered.
int maxDiff(const BackendRun& a, const BackendRun& b) {
  if (!a.time.ok() || !b.time.ok()) return -1;
  return compareImages(a.image, b.image).maxChannelDiff();
}

std::string describe(const char* backend, const Timing& t) {
  if (!t.ok()) return std::string(backend) + " " + t.failure;
  if (std::isnan(t.deviceMs)) return formatText("%s %.2f ms", backend, t.wallMs);
  return formatText("%s %.2f ms (device %.2f)", backend, t.wallMs, t.deviceMs);
}

void printProgress(const SceneResult& r) {
  if (!r.failure.empty()) {
    std::printf("%s: failed: %s\n", r.name.c_str(), r.failure.c_str());
  } else {
    std::printf("%s: %llu triangles, %dx%d; %s, %s, %s; compute vs reference max diff %d\n", r.name.c_str(),
                static_cast<unsigned long long>(r.triangles), r.width, r.height,
                describe("reference", r.reference).c_str(), describe("compute", r.compute).c_str(),
                describe("graphics", r.graphics).c_str(), r.computeVsReference);
  }
  std::fflush(stdout);  // progress shows while the next scene runs
}

void renderAll(const VulkanContext& context, const SceneData& data, const FramePair& frames, int repeat,
               SceneResult& r) {
  std::vector<BackendRun> references, graphicsRuns;
  std::vector<ComputeRun> computes;
  for (int round = 0; round < SCENE_ROUNDS; ++round) {
    references.push_back(runReference(data, frames, repeat));
    computes.push_back(runCompute(context, data, frames, repeat));
    graphicsRuns.push_back(runGraphics(context, data, frames, repeat));
  }
  const BackendRun reference = medianRound(references);
  r.reference = reference.time;
  const ComputeRun compute = medianRound(computes);
  r.compute = compute.time;
  r.passes = compute.passes;
  r.computeSceneBytes = compute.sceneBytes;
  r.computeImageBytes = compute.imageBytes;
  r.shadedEveryFrame = compute.shadedEveryFrame;
  r.computeVsReference = maxDiff(compute, reference);
  const BackendRun graphics = medianRound(graphicsRuns);
  r.graphics = graphics.time;
  r.graphicsVsReference = maxDiff(graphics, reference);
}

}  // namespace

SceneResult measureScene(const VulkanContext& context, const SuiteScene& scene, int repeat) {
  SceneResult r;
  r.name = scene.name;
  r.group = scene.group;
  r.smallTriangles = scene.smallTriangles;
  r.cpuDeviceLanes = cpuDeviceLanes(context);
  try {
    const SceneSpec loaded = scene.load();
    const View view = makeView(loaded.camera);
    const SceneData data = buildSceneData(loaded);
    r.width = view.width;
    r.height = view.height;
    r.triangles = data.triangles.size();
    r.vertices = data.vertices.size();
    renderAll(context, data, makeFramePair(data, view), repeat, r);
  } catch (const std::exception& e) {
    r.failure = e.what();
  }
  r.hostPeakBytes = peakHostBytes();
  printProgress(r);
  return r;
}

SetupResult measureSetup(const SuiteScene& scene, int repeat) {
  SetupResult r;
  r.name = scene.name;
  const SceneSpec loaded = scene.load();
  const FrameTimes times = timeFrames(repeat, [&] {
    const SceneData data = buildSceneData(loaded);
    r.triangles = data.triangles.size();
    r.vertices = data.vertices.size();
    return NOT_MEASURED;
  });
  r.buildMs = median(times.wallMs);
  std::printf("mesh setup %s: %llu triangles in %.1f ms\n", r.name.c_str(),
              static_cast<unsigned long long>(r.triangles), r.buildMs);
  std::fflush(stdout);
  return r;
}

}  // namespace phongvk::bench
