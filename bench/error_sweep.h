// error_sweep.h — run time against error: one sphere under one light, tessellated ever finer (UV
// segments, icosphere subdivision), shaded flat, Gouraud and Phong with 1 and 4 samples per pixel,
// each rendered by the compute port and the reference and compared with the analytic ground truth
// (reference/raycast.h: exact sphere, per-pixel Phong, 16 samples per pixel box-filtered).
#pragma once

#include "measure.h"

#include <string>
#include <vector>

namespace phongvk::bench {

// Over all pixels and channels, in 8-bit units.
struct ImageError {
  double rmse = NOT_MEASURED;
  int maxAbs = -1;
  double psnr = NOT_MEASURED;  // dB, +inf when identical
};

struct SweepPoint {
  std::string mesh;             // "UV sphere" or "icosphere"
  std::string setting;          // "segments 32", "subdivide 3"
  std::string label;            // short, for the plot: "s32", "k3"
  std::string shading;          // "flat", "Gouraud", "Phong"
  int samples = 1;              // per pixel
  uint64_t triangles = 0;
  Timing compute;               // median wall and device ms
  double referenceMs = NOT_MEASURED;
  ImageError computeError;      // against the ground truth
  ImageError referenceError;
  int computeVsReference = -1;  // largest channel difference
  bool pareto = false;          // no other point is both faster and closer to the truth

  // What the front and the plot measure cost by: the compute frame's device time, or its wall
  // clock where the device has no timestamps.
  double cost() const;
};

struct SweepResult {
  int width = 0, height = 0;
  // Per shading mode (flat, Gouraud, Phong) UV spheres by segments, then icospheres by subdivision;
  // then Gouraud and Phong icospheres with 4 samples per pixel.
  std::vector<SweepPoint> points;
};

// One sentence on what the front says of the shading modes: the cheapest point where Phong shading
// reaches an error Gouraud reaches only on a finer, dearer mesh, or that it reaches none.
std::string frontFinding(const SweepResult& sweep);

// Errors of `image` against `truth` (same size).
ImageError imageError(const Image& truth, const Image& image);

// Sets `pareto` on the points no other point dominates in (cost, compute RMSE); points whose
// compute run failed are never on the front.
void markParetoFront(std::vector<SweepPoint>& points);

// The sweep; `quick` takes four coarse meshes at a small size, for the smoke test.
SweepResult runErrorSweep(const VulkanContext& context, bool quick, int repeat);

}  // namespace phongvk::bench
