// hull.h — the 3D convex hull of a point set, as a closed triangle mesh.
#pragma once

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace phongvk {

struct Hull {
  std::vector<glm::uvec3> triangles;  // indices into the input points; ccw seen from outside
  std::string error;  // why there is no hull ("the points are coplanar; ..."), or empty
};

// Incremental hull with conflict lists (each point not yet added is linked to a face it sees), in
// O(n log n) expected time for n points in any order: sets of more than 4,096 distinct points are
// added in a fixed pseudo-random order (the same hull on every run and machine); smaller ones in
// the order given, as before, so their triangles and the order of them do not change. Robust to
// duplicate points and to points on the hull's faces or edges: only the corners of the hull are
// used, so a flat face is split into triangles between its corners, never into slivers, and no
// triangle appears twice. Points within a tolerance relative to the set's extent (1e-9) of a face's
// plane count as on it. Fails (error set, no triangles) when the points have no volume: all equal,
// collinear or coplanar.
Hull convexHull(const std::vector<glm::dvec3>& points);

}  // namespace phongvk
