// clip.h — clipping against the near plane and the guard band, and the frustum test that culls a
// triangle off screen (docs/DESIGN.md "Rasterization"). Shared by the GPU passes and the reference; see
// glsl_cpp.h for the dialect rules. Positions are pixel-space h = (X, Y, z_view) (phong.h),
// homogeneous with W = homogeneousW(h) (edges.h).
#ifndef PHONGVK_CLIP_H
#define PHONGVK_CLIP_H

#include "glsl_cpp.h"
#include "exact_float.h"
#include "shared.h"
#include "edges.h"

SHARED_BEGIN

// Signed distances of h to the five clip planes (inside >= 0): near, and the guard band's
// left, right, top and bottom.
FN float clipDistance(vec3 h, int plane, float nearPlane, uint projection) {
  PRECISE float g = GUARD_BAND * homogeneousW(h, projection);
  if (plane == 0) return h.z - nearPlane;
  if (plane == 1) return h.x + g;
  if (plane == 2) return g - h.x;
  if (plane == 3) return h.y + g;
  return g - h.y;
}

// The point where segment inside -> outside crosses a plane. Always computed from the inside
// end, so two triangles sharing an edge produce bit-identical points (no crack, no overlap).
// Linear in h, which is right for both projections: with a perspective one the planes pass
// through the eye, with an orthographic one h is an affine map of the view position.
FN vec3 clipIntersect(vec3 inside, vec3 outside, float dIn, float dOut) {
  PRECISE float t = divide(dIn, dIn - dOut);
  PRECISE vec3 p = inside + t * (outside - inside);
  return p;
}

// A triangle clipped against the near plane alone, the first of clipTriangle's planes, in four
// named vertices (count 0, 3 or 4). Sutherland-Hodgman's output order for one plane, [v0], [x01],
// [v1], [x12], [v2], [x20] (a vertex where it is inside, an edge's crossing where its ends
// disagree), is picked per slot with selects.
struct NearPolygon {
  vec3 p0;
  vec3 p1;
  vec3 p2;
  vec3 p3;
  int count;
};

// The crossing of edge a -> b with a plane (distances da, db of different signs), from its inside
// end.
FN vec3 edgeCrossing(vec3 a, vec3 b, float da, float db) {
  return da >= 0.0f ? clipIntersect(a, b, da, db) : clipIntersect(b, a, db, da);
}

FN NearPolygon clipNear(vec3 h0, vec3 h1, vec3 h2, float nearPlane, uint projection) {
  float d0 = clipDistance(h0, 0, nearPlane, projection);
  float d1 = clipDistance(h1, 0, nearPlane, projection);
  float d2 = clipDistance(h2, 0, nearPlane, projection);
  bool in0 = d0 >= 0.0f;
  bool in1 = d1 >= 0.0f;
  bool in2 = d2 >= 0.0f;
  vec3 x01 = edgeCrossing(h0, h1, d0, d1);
  vec3 x12 = edgeCrossing(h1, h2, d1, d2);
  vec3 x20 = edgeCrossing(h2, h0, d2, d0);
  int inside = (in0 ? 1 : 0) + (in1 ? 1 : 0) + (in2 ? 1 : 0);
  NearPolygon q;
  q.count = inside == 0 ? 0 : (inside == 2 ? 4 : 3);
  q.p0 = in0 ? h0 : (in1 ? x01 : x12);
  q.p1 = in1 ? h1 : (in0 ? x01 : h2);
  q.p2 = in1 && in2 ? h2 : ((in0 && !in1 && !in2) || (!in0 && !in1 && in2) ? x20 : x12);
  q.p3 = in0 && !in1 && in2 ? h2 : x20;
  return q;
}

