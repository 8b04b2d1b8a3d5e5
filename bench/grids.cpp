// grids.cpp — see grids.h.
#include "grids.h"

#include <cmath>
#include <cstdint>

namespace phongvk::bench {

MeshArrays waveGrid(int n, float phase) {
  MeshArrays mesh;
  for (int y = 0; y <= n; ++y) {
    for (int x = 0; x <= n; ++x) {
      const float u = float(x) / float(n) - 0.5f, v = float(y) / float(n) - 0.5f;
      mesh.positions.insert(mesh.positions.end(), {u, v, 0.05f * std::sin(12.0f * u + phase) * std::cos(9.0f * v)});
    }
  }
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      const int64_t a = int64_t(y) * (n + 1) + x, b = a + 1, c = a + n + 1, d = c + 1;
      mesh.triangles.insert(mesh.triangles.end(), {a, b, d, a, d, c});
    }
  }
  return mesh;
}

}  // namespace phongvk::bench
