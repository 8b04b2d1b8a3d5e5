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
// division and then made exact with integer tests (64-bit integer division is slow on SIMD CPUs),
// so the span holds exactly the pixels covers() accepts. Everything is taken to 64 bits first:
// differences taken in 32 bits and then widened gave lavapipe other spans (fig3's sphere).
FN ivec2 clipSpanToEdge(ivec2 span, ivec2 from, ivec2 to, int bias, int y, ivec2 origin) {
  i64vec2 a = i64vec2(from);
  i64vec2 b = i64vec2(to);
  int64_t dx = b.x - a.x;
  int64_t dy = b.y - a.y;
  i64vec2 p = pixelCentre(0, y) - i64vec2(origin);
  int64_t c = dx * (p.y - a.y) - dy * (p.x - a.x) + int64_t(bias);
  int64_t k = dy * int64_t(SUBPIXEL_ONE);
  if (dy == int64_t(0)) return c >= int64_t(0) ? span : ivec2(1, 0);
  float estimate = floor(float(c) / float(k));
  if (dy > int64_t(0)) {  // passes for x <= c / k: find the last such x in the span
    int q = int(clamp(estimate, float(span.x - 1), float(span.y)));
    while (q >= span.x && c - k * int64_t(q) < int64_t(0)) --q;
    while (q < span.y && c - k * int64_t(q + 1) >= int64_t(0)) ++q;
    return ivec2(span.x, q);
  }
  int q = int(clamp(estimate + 1.0f, float(span.x), float(span.y + 1)));  // passes for x >= c / k
  while (q <= span.y && c - k * int64_t(q) < int64_t(0)) ++q;
  while (q > span.x && c - k * int64_t(q - 1) >= int64_t(0)) --q;
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
