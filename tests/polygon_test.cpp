// polygon_test.cpp — polygons of mesh files cut into triangles (polygon.h): concave ones exactly as
// ear clipping cuts them, and self-intersecting ones of many corners in bounded time.
#include "geometry/polygon.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <numeric>
#include <random>
#include <vector>

namespace phongvk {
namespace {

// Processor seconds that mean a hang (the code before took from seconds to hours on these
// inputs), not a speed claim. The sanitizer build (scripts/sanitize.sh) runs several times slower.
#ifdef __SANITIZE_ADDRESS__
constexpr double kHangSeconds = 10;
#else
constexpr double kHangSeconds = 2;
#endif

std::vector<uint32_t> inOrder(size_t n) {
  std::vector<uint32_t> corners(n);
  std::iota(corners.begin(), corners.end(), 0u);
  return corners;
}

// Twice the signed area of triangle t seen from +z (counter-clockwise positive).
double doubleArea(const std::vector<glm::vec3>& p, const glm::uvec3& t) {
  const glm::dvec3 a(p[t.x]), b(p[t.y]), c(p[t.z]);
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// Cuts `positions` (one polygon, corners in order) and checks what every polygon's cut must be:
// n - 2 triangles of its own corners, and no hang.
std::vector<glm::uvec3> cutWithinTime(const std::vector<glm::vec3>& positions) {
  std::vector<glm::uvec3> triangles;
  const std::clock_t start = std::clock();
  triangulatePolygon(positions, inOrder(positions.size()), triangles);
  EXPECT_LT(double(std::clock() - start) / CLOCKS_PER_SEC, kHangSeconds);
  EXPECT_EQ(triangles.size(), positions.size() - 2);
  for (const glm::uvec3& t : triangles)
    for (uint32_t c : {t.x, t.y, t.z}) EXPECT_LT(c, positions.size());
  return triangles;
}

TEST(Polygon, ConcavePolygonsGiveTheirEarsInOrder) {
  // Neither polygon is star-shaped from its first corner, so both are cut by ear clipping; the
  // triangles and their order are pinned, as a mesh's triangle order reaches the image.
  const std::vector<glm::vec3> l = {{2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}, {0, 0, 0}, {2, 0, 0}};
  // A comb: a base 5 x 1 with three teeth 2 high, the list starting at a gap's reflex corner.
  const std::vector<glm::vec3> comb = {{1, 1, 0}, {1, 3, 0}, {0, 3, 0}, {0, 0, 0}, {5, 0, 0}, {5, 3, 0},
                                       {4, 3, 0}, {4, 1, 0}, {3, 1, 0}, {3, 3, 0}, {2, 3, 0}, {2, 1, 0}};
  const std::vector<std::vector<glm::uvec3>> expected = {
      {{5, 0, 1}, {4, 5, 1}, {3, 4, 1}, {2, 3, 1}},
      {{0, 1, 2}, {0, 2, 3}, {11, 0, 3}, {11, 3, 4}, {4, 5, 6}, {4, 6, 7}, {4, 7, 8}, {11, 4, 8}, {10, 11, 8},
       {9, 10, 8}}};
  const double areas[] = {3, 5 + 3 * 2};
  int k = 0;
  for (const std::vector<glm::vec3>& polygon : {l, comb}) {
    SCOPED_TRACE(k);
    std::vector<glm::uvec3> triangles;
    triangulatePolygon(polygon, inOrder(polygon.size()), triangles);
    EXPECT_EQ(triangles, expected[k]);
    double area = 0;
    for (const glm::uvec3& t : triangles) {
      EXPECT_GT(doubleArea(polygon, t), 0.0);  // none inverted: wound as the polygon
      area += doubleArea(polygon, t) / 2;
    }
    EXPECT_DOUBLE_EQ(area, areas[k]);  // they cover the polygon, nothing twice
    ++k;
  }
}

TEST(Polygon, CircleWrittenWithSixDigitsIsCutIntoEars) {
  // Rounding makes thousands of the 100,000 corners a hair reflex, so the fan does not fit and
  // every corner is an ear test; the ears are long thin chords (seconds with a uniform grid).
  std::vector<glm::vec3> circle;
  char text[32];
  for (int i = 0; i < 100000; ++i) {
    const double a = 2 * M_PI * i / 100000;
    glm::vec3 p(0);
    for (int axis = 0; axis < 2; ++axis) {
      std::snprintf(text, sizeof text, "%.6f", axis == 0 ? std::cos(a) : std::sin(a));
      p[axis] = std::strtof(text, nullptr);
    }
    circle.push_back(p);
  }
  double area = 0, polygonArea = 0;
  for (const glm::uvec3& t : cutWithinTime(circle)) {
    EXPECT_GE(doubleArea(circle, t), 0.0);  // ears only: none inverted
    area += doubleArea(circle, t) / 2;
  }
  for (uint32_t k = 1; k + 1 < circle.size(); ++k) polygonArea += doubleArea(circle, {0, k, k + 1}) / 2;
  EXPECT_NEAR(area, polygonArea, 1e-9);
}

TEST(Polygon, SelfIntersectingPolygonsAreCutInBoundedTime) {
  // Where no ear is left, ear clipping walks a lap of the ring before cutting a corner anyway,
  // lap after lap: 8,000 points in random order took 17 s, 100,000 would take hours. Past a
  // budget of work proportional to the corners the rest is cut without ear tests.
  std::mt19937 random(7);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (int n : {8000, 100000}) {
    SCOPED_TRACE(n);
    std::vector<glm::vec3> scattered, star;
    for (int k = 0; k < n; ++k) {
      scattered.push_back({unit(random), unit(random), 0});
      const double a = 2 * M_PI * double((int64_t(k) * 3) % n) / n;  // the star {n/3}: every third corner
      star.push_back({float(std::cos(a)), float(std::sin(a)), 0});
    }
    cutWithinTime(scattered);
    cutWithinTime(star);
  }
}

}  // namespace
}  // namespace phongvk
