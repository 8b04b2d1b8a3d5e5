// moving_object.cpp — see moving_object.h.
#include "moving_object.h"

#include "grids.h"

#include "api/timing.h"
#include "phongvk/phongvk.h"
#include "tools/statistics.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>

namespace phongvk::bench {

namespace {

// A turn by `angle` about z and a small shift: the object's pose for frame `k`.
Matrix4 poseAt(int k) {
  const double angle = 0.02 * k, c = std::cos(angle), s = std::sin(angle);
  return {c, -s, 0, 0.01 * k, s, c, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
}

// The camera for frame `k`: a small orbit about the object.
Camera cameraAt(int k) {
  const double angle = 0.02 * k;
  return {.position = {1.1 * std::sin(angle), -1.1 * std::cos(angle), 0.9}, .lookAt = {0, 0, 0}};
}

MovingObjectRun named(Backend backend, int n, int width, int height) {
  const size_t triangles = size_t(2) * size_t(n) * size_t(n);
  return {std::string(backendName(backend)) + ", " + std::to_string(triangles) + " triangles", backendName(backend),
          triangles, width, height};
}

MovingObjectRun measure(Backend backend, int n, int width, int height, int rounds) {
  MovingObjectRun run = named(backend, n, width, height);
  Renderer renderer(backend);
  Scene scene(width, height);
  scene.setLights({{.position = {0.5, -1, 2}}});
  scene.setCamera(cameraAt(0));
  const ObjectId object = scene.add(waveGrid(n, 0.0f), poseAt(0), Material{.ks = 0.4, .attenuation = {1, 0, 0}});
  renderer.render(scene);  // warm-up: the build and every pipeline the frames use
  scene.setPose(object, poseAt(1));
  renderer.render(scene);
  const uint64_t buildsBefore = renderer.stats().sceneBuilds;
  std::vector<double> cameraMs, objectMs;
  int k = 2;
  for (int round = 0; round < rounds; ++round) {
    for (int f = 0; f < MOVING_OBJECT_FRAMES; ++f, ++k) {
      scene.setCamera(cameraAt(k));  // the user's side of the frame, before the clock starts
      const auto start = Clock::now();
      renderer.render(scene);
      cameraMs.push_back(msSince(start));
    }
    for (int f = 0; f < MOVING_OBJECT_FRAMES; ++f, ++k) {
      scene.setPose(object, poseAt(k));
      const auto start = Clock::now();
      renderer.render(scene);
      objectMs.push_back(msSince(start));
    }
  }
  run.cameraMs = median(cameraMs);
  run.objectMs = median(objectMs);
  run.builds = renderer.stats().sceneBuilds - buildsBefore;
  return run;
}

}  // namespace

std::vector<MovingObjectRun> runMovingObjects(bool quick) {
  const int n = quick ? 100 : 708;  // 20,000 or 1,002,528 triangles
  std::vector<MovingObjectRun> runs;
  for (Backend backend : {Backend::Gpu, Backend::Cpu}) {
    try {
      runs.push_back(measure(backend, n, 1280, 720, quick ? 1 : MOVING_OBJECT_ROUNDS));
    } catch (const std::exception& e) {
      runs.push_back(named(backend, n, 1280, 720));
      runs.back().failure = e.what();
    }
    const MovingObjectRun& r = runs.back();
    std::printf("  %s, %zu triangles: camera moved %.2f ms, object moved %.2f ms, %.2fx, %llu builds%s\n",
                r.backend.c_str(), r.triangles, r.cameraMs, r.objectMs, r.ratio(), (unsigned long long)r.builds,
                r.failure.empty() ? "" : " (failed)");
  }
  return runs;
}

}  // namespace phongvk::bench
