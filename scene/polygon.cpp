// polygon.cpp — see polygon.h. Ear clipping on a ring of corners (linked by prev/next), where an
// ear test looks only at the reflex corners near the ear (a grid holds them), and each cut steps
// back to the corner before it, so that ears stay small: near-linear time on the polygons files
// hold (a 100,000-corner circle written with 6 digits, whose rounding makes thousands of corners
// a hair reflex, is cut in well under a second).
#include "scene/polygon.h"

#include <algorithm>
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

class Ring {
 public:
  explicit Ring(std::vector<glm::dvec2> points) : points_(std::move(points)), prev_(points_.size()), next_(points_.size()) {
    const size_t n = points_.size();
    for (size_t i = 0; i < n; ++i) {
      prev_[i] = (i + n - 1) % n;
      next_[i] = (i + 1) % n;
    }
    std::vector<size_t> reflex;
    for (size_t i = 0; i < n; ++i)
      if (turn(i) <= 0) reflex.push_back(i);
    buildGrid(reflex);
    left_ = n;
  }

  size_t left() const { return left_; }
  size_t prev(size_t i) const { return prev_[i]; }
  size_t next(size_t i) const { return next_[i]; }
  double turn(size_t i) const { return cross2(points_[prev_[i]], points_[i], points_[next_[i]]); }

  // Every triangle of the fan of corner 0 turns the polygon's way (none backwards; flat ones are
  // allowed) and together they sweep less than a full turn about corner 0: the polygon is
  // star-shaped from corner 0 and the fan cuts it exactly. Convex polygons pass, also where
  // rounding makes neighbouring corners collinear or a hair reflex (a circle written with 6 digits).
  bool fanFits() const {
    double sweep = 0;
    const glm::dvec2 o = points_[0];
    for (size_t k = 1; k + 1 < points_.size(); ++k) {
      const glm::dvec2 a = points_[k] - o, b = points_[k + 1] - o;
      const double cross = a.x * b.y - a.y * b.x;
      if (cross < 0) return false;
      sweep += std::atan2(cross, a.x * b.x + a.y * b.y);
    }
    return sweep < 2 * M_PI - 1e-9;
  }

  // Convex, with no reflex corner inside or on its triangle (looked up in the grid cells the
  // triangle's box touches).
  bool isEar(size_t i) const {
    if (turn(i) <= 0) return false;
    const size_t a = prev_[i], c = next_[i];
    const glm::dvec2 lo = glm::min(points_[a], glm::min(points_[i], points_[c]));
    const glm::dvec2 hi = glm::max(points_[a], glm::max(points_[i], points_[c]));
    const glm::ivec2 from = cellOf(lo), to = cellOf(hi);
    for (int y = from.y; y <= to.y; ++y) {
      for (int x = from.x; x <= to.x; ++x) {
        for (size_t r : cells_[size_t(y) * size_t(side_) + size_t(x)]) {
          if (removed(r) || r == a || r == i || r == c || turn(r) > 0) continue;  // gone, a neighbour, or convex by now
          if (inside(points_[r], points_[a], points_[i], points_[c])) return false;
        }
      }
    }
    return true;
  }

  void remove(size_t i) {
    next_[prev_[i]] = next_[i];
    prev_[next_[i]] = prev_[i];
    prev_[i] = next_[i] = i;  // marks it removed
    --left_;
  }

 private:
  bool removed(size_t i) const { return prev_[i] == i; }

  // The reflex corners in a side_ x side_ grid over the polygon's box, about one a cell.
  void buildGrid(const std::vector<size_t>& reflex) {
    lo_ = hi_ = points_[0];
    for (const glm::dvec2& p : points_) {
      lo_ = glm::min(lo_, p);
      hi_ = glm::max(hi_, p);
    }
    side_ = std::max(1, int(std::sqrt(double(reflex.size()))));
    const double extent = std::max(hi_.x - lo_.x, hi_.y - lo_.y);
    cellSize_ = extent > 0 ? extent / side_ : 1.0;
    cells_.assign(size_t(side_) * size_t(side_), {});
    for (size_t r : reflex) {
      const glm::ivec2 c = cellOf(points_[r]);
      cells_[size_t(c.y) * size_t(side_) + size_t(c.x)].push_back(r);
    }
  }

  glm::ivec2 cellOf(glm::dvec2 p) const {
    const glm::dvec2 f = (p - lo_) / cellSize_;
    return glm::clamp(glm::ivec2(int(std::floor(f.x)), int(std::floor(f.y))), glm::ivec2(0), glm::ivec2(side_ - 1));
  }

  std::vector<glm::dvec2> points_;
  std::vector<size_t> prev_, next_;
  // Corners reflex at the start (a corner only turns convex as ears go), by grid cell.
  std::vector<std::vector<size_t>> cells_;
  glm::dvec2 lo_{0.0}, hi_{0.0};
  double cellSize_ = 1;
  int side_ = 1;
  size_t left_ = 0;
};

// Squared length of b - a, in float as tinyobjloader computes it for its quads.
float squaredDistance(const glm::vec3& a, const glm::vec3& b) {
  const float x = b.x - a.x, y = b.y - a.y, z = b.z - a.z;
  const float xx = x * x, yy = y * y, zz = z * z;
  return xx + yy + zz;
}

}  // namespace

void triangulatePolygon(const std::vector<glm::vec3>& positions, const std::vector<uint32_t>& corners,
                        std::vector<glm::uvec3>& triangles) {
  if (corners.size() == 3) {
    triangles.push_back({corners[0], corners[1], corners[2]});
    return;
  }
  Ring ring(projected(positions, corners));
  if (corners.size() > 4 && ring.fanFits()) {  // the fan of corner 0, in linear time
    for (size_t k = 1; k + 1 < corners.size(); ++k) triangles.push_back({corners[0], corners[k], corners[k + 1]});
    return;
  }
  if (corners.size() == 4 && ring.turn(0) > 0 && ring.turn(1) > 0 && ring.turn(2) > 0 && ring.turn(3) > 0) {
    // A convex quad is split along its shorter diagonal (a non-planar quad then bends where it is
    // least stretched), as tinyobjloader splits them.
    const uint32_t* c = corners.data();
    if (squaredDistance(positions[c[0]], positions[c[2]]) < squaredDistance(positions[c[1]], positions[c[3]])) {
      triangles.push_back({c[0], c[1], c[2]});
      triangles.push_back({c[0], c[2], c[3]});
    } else {
      triangles.push_back({c[0], c[1], c[3]});
      triangles.push_back({c[1], c[2], c[3]});
    }
    return;
  }
  size_t at = 0, tested = 0;  // corners tested since the last cut
  while (ring.left() > 3) {
    // After a whole lap without an ear (a self-intersecting or degenerate polygon), cut anyway:
    // every polygon of n corners still gives n - 2 triangles.
    if (ring.isEar(at) || tested > ring.left()) {
      const size_t before = ring.prev(at), after = ring.next(at);
      triangles.push_back({corners[before], corners[at], corners[after]});
      ring.remove(at);
      at = before;  // its ear status changed (so did after's, tested next): ears stay small
      tested = 0;
    } else {
      at = ring.next(at);
      ++tested;
    }
  }
  triangles.push_back({corners[ring.prev(at)], corners[at], corners[ring.next(at)]});
}

}  // namespace phongvk
