// targets.h — the benchmark's targets, judged from the measured results: per scene, whether each target
// that applies is met and, where not, by how much and what the frame's time or memory went to.
#pragma once

#include "scene_bench.h"

#include <string>
#include <vector>

namespace phongvk::bench {

// Compute at least as fast as the graphics pipeline on every scene...
inline constexpr double GRAPHICS_SPEEDUP = 1.0;
// ...and twice as fast on scenes of 1M+ small triangles (the icosphere grids).
inline constexpr double GRAPHICS_SPEEDUP_SMALL = 2.0;
inline constexpr uint64_t SMALL_TRIANGLES_FROM = 1'000'000;
// 20x the single-threaded reference on scenes of 100k+ triangles.
inline constexpr double REFERENCE_SPEEDUP = 20.0;
inline constexpr uint64_t REFERENCE_TARGET_FROM = 100'000;
// Device memory of the compute port: this much per triangle (vertices included) plus per pixel.
inline constexpr double BUDGET_BYTES_PER_TRIANGLE = 96;
inline constexpr double BUDGET_BYTES_PER_PIXEL = 12;
// Mesh setup: a 5M-triangle scene in "well under a second", read as at most half a second; and
// linear, read as every scene of 100k+ triangles within 2x of the cheapest one's time per triangle.
inline constexpr uint64_t SETUP_TARGET_TRIANGLES = 5'000'000;
inline constexpr double SETUP_TARGET_MS = 500;
inline constexpr uint64_t SETUP_LINEAR_FROM = 100'000;
inline constexpr double SETUP_LINEAR_SPREAD = 2.0;

enum class Target { GraphicsAll, GraphicsSmall, Reference, Memory };

struct Verdict {
  Target target;
  bool met = false;
  std::string result;  // "2.31x", "41.2 MiB of 52.0 MiB"
  std::string miss;    // empty when met: by how much not, and why
};

// One line naming the target, for tables ("compute >= 2x the graphics pipeline, 1M+ small triangles").
std::string targetName(Target target);

// The targets that apply to a scene (none when a backend they compare could not run: the scene's
// row says why), each judged.
std::vector<Verdict> judgeScene(const SceneResult& scene);

struct SetupVerdict {
  bool met = false;
  std::string result;  // what was measured, one sentence
};
SetupVerdict judgeSetup(const std::vector<SetupResult>& setups);

// Speed of `compute` relative to `other` (other / compute, wall clock); NaN unless both ran.
double speedup(const Timing& other, const Timing& compute);

// Device memory budget of the compute port for a scene, in bytes.
double memoryBudget(const SceneResult& scene);

}  // namespace phongvk::bench
