// raster.h — triangle setup, coverage, depth key and Gouraud interpolation (DESIGN.md
// "Rasterization", "Visibility", "Gouraud"). Shared by the raster/resolve shaders and the C++
// reference; see glsl_cpp.h for the dialect rules.
//
// Coordinates: a vertex's homogeneous pixel-space position h = (X, Y, W) (phong.h). Its screen
// position is principal + h.xy / W, y down. Pixel (x, y) has its centre at (x + 0.5, y + 0.5),
// i.e. at p = (x + 0.5 - cx, y + 0.5 - cy, 1) in the same frame as h.
//
// Coverage uses the triangle clipped against the near plane (and a far guard band), snapped to
// 1/256 pixel, with integer edge functions and the top-left rule. Depth and colour use the
// original triangle's plane: the ray through the pixel centre meets it at view depth
// z = dot(h0, n) / dot(p, n), n = (h1 - h0) x (h2 - h0); the same quantities give
// perspective-correct barycentrics. No w <= 0 is ever divided by.
#ifndef PHONGVK_RASTER_H
#define PHONGVK_RASTER_H

#include "glsl_cpp.h"
#include "exact_float.h"
#include "phong.h"
#include "shared.h"

SHARED_BEGIN

// ---- Clipping ----

// Signed distances of h to the five clip planes (inside >= 0): near, and the guard band's
// left, right, top and bottom.
FN float clipDistance(vec3 h, int plane, float nearPlane) {
  PRECISE float g = GUARD_BAND * h.z;
  if (plane == 0) return h.z - nearPlane;
  if (plane == 1) return h.x + g;
  if (plane == 2) return g - h.x;
  if (plane == 3) return h.y + g;
  return g - h.y;
}

// The point where segment inside -> outside crosses a plane. Always computed from the inside
// end, so two triangles sharing an edge produce bit-identical points (no crack, no overlap).
FN vec3 clipIntersect(vec3 inside, vec3 outside, float dIn, float dOut) {
  PRECISE float t = divide(dIn, dIn - dOut);
  PRECISE vec3 p = inside + t * (outside - inside);
  return p;
}

// Sutherland-Hodgman against one plane: poly (count n) -> result; returns the new count.
FN int clipAgainstPlane(INOUT_ARRAY(vec3, poly, MAX_CLIP_VERTICES), int n, int plane, float nearPlane) {
  vec3 result[MAX_CLIP_VERTICES];
  int m = 0;
  for (int i = 0; i < n; ++i) {
    vec3 a = poly[i];
    vec3 b = poly[(i + 1) % n];
    float da = clipDistance(a, plane, nearPlane);
    float db = clipDistance(b, plane, nearPlane);
    if (da >= 0.0f) result[m++] = a;
    if ((da >= 0.0f) != (db >= 0.0f)) {
      result[m++] = da >= 0.0f ? clipIntersect(a, b, da, db) : clipIntersect(b, a, db, da);
    }
  }
  for (int i = 0; i < m; ++i) poly[i] = result[i];
  return m;
}

// Clips triangle h0 h1 h2 to the near plane and guard band. Returns the vertex count of the
// convex polygon left in poly (0 when nothing is in front of the near plane).
FN int clipTriangle(vec3 h0, vec3 h1, vec3 h2, float nearPlane, OUT_ARRAY(vec3, poly, MAX_CLIP_VERTICES)) {
  poly[0] = h0;
  poly[1] = h1;
  poly[2] = h2;
  int n = 3;
  for (int plane = 0; plane < 5 && n > 0; ++plane) {
    bool allInside = true;
    for (int i = 0; i < n; ++i) allInside = allInside && clipDistance(poly[i], plane, nearPlane) >= 0.0f;
    if (!allInside) n = clipAgainstPlane(poly, n, plane, nearPlane);
  }
  return n < 3 ? 0 : n;
}

// True when the whole triangle is outside one of the view frustum's planes (off screen, behind
// the near plane or beyond the far plane): it cannot cover a pixel. Valid for any sign of W.
FN bool outsideFrustum(vec3 h0, vec3 h1, vec3 h2, FrameData frame) {
  vec3 lim = vec3(frame.principal.x, frame.principal.y, 0.0f);
  for (int plane = 0; plane < 6; ++plane) {
    bool allOut = true;
    for (int i = 0; i < 3; ++i) {
      vec3 h = i == 0 ? h0 : (i == 1 ? h1 : h2);
      PRECISE float d;
      if (plane == 0) d = h.z - frame.nearPlane;
      else if (plane == 1) d = frame.farPlane - h.z;
      else if (plane == 2) d = h.x + lim.x * h.z;
      else if (plane == 3) d = lim.x * h.z - h.x;
      else if (plane == 4) d = h.y + lim.y * h.z;
      else d = lim.y * h.z - h.y;
      allOut = allOut && d < 0.0f;
    }
    if (allOut) return true;
  }
  return false;
}

