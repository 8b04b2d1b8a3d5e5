// points.h — what a point cloud costs against triangles (docs/DESIGN.md "Points and lines"): a
// cloud of N points at 1080p against an N-triangle grid over the same surface, interleaved, each
// frame moving the camera (so every frame shades its vertices again), on both backends.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace phongvk::bench {

// A point cloud's frame within this factor of a grid of as many triangles (points are cheaper).
inline constexpr double POINTS_TARGET = 1.0;
// Interleaved rounds, each of this many frames each way (the medians are over all of them).
inline constexpr int POINTS_ROUNDS = 3, POINTS_FRAMES = 3;

struct PointsRun {
  std::string name;       // "gpu, 8000000 points"
  std::string backend;    // "gpu" or "cpu"
  size_t count = 0;       // points, and the grid's triangles (about)
  size_t triangles = 0;   // the grid's
  double gridMs = 0;      // a frame of the grid, median
  double pointsMs = 0;    // a frame of the cloud, median
  std::string failure;
  double ratio() const { return pointsMs / gridMs; }
};

// `quick`: 200,000 points, one round; else 10M (where the device holds them) and 8M on the compute
// port, 1M on the reference.
std::vector<PointsRun> runPoints(bool quick);

}  // namespace phongvk::bench
