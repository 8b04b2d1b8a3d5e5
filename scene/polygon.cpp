// polygon.cpp — see polygon.h.
#include "scene/polygon.h"

#include <cmath>

namespace phongvk {
namespace {

double cross2(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) { return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x); }

// p inside or on triangle (a, b, c), counter-clockwise.
bool inside(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
  return cross2(a, b, p) >= 0 && cross2(b, c, p) >= 0 && cross2(c, a, p) >= 0;
}

// The corners in the plane the polygon faces most, turned so that the polygon runs counter-clockwise.
std::vector<glm::dvec2> projected(const std::vector<glm::vec3>& positions, const std::vector<uint32_t>& corners) {
  glm::dvec3 normal(0.0);  // Newell's method: robust for non-planar and concave polygons
  for (size_t i = 0; i < corners.size(); ++i) {
    const glm::dvec3 a(positions[corners[i]]), b(positions[corners[(i + 1) % corners.size()]]);
    normal += glm::dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
  }
  const glm::dvec3 m = glm::abs(normal);
  const int drop = m.x >= m.y && m.x >= m.z ? 0 : (m.y >= m.z ? 1 : 2);
  const int u = (drop + 1) % 3, v = (drop + 2) % 3;
  const bool flip = normal[drop] < 0;
  std::vector<glm::dvec2> points;
  for (uint32_t c : corners) {
    const glm::dvec3 p(positions[c]);
    points.push_back({p[u], flip ? -p[v] : p[v]});
  }
  return points;
}

}  // namespace

void triangulatePolygon(const std::vector<glm::vec3>& positions, const std::vector<uint32_t>& corners,
                        std::vector<glm::uvec3>& triangles) {
  if (corners.size() == 3) {
    triangles.push_back({corners[0], corners[1], corners[2]});
    return;
  }
  const std::vector<glm::dvec2> points = projected(positions, corners);
  std::vector<size_t> left(corners.size());
  for (size_t i = 0; i < left.size(); ++i) left[i] = i;
  while (left.size() > 3) {
    const size_t n = left.size();
    size_t cut = n, sharpest = 0;
    double sharpestTurn = -HUGE_VAL;
    for (size_t k = 0; k < n && cut == n; ++k) {
      const glm::dvec2 a = points[left[(k + n - 1) % n]], b = points[left[k]], c = points[left[(k + 1) % n]];
      const double turn = cross2(a, b, c);
      if (turn > sharpestTurn) {
        sharpestTurn = turn;
        sharpest = k;
      }
      if (turn <= 0) continue;  // reflex or flat: not an ear
      bool empty = true;
      for (size_t j = 0; j < n && empty; ++j) {
        if (j == k || j == (k + n - 1) % n || j == (k + 1) % n) continue;
        empty = !inside(points[left[j]], a, b, c);
      }
      if (empty) cut = k;
    }
    if (cut == n) cut = sharpest;
    triangles.push_back({corners[left[(cut + n - 1) % n]], corners[left[cut]], corners[left[(cut + 1) % n]]});
    left.erase(left.begin() + long(cut));
  }
  triangles.push_back({corners[left[0]], corners[left[1]], corners[left[2]]});
}

}  // namespace phongvk
