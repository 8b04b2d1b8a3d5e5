// hull.cpp — see hull.h. Two passes: an incremental hull of the distinct points (points within
// epsilon of a face's plane are not added, so no inward slivers), then, if some hull vertices turn
// out not to be corners (they lie inside a flat face or on a straight edge, because they were added
// before the points that made them flat), the hull of the corners alone.
#include "geometry/hull.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cstdint>
#include <numeric>
#include <random>
#include <utility>

namespace phongvk {
namespace {

// Relative to the point set's extent: what counts as "on a plane".
constexpr double kRelativeEpsilon = 1e-9;

// Sets of up to this many distinct points are added in the order given, as they always were, so
// that their hulls keep their triangles and the order of them (an adversarial order is quadratic,
// which at this size is still little); larger sets in a fixed pseudo-random order, so that no
// order of the input (points sorted along a curve) makes the hull quadratic.
constexpr size_t kGivenOrderLimit = 4096;

constexpr uint32_t kNone = ~0u;

struct Face {
  uint32_t a, b, c;
  glm::dvec3 normal;  // unit, outward
  std::array<uint32_t, 3> neighbour{kNone, kNone, kNone};  // across a-b, b-c, c-a
  uint32_t outside = kNone;  // the first of the points not yet added that see it (a linked list)
  bool alive = true;
  uint64_t made = 0;  // when it was made: the order of the hull's faces
  uint32_t testedAt = 0, visibleAt = 0;  // the last add() that tested it, that found it seen
  uint64_t searchedAt = 0;               // the last relist() that looked at it
};

Face makeFace(const std::vector<glm::dvec3>& p, uint32_t a, uint32_t b, uint32_t c) {
  glm::dvec3 n = glm::cross(p[b] - p[a], p[c] - p[a]);
  assert(glm::length(n) > 0.0);
  return {a, b, c, glm::normalize(n)};
}

double distanceTo(const Face& f, const std::vector<glm::dvec3>& p, const glm::dvec3& q) {
  return glm::dot(f.normal, q - p[f.a]);
}

glm::uvec2 edgeOf(const Face& f, int k) {
  return k == 0 ? glm::uvec2(f.a, f.b) : (k == 1 ? glm::uvec2(f.b, f.c) : glm::uvec2(f.c, f.a));
}

using Faces = std::vector<Face>;

// The first tetrahedron: two far-apart points, the point farthest from their line, the point
// farthest from their plane. Empty (and `error` set) when the points have no volume.
Faces initialSimplex(const std::vector<glm::dvec3>& p, const std::vector<uint32_t>& ids, double eps,
                     std::string& error) {
  auto farthest = [&](auto&& distance) {
    return *std::max_element(ids.begin(), ids.end(), [&](uint32_t x, uint32_t y) {
      return distance(p[x]) < distance(p[y]);
    });
  };
  const uint32_t i0 = ids.front();
  const uint32_t i1 = farthest([&](glm::dvec3 q) { return glm::length(q - p[i0]); });
  const glm::dvec3 axis = glm::normalize(p[i1] - p[i0]);
  auto fromLine = [&](glm::dvec3 q) { return glm::length(glm::cross(q - p[i0], axis)); };
  const uint32_t i2 = farthest(fromLine);
  if (glm::length(p[i1] - p[i0]) <= eps || fromLine(p[i2]) <= eps) {
    error = "the points are collinear; a polyhedron needs volume";
    return {};
  }
  const glm::dvec3 n = glm::normalize(glm::cross(p[i1] - p[i0], p[i2] - p[i0]));
  auto fromPlane = [&](glm::dvec3 q) { return std::abs(glm::dot(n, q - p[i0])); };
  const uint32_t i3 = farthest(fromPlane);
  if (fromPlane(p[i3]) <= eps) {
    error = "the points are coplanar; a polyhedron needs volume";
    return {};
  }
  const glm::dvec3 inside = (p[i0] + p[i1] + p[i2] + p[i3]) * 0.25;
  Faces faces;
  for (glm::uvec3 t : {glm::uvec3(i0, i1, i2), glm::uvec3(i0, i3, i1), glm::uvec3(i1, i3, i2),
                       glm::uvec3(i2, i3, i0)}) {
    Face f = makeFace(p, t.x, t.y, t.z);
    faces.push_back(distanceTo(f, p, inside) < 0.0 ? f : makeFace(p, t.x, t.z, t.y));
  }
  for (uint32_t f = 0; f < faces.size(); ++f) faces[f].made = f;
  for (Face& f : faces)  // each edge's reverse is in exactly one other face
    for (int k = 0; k < 3; ++k)
      for (uint32_t g = 0; g < faces.size(); ++g)
        for (int j = 0; j < 3; ++j)
          if (edgeOf(faces[g], j) == glm::uvec2(edgeOf(f, k).y, edgeOf(f, k).x)) f.neighbour[k] = g;
  return faces;
}

// An incremental hull that keeps, for each face, the points not yet added that see it (each such
// point listed by one face), so that adding a point costs the faces it replaces and the points
// those listed, not a pass over the whole hull. Faces within eps of a point do not see it: such
// points are not added, so no inward slivers.
class IncrementalHull {
 public:
  // Starts from `start` (a tetrahedron) and lists each of `ids` with the first face it sees.
  IncrementalHull(const std::vector<glm::dvec3>& p, double eps, Faces start, const std::vector<uint32_t>& ids)
      : p_(p), eps_(eps), faces_(std::move(start)), made_(faces_.size()), listedBy_(p.size(), kNone),
        nextListed_(p.size(), kNone), fanFaceFrom_(p.size(), kNone) {
    for (uint32_t i : ids)
      for (uint32_t f = 0; f < faces_.size(); ++f)
        if (sees(f, i)) {
          list(i, f);
          break;
        }
  }

