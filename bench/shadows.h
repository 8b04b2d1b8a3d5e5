// shadows.h — what shadows cost (docs/DESIGN.md "Shadows"): frames whose lights cast shadows
// against the same frames without, interleaved, on the paper's cube and a 1M-triangle grid under
// one and eight lights, each frame moving the lights (so every frame lights its vertices again),
// with the shadow rays a frame traces and the tree's build on 5M triangles.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace phongvk::bench {

// A shadowed frame within this factor of the unshadowed one: the paper's scenes (per vertex) and
// the 1M-triangle grid.
inline constexpr double SHADOW_PAPER_TARGET = 1.5, SHADOW_GRID_TARGET = 3.0;
// The tree's build for 5M triangles within this many seconds.
inline constexpr double SHADOW_BUILD_TARGET_SECONDS = 0.5;
// Interleaved rounds, each of this many frames each way (the medians are over all of them).
inline constexpr int SHADOW_ROUNDS = 5, SHADOW_FRAMES = 5;

struct ShadowRun {
  std::string name;           // "gpu, grid 1M, 8 lights"
  std::string scene;          // "paper cube", "grid 1M, 8 lights"
  std::string backend;        // "gpu" or "cpu"
  size_t triangles = 0;
  int lights = 0;             // that cast shadows
  double target = 0;          // the ratio the run should stay within
  double plainMs = 0;         // a frame without shadows, median
  double shadowedMs = 0;      // the same frame with every light casting shadows, median
  double rays = 0;            // shadow rays a shadowed frame may trace: vertices x lights (Gouraud)
  std::string failure;
  double ratio() const { return shadowedMs / plainMs; }
  double raysPerSecond() const { return rays / (shadowedMs / 1000); }
};

struct ShadowBuild {
  size_t triangles = 0;
  double seconds = 0;         // median of 3 builds of the tree (prepare/shadow_bvh.h)
};

// `quick`: a 20,000-triangle grid, one round; else 1M triangles.
std::vector<ShadowRun> runShadows(const std::string& sourceDir, bool quick);
// `quick`: 200,000 triangles; else 5M.
ShadowBuild timeShadowBuild(bool quick);

}  // namespace phongvk::bench
