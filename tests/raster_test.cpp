// Rasterization rules (docs/DESIGN.md "Rasterization", "Visibility") through the shared maths both
// renderers run (shaders/clip.h, edges.h, depth.h, triangle_setup.h, gouraud.h).
#include "reference/render_reference.h"
#include "shaders/gouraud.h"
#include "shaders/triangle_setup.h"

#include <gtest/gtest.h>

#include <bit>
#include <random>
#include <vector>

namespace phongvk {
namespace {

using namespace gpu;


constexpr uint W = 48;
constexpr uint H = 40;

FrameData frame() {
  FrameData f{};
  f.width = W;
  f.height = H;
  f.principal = vec2(W * 0.5f, H * 0.5f);
  f.nearPlane = 0.05f;
  f.farPlane = 1000.0f;
  return f;
}

// The homogeneous position of screen point (sx, sy) at view depth z.
vec3 at(float sx, float sy, float z = 1.0f) {
  return vec3((sx - W * 0.5f) * z, (sy - H * 0.5f) * z, z);
}

// How many times each pixel centre is covered by the triangles (no depth test).
std::vector<int> coverageCounts(const std::vector<std::array<vec3, 3>>& triangles) {
  std::vector<int> counts(W * H, 0);
  const FrameData f = frame();
  for (const auto& tri : triangles) {
    TriangleSetup t;
    if (!setupTriangle(tri[0], tri[1], tri[2], false, 0u, f, t)) continue;
    for (int k = 0; k + 2 < t.count; ++k) {
      EdgeSetup s;
      if (!setupFan(t, k, f, s)) continue;
      for (int y = s.bbox.y; y <= s.bbox.w; ++y)
        for (int x = s.bbox.x; x <= s.bbox.z; ++x) counts[y * W + x] += covers(s, pixelCentre(x, y));
    }
  }
  return counts;
}

// A grid of quads sharing edges, reaching past the image on every side. Interior vertices are
// jittered by whole 1/256 px steps, some landing exactly on pixel centres (the tie cases), and
// each quad is split along a random diagonal.
std::vector<std::array<vec3, 3>> jitteredGrid(unsigned seed, float offset) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> jitter(-300, 300);
  const int n = 9;
  const float step = (W + 16.0f) / n;
  std::vector<vec3> v;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      float x = -8.0f + i * step + offset;
      float y = -8.0f + j * step + offset * 0.37f;
      if (i > 0 && i < n && j > 0 && j < n) {
        if (rng() % 4 == 0) {  // exactly on a pixel centre
          x = std::floor(x) + 0.5f;
          y = std::floor(y) + 0.5f;
        } else {
          x += jitter(rng) / 256.0f;
          y += jitter(rng) / 256.0f;
        }
      }
      v.push_back(at(x, y, 1.0f + 0.01f * float(i + j)));
    }
  }
  std::vector<std::array<vec3, 3>> tris;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const vec3 a = v[j * (n + 1) + i], b = v[j * (n + 1) + i + 1];
      const vec3 c = v[(j + 1) * (n + 1) + i], d = v[(j + 1) * (n + 1) + i + 1];
      if (rng() % 2) {
        tris.push_back({a, b, d});
        tris.push_back({a, d, c});
      } else {
        tris.push_back({a, b, c});
        tris.push_back({b, d, c});
      }
    }
  }
  return tris;
}

TEST(Raster, SharedEdgeGridCoversEveryPixelExactlyOnce) {
  // No cracks and no double hits, at many subpixel offsets of the whole grid.
  for (int trial = 0; trial < 40; ++trial) {
    const float offset = trial / 7.0f;
    const std::vector<int> counts = coverageCounts(jitteredGrid(1000 + trial, offset));
    for (uint p = 0; p < W * H; ++p) {
      ASSERT_EQ(counts[p], 1) << "pixel (" << p % W << ", " << p / W << ") at trial " << trial;
    }
  }
}

