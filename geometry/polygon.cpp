// polygon.cpp — see polygon.h. Ear clipping on a ring of corners (linked by prev/next), where an
// ear test looks only at the reflex corners that meet the ear (a k-d tree holds them), and each
// cut steps back to the corner before it, so that ears stay small: near-linear time on the
// polygons files hold (a 100,000-corner circle written with 6 digits, whose rounding makes
// thousands of corners a hair reflex and every ear a long chord). A self-intersecting polygon can
// leave no ear for lap after lap; a budget of work in proportion to the corners bounds that.
#include "geometry/polygon.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

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

// Reflex corners in a k-d tree whose nodes count the corners still worth testing (not removed,
// still reflex): an ear test visits only nodes that hold such corners and meet the ear's triangle,
// so a long thin ear (a chord of a circle) costs about a root-to-leaf path, not its box's area.
class ReflexTree {
 public:
  // Over `reflex`, the corners of `points` reflex at the start (a corner only turns convex as
  // ears go; one turned reflex by a forced cut is not added, as before).
  ReflexTree(const std::vector<glm::dvec2>& points, const std::vector<size_t>& reflex) : slotOf_(points.size(), kNone) {
    double largest = 0;
    for (const glm::dvec2& p : points) largest = std::max({largest, std::abs(p.x), std::abs(p.y)});
    margin_ = 1e-12 * largest;
    for (size_t r : reflex) slots_.push_back({points[r], uint32_t(r), true});
    leafOf_.resize(slots_.size());
    if (!slots_.empty()) build(0, uint32_t(slots_.size()), kNone);
    for (uint32_t k = 0; k < slots_.size(); ++k) slotOf_[slots_[k].corner] = k;
  }

  // Keeps `corner`'s count in step with whether it is worth testing.
  void setCounted(size_t corner, bool counted) {
    const uint32_t k = slotOf_[corner];
    if (k == kNone || slots_[k].counted == counted) return;
    slots_[k].counted = counted;
    for (uint32_t node = leafOf_[k]; node != kNone; node = nodes_[node].parent) nodes_[node].live += counted ? 1 : -1;
  }

  // Whether a counted corner other than a, b, c lies inside or on triangle (a, b, c),
  // counter-clockwise. Adds one to `work` for each node and each corner looked at.
  bool anyInside(const std::vector<glm::dvec2>& points, size_t a, size_t b, size_t c, size_t& work) const {
    const glm::dvec2 pa = points[a], pb = points[b], pc = points[c];
    const Triangle triangle{glm::min(pa, glm::min(pb, pc)), glm::max(pa, glm::max(pb, pc)), {pa, pb, pc}, {pb, pc, pa}};
    std::array<uint32_t, 128> stack;  // one entry a level and one more; each level halves the corners
    size_t top = 0;
    if (!nodes_.empty()) stack[top++] = 0;
    while (top > 0) {
      const Node& node = nodes_[stack[--top]];
      ++work;
      if (node.live == 0 || !meets(node, triangle)) continue;
      if (node.left != kNone) {
        stack[top++] = node.left;
        stack[top++] = node.right;
        continue;
      }
      for (uint32_t k = node.begin; k < node.end; ++k) {
        const Slot& slot = slots_[k];
        ++work;
        if (!slot.counted || slot.corner == a || slot.corner == b || slot.corner == c) continue;
        if (inside(slot.point, pa, pb, pc)) return true;
      }
    }
    return false;
  }

 private:
  static constexpr uint32_t kNone = ~0u;
  static constexpr uint32_t kLeafSize = 8;

  struct Slot {
    glm::dvec2 point;
    uint32_t corner;
    bool counted;  // not removed and still reflex
  };

  struct Node {
    glm::dvec2 lo, hi;    // the box of its corners, grown by margin_
    uint32_t begin, end;  // its corners: slots_[begin, end)
    uint32_t left, right, parent;
    int32_t live;  // corners counted
  };

  // A triangle's box and edges, for meets().
  struct Triangle {
    glm::dvec2 lo, hi;
    std::array<glm::dvec2, 3> from, to;
  };

  // False where no corner in the box can be inside the triangle: the box is outside the
  // triangle's box, or its corner farthest to the left of an edge is right of it. The box's margin
  // keeps this true of corners that inside() finds inside by rounding.
  static bool meets(const Node& node, const Triangle& t) {
    if (node.hi.x < t.lo.x || node.lo.x > t.hi.x || node.hi.y < t.lo.y || node.lo.y > t.hi.y) return false;
    for (int e = 0; e < 3; ++e) {
      const glm::dvec2 from = t.from[e], to = t.to[e];
      const glm::dvec2 farthest(to.y > from.y ? node.lo.x : node.hi.x, to.x > from.x ? node.hi.y : node.lo.y);
      if (cross2(from, to, farthest) < 0) return false;
    }
    return true;
  }