// Sutherland-Hodgman against one guard-band plane: poly (count n) -> poly; returns the new count.
// Every index is a constant once the loops unroll, so a SIMD device keeps the polygon in registers
// (indexed per lane, lavapipe put it in memory and took seconds to generate the pass's code:
// docs/DECISIONS.md). The storage-array builds keep the loops, which SwiftShader's compiler took
// 35 s and more to unroll (glsl_cpp.h UNROLL_TEXELS). Each output, p_i where it is inside and the
// crossing of edge i where its ends disagree, is pushed onto the front of the result, walking the
// edges from the last, which leaves the result in Sutherland-Hodgman's order. A convex polygon
// gains at most one vertex per plane (the near plane's has at most four, so four more planes make
// at most eight); outputs past MAX_CLIP_VERTICES, which only rounding could make, are dropped from
// the end.
FN int clipAgainstPlane(INOUT_ARRAY(vec3, poly, MAX_CLIP_VERTICES), int n, int plane, float nearPlane, uint projection) {
  const int last = int(MAX_CLIP_VERTICES) - 1;
  vec3 result[MAX_CLIP_VERTICES];
  UNROLL_TEXELS for (int j = 0; j <= last; ++j) result[j] = poly[0];
  int m = 0;
  UNROLL_TEXELS for (int i = last; i >= 0; --i) {
    vec3 a = poly[i];
    vec3 b = i < last && i + 1 < n ? poly[min(i + 1, last)] : poly[0];
    float da = clipDistance(a, plane, nearPlane, projection);
    float db = clipDistance(b, plane, nearPlane, projection);
    bool edge = i < n;
    bool crosses = edge && (da >= 0.0f) != (db >= 0.0f);
    bool keeps = edge && da >= 0.0f;
    vec3 x = crosses ? edgeCrossing(a, b, da, db) : a;
    UNROLL_TEXELS for (int j = last; j > 0; --j) result[j] = crosses ? result[j - 1] : result[j];
    result[0] = crosses ? x : result[0];
    UNROLL_TEXELS for (int j = last; j > 0; --j) result[j] = keeps ? result[j - 1] : result[j];
    result[0] = keeps ? a : result[0];
    m += (crosses ? 1 : 0) + (keeps ? 1 : 0);
  }
  UNROLL_TEXELS for (int j = 0; j <= last; ++j) poly[j] = result[j];
  return min(m, last + 1);
}

// Clips triangle h0 h1 h2 to the near plane and guard band. Returns the vertex count of the
// convex polygon left in poly (0 when nothing is in front of the near plane): the near plane's
// polygon (clipNear), then Sutherland-Hodgman against the guard band's four planes in turn, in a
// loop that stays a loop (one copy of the step: a quarter of the code to generate).
FN int clipTriangle(vec3 h0, vec3 h1, vec3 h2, float nearPlane, uint projection, OUT_ARRAY(vec3, poly, MAX_CLIP_VERTICES)) {
  NearPolygon q = clipNear(h0, h1, h2, nearPlane, projection);
  UNROLL for (int j = 0; j < int(MAX_CLIP_VERTICES); ++j) poly[j] = q.p0;
  poly[1] = q.p1;
  poly[2] = q.p2;
  poly[3] = q.p3;
  int n = q.count;
  DONT_UNROLL for (int plane = 1; plane < 5; ++plane) n = clipAgainstPlane(poly, n, plane, nearPlane, projection);
  return n < 3 ? 0 : n;
}

// True when the whole triangle is outside one of the view frustum's planes (off screen, behind
// the near plane or beyond the far plane): it cannot cover a pixel. Valid for any sign of W. The
// image spans -lo .. hi about the principal point (lo = hi for a centred one: exact in float).
FN bool outsideFrustum(vec3 h0, vec3 h1, vec3 h2, FrameData frame) {
  vec2 lo = frame.principal;
  PRECISE vec2 hi = vec2(float(frame.width), float(frame.height)) - frame.principal;
  for (int plane = 0; plane < 6; ++plane) {
    bool allOut = true;
    for (int i = 0; i < 3; ++i) {
      vec3 h = i == 0 ? h0 : (i == 1 ? h1 : h2);
      float w = homogeneousW(h, frame.projection);
      PRECISE float d;
      if (plane == 0) d = h.z - frame.nearPlane;
      else if (plane == 1) d = frame.farPlane - h.z;
      else if (plane == 2) d = h.x + lo.x * w;
      else if (plane == 3) d = hi.x * w - h.x;
      else if (plane == 4) d = h.y + lo.y * w;
      else d = hi.y * w - h.y;
      allOut = allOut && d < 0.0f;
    }
    if (allOut) return true;
  }
  return false;
}

// True when vertex h is outside none of the five planes (no clipDistance below 0).
FN bool insidePlanes(vec3 h, float nearPlane, uint projection) {
  return !(clipDistance(h, 0, nearPlane, projection) < 0.0f || clipDistance(h, 1, nearPlane, projection) < 0.0f ||
           clipDistance(h, 2, nearPlane, projection) < 0.0f || clipDistance(h, 3, nearPlane, projection) < 0.0f ||
           clipDistance(h, 4, nearPlane, projection) < 0.0f);
}

// True when no vertex is outside the near plane or the guard band: the polygon is the triangle.
// Spelled out plane by plane, not as a loop over the planes with an early return: the triangle
// pass asks it of every triangle, and lavapipe ran that loop for real, 5 masked trips per SIMD
// batch with its state spilled: a measurable share of a frame of small triangles
// (docs/PERFORMANCE.md, "Raster").
FN bool insideClipVolume(vec3 h0, vec3 h1, vec3 h2, float nearPlane, uint projection) {
  return insidePlanes(h0, nearPlane, projection) && insidePlanes(h1, nearPlane, projection) &&
         insidePlanes(h2, nearPlane, projection);
}

SHARED_END

#endif  // PHONGVK_CLIP_H