TEST(Raster, SharedEdgesCrossingTheNearPlaneStayCrackFree) {
  // A jittered grid on the plane Z = 0.1 + Y / 15 (homogeneous pixel space) that passes behind
  // the eye; its near-plane line (Z = 0.05) crosses the image at py = -15, so many shared edges
  // are clipped on screen. Both triangles of an edge must clip it at the same point: no pixel is
  // covered twice, and none is missed where the pixel's ray meets the plane in front of the near
  // plane, inside the grid.
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> jitter(-0.3f, 0.3f);
  const int n = 16;
  const float x0 = -10.0f, x1 = 10.0f, y0 = -10.0f, y1 = 14.0f;
  std::vector<vec3> v;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      float X = x0 + (x1 - x0) * i / n;
      float Y = y0 + (y1 - y0) * j / n;
      if (i > 0 && i < n && j > 0 && j < n) {
        X += jitter(rng);
        Y += jitter(rng);
      }
      v.push_back(vec3(X, Y, 0.1f + Y / 15.0f));
    }
  }
  std::vector<std::array<vec3, 3>> tris;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i;
      tris.push_back({v[a], v[a + 1], v[a + n + 2]});
      tris.push_back({v[a], v[a + n + 2], v[a + n + 1]});
    }
  }
  const std::vector<int> counts = coverageCounts(tris);
  int inside = 0;
  for (uint y = 0; y < H; ++y) {
    for (uint x = 0; x < W; ++x) {
      const float px = x + 0.5f - W * 0.5f, py = y + 0.5f - H * 0.5f;
      const float t = 0.1f / (1.0f - py / 15.0f);  // depth where the ray meets the plane
      const bool wellInside = py < 15.0f && t > 0.052f && t * px > x0 + 0.5f && t * px < x1 - 0.5f &&
                              t * py > y0 + 0.5f && t * py < y1 - 0.5f;
      ASSERT_LE(counts[y * W + x], 1) << x << "," << y;
      if (wellInside) {
        ++inside;
        ASSERT_EQ(counts[y * W + x], 1) << x << "," << y;
      }
    }
  }
  EXPECT_GT(inside, 800);
}

TEST(Raster, TopLeftRuleOnASquareThroughPixelCentres) {
  // Square with corners on the centres of pixels (2,2) and (6,6), split along the anti-diagonal.
  // Top and left edges are in, bottom and right edges out: exactly pixels 2..5 x 2..5, and the
  // diagonal's pixels (x + y = 8) go to exactly one of the two triangles.
  const vec3 a = at(2.5f, 2.5f), b = at(6.5f, 2.5f), c = at(2.5f, 6.5f), d = at(6.5f, 6.5f);
  const std::vector<int> upper = coverageCounts({{a, b, c}});
  const std::vector<int> lower = coverageCounts({{b, d, c}});
  int upperCount = 0, lowerCount = 0;
  for (uint y = 0; y < H; ++y) {
    for (uint x = 0; x < W; ++x) {
      const bool inSquare = x >= 2 && x <= 5 && y >= 2 && y <= 5;
      EXPECT_EQ(upper[y * W + x] + lower[y * W + x], inSquare ? 1 : 0) << x << "," << y;
      upperCount += upper[y * W + x];
      lowerCount += lower[y * W + x];
    }
  }
  EXPECT_EQ(upperCount, 10);  // x, y >= 2 and x + y <= 7
  EXPECT_EQ(lowerCount, 6);   // x, y <= 5 and x + y >= 8
  EXPECT_EQ(upper[2 * W + 2], 1);  // top-left corner pixel: on the top and the left edge
}

TEST(Raster, WindingDoesNotChangeCoverage) {
  const vec3 a = at(3.2f, 1.7f), b = at(20.9f, 6.1f), c = at(7.3f, 18.4f);
  EXPECT_EQ(coverageCounts({{a, b, c}}), coverageCounts({{a, c, b}}));
}

TEST(Raster, ZeroAreaTrianglesAreSkipped) {
  const vec3 a = at(3.5f, 3.5f), b = at(10.5f, 10.5f);
  TriangleSetup t;
  EXPECT_FALSE(setupTriangle(a, b, at(17.5f, 17.5f), false, 0u, frame(), t));  // collinear
  EXPECT_FALSE(setupTriangle(a, a, b, false, 0u, frame(), t));                 // repeated vertex
}

TEST(Raster, BackFacesOfClosedObjectsAreCulled) {
  // Counter-clockwise seen from the eye (on a y-down screen: a, c, b clockwise) is front-facing.
  const vec3 a = at(5, 5), b = at(5, 20), c = at(20, 5);
  TriangleSetup t;
  EXPECT_TRUE(setupTriangle(a, b, c, true, 0u, frame(), t));
  EXPECT_TRUE(t.frontFacing);
  EXPECT_FALSE(setupTriangle(a, c, b, true, 0u, frame(), t));
  EXPECT_TRUE(setupTriangle(a, c, b, false, 0u, frame(), t));
}

