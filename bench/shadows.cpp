// shadows.cpp — see shadows.h.
#include "shadows.h"

#include "grids.h"
#include "interleave.h"

#include "api/timing.h"
#include "phongvk/phongvk.h"
#include "prepare/shadow_bvh.h"
#include "tools/statistics.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>

namespace phongvk::bench {

namespace {

// `scene` with its lights moved by `k` small steps about z (every frame lights its vertices again)
// and casting shadows or not.
Scene withLights(Scene scene, const std::vector<Light>& lights, int k, bool shadows) {
  std::vector<Light> moved = lights;
  const double angle = 0.01 * k, c = std::cos(angle), s = std::sin(angle);
  for (Light& l : moved) {
    l.position = {c * l.position[0] - s * l.position[1], s * l.position[0] + c * l.position[1], l.position[2]};
    l.shadows = shadows;
  }
  scene.setLights(moved);
  return scene;
}

// The wavy grid a metre across, a sphere 0.3 m above it, under `lights` lights in a ring.
Scene gridScene(int n, int lights, std::vector<Light>& ring) {
  Scene scene = parseScene(R"({"camera": {"position": [0.2, -1.1, 0.9], "look_at": [0, 0, 0], "width": 1280, "height": 720},
    "objects": [{"shape": "icosphere", "center": [0, 0, 0.3], "radius": 0.12, "subdivide": 3}]})");
  scene.addMesh(waveGrid(n, 0.0f), Material{.ks = 0.4, .attenuation = {1, 0, 0}});
  ring.clear();
  for (int i = 0; i < lights; ++i) {
    const double a = 6.283185307 * i / lights;
    ring.push_back({.position = {0.6 * std::cos(a), 0.6 * std::sin(a), 1.5}, .intensity = 1.0 / lights});
  }
  return scene;
}

ShadowRun measure(Backend backend, const std::string& name, const Scene& base, const std::vector<Light>& lights,
                  double target, int rounds) {
  ShadowRun run{std::string(backendName(backend)) + ", " + name, name, backendName(backend), 0, int(lights.size()), target};
  Renderer plain(backend), shadowed(backend);
  plain.render(withLights(base, lights, 0, false));  // warm-ups: the builds and every pipeline
  shadowed.render(withLights(base, lights, 0, true));
  std::vector<double> plainMs, shadowedMs;
  Scene frame = base;  // the frame being rendered, on either side
  const auto lit = [&](bool shadows) {
    return [&, shadows](int k) -> const Scene& { return frame = withLights(base, lights, k, shadows); };
  };
  timeInterleaved({{plain, lit(false), plainMs}, {shadowed, lit(true), shadowedMs}}, rounds, SHADOW_FRAMES);
  run.plainMs = median(plainMs);
  run.shadowedMs = median(shadowedMs);
  run.triangles = shadowed.stats().triangles;
  run.rays = double(base.triangles().mesh.positions.size() / 3) * double(lights.size());
  return run;
}

void print(const ShadowRun& r) {
  std::printf("  %s, %s, %zu triangles, %d shadowed lights: %.2f ms without, %.2f ms with, %.2fx, %.3g rays/s%s\n",
              r.scene.c_str(), r.backend.c_str(), r.triangles, r.lights, r.plainMs, r.shadowedMs, r.ratio(),
              r.raysPerSecond(), r.failure.empty() ? "" : (" (failed: " + r.failure + ")").c_str());
}

}  // namespace

std::vector<ShadowRun> runShadows(const std::string& sourceDir, bool quick) {
  const int n = quick ? 100 : 708, rounds = quick ? 1 : SHADOW_ROUNDS;
  const std::string grid = quick ? "grid 20k" : "grid 1M";
  std::vector<ShadowRun> runs;
  for (Backend backend : {Backend::Gpu, Backend::Cpu}) {
    const auto attempt = [&](const std::string& name, const Scene& scene, const std::vector<Light>& lights, double target) {
      try {
        runs.push_back(measure(backend, name, scene, lights, target, rounds));
      } catch (const std::exception& e) {
        runs.push_back({std::string(backendName(backend)) + ", " + name, name, backendName(backend), 0, int(lights.size()),
                        target});
        runs.back().failure = e.what();
      }
      print(runs.back());
    };
    const Scene cube = loadScene(sourceDir + "/scenes/paper/fig1_cube.json");
    attempt("paper cube", cube, cube.lights(), SHADOW_PAPER_TARGET);
    for (int lights : {1, 8}) {
      std::vector<Light> ring;
      const Scene scene = gridScene(n, lights, ring);
      attempt(grid + ", " + std::to_string(lights) + (lights == 1 ? " light" : " lights"), scene, ring, SHADOW_GRID_TARGET);
    }
  }
  return runs;
}

ShadowBuild timeShadowBuild(bool quick) {
  const int n = quick ? 316 : 1581;  // 2n² triangles: 199,712 or 4,999,122
  const MeshArrays mesh = waveGrid(n, 0.0f);
  std::vector<gpu::ShadowTriangle> triangles(mesh.triangles.size() / 3);
  const auto vertex = [&](int64_t i) {
    return glm::vec3(mesh.positions[size_t(3 * i)], mesh.positions[size_t(3 * i + 1)], mesh.positions[size_t(3 * i + 2)]);
  };
  for (size_t t = 0; t < triangles.size(); ++t) {
    const int64_t* v = &mesh.triangles[3 * t];
    triangles[t] = {vertex(v[0]), uint32_t(t), vertex(v[1]), uint32_t(v[0]), vertex(v[2]), uint32_t(v[1]), uint32_t(v[2])};
  }
  std::vector<double> seconds;
  for (int i = 0; i < 3; ++i) {
    std::vector<gpu::ShadowTriangle> input = triangles;  // the scene's builder hands its own over (moved)
    const auto start = Clock::now();
    const gpu::ShadowGeometry tree = buildShadowBvh(std::move(input));
    seconds.push_back(msSince(start) / 1000);
    if (tree.triangles.size() != triangles.size()) throw std::logic_error("the tree lost triangles");
  }
  const ShadowBuild build{triangles.size(), median(seconds)};
  std::printf("  the shadow rays' tree for %zu triangles: %.3f s\n", build.triangles, build.seconds);
  return build;
}

}  // namespace phongvk::bench
