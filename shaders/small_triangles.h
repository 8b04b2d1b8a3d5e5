// small_triangles.h — the GPU triangle pass's 32-bit edge functions for small triangles (not part of
// the contract: the reference uses edges.h's 64-bit ones; tests check both cover the same pixels).
#ifndef PHONGVK_SMALL_TRIANGLES_H
#define PHONGVK_SMALL_TRIANGLES_H

#include "glsl_cpp.h"
#include "shared.h"
#include "edges.h"

SHARED_BEGIN

// A sub-triangle whose snapped extent is below SMALL_EXTENT subpixels in x and y has edge functions
// that, taken relative to its own corner, fit 32-bit integers exactly (|dx|, |dy|, |p - a| < 2^14,
// products < 2^28): the same values, signs and spans as the 64-bit set-up (edges.h), without 64-bit
// arithmetic, which SIMD CPUs (lavapipe) emulate. 16 pixels: a box of at most 256 pixels, the
// clip pass's SMALL_TRIANGLE_MAX_PIXELS; testing up to 1024 pixels one invocation each (32 pixels)
// made a 2x2 grid of spheres of ~200-pixel triangles slower (docs/PERFORMANCE.md, "Raster").
PHONGVK_CONST int SMALL_EXTENT = 4096;  // subpixels: 16 pixels

FN bool fitsSmallEdges(ivec2 a, ivec2 b, ivec2 c) {
  ivec2 extent = max(a, max(b, c)) - min(a, min(b, c));
  return extent.x < SMALL_EXTENT && extent.y < SMALL_EXTENT;
}

// setupEdges in 32 bits, for a sub-triangle that fitsSmallEdges: relative to its lower corner.
FN bool setupSmallEdges(ivec2 a, ivec2 b, ivec2 c, bool frontFacing, uint width, uint height, OUT(EdgeSetup) s) {
  ivec2 origin = min(a, min(b, c));
  ivec2 ra = a - origin;
  ivec2 rb = b - origin;
  ivec2 rc = c - origin;
  int area = edgeFunction(ra, rb, rc);
  if (!orientEdges(ra, rb, rc, area > 0 ? 1 : (area < 0 ? -1 : 0), frontFacing, s)) return false;
  s.origin = origin;
  s.bbox = pixelBounds(origin, max(a, max(b, c)), width, height);
  return !isEmpty(s.bbox);
}

// covers() in 32 bits: whether pixel (x, y)'s centre is inside a small sub-triangle (set up by
// setupSmallEdges; the pixel in its box). The triangle pass tests every pixel of a small
// triangle's box (as the reference does with covers()): cheaper on lavapipe than row spans, whose
// per-edge division and search loops every lane runs.
FN bool coversSmall(EdgeSetup s, int x, int y) {
  ivec2 p = ivec2(x * SUBPIXEL_ONE + SUBPIXEL_HALF, y * SUBPIXEL_ONE + SUBPIXEL_HALF) - s.origin;
  return edgeFunction(s.v1, s.v2, p) + s.bias0 >= 0 && edgeFunction(s.v2, s.v0, p) + s.bias1 >= 0 &&
         edgeFunction(s.v0, s.v1, p) + s.bias2 >= 0;
}

SHARED_END

#endif  // PHONGVK_SMALL_TRIANGLES_H