  // The node over slots_[begin, end), split at the median of its box's longer side; its index.
  uint32_t build(uint32_t begin, uint32_t end, uint32_t parent) {
    glm::dvec2 lo = slots_[begin].point, hi = lo;
    for (uint32_t k = begin; k < end; ++k) {
      lo = glm::min(lo, slots_[k].point);
      hi = glm::max(hi, slots_[k].point);
    }
    const uint32_t index = uint32_t(nodes_.size());
    nodes_.push_back({lo - margin_, hi + margin_, begin, end, kNone, kNone, parent, int32_t(end - begin)});
    if (end - begin <= kLeafSize) {
      for (uint32_t k = begin; k < end; ++k) leafOf_[k] = index;
      return index;
    }
    const int axis = hi.x - lo.x >= hi.y - lo.y ? 0 : 1;
    const uint32_t mid = begin + (end - begin) / 2;
    std::nth_element(slots_.begin() + begin, slots_.begin() + mid, slots_.begin() + end,
                     [&](const Slot& x, const Slot& y) { return x.point[axis] < y.point[axis]; });
    const uint32_t left = build(begin, mid, index);
    const uint32_t right = build(mid, end, index);
    nodes_[index].left = left;
    nodes_[index].right = right;
    return index;
  }

  std::vector<Slot> slots_;        // the reflex corners, each node's together
  std::vector<Node> nodes_;        // the root first
  std::vector<uint32_t> leafOf_;   // per slot
  std::vector<uint32_t> slotOf_;   // per corner; kNone if not reflex at the start
  double margin_ = 0;              // far above rounding in cross2: pruning never loses a corner
};

class Ring {
 public:
  explicit Ring(std::vector<glm::dvec2> points)
      : points_(std::move(points)), prev_(points_.size()), next_(points_.size()), reflex_(points_, reflexCorners()) {
    left_ = points_.size();
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

  // Convex, with no reflex corner inside or on its triangle. Adds to `work` one for the test and
  // what the reflex tree looks at.
  bool isEar(size_t i, size_t& work) const {
    ++work;
    return turn(i) > 0 && !reflex_.anyInside(points_, prev_[i], i, next_[i], work);
  }

  void remove(size_t i) {
    const size_t before = prev_[i], after = next_[i];
    next_[before] = after;
    prev_[after] = before;
    --left_;
    reflex_.setCounted(i, false);
    reflex_.setCounted(before, turn(before) <= 0);  // their turns changed
    reflex_.setCounted(after, turn(after) <= 0);
  }

 private:
  // Links the ring and lists the corners that turn against the polygon (or not at all).
  std::vector<size_t> reflexCorners() {
    const size_t n = points_.size();
    for (size_t i = 0; i < n; ++i) {
      prev_[i] = (i + n - 1) % n;
      next_[i] = (i + 1) % n;
    }
    std::vector<size_t> reflex;
    for (size_t i = 0; i < n; ++i)
      if (turn(i) <= 0) reflex.push_back(i);
    return reflex;
  }

  std::vector<glm::dvec2> points_;
  std::vector<size_t> prev_, next_;
  ReflexTree reflex_;  // built from points_, prev_ and next_, so declared after them
  size_t left_ = 0;
};

// The work (ear tests, and the tree nodes and corners they look at) allowed before the rest of a
// polygon is cut without ear tests. Simple polygons take less: a 6-digit circle, combs and Koch
// snowflakes of 100,000 to 200,000 corners about 50 to 80 a corner, random star-shaped polygons
// of 100,000 about 270 (the base covers that); so they are cut as before.
constexpr size_t kWorkPerCorner = 256;
constexpr size_t kWorkBase = size_t(1) << 22;

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
  auto cut = [&](size_t corner) {
    triangles.push_back({corners[ring.prev(corner)], corners[corner], corners[ring.next(corner)]});
    ring.remove(corner);
  };
  // A self-intersecting polygon can have no ear for lap after lap; past this much work (counted
  // by isEar, the same on every machine) the rest is cut without looking for ears.
  const size_t budget = kWorkPerCorner * corners.size() + kWorkBase;
  size_t at = 0, tested = 0, work = 0;  // tested: corners tested since the last cut
  while (ring.left() > 3 && work <= budget) {
    // After a whole lap without an ear (a self-intersecting or degenerate polygon), cut anyway:
    // every polygon of n corners still gives n - 2 triangles.
    if (ring.isEar(at, work) || tested > ring.left()) {
      const size_t before = ring.prev(at);
      cut(at);
      at = before;  // its ear status changed (so did after's, tested next): ears stay small
      tested = 0;
    } else {
      at = ring.next(at);
      ++tested;
    }
  }
  while (ring.left() > 3) {  // out of work: the fan of the corner before `at`
    const size_t after = ring.next(at);
    cut(at);
    at = after;
  }
  cut(at);
}

}  // namespace phongvk