  // Adds point i if it sees some face: the faces it sees go, and their horizon edges fan to i.
  void add(uint32_t i) {
    if (listedBy_[i] == kNone) return;  // inside or on the hull
    ++step_;
    const std::vector<uint32_t> visible = visibleFaces(i);
    fan_.clear();
    for (uint32_t f : visible)  // in the order made, edges in order: deterministic
      for (int k = 0; k < 3; ++k) {
        const uint32_t other = faces_[f].neighbour[k];
        if (faces_[other].visibleAt == step_) continue;
        const glm::uvec2 e = edgeOf(faces_[f], k);  // a horizon edge
        const uint32_t made = makeFace(e.x, e.y, i);
        faces_[made].neighbour[0] = other;
        for (uint32_t& n : faces_[other].neighbour)
          if (n == f) n = made;
        faces_[f].neighbour[k] = made;  // the dead face leads to its replacement, for relist()
        fanFaceFrom_[e.x] = made;
        fan_.push_back(made);
      }
    for (uint32_t n : fan_) {  // the fan's faces meet along edges to i
      const uint32_t next = fanFaceFrom_[faces_[n].b];
      faces_[n].neighbour[1] = next;
      faces_[next].neighbour[2] = n;
    }
    for (uint32_t f : visible) faces_[f].alive = false;
    for (uint32_t f : visible)
      for (uint32_t q = faces_[f].outside, next; q != kNone; q = next) {
        next = nextListed_[q];
        if (q != i) relist(q, f);
      }
    free_.insert(free_.end(), visible.begin(), visible.end());  // no longer needed by relist()
  }

  // The live faces, in the order made.
  Faces faces() const {
    std::vector<std::pair<uint64_t, uint32_t>> order;  // (made, index) of the live ones
    for (uint32_t f = 0; f < faces_.size(); ++f)
      if (faces_[f].alive) order.push_back({faces_[f].made, f});
    std::sort(order.begin(), order.end());
    Faces live;
    for (auto [made, f] : order) live.push_back(faces_[f]);
    return live;
  }

 private:
  bool sees(uint32_t f, uint32_t q) const { return distanceTo(faces_[f], p_, p_[q]) > eps_; }