// ---- Snapping and edge functions ----

// Screen position in 1/256 pixel units, rounded to nearest (ties up). W >= near here, and h is
// inside the guard band, so the result is below 2^28 in magnitude: an int holds it exactly (and
// a SIMD CPU converts to 32-bit integers natively, to 64-bit lane by lane).
FN ivec2 snapToSubpixel(vec3 h, vec2 principal) {
  PRECISE float sx = (divide(h.x, h.z) + principal.x) * float(SUBPIXEL_ONE) + 0.5f;
  PRECISE float sy = (divide(h.y, h.z) + principal.y) * float(SUBPIXEL_ONE) + 0.5f;
  return ivec2(int(floor(sx)), int(floor(sy)));
}

// Twice the signed area of a b p in subpixel units; > 0 when p is inside a clockwise-on-screen
// (y down) oriented edge a -> b.
FN int64_t edgeFunction(i64vec2 a, i64vec2 b, i64vec2 p) {
  return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

// Top-left rule for triangles oriented so edge functions are positive inside (y down): a top edge
// is horizontal with the inside below it, a left edge goes up. Pixels exactly on such an edge
// are covered; on any other edge they are not. Returned as the bias added before the >= 0 test.
FN int64_t topLeftBias(i64vec2 a, i64vec2 b) {
  int64_t dx = b.x - a.x;
  int64_t dy = b.y - a.y;
  bool topLeft = (dy == int64_t(0) && dx > int64_t(0)) || dy < int64_t(0);
  return topLeft ? int64_t(0) : int64_t(-1);
}

// A snapped sub-triangle ready to rasterize: vertices oriented so that inside is positive,
// per-edge top-left biases, and its pixel bounding box clipped to the image (x0 > x1 if empty).
struct EdgeSetup {
  i64vec2 v0;
  i64vec2 v1;
  i64vec2 v2;
  int64_t bias0;
  int64_t bias1;
  int64_t bias2;
  ivec4 bbox;  // x0, y0, x1, y1 inclusive
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

// Sets up sub-triangle a b c. frontFacing says which screen orientation the whole triangle has;
// a sub-triangle whose snapped orientation disagrees (snapping flipped a sliver) or whose snapped
// area is zero covers nothing and is rejected (returns false), as is one covering no pixel centre
// of the image's bounding box.
FN bool setupEdges(i64vec2 a, i64vec2 b, i64vec2 c, bool frontFacing, uint width, uint height, OUT(EdgeSetup) s) {
  int64_t area = edgeFunction(a, b, c);
  if (area == int64_t(0) || (area < int64_t(0)) != frontFacing) return false;
  s.v0 = a;
  s.v1 = frontFacing ? c : b;  // front faces are counter-clockwise on a y-down screen: flip them
  s.v2 = frontFacing ? b : c;
  s.bias0 = topLeftBias(s.v1, s.v2);
  s.bias1 = topLeftBias(s.v2, s.v0);
  s.bias2 = topLeftBias(s.v0, s.v1);
  s.bbox = pixelBounds(ivec2(min(a, min(b, c))), ivec2(max(a, max(b, c))), width, height);
  return !isEmpty(s.bbox);
}

// The subpixel position of pixel (x, y)'s centre.
FN i64vec2 pixelCentre(int x, int y) {
  return i64vec2(int64_t(x) * int64_t(SUBPIXEL_ONE) + int64_t(SUBPIXEL_HALF),
                 int64_t(y) * int64_t(SUBPIXEL_ONE) + int64_t(SUBPIXEL_HALF));
}

FN bool covers(EdgeSetup s, i64vec2 p) {
  return edgeFunction(s.v1, s.v2, p) + s.bias0 >= int64_t(0) &&
         edgeFunction(s.v2, s.v0, p) + s.bias1 >= int64_t(0) &&
         edgeFunction(s.v0, s.v1, p) + s.bias2 >= int64_t(0);
}

// ---- Row spans (the GPU's loops visit only these; the reference checks every box pixel) ----

// Narrows [span.x, span.y] to the pixels x of row y where edge a -> b passes: E(x) + bias >= 0
// with E(x) = c - k x, k = 256 dy. The bound is estimated with one float division and then made
// exact with integer tests (64-bit integer division is slow on SIMD CPUs), so the span holds
// exactly the pixels covers() accepts.
FN ivec2 clipSpanToEdge(ivec2 span, i64vec2 a, i64vec2 b, int64_t bias, int y) {
  int64_t dx = b.x - a.x;
  int64_t dy = b.y - a.y;
  i64vec2 p = pixelCentre(0, y);
  int64_t c = dx * (p.y - a.y) - dy * (p.x - a.x) + bias;
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
  span = clipSpanToEdge(span, s.v1, s.v2, s.bias0, y);
  span = clipSpanToEdge(span, s.v2, s.v0, s.bias1, y);
  span = clipSpanToEdge(span, s.v0, s.v1, s.bias2, y);
  return span;
}

// ---- 32-bit edges for small triangles (the GPU's triangle pass) ----
// A sub-triangle whose snapped extent is below SMALL_EXTENT subpixels in x and y has edge functions
// that, taken relative to its own corner, fit 32-bit integers exactly (|dx|, |dy|, |p - a| < 2^14,
// products < 2^28): the same values, signs and spans as the 64-bit setup above, without 64-bit
// arithmetic, which SIMD CPUs (lavapipe) emulate. The reference uses the 64-bit code; tests check
// that both give the same spans.
// 16 pixels since session 5 (was 32): a box of at most 256 pixels, the clip pass's
// SMALL_TRIANGLE_MAX_PIXELS, instead of up to 1024 tested one invocation each; a 2x2 grid of
// spheres of ~200-pixel triangles -20%, nothing measured slower.
PHONGVK_CONST int SMALL_EXTENT = 4096;  // subpixels: 16 pixels

struct EdgeSetup32 {
  ivec2 v0;      // relative to origin, oriented so that inside is positive
  ivec2 v1;
  ivec2 v2;
  int bias0;
  int bias1;
  int bias2;
  ivec4 bbox;    // pixels, clipped to the image (as EdgeSetup's)
  ivec2 origin;  // subpixels: the sub-triangle's lower corner
};

FN int edgeFunction32(ivec2 a, ivec2 b, ivec2 p) { return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x); }

FN int topLeftBias32(ivec2 a, ivec2 b) {
  int dx = b.x - a.x;
  int dy = b.y - a.y;
  return (dy == 0 && dx > 0) || dy < 0 ? 0 : -1;
}

FN bool fitsSmallEdges(ivec2 a, ivec2 b, ivec2 c) {
  ivec2 extent = max(a, max(b, c)) - min(a, min(b, c));
  return extent.x < SMALL_EXTENT && extent.y < SMALL_EXTENT;
}

// setupEdges in 32 bits, for a sub-triangle that fitsSmallEdges.
FN bool setupEdges32(ivec2 a, ivec2 b, ivec2 c, bool frontFacing, uint width, uint height, OUT(EdgeSetup32) s) {
  s.origin = min(a, min(b, c));
  ivec2 ra = a - s.origin;
  ivec2 rb = b - s.origin;
  ivec2 rc = c - s.origin;
  int area = edgeFunction32(ra, rb, rc);
  if (area == 0 || (area < 0) != frontFacing) return false;
  s.v0 = ra;
  s.v1 = frontFacing ? rc : rb;
  s.v2 = frontFacing ? rb : rc;
  s.bias0 = topLeftBias32(s.v1, s.v2);
  s.bias1 = topLeftBias32(s.v2, s.v0);
  s.bias2 = topLeftBias32(s.v0, s.v1);
  s.bbox = pixelBounds(s.origin, max(a, max(b, c)), width, height);
  return !isEmpty(s.bbox);
}

// covers() in 32 bits: whether pixel (x, y)'s centre is inside the small sub-triangle. The
// triangle pass tests every pixel of a small triangle's box (as the reference does with covers()):
// cheaper on lavapipe than row spans, whose per-edge division and search loops every lane runs.
FN bool covers32(EdgeSetup32 s, int x, int y) {
  ivec2 p = ivec2(x * SUBPIXEL_ONE + SUBPIXEL_HALF, y * SUBPIXEL_ONE + SUBPIXEL_HALF) - s.origin;
  return edgeFunction32(s.v1, s.v2, p) + s.bias0 >= 0 && edgeFunction32(s.v2, s.v0, p) + s.bias1 >= 0 &&
         edgeFunction32(s.v0, s.v1, p) + s.bias2 >= 0;
}

// ---- Depth and visibility key ----

// The triangle's plane in pixel space: n = (h1 - h0) x (h2 - h0) and dot(h0, n). dot(h0, n) < 0
// exactly when the triangle faces the eye (counter-clockwise seen from outside).
struct TrianglePlane {
  vec3 n;
  float h0n;
};

FN TrianglePlane trianglePlane(vec3 h0, vec3 h1, vec3 h2) {
  TrianglePlane t;
  t.n = cross3(h1 - h0, h2 - h0);
  t.h0n = dot3(h0, t.n);
  return t;
}

// The pixel centre as a ray direction in pixel space: (x + 0.5 - cx, y + 0.5 - cy, 1).
FN vec3 pixelRay(int x, int y, vec2 principal) {
  PRECISE vec3 p = vec3(float(x) + 0.5f - principal.x, float(y) + 0.5f - principal.y, 1.0f);
  return p;
}

// View depth where the pixel's ray meets the triangle's plane.
FN float depthAt(TrianglePlane t, vec3 p) {
  PRECISE float z = divide(t.h0n, dot3(p, t.n));
  return z;
}

PHONGVK_CONST uint64_t KEY_CLEAR = 0xFFFFFFFFFFFFFFFFul;
// A resolved pixel's final colour kept in its key slot (FrameData.colorsInKeys): this tag above,
// the packed RGBA8 below. The tag's upper word is a NaN's bits, so no depth key reaches it: every
// slot at or above the tag (KEY_CLEAR included) holds no key, and a pass skips it.
PHONGVK_CONST uint64_t KEY_COLOR_TAG = 0xFFFFFFFE00000000ul;

FN uint64_t colorSlot(uint color) { return KEY_COLOR_TAG | uint64_t(color); }

// The 64-bit visibility key: depth's float bits above, the triangle id below; the smallest key
// wins a pixel, so equal depths go to the lower triangle id. The depth is held to the depth range
// [zMin, zMax] of the clipped polygon: a pixel centre covered only thanks to snapping must not
// extrapolate an edge-on plane to a depth in front of the eye (or to NaN, which goes to zMin).
// Returns KEY_CLEAR for a fragment beyond the far plane.
FN uint64_t depthKey(float z, float zMin, float zMax, float farPlane, uint triangle) {
  float depth = z >= zMin ? (z <= zMax ? z : zMax) : zMin;
  if (depth > farPlane) return KEY_CLEAR;
  return (uint64_t(floatBitsToUint(depth)) << 32) | uint64_t(triangle);
}

// ---- One triangle, start to finish ----

// Everything the raster loops need from one triangle: its clipped polygon snapped to subpixels,
// facing, depth range and plane, and the pixel bounding box of the whole polygon. (Large
// triangles are stored for resolve as the smaller LargeTriangle.)
struct TriangleSetup {
  ivec2 snapped[MAX_CLIP_VERTICES];  // subpixels; the guard band keeps them below 2^28
  ivec4 bbox;
  TrianglePlane plane;
  int count;          // polygon vertices; sub-triangles are the fan (0, k + 1, k + 2)
  uint frontFacing;   // 1 when the triangle faces the eye
  float zMin;
  float zMax;
  uint triangle;      // its id: the low word of its visibility keys
};

// True when vertex h is outside none of the five planes (no clipDistance below 0).
FN bool insidePlanes(vec3 h, float nearPlane) {
  return !(clipDistance(h, 0, nearPlane) < 0.0f || clipDistance(h, 1, nearPlane) < 0.0f ||
           clipDistance(h, 2, nearPlane) < 0.0f || clipDistance(h, 3, nearPlane) < 0.0f ||
           clipDistance(h, 4, nearPlane) < 0.0f);
}

// True when no vertex is outside the near plane or the guard band: the polygon is the triangle.
// Spelled out plane by plane, not as a loop over the planes with an early return: the triangle
// pass asks it of every triangle, and lavapipe ran that loop for real, 5 masked trips per SIMD
// batch with its state spilled (~7% of a 1M-triangle frame).
FN bool insideClipVolume(vec3 h0, vec3 h1, vec3 h2, float nearPlane) {
  return insidePlanes(h0, nearPlane) && insidePlanes(h1, nearPlane) && insidePlanes(h2, nearPlane);
}

// The rest of setupTriangle for a triangle that needs no clipping (nearly all of them): the same
// operations in the same order as the general path, but only constant indices, so a SIMD CPU
// keeps everything in registers instead of per-lane arrays in memory.
FN bool setupUnclipped(vec3 h0, vec3 h1, vec3 h2, FrameData frame, INOUT(TriangleSetup) t) {
  t.count = 3;
  t.zMin = min(min(h0.z, h1.z), h2.z);
  t.zMax = max(max(h0.z, h1.z), h2.z);
  ivec2 v0 = snapToSubpixel(h0, frame.principal);
  ivec2 v1 = snapToSubpixel(h1, frame.principal);
  ivec2 v2 = snapToSubpixel(h2, frame.principal);
  t.snapped[0] = v0;
  t.snapped[1] = v1;
  t.snapped[2] = v2;
  t.bbox = pixelBounds(min(min(v0, v1), v2), max(max(v0, v1), v2), frame.width, frame.height);
  return !isEmpty(t.bbox);
}

// The part of the setup every triangle goes through: culled off screen, edge-on or zero area, or
// as the back face of a closed object (false: draws nothing); otherwise its plane and facing.
FN bool setupPlane(vec3 h0, vec3 h1, vec3 h2, bool cullBack, uint triangle, FrameData frame, OUT(TriangleSetup) t) {
  if (outsideFrustum(h0, h1, h2, frame)) return false;
  t.plane = trianglePlane(h0, h1, h2);
  if (t.plane.h0n == 0.0f) return false;
  t.frontFacing = t.plane.h0n < 0.0f ? 1u : 0u;
  if (cullBack && t.frontFacing == 0u) return false;
  t.triangle = triangle;
  return true;
}

// The rest of the setup for a triangle that crosses the near plane or the guard band: clip, snap
// the polygon. False when nothing is left in front of the near plane or no pixel centre is in the
// bounding box. (The GPU runs this in a pass of its own, clip_triangles.comp: on SIMD CPUs its
// per-lane arrays slow down every triangle of a pass that merely contains them.)
FN bool setupClipped(vec3 h0, vec3 h1, vec3 h2, FrameData frame, INOUT(TriangleSetup) t) {
  vec3 poly[MAX_CLIP_VERTICES];
  t.count = clipTriangle(h0, h1, h2, frame.nearPlane, poly);
  if (t.count == 0) return false;
  t.zMin = poly[0].z;
  t.zMax = poly[0].z;
  ivec2 lo = snapToSubpixel(poly[0], frame.principal);
  ivec2 hi = lo;
  t.snapped[0] = lo;
  for (int i = 1; i < t.count; ++i) {
    t.zMin = min(t.zMin, poly[i].z);
    t.zMax = max(t.zMax, poly[i].z);
    ivec2 v = snapToSubpixel(poly[i], frame.principal);
    t.snapped[i] = v;
    lo = min(lo, v);
    hi = max(hi, v);
  }
  t.bbox = pixelBounds(lo, hi, frame.width, frame.height);
  return !isEmpty(t.bbox);
}

// Culls, clips and snaps a triangle for rasterization. False: it draws nothing.
FN bool setupTriangle(vec3 h0, vec3 h1, vec3 h2, bool cullBack, uint triangle, FrameData frame, OUT(TriangleSetup) t) {
  if (!setupPlane(h0, h1, h2, cullBack, triangle, frame, t)) return false;
  if (insideClipVolume(h0, h1, h2, frame.nearPlane)) return setupUnclipped(h0, h1, h2, frame, t);
  return setupClipped(h0, h1, h2, frame, t);
}

FN int boxPixels(ivec4 box) { return (box.z - box.x + 1) * (box.w - box.y + 1); }

// Fan sub-triangle k of a clipped polygon as a triangle setup of its own (same plane, depth range
// and id; its own box), so later passes only ever see count == 3 and index constantly.
FN TriangleSetup fanTriangle(TriangleSetup t, int k, FrameData frame) {
  TriangleSetup sub = t;
  sub.count = 3;
  sub.snapped[1] = t.snapped[k + 1];
  sub.snapped[2] = t.snapped[k + 2];
  ivec2 a = sub.snapped[0];
  ivec2 b = sub.snapped[1];
  ivec2 c = sub.snapped[2];
  sub.bbox = pixelBounds(min(a, min(b, c)), max(a, max(b, c)), frame.width, frame.height);
  return sub;
}

// The only sub-triangle of an unclipped triangle (count == 3), with constant indices.
FN bool setupSingle(TriangleSetup t, FrameData frame, OUT(EdgeSetup) s) {
  return setupEdges(i64vec2(t.snapped[0]), i64vec2(t.snapped[1]), i64vec2(t.snapped[2]), t.frontFacing != 0u,
                    frame.width, frame.height, s);
}

// Sub-triangle k (0 <= k < count - 2) of a set-up triangle's fan.
FN bool setupFan(TriangleSetup t, int k, FrameData frame, OUT(EdgeSetup) s) {
  return setupEdges(i64vec2(t.snapped[0]), i64vec2(t.snapped[k + 1]), i64vec2(t.snapped[k + 2]),
                    t.frontFacing != 0u, frame.width, frame.height, s);
}

// The key a triangle with this plane, depth range and id offers pixel (x, y), which it covers.
FN uint64_t planeKey(TrianglePlane plane, float zMin, float zMax, uint triangle, int x, int y, FrameData frame) {
  float z = depthAt(plane, pixelRay(x, y, frame.principal));
  return depthKey(z, zMin, zMax, frame.farPlane, triangle);
}

FN uint64_t coveredKey(TriangleSetup t, int x, int y, FrameData frame) {
  return planeKey(t.plane, t.zMin, t.zMax, t.triangle, x, y, frame);
}

// ---- Large triangles, a block of pixels at a time (the GPU's resolve pass) ----

// What resolve needs of a large sub-triangle, set up once by the triangle or clip pass (std430,
// 80 bytes): its oriented vertices and edge biases (EdgeSetup in 32 bits: snapped coordinates
// stay below 2^28), box, plane, depth range and id.
struct LargeTriangle {
  ivec4 bbox;
  TrianglePlane plane;
  ivec2 v0;
  ivec2 v1;
  ivec2 v2;
  int bias0;
  int bias1;
  int bias2;
  float zMin;
  float zMax;
  uint triangle;
};

FN LargeTriangle largeTriangle(TriangleSetup t, EdgeSetup s) {
  LargeTriangle l;
  l.bbox = s.bbox;
  l.plane = t.plane;
  l.v0 = ivec2(s.v0);
  l.v1 = ivec2(s.v1);
  l.v2 = ivec2(s.v2);
  l.bias0 = int(s.bias0);
  l.bias1 = int(s.bias1);
  l.bias2 = int(s.bias2);
  l.zMin = t.zMin;
  l.zMax = t.zMax;
  l.triangle = t.triangle;
  return l;
}

// The three edge functions (plus biases) at the centre of pixel `origin`, the first of a block.
struct BlockEdges {
  int64_t e0;
  int64_t e1;
  int64_t e2;
};

FN BlockEdges blockEdges(LargeTriangle t, ivec2 origin) {
  i64vec2 p = pixelCentre(origin.x, origin.y);
  BlockEdges e;
  e.e0 = edgeFunction(i64vec2(t.v1), i64vec2(t.v2), p) + int64_t(t.bias0);
  e.e1 = edgeFunction(i64vec2(t.v2), i64vec2(t.v0), p) + int64_t(t.bias1);
  e.e2 = edgeFunction(i64vec2(t.v0), i64vec2(t.v1), p) + int64_t(t.bias2);
  return e;
}

// Edge a -> b's function at pixel origin + (i, j), from its value e there: one pixel right adds
// 256 (a.y - b.y), one down 256 (b.x - a.x). Exact, so it equals edgeFunction at that centre.
FN int64_t edgeStep(ivec2 a, ivec2 b, int64_t e, int i, int j) {
  return e + int64_t(a.y - b.y) * int64_t(SUBPIXEL_ONE * i) + int64_t(b.x - a.x) * int64_t(SUBPIXEL_ONE * j);
}

// How a block relates to a large triangle's pixel centres: none covered, some may be, all covered.
PHONGVK_CONST int BLOCK_OUTSIDE = 0;
PHONGVK_CONST int BLOCK_PARTIAL = 1;
PHONGVK_CONST int BLOCK_INSIDE = 2;

// One edge over the size x size block at pixel `origin`: the function is affine, so its extremes
// are at the corner pixels, reached by stepping from e.
FN int classifyEdge(ivec2 a, ivec2 b, int64_t e, int size) {
  int64_t right = edgeStep(a, b, int64_t(0), size - 1, 0);
  int64_t down = edgeStep(a, b, int64_t(0), 0, size - 1);
  int64_t lo = e + min(right, int64_t(0)) + min(down, int64_t(0));
  int64_t hi = e + max(right, int64_t(0)) + max(down, int64_t(0));
  if (hi < int64_t(0)) return BLOCK_OUTSIDE;
  return lo >= int64_t(0) ? BLOCK_INSIDE : BLOCK_PARTIAL;
}

// BLOCK_INSIDE: covers() holds at every pixel centre of the size x size block at `origin` (which
// may reach past the image); BLOCK_OUTSIDE: at none (within the image); else test each pixel.
FN int classifyBlock(LargeTriangle t, BlockEdges e, ivec2 origin, int size) {
  if (origin.x > t.bbox.z || origin.x + size - 1 < t.bbox.x || origin.y > t.bbox.w || origin.y + size - 1 < t.bbox.y) {
    return BLOCK_OUTSIDE;
  }
  int c0 = classifyEdge(t.v1, t.v2, e.e0, size);
  int c1 = classifyEdge(t.v2, t.v0, e.e1, size);
  int c2 = classifyEdge(t.v0, t.v1, e.e2, size);
  return min(c0, min(c1, c2));
}

// The tiles of the bin at pixel `origin` where the triangle may cover a pixel centre (x): bit
// j * BIN_TILES + i for tile (i, j) unless classifyBlock calls it outside, 0 for none; and those
// it owns (y): every pixel centre of the tile covered (BLOCK_INSIDE) and no depth of the triangle
// past the far plane, so wherever nothing else reaches such a tile the triangle wins each of its
// pixels without a depth test (resolve_large.comp). Unrolled: lavapipe counts every loop
// iteration against one invocation's budget (bindings.glsl checkLoopBudget), and 16 of them per
// bin of a triangle across a 4K image's 8160 bins pass it.
FN uvec2 binTileMasks(LargeTriangle t, ivec2 origin, float farPlane) {
  BlockEdges e = blockEdges(t, origin);
  uvec2 masks = uvec2(0u);
  UNROLL for (int j = 0; j < int(BIN_TILES); ++j) {
    UNROLL for (int i = 0; i < int(BIN_TILES); ++i) {
      ivec2 step = ivec2(i, j) * int(TILE_SIZE);
      BlockEdges tile;
      tile.e0 = edgeStep(t.v1, t.v2, e.e0, step.x, step.y);
      tile.e1 = edgeStep(t.v2, t.v0, e.e1, step.x, step.y);
      tile.e2 = edgeStep(t.v0, t.v1, e.e2, step.x, step.y);
      int block = classifyBlock(t, tile, origin + step, int(TILE_SIZE));
      uint bit = 1u << uint(j * int(BIN_TILES) + i);
      if (block != BLOCK_OUTSIDE) masks.x |= bit;
      if (block == BLOCK_INSIDE) masks.y |= bit;
    }
  }
  if (!(t.zMax <= farPlane)) masks.y = 0u;
  return masks;
}

// The edge values walking down column i of a block: at the current row (starting at row 0), and
// what one row down adds. Integer steps, so each row's values are exactly edgeFunction's there.
struct ColumnEdges {
  BlockEdges at;
  BlockEdges down;
};

FN ColumnEdges columnEdges(LargeTriangle t, BlockEdges e, int i) {
  ColumnEdges c;
  c.at.e0 = edgeStep(t.v1, t.v2, e.e0, i, 0);
  c.at.e1 = edgeStep(t.v2, t.v0, e.e1, i, 0);
  c.at.e2 = edgeStep(t.v0, t.v1, e.e2, i, 0);
  c.down.e0 = edgeStep(t.v1, t.v2, int64_t(0), 0, 1);
  c.down.e1 = edgeStep(t.v2, t.v0, int64_t(0), 0, 1);
  c.down.e2 = edgeStep(t.v0, t.v1, int64_t(0), 0, 1);
  return c;
}

FN bool columnCovers(ColumnEdges c) {
  return c.at.e0 >= int64_t(0) && c.at.e1 >= int64_t(0) && c.at.e2 >= int64_t(0);
}

FN ColumnEdges nextRow(ColumnEdges c) {
  c.at.e0 += c.down.e0;
  c.at.e1 += c.down.e1;
  c.at.e2 += c.down.e2;
  return c;
}

// The key the triangle offers pixel (x, y), or KEY_CLEAR if it does not cover it.
FN uint64_t fragmentKey(TriangleSetup t, EdgeSetup s, int x, int y, FrameData frame) {
  if (!covers(s, pixelCentre(x, y))) return KEY_CLEAR;
  return coveredKey(t, x, y, frame);
}

// ---- Gouraud ----

// What Gouraud interpolation needs of one triangle, whatever the pixel: the plane normal n, the
// planes whose dot with the pixel ray give the barycentrics of vertices 1 and 2 (up to a common
// factor), the vertex colours as c0 + b1 dc1 + b2 dc2, and for screen-space interpolation
// dot(h0, n) and the vertices' W.
struct GouraudTriangle {
  vec3 n;
  float det;
  vec3 u1;
  float w1;
  vec3 u2;
  float w2;
  vec3 c0;
  vec3 dc1;
  vec3 dc2;
};

FN GouraudTriangle gouraudTriangle(ShadedVertex a, ShadedVertex b, ShadedVertex c) {
  vec3 h0 = vec3(a.hpos);
  vec3 h1 = vec3(b.hpos);
  vec3 h2 = vec3(c.hpos);
  PRECISE vec3 e1 = h1 - h0;
  PRECISE vec3 e2 = h2 - h0;
  GouraudTriangle g;
  g.n = cross3(e1, e2);
  g.det = dot3(h0, g.n);
  g.u1 = cross3(e2, h0);  // dot(p, u1) is proportional to the barycentric of vertex 1
  g.u2 = cross3(h0, e1);  // ... of vertex 2
  g.w1 = h1.z;
  g.w2 = h2.z;
  g.c0 = vec3(a.color);
  PRECISE vec3 dc1 = vec3(b.color) - g.c0;
  PRECISE vec3 dc2 = vec3(c.color) - g.c0;
  g.dc1 = dc1;
  g.dc2 = dc2;
  return g;
}

// The colour interpolated at pixel ray p, perspective-correct or linear in screen space.
FN vec3 interpolateColor(GouraudTriangle g, vec3 p, uint mode) {
  PRECISE float d1 = dot3(p, g.u1);
  PRECISE float d2 = dot3(p, g.u2);
  PRECISE float b1;
  PRECISE float b2;
  if (mode == INTERP_SCREEN) {
    // Screen-space barycentrics are the perspective ones times W / (interpolated W).
    b1 = divide(d1 * g.w1, g.det);
    b2 = divide(d2 * g.w2, g.det);
  } else {
    PRECISE float pn = dot3(p, g.n);
    b1 = divide(d1, pn);
    b2 = divide(d2, pn);
  }
  // Held to [0, 1] (NaN to 0): only pixels covered thanks to snapping extrapolate.
  b1 = b1 >= 0.0f ? (b1 <= 1.0f ? b1 : 1.0f) : 0.0f;
  b2 = b2 >= 0.0f ? (b2 <= 1.0f ? b2 : 1.0f) : 0.0f;
  PRECISE vec3 c = g.c0 + b1 * g.dc1 + b2 * g.dc2;
  return c;
}

// A large triangle's GouraudTriangle as resolve reads it for each tile the triangle may cover:
// stored with its set-up by the clip pass (LargeSetup) instead of the triangle's index, its three
// vertices' positions and colours and the products above. n and det are the triangle plane's n
// and h0n (trianglePlane: the same products of the same positions), so they are not stored; and
// since perspective-correct interpolation reads only t0..t3, resolve reads t4 (W) only for
// screen-space interpolation.
struct LargeShading {
  vec4 t0;  // u1, c0.x
  vec4 t1;  // u2, c0.y
  vec4 t2;  // dc1, c0.z
  vec4 t3;  // dc2, 0
  vec4 t4;  // w1, w2, 0, 0
};

FN LargeShading packShading(GouraudTriangle g) {
  LargeShading s;
  s.t0 = vec4(g.u1, g.c0.x);
  s.t1 = vec4(g.u2, g.c0.y);
  s.t2 = vec4(g.dc1, g.c0.z);
  s.t3 = vec4(g.dc2, 0.0f);
  s.t4 = vec4(g.w1, g.w2, 0.0f, 0.0f);
  return s;
}

// The GouraudTriangle that packShading(g) kept, with n and det from g's triangle's plane: every
// field equals g's, bit for bit (t4 may be left zero in perspective mode, which does not read W).
// With n shared, the dot product of the pixel ray and n is the same value in depthAt and in
// interpolateColor, computed once per pixel.
FN GouraudTriangle unpackShading(LargeShading s, TrianglePlane plane) {
  GouraudTriangle g;
  g.u1 = vec3(s.t0);
  g.u2 = vec3(s.t1);
  g.c0 = vec3(s.t0.w, s.t1.w, s.t2.w);
  g.n = plane.n;
  g.det = plane.h0n;
  g.w1 = s.t4.x;
  g.w2 = s.t4.y;
  g.dc1 = vec3(s.t2);
  g.dc2 = vec3(s.t3);
  return g;
}

// Clamp to [0, 1], round(c * 255), pack as RGBA8 with opaque alpha.
FN uint packColor(vec3 c) {
  PRECISE vec3 q = floor(clamp(c, vec3(0.0f), vec3(1.0f)) * 255.0f + 0.5f);
  return uint(q.x) | (uint(q.y) << 8) | (uint(q.z) << 16) | (255u << 24);
}

// Word w (bytes 4w..4w+3) of an image's RGB bytes, pixel k at bytes 3k..3k+2, from the packed
// colours (r in the low byte) of pixel 4w / 3, the first it reaches into, and the pixel after it:
// byte 4w + j is channel (4w + j) % 3 of pixel (4w + j) / 3.
FN uint rgbWord(uint w, uint first, uint next) {
  uint word = 0u;
  for (uint j = 0u; j < 4u; ++j) {
    uint k = 4u * w + j;
    uint color = k / 3u == 4u * w / 3u ? first : next;
    word |= ((color >> (8u * (k % 3u))) & 0xFFu) << (8u * j);
  }
  return word;
}

// The final RGBA8 of pixel (x, y) won by triangle g; `mode` is frame.interpolation (a
// specialization constant in the shader).
FN uint shadePixel(GouraudTriangle g, int x, int y, FrameData frame, uint mode) {
  return packColor(interpolateColor(g, pixelRay(x, y, frame.principal), mode));
}

// shadePixel for the triangle with these vertices.
FN uint resolvePixel(ShadedVertex a, ShadedVertex b, ShadedVertex c, int x, int y, FrameData frame, uint mode) {
  return shadePixel(gouraudTriangle(a, b, c), x, y, frame, mode);
}

// What the clip pass stores per large sub-triangle (std430, 160 bytes = 10 texels): resolve's
// bin-entry loop reads both halves for each tile the triangle may cover (LargeEntry.tiles).
struct LargeSetup {
  LargeTriangle raster;
  LargeShading shading;
};

SHARED_END

#ifdef __cplusplus
static_assert(sizeof(phongvk::gpu::LargeSetup) == 160 && offsetof(phongvk::gpu::LargeSetup, shading) == 80);
static_assert(sizeof(phongvk::gpu::LargeTriangle) == 80 && offsetof(phongvk::gpu::LargeTriangle, v0) == 32);
static_assert(offsetof(phongvk::gpu::LargeTriangle, zMin) == 68 && offsetof(phongvk::gpu::LargeTriangle, triangle) == 76);
static_assert(offsetof(phongvk::gpu::LargeTriangle, bias0) == 56 && offsetof(phongvk::gpu::LargeTriangle, bias2) == 64);
#endif

#endif  // PHONGVK_RASTER_H
