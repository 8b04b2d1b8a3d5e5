// coverage_test.cpp — the fill rule, counted. Both renderers keep only the nearest fragment per
// pixel, so a pixel covered twice (or a crack filled by a triangle behind) is invisible in their
// images. Here edges.h's own setup and coverage functions are called directly and every pixel
// centre's coverage is counted: meshes that tile a region with shared edges must cover every
// pixel centre inside it exactly once, at every subpixel offset, in every orientation.

#include "shaders/triangle_setup.h"
#include "stress_geometry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace phongvk {
namespace {

using gpu::FrameData;
using glm::vec2;
using glm::vec3;

constexpr int kWidth = 48;
constexpr int kHeight = 32;

FrameData pixelFrame(int width, int height, float nearPlane) {
  FrameData frame{};
  frame.width = uint32_t(width);
  frame.height = uint32_t(height);
  frame.principal = vec2(float(width) * 0.5f, float(height) * 0.5f);
  frame.nearPlane = nearPlane;
  frame.farPlane = 1000.0f;
  return frame;
}

// How many triangles cover each pixel centre, through the same setup, clipping, fan and edge
// tests the renderers use. No back-face culling: both orientations must tile.
std::vector<int> countCoverage(const std::vector<vec3>& h, const std::vector<glm::uvec3>& triangles,
                               const FrameData& frame) {
  std::vector<int> count(size_t(frame.width) * frame.height, 0);
  for (const glm::uvec3& tri : triangles) {
    gpu::TriangleSetup t;
    if (!gpu::setupTriangle(h[tri.x], h[tri.y], h[tri.z], false, 0u, frame, t)) continue;
    for (int k = 0; k + 2 < t.count; ++k) {
      gpu::EdgeSetup s;
      if (!gpu::setupFan(t, k, frame, s)) continue;
      for (int y = s.bbox.y; y <= s.bbox.w; ++y) {
        for (int x = s.bbox.x; x <= s.bbox.z; ++x) {
          count[size_t(y) * frame.width + x] += gpu::covers(s, gpu::pixelCentre(x, y)) ? 1 : 0;
        }
      }
    }
  }
  return count;
}

// The homogeneous pixel-space positions (X, Y, W) of a mesh's 2D positions.
std::vector<vec3> project(const test::TiledSquare& mesh, const std::function<vec3(vec2)>& toH) {
  std::vector<vec3> h;
  for (vec2 p : mesh.positions) h.push_back(toH(p));
  return h;
}

// Expected coverage of pixel (x, y): 1 inside, 0 outside, -1 too close to a boundary to say.
using Expectation = std::function<int(int x, int y)>;

// Checks every pixel against `expected`; reports the first few that disagree.
void expectCoverage(const std::vector<int>& count, const FrameData& frame, const Expectation& expected,
                    const std::string& what) {
  int failures = 0;
  for (int y = 0; y < int(frame.height); ++y) {
    for (int x = 0; x < int(frame.width); ++x) {
      const int n = count[size_t(y) * frame.width + x];
      const int want = expected(x, y);
      const bool ok = want < 0 ? n <= 1 : n == want;
      if (!ok && ++failures <= 5) {
        ADD_FAILURE() << what << ": pixel (" << x << ", " << y << ") covered " << n << " times, expected "
                      << (want < 0 ? "at most 1" : std::to_string(want));
      }
    }
  }
  EXPECT_EQ(failures, 0) << what << ": pixels covered the wrong number of times";
}

const Expectation kEverywhereOnce = [](int, int) { return 1; };

// A subpixel offset sequence that visits many fractions of a 1/256 grid in both axes.
vec2 subpixelOffset(int k) { return vec2(float(k) / 16.0f, float((k * 7) % 16) / 16.0f + 1.0f / 512.0f); }

// The square, scaled to 1.3x the image, in the image plane (W = 1), at many subpixel offsets.
TEST(Coverage, JitteredGridCoversEveryPixelOnceAtEverySubpixelOffset) {
  const FrameData frame = pixelFrame(kWidth, kHeight, 0.05f);
  const test::TiledSquare grid = test::jitteredGrid(20, 0.15f, 1);
  for (int k = 0; k < 32; ++k) {
    const vec2 offset = subpixelOffset(k);
    const auto h = project(grid, [&](vec2 p) { return vec3(p * 32.0f + offset, 1.0f); });
    expectCoverage(countCoverage(h, grid.triangles, frame), frame, kEverywhereOnce,
                   "offset " + std::to_string(offset.x) + "," + std::to_string(offset.y));
  }
}

// Unjittered, 4-pixel cells offset by half a pixel: every vertex sits on a pixel centre and every
// edge (horizontal, vertical, diagonal) passes through pixel centres, so only the top-left rule
// decides who owns them.
TEST(Coverage, EdgesThroughPixelCentresAreOwnedOnce) {
  const FrameData frame = pixelFrame(kWidth, kHeight, 0.05f);
  const test::TiledSquare grid = test::jitteredGrid(16, 0.0f, 1);
  for (float mirror : {1.0f, -1.0f}) {  // -1 flips the winding: back faces must tile too
    const auto h = project(grid, [&](vec2 p) { return vec3(mirror * p.x * 32.0f + 0.5f, p.y * 32.0f + 0.5f, 1.0f); });
    expectCoverage(countCoverage(h, grid.triangles, frame), frame, kEverywhereOnce,
                   mirror > 0 ? "front facing" : "back facing");
  }
}

// A tilted plane seen in perspective: W differs per vertex, so shared edges are only shared after
// the divide and the snap.
TEST(Coverage, PerspectiveGridCoversEveryPixelOnce) {
  const FrameData frame = pixelFrame(kWidth, kHeight, 0.05f);
  const test::TiledSquare grid = test::jitteredGrid(24, 0.15f, 2);
  for (int k = 0; k < 8; ++k) {
    const vec2 offset = subpixelOffset(k * 3);
    const auto h = project(grid, [&](vec2 p) {
      const vec3 view(3.0f * p.x, 3.0f * p.y, 2.0f + 0.8f * p.x + 0.5f * p.y);
      return vec3(40.0f * view.x + offset.x * view.z, 40.0f * view.y + offset.y * view.z, view.z);
    });
    expectCoverage(countCoverage(h, grid.triangles, frame), frame, kEverywhereOnce, "offset " + std::to_string(k));
  }
}

// The plane z = x / 6 + 0.25 crosses the near plane (0.2) at screen x = -1.5 f = -15 pixels from
// the centre and runs behind the eye beyond it. Clipped edges must still be shared exactly:
// right of that line every pixel is covered once, left of it none.
TEST(Coverage, GridCrossingTheNearPlaneCoversOnceInFrontAndNeverBehind) {
  const float f = 10.0f;
  const FrameData frame = pixelFrame(kWidth, kHeight, 0.2f);
  const test::TiledSquare grid = test::jitteredGrid(24, 0.15f, 3);
  const auto h = project(grid, [&](vec2 p) {
    const vec3 view(3.0f * p.x, 3.0f * p.y, p.x * 0.5f + 0.25f);
    return vec3(f * view.x, f * view.y, view.z);
  });
  const Expectation expected = [&](int x, int) {
    const float sx = float(x) + 0.5f - frame.principal.x;  // the clip line is at sx = -15
    return sx > -14.0f ? 1 : (sx < -16.0f ? 0 : -1);
  };
  expectCoverage(countCoverage(h, grid.triangles, frame), frame, expected, "near plane");
}

// 100000 slivers (each ~0.0005 pixels wide, aspect ratio ~1e5) fanned over the whole image.
TEST(Coverage, SliverFanCoversEveryPixelOnce) {
  const FrameData frame = pixelFrame(16, 16, 0.05f);
  const test::TiledSquare fan = test::sliverFan(100000);
  for (int k = 0; k < 4; ++k) {
    const vec2 offset = subpixelOffset(k * 5);
    const auto h = project(fan, [&](vec2 p) { return vec3(p * 11.0f + offset, 1.0f); });
    expectCoverage(countCoverage(h, fan.triangles, frame), frame, kEverywhereOnce, "offset " + std::to_string(k));
  }
}

// Zero-area triangles (a repeated vertex, three collinear points, one point) cover nothing, and a
// triangle whose snapped area is zero though its float area is not covers nothing either.
TEST(Coverage, ZeroAreaTrianglesCoverNothing) {
  const FrameData frame = pixelFrame(kWidth, kHeight, 0.05f);
  const std::vector<vec3> h = {{-10, -10, 1}, {10, 5, 1},        {0, 20, 1},  // a real one: 0 1 2
                               {-20, -20, 1}, {20, 20, 1},       {0, 0, 1},   // collinear: 3 4 5
                               {3, 3, 1},     {3.001f, 3.001f, 1}, {3.0005f, 3.002f, 1}};  // snaps to a point
  const std::vector<glm::uvec3> degenerate = {{0, 0, 1}, {0, 1, 1}, {2, 2, 2}, {3, 4, 5}, {6, 7, 8}};
  const std::vector<int> count = countCoverage(h, degenerate, frame);
  expectCoverage(count, frame, [](int, int) { return 0; }, "degenerate");
  // The real triangle, for contrast, does cover pixels.
  const std::vector<int> real = countCoverage(h, {{0, 1, 2}}, frame);
  int covered = 0;
  for (int n : real) covered += n;
  EXPECT_GT(covered, 100);
}

}  // namespace
}  // namespace phongvk
