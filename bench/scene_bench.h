// scene_bench.h — one suite scene on all three backends, and mesh setup times: the rows of
// docs/BENCHMARKS.md's suite and mesh setup tables.
#pragma once

#include "measure.h"
#include "suite.h"

#include <algorithm>
#include <vector>

namespace phongvk::bench {

struct SceneResult {
  std::string name, group;
  bool smallTriangles = false;
  std::string failure;              // the scene itself could not be loaded or built
  int width = 0, height = 0;
  uint64_t triangles = 0, vertices = 0;
  Timing reference, compute, graphics;
  PassTimes passes;                 // compute, device ms per pass
  uint64_t computeSceneBytes = 0;   // device memory: geometry and per-vertex buffers
  uint64_t computeImageBytes = 0;   // device memory: per-pixel buffers
  bool shadedEveryFrame = true;
  int computeVsReference = -1;      // largest channel difference (8-bit units); -1: not compared
  int graphicsVsReference = -1;
  uint64_t hostPeakBytes = 0;       // process peak RSS after this scene (scenes run in table order)
  unsigned cpuDeviceLanes = 0;      // machine.h cpuDeviceLanes: 0 on a GPU

  uint64_t pixels() const { return uint64_t(width) * uint64_t(height); }
};

struct SetupResult {
  std::string name;
  uint64_t triangles = 0, vertices = 0;
  double buildMs = NOT_MEASURED;    // median buildSceneData
};

// The backends are measured in SCENE_ROUNDS interleaved rounds (reference, compute, graphics
// pipeline, then again) and each reports its median round: a burst of load on a shared machine
// then slows all three alike instead of one backend's whole measurement.
inline constexpr int SCENE_ROUNDS = 3;

// The run whose wall time is the median of the rounds (a failed run, if any failed).
template <typename Run>
Run medianRound(std::vector<Run> runs) {
  for (const Run& run : runs) {
    if (!run.time.ok()) return run;
  }
  std::sort(runs.begin(), runs.end(), [](const Run& a, const Run& b) { return a.time.wallMs < b.time.wallMs; });
  return runs[runs.size() / 2];
}

// Loads, builds and renders the scene on the reference, the compute port and the baseline.
// Prints one progress line. Never throws for a scene that fails: the result says why.
SceneResult measureScene(const VulkanContext& context, const SuiteScene& scene, int repeat);

SetupResult measureSetup(const SuiteScene& scene, int repeat);

}  // namespace phongvk::bench
