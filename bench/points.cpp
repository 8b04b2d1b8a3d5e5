// points.cpp — see points.h.
#include "points.h"

#include "grids.h"
#include "interleave.h"

#include "phongvk/phongvk.h"
#include "tools/statistics.h"

#include <cmath>
#include <cstdio>
#include <exception>

namespace phongvk::bench {

namespace {

// The camera k small steps about z around the grid a metre across, at 1080p.
Camera cameraAt(int k) {
  const double angle = 0.02 * k;
  Camera camera;
  camera.position = {1.1 * std::sin(angle), -1.1 * std::cos(angle), 0.9};
  camera.lookAt = {0, 0, 0};
  camera.width = 1920;
  camera.height = 1080;
  return camera;
}

// An n x n wavy grid's vertices as a point cloud (n² points on the grid's surface), coloured.
MeshArrays cloudOf(int n) {
  MeshArrays cloud;
  cloud.positions = waveGrid(n, 0.0f).positions;
  const size_t points = cloud.positions.size() / 3;
  cloud.colors.resize(4 * points);
  for (size_t i = 0; i < points; ++i) {
    const uint32_t h = uint32_t(i) * 2654435761u;
    cloud.colors[4 * i] = uint8_t(h >> 24), cloud.colors[4 * i + 1] = uint8_t(h >> 16), cloud.colors[4 * i + 2] = uint8_t(h >> 8);
    cloud.colors[4 * i + 3] = 255;
  }
  return cloud;
}

Scene sceneOf(const MeshArrays& mesh) {
  Scene scene(1920, 1080);
  scene.addMesh(mesh);
  scene.setCamera(cameraAt(0));
  return scene;
}

PointsRun measure(Backend backend, size_t count, bool quick) {
  PointsRun run{"", backendName(backend), count};
  const int cloudSide = int(std::lround(std::sqrt(double(count)))), gridSide = int(std::lround(std::sqrt(count / 2.0)));
  Scene grid = sceneOf(waveGrid(gridSide, 0.0f)), cloud = sceneOf(cloudOf(cloudSide));
  Renderer gridRenderer(backend), cloudRenderer(backend);
  gridRenderer.render(grid);  // warm-ups: the builds and every pipeline
  cloudRenderer.render(cloud);
  std::vector<double> gridMs, pointsMs;
  const auto moved = [](Scene& scene) {
    return [&scene](int k) -> const Scene& {
      scene.setCamera(cameraAt(k));
      return scene;
    };
  };
  timeInterleaved({{gridRenderer, moved(grid), gridMs}, {cloudRenderer, moved(cloud), pointsMs}}, quick ? 1 : POINTS_ROUNDS,
                  POINTS_FRAMES);
  run.count = size_t(cloudSide) * size_t(cloudSide);
  run.name = run.backend + ", " + std::to_string(run.count) + " points";
  run.triangles = gridRenderer.stats().triangles;
  run.gridMs = median(gridMs);
  run.pointsMs = median(pointsMs);
  return run;
}

void print(const PointsRun& r) {
  if (!r.failure.empty()) {
    std::printf("  %s, %zu points: failed: %s\n", r.backend.c_str(), r.count, r.failure.c_str());
    return;
  }
  std::printf("  %s, %zu points: %.1f ms a frame, a grid of %zu triangles %.1f ms, %.2fx\n", r.backend.c_str(), r.count,
              r.pointsMs, r.triangles, r.gridMs, r.ratio());
}

}  // namespace

std::vector<PointsRun> runPoints(bool quick) {
  std::vector<PointsRun> runs;
  for (Backend backend : {Backend::Gpu, Backend::Cpu}) {
    // The reference, one thread, at 1M: its ratio is the same work's, and 8M would take minutes.
    const std::vector<size_t> counts = quick                      ? std::vector<size_t>{200000}
                                       : backend == Backend::Gpu ? std::vector<size_t>{10000000, 8000000}
                                                                 : std::vector<size_t>{1000000};
    for (size_t count : counts) {
      try {
        runs.push_back(measure(backend, count, quick));
      } catch (const std::exception& e) {
        runs.push_back({std::string(backendName(backend)) + ", " + std::to_string(count) + " points", backendName(backend), count});
        runs.back().failure = e.what();
      }
      print(runs.back());
    }
  }
  return runs;
}

}  // namespace phongvk::bench
