// hull.cpp — see hull.h. Two passes: an incremental hull of the distinct points (points within
// epsilon of a face's plane are not added, so no inward slivers), then, if some hull vertices turn
// out not to be corners (they lie inside a flat face or on a straight edge, because they were added
// before the points that made them flat), the hull of the corners alone.
#include "scene/hull.h"

#include <algorithm>
#include <cassert>
#include <cstdint>
#include <numeric>

namespace phongvk {
namespace {

// Relative to the point set's extent: what counts as "on a plane".
constexpr double kRelativeEpsilon = 1e-9;

struct Face {
  uint32_t a, b, c;
  glm::dvec3 normal;  // unit, outward
  glm::dvec3 point;   // p[a]
};

Face makeFace(const std::vector<glm::dvec3>& p, uint32_t a, uint32_t b, uint32_t c) {
  glm::dvec3 n = glm::cross(p[b] - p[a], p[c] - p[a]);
  assert(glm::length(n) > 0.0);
  return {a, b, c, glm::normalize(n), p[a]};
}

double distanceTo(const Face& f, const glm::dvec3& q) { return glm::dot(f.normal, q - f.point); }

uint64_t edgeKey(uint32_t from, uint32_t to) { return (uint64_t(from) << 32) | to; }

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
    faces.push_back(distanceTo(f, inside) < 0.0 ? f : makeFace(p, t.x, t.z, t.y));
  }
  return faces;
}

// Adds point i: the faces it sees (beyond eps) go, and their horizon edges fan to i.
void addPoint(Faces& faces, const std::vector<glm::dvec3>& p, uint32_t i, double eps) {
  std::vector<uint64_t> visibleEdges;
  for (const Face& f : faces)
    if (distanceTo(f, p[i]) > eps)
      for (uint64_t key : {edgeKey(f.a, f.b), edgeKey(f.b, f.c), edgeKey(f.c, f.a)})
        visibleEdges.push_back(key);
  if (visibleEdges.empty()) return;  // inside or on the hull
  std::vector<uint64_t> sorted = visibleEdges;
  std::sort(sorted.begin(), sorted.end());

  Faces next;
  for (const Face& f : faces)
    if (distanceTo(f, p[i]) <= eps) next.push_back(f);
  for (uint64_t key : visibleEdges) {  // in face order: deterministic
    uint32_t from = uint32_t(key >> 32), to = uint32_t(key);
    if (!std::binary_search(sorted.begin(), sorted.end(), edgeKey(to, from)))  // a horizon edge
      next.push_back(makeFace(p, from, to, i));
  }
  faces = std::move(next);
}

Faces incrementalHull(const std::vector<glm::dvec3>& p, const std::vector<uint32_t>& ids,
                      double eps, std::string& error) {
  Faces faces = initialSimplex(p, ids, eps, error);
  if (faces.empty()) return faces;
  for (uint32_t i : ids) addPoint(faces, p, i, eps);  // the simplex's own points are on it: no-ops
  return faces;
}

// Hull vertices where at least three distinct planes meet; the others lie inside a flat face (one
// plane) or on a straight edge (two) and are not needed.
std::vector<uint32_t> corners(const Faces& faces, const std::vector<glm::dvec3>& p, double eps) {
  std::vector<std::vector<uint32_t>> incident(p.size());
  for (uint32_t f = 0; f < faces.size(); ++f)
    for (uint32_t v : {faces[f].a, faces[f].b, faces[f].c}) incident[v].push_back(f);
  auto onPlane = [&](const Face& face, const Face& plane) {
    return std::abs(distanceTo(plane, p[face.a])) <= eps &&
           std::abs(distanceTo(plane, p[face.b])) <= eps &&
           std::abs(distanceTo(plane, p[face.c])) <= eps;
  };
  std::vector<uint32_t> result;
  for (uint32_t v = 0; v < p.size(); ++v) {
    std::vector<const Face*> planes;
    for (uint32_t f : incident[v]) {
      bool known = std::any_of(planes.begin(), planes.end(),
                               [&](const Face* q) { return onPlane(faces[f], *q); });
      if (!known) planes.push_back(&faces[f]);
      if (planes.size() == 3) break;
    }
    if (planes.size() == 3) result.push_back(v);
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
