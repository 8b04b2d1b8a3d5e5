#include "targets.h"

#include "text.h"

#include <algorithm>
#include <cmath>

namespace phongvk::bench {

namespace {

constexpr double MIB = 1024.0 * 1024.0;

// Why a CPU device spends a compute frame where it does, by the kind of scene (its per-pass
// timestamps are not reliable enough to say; docs/PERFORMANCE.md has the split measured by taking
// passes out, and the measurements behind each cause).
std::string cpuDeviceCause(const SceneResult& s) {
  if (s.smallTriangles) {
    return "; on this CPU device a frame of small triangles goes to the triangle pass (one invocation per "
           "triangle, its vertex fetches a loop over the SIMD lanes each, a 64-bit atomicMin per covered pixel a "
           "locked compare-and-swap per lane) and to resolving each pixel's winner from its vertices";
  }
  return "; on this CPU device a frame of large triangles goes mostly to resolving them: per pixel and triangle "
         "the reference's exact depth and colour (correctly rounded divisions, 64-bit edge values and keys), "
         "where lavapipe's own rasterizer steps interpolants from pixel to pixel, and every pixel's store is a "
         "loop over the SIMD lanes";
}

// Where the compute frame's time went: the wall clock around render() (which also uploads the
// frame's data and reads the image back) and the device time, with the passes' shares on a GPU.
// lavapipe writes a timestamp after a dispatch and a barrier early at times, so its per-pass
// shares would mislead (a 4K floor's came out 82% triangle pass, where taking passes out shows
// resolve); the cause by kind of scene follows instead.
std::string computeBreakdown(const SceneResult& s) {
  std::string text = formatText("compute frame %.2f ms wall", s.compute.wallMs);
  const PassTimes& p = s.passes;
  if (std::isnan(p.total) || p.total <= 0) return text;
  text += formatText(", %.2f ms on the device", p.total);
  if (s.cpuDeviceLanes != 0) return text + cpuDeviceCause(s);
  return text + formatText(": shade %.0f%%, triangles %.0f%%, large triangles and resolve %.0f%%",
                           100 * p.shade / p.total, 100 * p.raster / p.total, 100 * p.resolve / p.total);
}

// Why a CPU device cannot reach `needed` times one scalar core's speed: it has fewer lanes.
std::string laneBound(const SceneResult& s, double needed) {
  if (s.cpuDeviceLanes == 0 || double(s.cpuDeviceLanes) >= needed) return "";
  return formatText("; this CPU device runs at most %u lanes at once (cores x SIMD lanes), so %.0fx one scalar core "
                    "is out of its reach however the work is split",
                    s.cpuDeviceLanes, needed);
}

Verdict speedVerdict(Target target, const SceneResult& s, const Timing& other, const char* otherName, double needed) {
  Verdict v{target};
  const double x = speedup(other, s.compute);
  v.met = x >= needed;
  v.result = formatText("%.2fx", x);
  if (!v.met) {
    v.miss = formatText("needs %.2fx, has %.2fx (%.2fx short): ", needed, x, needed / x) + otherName +
             formatText(" %.2f ms wall; ", other.wallMs) + computeBreakdown(s);
  }
  return v;
}

Verdict memoryVerdict(const SceneResult& s) {
  Verdict v{Target::Memory};
  const double used = double(s.computeSceneBytes + s.computeImageBytes);
  const double budget = memoryBudget(s);
  v.met = used <= budget;
  v.result = formatText("%.1f of %.1f MiB", used / MIB, budget / MIB);
  if (!v.met) {
    v.miss = formatText("over by %.1f MiB (%.0f%%): ", (used - budget) / MIB, 100 * (used - budget) / budget) +
             formatText("geometry and per-vertex buffers %.1f B/triangle (budget %.0f), ",
                    double(s.computeSceneBytes) / double(s.triangles), BUDGET_BYTES_PER_TRIANGLE) +
             formatText("per-pixel buffers %.1f B/pixel (budget %.0f)", double(s.computeImageBytes) / double(s.pixels()),
                    BUDGET_BYTES_PER_PIXEL);
  }
  return v;
}

// The targets a scene of this size and kind is held to.
std::vector<Target> applicable(const SceneResult& s) {
  std::vector<Target> targets = {Target::GraphicsAll};
  if (s.smallTriangles && s.triangles >= SMALL_TRIANGLES_FROM) targets.push_back(Target::GraphicsSmall);
  if (s.triangles >= REFERENCE_TARGET_FROM) targets.push_back(Target::Reference);
  targets.push_back(Target::Memory);
  return targets;
}

Verdict judge(Target target, const SceneResult& s) {
  if (!s.compute.ok()) return {target, false, s.compute.failureKind(), "the compute port " + s.compute.failure};
  switch (target) {
    case Target::GraphicsAll: return speedVerdict(target, s, s.graphics, "graphics pipeline", GRAPHICS_SPEEDUP);
    case Target::GraphicsSmall: return speedVerdict(target, s, s.graphics, "graphics pipeline", GRAPHICS_SPEEDUP_SMALL);
    case Target::Reference: {
      Verdict v = speedVerdict(target, s, s.reference, "reference", REFERENCE_SPEEDUP);
      if (!v.met) v.miss += laneBound(s, REFERENCE_SPEEDUP);
      return v;
    }
    case Target::Memory: return memoryVerdict(s);
  }
  return {target};
}

// A comparison with a backend that could not run is not a verdict on the compute port.
bool judgeable(Target target, const SceneResult& s) {
  switch (target) {
    case Target::GraphicsAll:
    case Target::GraphicsSmall: return s.graphics.ok() || !s.compute.ok();
    case Target::Reference: return s.reference.ok() || !s.compute.ok();
    case Target::Memory: return true;
  }
  return false;
}

}  // namespace

std::string targetName(Target target) {
  switch (target) {
    case Target::GraphicsAll: return "compute at least as fast as the graphics pipeline, every scene";
    case Target::GraphicsSmall: return "compute >= 2x the graphics pipeline, scenes of 1M+ small triangles";
    case Target::Reference: return "compute >= 20x the single-threaded reference, scenes of 100k+ triangles";
    case Target::Memory: return "device memory <= 96 B/triangle (vertices included) + 12 B/pixel";
  }
  return "";
}

double speedup(const Timing& other, const Timing& compute) {
  if (!other.ok() || !compute.ok()) return NOT_MEASURED;
  return other.wallMs / compute.wallMs;
}

double memoryBudget(const SceneResult& scene) {
  return BUDGET_BYTES_PER_TRIANGLE * double(scene.triangles) + BUDGET_BYTES_PER_PIXEL * double(scene.pixels());
}

std::vector<Verdict> judgeScene(const SceneResult& scene) {
  std::vector<Verdict> verdicts;
  if (!scene.failure.empty()) return verdicts;
  for (Target t : applicable(scene)) {
    if (judgeable(t, scene)) verdicts.push_back(judge(t, scene));
  }
  return verdicts;
}

SetupVerdict judgeSetup(const std::vector<SetupResult>& setups) {
  const SetupResult* target = nullptr;  // the smallest scene of 5M+ triangles
  double cheapest = INFINITY, dearest = 0;
  for (const SetupResult& s : setups) {
    if (s.triangles >= SETUP_TARGET_TRIANGLES && (!target || s.triangles < target->triangles)) target = &s;
    if (s.triangles < SETUP_LINEAR_FROM) continue;
    const double ns = s.buildMs * 1e6 / double(s.triangles);
    cheapest = std::min(cheapest, ns);
    dearest = std::max(dearest, ns);
  }
  if (!target) return {false, "not measured: no scene of 5M+ triangles in this run"};
  const bool linear = dearest <= SETUP_LINEAR_SPREAD * cheapest;
  SetupVerdict v;
  v.met = target->buildMs <= SETUP_TARGET_MS && linear;
  v.result = target->name + formatText(": %.0f triangles in %.0f ms", double(target->triangles), target->buildMs) +
             formatText("; %.0f to %.0f ns per triangle from 100k triangles up", cheapest, dearest) +
             (linear ? " (linear)" : " (not linear: the spread is over 2x)");
  return v;
}

}  // namespace phongvk::bench
