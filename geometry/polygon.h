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
// neighbours collinear) gives that corner's fan, in linear time. Other polygons take O(n log n)
// to set up and then at most a fixed budget of ear search a corner (kWorkPerCorner in
// polygon.cpp); one that needs more (a self-intersecting one, whose search for ears can lap the
// ring again and again) has the corners left cut as a fan once that is spent. So every polygon is
// cut in O(n log n) time, and one cut within the budget is cut as it always was.
void triangulatePolygon(const std::vector<glm::vec3>& positions, const std::vector<uint32_t>& corners,
                        std::vector<glm::uvec3>& triangles);

}  // namespace phongvk
