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
// degenerate polygon) a corner is cut anyway, so every polygon of n corners gives n - 2
// triangles. A convex quad is split along its shorter diagonal, as tinyobjloader splits them; a
// polygon that is star-shaped from its first corner (every convex one, also where rounding makes
// neighbours collinear) gives that corner's fan, in linear time. Other polygons are cut near-linearly
// (O(n·r) at worst, for n corners of which r are reflex).
void triangulatePolygon(const std::vector<glm::vec3>& positions, const std::vector<uint32_t>& corners,
                        std::vector<glm::uvec3>& triangles);

}  // namespace phongvk