  // A new face (a, b, c), in the place of a face dead since an earlier step if there is one.
  uint32_t makeFace(uint32_t a, uint32_t b, uint32_t c) {
    Face face = phongvk::makeFace(p_, a, b, c);
    face.made = made_++;
    if (free_.empty()) {
      faces_.push_back(face);
      return uint32_t(faces_.size() - 1);
    }
    const uint32_t index = free_.back();
    free_.pop_back();
    faces_[index] = face;
    return index;
  }

  void list(uint32_t q, uint32_t f) {
    nextListed_[q] = faces_[f].outside;
    faces_[f].outside = q;
    listedBy_[q] = f;
  }

  // The faces point i sees, reached from the one listing it through neighbours that see it too,
  // in the order made (marked visibleAt = step_).
  std::vector<uint32_t> visibleFaces(uint32_t i) {
    const uint32_t seen = listedBy_[i];
    std::vector<uint32_t> visible{seen};
    faces_[seen].testedAt = faces_[seen].visibleAt = step_;
    for (size_t k = 0; k < visible.size(); ++k)
      for (uint32_t n : faces_[visible[k]].neighbour) {
        if (faces_[n].testedAt == step_) continue;
        faces_[n].testedAt = step_;
        if (!sees(n, i)) continue;
        faces_[n].visibleAt = step_;
        visible.push_back(n);
      }
    std::sort(visible.begin(), visible.end(), [&](uint32_t x, uint32_t y) { return faces_[x].made < faces_[y].made; });
    return visible;
  }

  // Lists point q, listed by `dead` until now, with a new face that it sees, found by walking the
  // dead faces it sees from `dead` (if q is outside the new hull it sees such a face: a point
  // that sees a dead face and a live one across the horizon sees the new face between them).
  // Where it sees none it is inside the new hull and is not listed again, so never added.
  void relist(uint32_t q, uint32_t dead) {
    ++search_;
    listedBy_[q] = kNone;
    stack_.assign(1, dead);
    faces_[dead].searchedAt = search_;
    while (!stack_.empty()) {
      const uint32_t f = stack_.back();
      stack_.pop_back();
      for (uint32_t n : faces_[f].neighbour) {  // dead faces seen at this step, or new faces
        if (faces_[n].searchedAt == search_) continue;
        faces_[n].searchedAt = search_;
        if (!sees(n, q)) continue;
        if (faces_[n].alive) {
          list(q, n);
          return;
        }
        stack_.push_back(n);
      }
    }
  }

