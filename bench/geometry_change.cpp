// geometry_change.cpp — see geometry_change.h.
#include "geometry_change.h"

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

constexpr int FRAMES = GEOMETRY_CHANGE_FRAMES;

Scene sceneOf(const MeshArrays& mesh, int width, int height) {
  Scene scene(width, height);
  scene.setCamera({.position = {0.2, -1.1, 0.9}, .lookAt = {0, 0, 0}});
  scene.setLights({{.position = {0.5, -1, 2}}});
  scene.addMesh(mesh, Material{.ks = 0.4, .attenuation = {1, 0, 0}});
  return scene;
}

GeometryChangeRun named(Backend backend, int n, int width, int height) {
  const size_t triangles = size_t(2) * size_t(n) * size_t(n);
  return {std::string(backendName(backend)) + ", " + std::to_string(triangles) + " triangles", backendName(backend),
          triangles, width, height};
}

GeometryChangeRun measure(Backend backend, int n, int width, int height, int rounds) {
  GeometryChangeRun run = named(backend, n, width, height);
  Renderer renderer(backend);
  const Scene fixed = sceneOf(waveGrid(n, 0), width, height);
  const Scene variants[2] = {fixed.withRender({.specular = Specular::Blinn}), fixed.withRender({.specular = Specular::Phong})};
  renderer.render(sceneOf(waveGrid(n, 0.5f), width, height));  // warm-up: every pipeline the frames use
  for (const Scene& s : variants) renderer.render(s);
  std::vector<double> fixedMs, newMs, buildMs;
  double pipelines = 0;
  for (int round = 0; round < rounds; ++round) {
    for (int f = 0; f < FRAMES; ++f) {
      const auto start = Clock::now();
      renderer.render(variants[f % 2]);
      fixedMs.push_back(msSince(start));
    }
    std::vector<Scene> meshes;  // built before the clock starts: the user's side of the frame
    for (int f = 0; f < FRAMES; ++f) meshes.push_back(sceneOf(waveGrid(n, 1.0f + float(round * FRAMES + f)), width, height));
    const double compiledBefore = renderer.stats().pipelinesMs;
    for (const Scene& s : meshes) {
      const double builtBefore = renderer.stats().buildMs;
      const auto start = Clock::now();
      renderer.render(s);
      newMs.push_back(msSince(start));
      buildMs.push_back(renderer.stats().buildMs - builtBefore);
    }
    pipelines += renderer.stats().pipelinesMs - compiledBefore;
  }
  run.fixedMs = median(fixedMs);
  run.newMeshMs = median(newMs);
  run.buildMs = median(buildMs);
  run.pipelinesMs = pipelines;
  return run;
}

}  // namespace

std::vector<GeometryChangeRun> runGeometryChanges(bool quick) {
  struct Size {
    int n, width, height;
  };
  std::vector<Size> sizes = {{25, 640, 480}};  // 1,250 triangles
  if (!quick) sizes.push_back({200, 1280, 720});  // 80,000 triangles
  std::vector<GeometryChangeRun> runs;
  for (const Size& size : sizes) {
    for (Backend backend : {Backend::Gpu, Backend::Cpu}) {
      try {
        runs.push_back(measure(backend, size.n, size.width, size.height, quick ? 1 : GEOMETRY_CHANGE_ROUNDS));
      } catch (const std::exception& e) {
        runs.push_back(named(backend, size.n, size.width, size.height));
        runs.back().failure = e.what();
      }
      const GeometryChangeRun& r = runs.back();
      std::printf("  %s, %zu triangles: fixed %.2f ms, new mesh %.2f ms (build %.2f), %.2fx%s\n", r.backend.c_str(),
                  r.triangles, r.fixedMs, r.newMeshMs, r.buildMs, r.ratio(), r.failure.empty() ? "" : " (failed)");
    }
  }
  return runs;
}

}  // namespace phongvk::bench
