// row_spans.h — the clip pass's row spans: the GPU loops visit only the covered pixels of each row
// of a medium-sized sub-triangle, where the reference tests every pixel of its box with covers().
// Tests check that both give the same pixels.
#ifndef PHONGVK_ROW_SPANS_H
#define PHONGVK_ROW_SPANS_H

#include "glsl_cpp.h"
#include "shared.h"
#include "edges.h"

SHARED_BEGIN

// Narrows [span.x, span.y] to the pixels x of row y where edge from -> to (relative to `origin`)
// passes: E(x) + bias >= 0 with E(x) = c - k x, k = 256 dy. The bound is estimated with one float
// division and then made exact with integer tests (64-bit integer division is slow on SIMD CPUs,
// and the 32-bit key path has none), so the span holds exactly the pixels covers() accepts.
FN ivec2 clipSpanToEdge(ivec2 span, ivec2 from, ivec2 to, int bias, int y, ivec2 origin) {
  int dy = to.y - from.y;
  EdgeInt c = edgeAdd(edgeAt(from, to, pixelCentre(0, y) - origin), edgeInt(bias));
  if (dy == 0) return !edgeNegative(c) ? span : ivec2(1, 0);
  float estimate = floor(edgeEstimate(c) / (float(dy) * float(SUBPIXEL_ONE)));
  if (dy > 0) {  // passes for x <= c / k: find the last such x in the span
    int q = int(clamp(estimate, float(span.x - 1), float(span.y)));
    while (q >= span.x && edgeLess(c, edgePixels(dy, q))) --q;
    while (q < span.y && !edgeLess(c, edgePixels(dy, q + 1))) ++q;
    return ivec2(span.x, q);
  }
  int q = int(clamp(estimate + 1.0f, float(span.x), float(span.y + 1)));  // passes for x >= c / k
  while (q <= span.y && edgeLess(c, edgePixels(dy, q))) ++q;
  while (q > span.x && !edgeLess(c, edgePixels(dy, q - 1))) --q;
  return ivec2(q, span.y);
}

// The pixels of row y (within the sub-triangle's box) whose centres it covers; empty if x > y.
FN ivec2 rowSpan(EdgeSetup s, int y) {
  ivec2 span = ivec2(s.bbox.x, s.bbox.z);
  span = clipSpanToEdge(span, s.v1, s.v2, s.bias0, y, s.origin);
  span = clipSpanToEdge(span, s.v2, s.v0, s.bias1, y, s.origin);
  span = clipSpanToEdge(span, s.v0, s.v1, s.bias2, y, s.origin);
  return span;
}

SHARED_END

#endif  // PHONGVK_ROW_SPANS_H
