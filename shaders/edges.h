// edges.h — snapping to 1/256 pixel and the integer edge functions with the top-left rule
// (docs/DESIGN.md "Rasterization"): which pixel centres a snapped sub-triangle covers. Shared by the GPU
// passes and the reference; see glsl_cpp.h for the dialect rules.
#ifndef PHONGVK_EDGES_H
#define PHONGVK_EDGES_H

#include "glsl_cpp.h"
#include "exact_float.h"
#include "shared.h"
#include "edge_int.h"

SHARED_BEGIN

// The homogeneous W of h: its view depth with a perspective camera, 1 with an orthographic one
// (shared.h PROJECTION_*). h.z is the view depth either way.
FN float homogeneousW(vec3 h, uint projection) { return projection == PROJECTION_ORTHOGRAPHIC ? 1.0f : h.z; }

// Screen position in 1/256 pixel units, rounded to nearest (ties up). W >= near here, and h is
// inside the guard band, so the result is below 2^28 in magnitude: an int holds it exactly (and
// a SIMD CPU converts to 32-bit integers natively, to 64-bit lane by lane). Division by W = 1 is
// exact, so an orthographic position is snapped as it is.
FN ivec2 snapToSubpixel(vec3 h, vec2 principal, uint projection) {
  float w = homogeneousW(h, projection);
  PRECISE float sx = (divide(h.x, w) + principal.x) * float(SUBPIXEL_ONE) + 0.5f;
  PRECISE float sy = (divide(h.y, w) + principal.y) * float(SUBPIXEL_ONE) + 0.5f;
  return ivec2(int(floor(sx)), int(floor(sy)));
}

// Twice the signed area of a b p in subpixel units; > 0 when p is inside a clockwise-on-screen
// (y down) oriented edge a -> b. In 32 bits for a small triangle's coordinates taken relative to
// its corner (small_triangles.h), where it is exact; edge_int.h edgeAt for any snapped coordinates.
#define PHONGVK_EDGE_FUNCTION(T, V) \
  FN T edgeFunction(V a, V b, V p) { return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x); }
PHONGVK_EDGE_FUNCTION(int, ivec2)
#ifdef __cplusplus
PHONGVK_EDGE_FUNCTION(int64_t, i64vec2)  // what the tests check edgeAt against
#endif
#undef PHONGVK_EDGE_FUNCTION

// Top-left rule for triangles oriented so edge functions are positive inside (y down): a top edge
// is horizontal with the inside below it, a left edge goes up. Pixels exactly on such an edge
// are covered; on any other edge they are not. Returned as the bias added before the >= 0 test.
// Snapped coordinates stay below 2^28, so their differences fit an int.
FN int topLeftBias(ivec2 a, ivec2 b) {
  int dx = b.x - a.x;
  int dy = b.y - a.y;
  return (dy == 0 && dx > 0) || dy < 0 ? 0 : -1;
}

// A snapped sub-triangle ready to rasterize: vertices relative to `origin`, oriented so that
// inside is positive, per-edge top-left biases, and its pixel bounding box clipped to the image
// (x0 > x1 if empty).
struct EdgeSetup {
  ivec2 v0;
  ivec2 v1;
  ivec2 v2;
  int bias0;
  int bias1;
  int bias2;
  ivec4 bbox;    // x0, y0, x1, y1 inclusive
  ivec2 origin;  // subpixels: (0, 0) from setupEdges, the lower corner from setupSmallEdges
};

// floor(v / 256): an arithmetic shift (defined for negative v in GLSL and in C++20).
FN int floorDiv256(int v) { return v >> 8; }

// The pixels whose centres lie in the subpixel box [lo, hi] (snapped coordinates, below 2^28),
// clipped to the image: (x0, y0, x1, y1) inclusive, empty when x0 > x1 or y0 > y1, and then
// just outside the image. Pixel x's centre is x * 256 + 128.
FN ivec4 pixelBounds(ivec2 lo, ivec2 hi, uint width, uint height) {
  int x0 = max(floorDiv256(lo.x - SUBPIXEL_HALF + 255), 0);
  int y0 = max(floorDiv256(lo.y - SUBPIXEL_HALF + 255), 0);
  int x1 = min(floorDiv256(hi.x - SUBPIXEL_HALF), int(width) - 1);
  int y1 = min(floorDiv256(hi.y - SUBPIXEL_HALF), int(height) - 1);
  return ivec4(min(x0, int(width)), min(y0, int(height)), max(x1, -1), max(y1, -1));
}

FN bool isEmpty(ivec4 box) { return box.x > box.z || box.y > box.w; }

// Orients sub-triangle a b c, whose doubled area has the sign `areaSign`, and sets up its edge
// biases. frontFacing says which screen orientation the whole triangle has; a sub-triangle whose
// snapped orientation disagrees (snapping flipped a sliver) or whose snapped area is zero covers
// nothing and is rejected (returns false).
FN bool orientEdges(ivec2 a, ivec2 b, ivec2 c, int areaSign, bool frontFacing, OUT(EdgeSetup) s) {
  if (areaSign == 0 || (areaSign < 0) != frontFacing) return false;
  s.v0 = a;
  s.v1 = frontFacing ? c : b;  // front faces are counter-clockwise on a y-down screen: flip them
  s.v2 = frontFacing ? b : c;
  s.bias0 = topLeftBias(s.v1, s.v2);
  s.bias1 = topLeftBias(s.v2, s.v0);
  s.bias2 = topLeftBias(s.v0, s.v1);
  return true;
}

// Sets up sub-triangle a b c (snapped coordinates) with exact edge functions (edge_int.h):
// orientEdges, and its pixel box. False where orientEdges rejects it or it covers no pixel centre
// of the image.
FN bool setupEdges(ivec2 a, ivec2 b, ivec2 c, bool frontFacing, uint width, uint height, OUT(EdgeSetup) s) {
  if (!orientEdges(a, b, c, edgeSign(edgeAt(a, b, c)), frontFacing, s)) return false;
  s.origin = ivec2(0);
  s.bbox = pixelBounds(min(a, min(b, c)), max(a, max(b, c)), width, height);
  return !isEmpty(s.bbox);
}

// The subpixel position of pixel (x, y)'s centre (below 2^31: images are at most 16384 pixels wide).
FN ivec2 pixelCentre(int x, int y) { return ivec2(x * SUBPIXEL_ONE + SUBPIXEL_HALF, y * SUBPIXEL_ONE + SUBPIXEL_HALF); }

FN bool covers(EdgeSetup s, ivec2 p) {
  ivec2 q = p - s.origin;
  return !edgeNegative(edgeAdd(edgeAt(s.v1, s.v2, q), edgeInt(s.bias0))) &&
         !edgeNegative(edgeAdd(edgeAt(s.v2, s.v0, q), edgeInt(s.bias1))) &&
         !edgeNegative(edgeAdd(edgeAt(s.v0, s.v1, q), edgeInt(s.bias2)));
}

SHARED_END

#endif  // PHONGVK_EDGES_H