TEST(Raster, DepthKeyOrdersByDepthThenTriangleId) {
  const uint64_t near2 = depthKey(2.0f, 0.05f, 10.0f, 1000.0f, 7);
  EXPECT_EQ(near2, (uint64_t(std::bit_cast<uint32_t>(2.0f)) << 32) | 7u);
  EXPECT_LT(near2, depthKey(2.5f, 0.05f, 10.0f, 1000.0f, 3));
  EXPECT_LT(depthKey(2.0f, 0.05f, 10.0f, 1000.0f, 3), near2);
  EXPECT_EQ(depthKey(1001.0f, 0.05f, 2000.0f, 1000.0f, 3), KEY_CLEAR);  // beyond far
  // Depth is held to the polygon's range, and NaN goes to its near end.
  EXPECT_EQ(depthKey(-5.0f, 0.5f, 10.0f, 1000.0f, 1) >> 32, std::bit_cast<uint32_t>(0.5f));
  EXPECT_EQ(depthKey(std::nanf(""), 0.5f, 10.0f, 1000.0f, 1) >> 32, std::bit_cast<uint32_t>(0.5f));
}

// Two overlapping triangles through the reference's rasterize(): who wins the pixel (24, 20).
uint32_t winnerAtCentre(float depth0, float depth1) {
  SceneData data;
  data.objects.resize(1);
  data.triangles = {{0, 1, 2, 0}, {3, 4, 5, 0}};
  std::vector<ShadedVertex> shaded(6);
  const vec3 corners[3] = {at(2, 2), at(2, 38), at(46, 2)};
  for (int i = 0; i < 3; ++i) {
    shaded[i].hpos = vec4(corners[i] * depth0, 1.0f);
    shaded[3 + i].hpos = vec4(corners[i] * depth1, 1.0f);
  }
  const std::vector<uint64_t> keys = rasterize(data, shaded, frame());
  return static_cast<uint32_t>(keys[10 * W + 12]);
}

TEST(Raster, NearerTriangleWinsWhateverItsId) {
  EXPECT_EQ(winnerAtCentre(3.0f, 2.0f), 1u);
  EXPECT_EQ(winnerAtCentre(2.0f, 3.0f), 0u);
}

TEST(Raster, EqualDepthGoesToTheLowerTriangleId) {
  EXPECT_EQ(winnerAtCentre(2.0f, 2.0f), 0u);
}

TEST(Raster, TriangleCrossingTheNearPlaneIsClippedNotDividedByW) {
  // One vertex behind the eye (z = -1): the visible part is clipped at z = near; every covered
  // pixel gets a finite depth between near and the far end of the visible part.
  SceneData data;
  data.objects.resize(1);
  data.triangles = {{0, 1, 2, 0}};
  std::vector<ShadedVertex> shaded(3);
  shaded[0].hpos = vec4(at(10, 30, 2.0f), 1.0f);
  shaded[1].hpos = vec4(at(40, 30, 2.0f), 1.0f);
  shaded[2].hpos = vec4(-2.0f, -20.0f, -1.0f, 1.0f);  // behind the camera
  const std::vector<uint64_t> keys = rasterize(data, shaded, frame());
  int covered = 0;
  for (uint64_t key : keys) {
    if (key == KEY_CLEAR) continue;
    ++covered;
    const float z = std::bit_cast<float>(uint32_t(key >> 32));
    EXPECT_TRUE(std::isfinite(z));
    EXPECT_GE(z, 0.05f);
    EXPECT_LE(z, 2.0f);
  }
  EXPECT_GT(covered, 100);
}

TEST(Raster, TriangleEntirelyBehindTheEyeDrawsNothing) {
  TriangleSetup t;
  EXPECT_FALSE(setupTriangle(vec3(1, 1, -1), vec3(5, 1, -1), vec3(1, 5, -2), false, 0u, frame(), t));
}

TEST(Raster, PackColorClampsAndRounds) {
  EXPECT_EQ(packColor(vec3(0.0f, 1.0f, 0.5f)), 0xFF800000u | 0x0000FF00u);  // 0.5 * 255 = 127.5 -> 128
  EXPECT_EQ(packColor(vec3(-1.0f, 2.0f, 0.2f)), 0xFF000000u | (51u << 16) | (255u << 8));
}

}  // namespace
}  // namespace phongvk
