// polygon.h — polygons of a mesh file (PLY faces of more than three vertices) cut into triangles by
// ear clipping, so that a concave face (an L, a ring's thin wedge) covers what it covers, not the
// fan of its first vertex.
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace phongvk {

// Appends to `triangles` the triangles of the polygon whose corners are `corners` (indices into
// `positions`, in order, at least three), each wound as the polygon is. Ear clipping in the plane
// that the polygon's Newell normal faces most; where no ear is left (a self-intersecting or
// degenerate polygon) the sharpest corner is cut, so every polygon of n corners gives n - 2
// triangles. O(n²) for n corners.
void triangulatePolygon(const std::vector<glm::vec3>& positions, const std::vector<uint32_t>& corners,
                        std::vector<glm::uvec3>& triangles);

}  // namespace phongvk
