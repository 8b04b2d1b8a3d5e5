// suite.h — the benchmark's scenes: the paper's scenes, icosphere grids from 1k to past
// the largest single storage buffer binding, large-triangle scenes, and 4K renders.
#pragma once

#include "scene/scene.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace phongvk::bench {

struct SuiteScene {
  std::string name;                 // as the tables show it, e.g. "grid 1M (7x7, subdivide 5)"
  std::string group;                // "paper", "grid", "large triangles", "4K"
  std::function<SceneSpec()> load;      // lazily: a scene file may be broken (its row says so)
  bool smallTriangles = false;      // an icosphere grid: counts for the 1M+ small-triangle target
};

// Every scene of the suite, smallest first within each group. `sourceDir` is the repository root
// (scenes/...). The paper's scenes are whatever scenes/paper/*.json exist now (frame 0 of the
// animated ones). `quick` keeps a few small scenes at a small image size, for the smoke test.
std::vector<SuiteScene> makeSuite(const std::string& sourceDir, bool quick);

// The device table's scenes (device_table.h): the paper's, the 1M-triangle grid and a small frame;
// `quick`: the small frame alone.
std::vector<SuiteScene> makeDeviceScenes(const std::string& sourceDir, bool quick);

// Scenes whose mesh setup (buildSceneData) is timed: the grids and one 5M-triangle icosphere.
std::vector<SuiteScene> makeSetupScenes(bool quick);

// n x n icospheres subdivided `subdivide` times (20 * 4^subdivide triangles each), on a 1 m grid
// facing the camera so every sphere is in view and its triangles are a pixel or two.
SceneSpec icosphereGrid(int n, int subdivide);

}  // namespace phongvk::bench
