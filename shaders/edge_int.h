// edge_int.h — the integers the edge functions are computed in: int64_t where the device has 64-bit
// integers, wide_int.h's Wide (two 32-bit words, the same values) on the 32-bit key path
// (PHONGVK_KEYS32). edges.h, row_spans.h and large_triangles.h are written once against the
// functions below, so both paths run the same maths and every value is the same integer. Shared by
// GLSL and C++ (glsl_cpp.h).
#ifndef PHONGVK_EDGE_INT_H
#define PHONGVK_EDGE_INT_H

#include "glsl_cpp.h"
#include "shared.h"
#include "wide_int.h"

SHARED_BEGIN

#ifdef PHONGVK_KEYS32
#define EdgeInt Wide
FN Wide edgeInt(int v) { return wideOf(v); }
FN Wide edgeAdd(Wide a, Wide b) { return wideAdd(a, b); }
FN Wide edgeSub(Wide a, Wide b) { return wideSub(a, b); }
FN Wide edgeProduct(int a, int b) { return wideProduct(a, b); }
FN bool edgeNegative(Wide a) { return wideNegative(a); }
FN int edgeSign(Wide a) { return wideSign(a); }
FN bool edgeLess(Wide a, Wide b) { return wideLess(a, b); }
FN bool edgeEqual(Wide a, Wide b) { return a.lo == b.lo && a.hi == b.hi; }
FN float edgeEstimate(Wide a) { return wideEstimate(a); }
FN int edgeQuotient(Wide n, int d) { return wideQuotient(n, d); }
FN Wide edgeFloorDiv256(Wide a) { return wideFloorDiv256(a); }
FN uint edgeClampToUint(Wide a) { return wideClampToUint(a); }
// (b.x - a.x) (p.y - a.y) - (b.y - a.y) (p.x - a.x): the differences fit an int (snapped
// coordinates and pixel centres stay below 2^28 and 2^31 subpixels).
FN Wide edgeAt(ivec2 a, ivec2 b, ivec2 p) { return wideEdgeFunction(a, b, p); }
#else
#define EdgeInt int64_t
FN int64_t edgeInt(int v) { return int64_t(v); }
FN int64_t edgeAdd(int64_t a, int64_t b) { return a + b; }
FN int64_t edgeSub(int64_t a, int64_t b) { return a - b; }
FN int64_t edgeProduct(int a, int b) { return int64_t(a) * int64_t(b); }
FN bool edgeNegative(int64_t a) { return a < int64_t(0); }
FN int edgeSign(int64_t a) { return a > int64_t(0) ? 1 : (a < int64_t(0) ? -1 : 0); }
FN bool edgeLess(int64_t a, int64_t b) { return a < b; }
FN bool edgeEqual(int64_t a, int64_t b) { return a == b; }
FN float edgeEstimate(int64_t a) { return float(a); }
FN int edgeQuotient(int64_t n, int d) { return int(n / int64_t(d)); }
FN int64_t edgeFloorDiv256(int64_t a) { return a >> 8; }  // arithmetic: toward minus infinity
FN uint edgeClampToUint(int64_t a) { return a < int64_t(0) ? 0u : (a > int64_t(0xFFFFFFFFu) ? 0xFFFFFFFFu : uint(a)); }
// The edge function with every coordinate taken to 64 bits first.
FN int64_t edgeAt(ivec2 a, ivec2 b, ivec2 p) {
  return (int64_t(b.x) - int64_t(a.x)) * (int64_t(p.y) - int64_t(a.y)) -
         (int64_t(b.y) - int64_t(a.y)) * (int64_t(p.x) - int64_t(a.x));
}
#endif

FN EdgeInt edgeMin(EdgeInt a, EdgeInt b) { return edgeLess(b, a) ? b : a; }
FN EdgeInt edgeMax(EdgeInt a, EdgeInt b) { return edgeLess(a, b) ? b : a; }

// d * 256 * n, the change of an edge function over n pixels along an axis where its coordinate
// difference is d (n * 256 fits an int: images are narrower than 2^23 pixels).
FN EdgeInt edgePixels(int d, int n) { return edgeProduct(d, SUBPIXEL_ONE * n); }

SHARED_END

#endif  // PHONGVK_EDGE_INT_H
