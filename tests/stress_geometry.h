// stress_geometry.h — meshes that tile a square with shared edges, for the coverage tests
// (coverage_test.cpp counts coverage in the reference; stress_gpu_test.cpp compares the backends).
// Header-only: both suites include it and neither links the other's libraries.
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <random>
#include <vector>

namespace phongvk::test {

// A triangle mesh over the square [-1, 1]^2 (z = 0). Every point of the square's interior lies in
// exactly one triangle, and every interior edge is shared by index by two triangles.
struct TiledSquare {
  std::vector<glm::vec2> positions;
  std::vector<glm::uvec3> triangles;  // counter-clockwise seen from +z
};

// n x n quads; interior vertices moved by up to `jitter` of a cell (<= 0.15 keeps every triangle
// counter-clockwise: no fold, no overlap), the
// diagonal's direction alternating, so edges take every slope. Seeded: the same mesh every run.
inline TiledSquare jitteredGrid(int n, float jitter, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> offset(-jitter, jitter);
  TiledSquare grid;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      const float dx = (i > 0 && i < n) ? offset(rng) : 0.0f;  // the border stays straight
      const float dy = (j > 0 && j < n) ? offset(rng) : 0.0f;
      grid.positions.push_back(glm::vec2((float(i) + dx) / float(n), (float(j) + dy) / float(n)) * 2.0f - 1.0f);
    }
  }
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const uint32_t a = uint32_t(j * (n + 1) + i), b = a + 1, c = a + uint32_t(n + 1), d = c + 1;
      if ((i + j) % 2) {
        grid.triangles.push_back({a, b, d});
        grid.triangles.push_back({a, d, c});
      } else {
        grid.triangles.push_back({a, b, c});
        grid.triangles.push_back({b, d, c});
      }
    }
  }
  return grid;
}

// `count` slivers fanned from (-1, -1) to points spread along the square's top and right sides:
// long thin triangles (aspect ratio ~count) that share their long edges.
inline TiledSquare sliverFan(int count) {
  TiledSquare fan;
  fan.positions.push_back(glm::vec2(-1.0f, -1.0f));
  for (int k = 0; k <= count; ++k) {
    const float t = 4.0f * float(k) / float(count);  // walks (1, -1) -> (1, 1) -> (-1, 1)
    fan.positions.push_back(t <= 2.0f ? glm::vec2(1.0f, t - 1.0f) : glm::vec2(3.0f - t, 1.0f));
  }
  for (int k = 0; k < count; ++k) fan.triangles.push_back({0u, uint32_t(k + 1), uint32_t(k + 2)});
  return fan;
}

}  // namespace phongvk::test
