#include "error_sweep.h"

#include "text.h"

#include "scene/camera.h"
#include "phongvk/compare.h"
#include "tools/contact_sheet.h"
#include "reference/raycast.h"

#include <cmath>
#include <cstdio>

namespace phongvk::bench {

namespace {

struct Tessellation {
  Shape shape;
  int level;  // UV segments, or icosphere subdivisions
  Shading shading;
  int samples;
};

// Every shading mode over both meshes with one sample; Gouraud and Phong over the icospheres with
// 4 samples (2x2), which the ground truth's 16 samples show as smoother silhouettes.
std::vector<Tessellation> sweepSettings(bool quick) {
  const std::vector<int> segments = quick ? std::vector<int>{8} : std::vector<int>{8, 16, 32, 64, 128, 256};
  const int subdivisions = quick ? 2 : 7;  // icospheres: subdivide 0 .. subdivisions - 1
  std::vector<Tessellation> settings;
  for (Shading shading : {Shading::Flat, Shading::Gouraud, Shading::Phong}) {
    for (int s : segments) settings.push_back({Shape::Sphere, s, shading, 1});
    for (int k = 0; k < subdivisions; ++k) settings.push_back({Shape::Icosphere, k, shading, 1});
  }
  for (Shading shading : {Shading::Gouraud, Shading::Phong}) {
    for (int k = 0; k < subdivisions; ++k) settings.push_back({Shape::Icosphere, k, shading, 4});
  }
  return settings;
}

// The ground truth's samples per pixel (a side of 4: 16), box-filtered as render.samples is.
constexpr int TRUTH_SAMPLE_SIDE = 4;

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
  scene.shading = t.shading;
  scene.samples = t.samples;
  return scene;
}

void describe(SweepPoint& p, const Tessellation& t) {
  const bool uv = t.shape == Shape::Sphere;
  p.mesh = uv ? "UV sphere" : "icosphere";
  p.setting = formatText(uv ? "segments %d" : "subdivide %d", t.level);
  p.label = formatText(uv ? "s%d" : "k%d", t.level);
  p.shading = t.shading == Shading::Flat ? "flat" : t.shading == Shading::Phong ? "Phong" : "Gouraud";
  p.samples = t.samples;
}

// A frame of `view`'s size from one rendered with `side` x `side` samples per pixel.
Image filtered(const Image& image, const View& view, int side) {
  return side == 1 ? image : downscale(image, view.width, view.height);
}

SweepPoint measurePoint(const VulkanContext& context, const SceneSpec& scene, const View& view, const Image& truth,
                        int repeat) {
  SweepPoint p;
  const SceneData data = buildSceneData(scene);
  p.triangles = data.triangles.size();
  const int side = sampleGridSide(scene.samples);
  const FramePair frames = makeFramePair(data, supersampled(view, side));
  const BackendRun reference = runReference(data, frames, repeat);
  p.referenceMs = reference.time.wallMs;
  const Image referenceImage = filtered(reference.image, view, side);
  p.referenceError = imageError(truth, referenceImage);
  const ComputeRun compute = runCompute(context, data, frames, repeat);
  p.compute = compute.time;
  if (compute.time.ok()) {
    const Image computeImage = filtered(compute.image, view, side);
    p.computeError = imageError(truth, computeImage);
    p.computeVsReference = compareImages(referenceImage, computeImage).maxChannelDiff();
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

namespace {

// The cheapest measured point of `shading` with one sample whose error, as the report prints it
// (two decimals), is at most `rmse`'s.
const SweepPoint* cheapestWithin(const SweepResult& sweep, const std::string& shading, double rmse) {
  const SweepPoint* best = nullptr;
  for (const SweepPoint& q : sweep.points) {
    if (q.shading != shading || q.samples != 1 || !q.compute.ok()) continue;
    if (std::round(q.computeError.rmse * 100) > std::round(rmse * 100)) continue;
    if (!best || q.cost() < best->cost()) best = &q;
  }
  return best;
}

std::string frontCounts(const SweepResult& sweep) {
  std::string counts;
  for (const char* shading : {"flat", "Gouraud", "Phong"}) {
    for (int samples : {1, 4}) {
      int n = 0;
      for (const SweepPoint& p : sweep.points) n += p.pareto && p.shading == shading && p.samples == samples;
      if (n > 0) counts += (counts.empty() ? "" : ", ") + formatText("%d %s with %d sample%s", n, shading, samples, samples == 1 ? "" : "s");
    }
  }
  return counts.empty() ? "no point" : counts;
}

}  // namespace

std::string frontFinding(const SweepResult& sweep) {
  // Per error one-sample Phong reaches, its cheapest point against the cheapest Gouraud point
  // reaching the same error (or none: Gouraud does not reach it with any mesh of the sweep).
  double low = INFINITY, high = 0, below = NAN;
  for (const SweepPoint& p : sweep.points) {
    if (p.shading != "Phong" || p.samples != 1 || !p.compute.ok()) continue;
    const SweepPoint* phong = cheapestWithin(sweep, "Phong", p.computeError.rmse);
    const SweepPoint* gouraud = cheapestWithin(sweep, "Gouraud", p.computeError.rmse);
    if (!gouraud || gouraud->cost() > phong->cost()) {
      if (std::isnan(below) || p.computeError.rmse > below) below = p.computeError.rmse;
      continue;
    }
    low = std::min(low, phong->cost() / gouraud->cost());
    high = std::max(high, phong->cost() / gouraud->cost());
  }
  std::string finding = "The front holds " + frontCounts(sweep) + ".";
  if (high > 0) {
    finding += formatText(" At the errors per-pixel Phong shading reaches, it costs %.2fx to %.2fx the cheapest Gouraud mesh "
                          "that reaches the same error (to two decimals)", low, high);
    finding += std::isnan(below) ? ", so on this device a finer mesh is the cheaper way to a given error."
                                 : formatText(", and to an RMSE of %.2f or less it is the cheaper way.", below);
  } else if (!std::isnan(below)) {
    finding += formatText(" To an RMSE of %.2f or less per-pixel Phong shading of a coarse mesh is cheaper than Gouraud "
                          "shading of any finer one.", below);
  }
  return finding;
}

SweepResult runErrorSweep(const VulkanContext& context, bool quick, int repeat) {
  SweepResult result;
  result.width = quick ? 160 : 640;
  result.height = quick ? 120 : 480;
  const std::vector<Tessellation> settings = sweepSettings(quick);
  // Every setting shares the camera, light and sphere, hence one ground truth.
  const SceneSpec first = sweepScene(settings.front(), result.width, result.height);
  const View view = makeView(first.camera);
  const Image truth = downscale(raycastSphere(first, supersampled(view, TRUTH_SAMPLE_SIDE)), view.width, view.height);
  for (const Tessellation& t : settings) {
    SweepPoint p = measurePoint(context, sweepScene(t, result.width, result.height), view, truth, repeat);
    describe(p, t);
    std::printf("error sweep %s %s, %s, %d sample(s): %llu triangles, compute %.2f ms, RMSE %.2f (reference %.2f)\n",
                p.mesh.c_str(), p.setting.c_str(), p.shading.c_str(), p.samples,
                static_cast<unsigned long long>(p.triangles), p.cost(), p.computeError.rmse, p.referenceError.rmse);
    std::fflush(stdout);
    result.points.push_back(p);
  }
  markParetoFront(result.points);
  return result;
}

}  // namespace phongvk::bench
