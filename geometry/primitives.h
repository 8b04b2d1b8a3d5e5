// primitives.h — the built-in shapes, centred on the local origin (z up), with the midpoint rule
// that keeps their subdivided vertices on the true surface.
//
// Every shape is closed and watertight when vertices are welded by (bitwise) position; winding is
// counter-clockwise seen from outside. Where a surface has a crease (cube edges, cylinder and cone
// rims) the two sides own separate vertices at bit-identical positions, each with its own normal.
#pragma once

#include "geometry/subdivide.h"

namespace phongvk {

// Edge length `size`; each face its own 4 vertices with the face normal: 24 vertices, 12 triangles.
SurfaceMesh makeCube(double size);

// UV sphere: `segments` around z, max(2, segments / 2) latitude bands, a single vertex at each pole
// (fans there, no degenerate triangles), no duplicated seam. V = 2 + s (bands - 1),
// T = 2 s (bands - 1). Normals are position / radius.
SurfaceMesh makeUvSphere(double radius, int segments);

// Icosahedron inscribed in the sphere: 12 vertices, 20 triangles. Subdivision projects onto the
// sphere, so k levels give 10 * 4^k + 2 vertices and 20 * 4^k triangles.
SurfaceMesh makeIcosphere(double radius);

// Axis z, from -height/2 to +height/2. Side: one band of 2 s triangles, radial normals. Caps: a
// centre vertex and a fan of s triangles, normals +-z. V = 4 s + 2, T = 4 s.
SurfaceMesh makeCylinder(double radius, double height, int segments);

// Base (radius `radius`) at -height/2, apex at +height/2; `rings` bands along the slant. The band
// at the apex is a fan to per-segment copies of the apex (no degenerate triangles), each with the
// cone normal at its segment's mid-angle. Base: a fan with normal -z. V = s (rings + 2) + 1, T = 2
// s rings.
SurfaceMesh makeCone(double radius, double height, int segments, int rings);

}  // namespace phongvk
