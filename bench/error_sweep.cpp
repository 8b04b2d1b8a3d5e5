#include "error_sweep.h"

#include "text.h"

#include "scene/camera.h"
#include "phongvk/compare.h"
#include "reference/raycast.h"

#include <cmath>
#include <cstdio>

namespace phongvk::bench {

namespace {

struct Tessellation {
  Shape shape;
  int level;  // UV segments, or icosphere subdivisions
};

std::vector<Tessellation> sweepSettings(bool quick) {
  const std::vector<int> segments = quick ? std::vector<int>{8, 16} : std::vector<int>{8, 16, 32, 64, 128, 256};
  const int subdivisions = quick ? 2 : 7;  // icospheres: subdivide 0 .. subdivisions - 1
  std::vector<Tessellation> settings;
  for (int s : segments) settings.push_back({Shape::Sphere, s});
  for (int k = 0; k < subdivisions; ++k) settings.push_back({Shape::Icosphere, k});
  return settings;
}

// A unit sphere seen from slightly above, lit from the upper left so the image holds a highlight,
// a terminator and the silhouette: the three places coarse tessellation shows. No attenuation and
// a specular exponent of 30 make the highlight small, where per-vertex lighting struggles most.
SceneSpec sweepScene(const Tessellation& t, int width, int height) {
  SceneSpec scene;
  scene.path = "error sweep sphere";
  scene.camera.position = {0, -4, 1.2};
  scene.camera.direction = {0, 4, -1.2};
  scene.camera.fov = 40;
  scene.camera.width = width;
  scene.camera.height = height;
  scene.lights.push_back({{-2.5, -3, 3}, 1.0f, {1, 1, 1}});
  scene.materials.push_back({0.1f, 0.7f, 0.6f, 30.0f, {1, 0, 0}, {0.9f, 0.35f, 0.25f}});
  Object sphere;
  sphere.shape = t.shape;
  sphere.radius = 1;
  if (t.shape == Shape::Sphere) sphere.segments = t.level;
  if (t.shape == Shape::Icosphere) sphere.subdivide = t.level;
  sphere.jsonPath = "objects[0]";
  scene.objects.push_back(sphere);
  return scene;
}

void describe(SweepPoint& p, const Tessellation& t) {
  const bool uv = t.shape == Shape::Sphere;
  p.mesh = uv ? "UV sphere" : "icosphere";
  p.setting = formatText(uv ? "segments %d" : "subdivide %d", t.level);
  p.label = formatText(uv ? "s%d" : "k%d", t.level);
}

SweepPoint measurePoint(const VulkanContext& context, const SceneSpec& scene, const View& view, const Image& truth,
                        int repeat) {
  SweepPoint p;
  const SceneData data = buildSceneData(scene);
  p.triangles = data.triangles.size();
  const FramePair frames = makeFramePair(data, view);
  const BackendRun reference = runReference(data, frames, repeat);
  p.referenceMs = reference.time.wallMs;
  p.referenceError = imageError(truth, reference.image);
  const ComputeRun compute = runCompute(context, data, frames, repeat);
  p.compute = compute.time;
  if (compute.time.ok()) {
    p.computeError = imageError(truth, compute.image);
    p.computeVsReference = compareImages(reference.image, compute.image).maxChannelDiff();
  }
  return p;
}

bool dominates(const SweepPoint& q, const SweepPoint& p) {
  const double qc = q.cost(), pc = p.cost(), qe = q.computeError.rmse, pe = p.computeError.rmse;
  return qc <= pc && qe <= pe && (qc < pc || qe < pe);
}

}  // namespace

double SweepPoint::cost() const { return std::isnan(compute.deviceMs) ? compute.wallMs : compute.deviceMs; }

ImageError imageError(const Image& truth, const Image& image) {
  const DiffStats stats = compareImages(truth, image);
  ImageError e;
  e.psnr = stats.psnr;
  e.rmse = std::isinf(stats.psnr) ? 0.0 : 255.0 / std::pow(10.0, stats.psnr / 20.0);  // PSNR's own MSE
  e.maxAbs = stats.maxChannelDiff();
  return e;
}

void markParetoFront(std::vector<SweepPoint>& points) {
  for (SweepPoint& p : points) {
    p.pareto = p.compute.ok();
    for (const SweepPoint& q : points) {
      if (p.pareto && q.compute.ok() && dominates(q, p)) p.pareto = false;
    }
  }
}

SweepResult runErrorSweep(const VulkanContext& context, bool quick, int repeat) {
  SweepResult result;
  result.width = quick ? 160 : 640;
  result.height = quick ? 120 : 480;
  const std::vector<Tessellation> settings = sweepSettings(quick);
  // Every setting shares the camera, light and sphere, hence one ground truth.
  const SceneSpec first = sweepScene(settings.front(), result.width, result.height);
  const View view = makeView(first.camera);
  const Image truth = raycastSphere(first, view);
  for (const Tessellation& t : settings) {
    SweepPoint p = measurePoint(context, sweepScene(t, result.width, result.height), view, truth, repeat);
    describe(p, t);
    std::printf("error sweep %s %s: %llu triangles, compute %.2f ms, RMSE %.2f (reference %.2f)\n", p.mesh.c_str(),
                p.setting.c_str(), static_cast<unsigned long long>(p.triangles), p.cost(), p.computeError.rmse,
                p.referenceError.rmse);
    std::fflush(stdout);
    result.points.push_back(p);
  }
  markParetoFront(result.points);
  return result;
}

}  // namespace phongvk::bench