  const std::vector<glm::dvec3>& p_;
  const double eps_;
  Faces faces_;                 // live faces and dead ones (those of the current add(), and free_)
  std::vector<uint32_t> free_;  // places of dead faces that relist() no longer needs
  uint64_t made_;               // faces made so far
  std::vector<uint32_t> fan_;   // the faces made by the last add()
  std::vector<uint32_t> listedBy_;     // per point: the face whose list holds it, or kNone
  std::vector<uint32_t> nextListed_;   // per point: the next point in its face's list
  std::vector<uint32_t> fanFaceFrom_;  // per point: the newest fan face whose horizon edge starts there
  std::vector<uint32_t> stack_;
  uint32_t step_ = 0;   // add() calls that added a point, to mark faces with (at most one a point)
  uint64_t search_ = 0;  // relist() calls, to mark faces with
};

// The points of `ids` in a fixed pseudo-random order (the same on every machine: mt19937's
// output is fixed by the standard, std::shuffle's use of it is not).
std::vector<uint32_t> shuffled(std::vector<uint32_t> ids) {
  std::mt19937 random(20240521u);
  for (size_t k = ids.size(); k > 1; --k) std::swap(ids[k - 1], ids[random() % k]);
  return ids;
}

Faces incrementalHull(const std::vector<glm::dvec3>& p, const std::vector<uint32_t>& ids, double eps,
                      std::string& error) {
  Faces start = initialSimplex(p, ids, eps, error);
  if (start.empty()) return start;
  const std::vector<uint32_t> order = ids.size() <= kGivenOrderLimit ? ids : shuffled(ids);
  IncrementalHull hull(p, eps, std::move(start), order);
  for (uint32_t i : order) hull.add(i);  // the simplex's own points see no face: no-ops
  return hull.faces();
}

// Hull vertices where at least three distinct planes meet; the others lie inside a flat face (one
// plane) or on a straight edge (two) and are not needed.
std::vector<uint32_t> corners(const Faces& faces, const std::vector<glm::dvec3>& p, double eps) {
  std::vector<uint32_t> start(p.size() + 1, 0), incident(3 * faces.size());  // v's faces: from start[v]
  for (const Face& f : faces)
    for (uint32_t v : {f.a, f.b, f.c}) ++start[v + 1];
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<uint32_t> filled(start.begin(), start.end() - 1);
  for (uint32_t f = 0; f < faces.size(); ++f)
    for (uint32_t v : {faces[f].a, faces[f].b, faces[f].c}) incident[filled[v]++] = f;
  auto onPlane = [&](const Face& face, const Face& plane) {
    return std::abs(distanceTo(plane, p, p[face.a])) <= eps &&
           std::abs(distanceTo(plane, p, p[face.b])) <= eps &&
           std::abs(distanceTo(plane, p, p[face.c])) <= eps;
  };
  std::vector<uint32_t> result;
  for (uint32_t v = 0; v < p.size(); ++v) {
    std::array<const Face*, 3> planes;
    size_t distinct = 0;
    for (uint32_t k = start[v]; k < start[v + 1] && distinct < 3; ++k) {
      const Face& face = faces[incident[k]];
      if (std::none_of(planes.begin(), planes.begin() + distinct, [&](const Face* q) { return onPlane(face, *q); }))
        planes[distinct++] = &face;
    }
    if (distinct == 3) result.push_back(v);
  }
  return result;
}

// Indices of the distinct points (the first of each run of equal ones), in input order.
std::vector<uint32_t> distinctPoints(const std::vector<glm::dvec3>& p) {
  std::vector<uint32_t> order(p.size());
  std::iota(order.begin(), order.end(), 0u);
  auto less = [&](uint32_t x, uint32_t y) {
    if (p[x].x != p[y].x) return p[x].x < p[y].x;
    if (p[x].y != p[y].y) return p[x].y < p[y].y;
    if (p[x].z != p[y].z) return p[x].z < p[y].z;
    return x < y;
  };
  std::sort(order.begin(), order.end(), less);
  std::vector<uint32_t> ids;
  for (size_t k = 0; k < order.size(); ++k)
    if (k == 0 || p[order[k]] != p[order[k - 1]]) ids.push_back(order[k]);
  std::sort(ids.begin(), ids.end());
  return ids;
}

}  // namespace

Hull convexHull(const std::vector<glm::dvec3>& points) {
  Hull hull;
  std::vector<uint32_t> ids = distinctPoints(points);
  if (ids.size() < 4) {
    hull.error = "a polyhedron needs at least 4 distinct points, got " + std::to_string(ids.size());
    return hull;
  }
  // Centre the points so the tolerance and the plane tests do not depend on where the set lies.
  glm::dvec3 centre(0.0);
  for (const glm::dvec3& q : points) centre += q;
  centre /= double(points.size());
  std::vector<glm::dvec3> p;
  double extent = 0.0;
  for (const glm::dvec3& q : points) {
    p.push_back(q - centre);
    extent = std::max(extent, glm::length(p.back()));
  }
  const double eps = kRelativeEpsilon * extent;

  Faces faces = incrementalHull(p, ids, eps, hull.error);
  if (faces.empty()) return hull;
  // V - E + F = 2 with E = 3F/2: a triangulated hull has F/2 + 2 vertices.
  const size_t hullVertices = faces.size() / 2 + 2;
  std::vector<uint32_t> cornerIds = corners(faces, p, eps);
  if (cornerIds.size() < hullVertices && cornerIds.size() >= 4) {
    std::string ignored;
    Faces tidy = incrementalHull(p, cornerIds, eps, ignored);
    if (!tidy.empty()) faces = std::move(tidy);
  }
  for (const Face& f : faces) hull.triangles.push_back({f.a, f.b, f.c});
  return hull;
}

}  // namespace phongvk
