// depth.h — depth and the visibility key (docs/DESIGN.md "Visibility"). The depth of a pixel is
// the view depth where its centre's ray meets the triangle's plane (not the clipped polygon's):
// with h0 h1 h2 the homogeneous pixel-space vertices and p the pixel's ray (x + 0.5 - cx,
// y + 0.5 - cy, 1), z = dot(h0, n) / dot(p, n), n = (h1 - h0) x (h2 - h0); the same quantities
// give perspective-correct barycentrics (gouraud.h). No w <= 0 is ever divided by. With an
// orthographic camera h0 h1 h2 are points (X, Y, z) of an affine space, n their plane's normal,
// and the pixel's depth is that plane's z over (x + 0.5 - cx, y + 0.5 - cy). Shared by the GPU
// passes and the reference; see glsl_cpp.h for the dialect rules.
#ifndef PHONGVK_DEPTH_H
#define PHONGVK_DEPTH_H

#include "glsl_cpp.h"
#include "exact_float.h"
#include "shared.h"
#include "vector_math.h"

SHARED_BEGIN

// The triangle's plane in pixel space: n = (h1 - h0) x (h2 - h0) and dot(h0, n).
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

// Below 0 exactly when the triangle faces the eye (counter-clockwise seen from outside), 0 when it
// is seen edge-on: dot(h0, n) with a perspective camera; n.z, twice its signed area on screen,
// with an orthographic one (dot(h0, n) is then a position's offset along n).
FN float facing(TrianglePlane t, uint projection) { return projection == PROJECTION_ORTHOGRAPHIC ? t.n.z : t.h0n; }

// The pixel centre as a ray direction in pixel space: (x + 0.5 - cx, y + 0.5 - cy, 1).
FN vec3 pixelRay(int x, int y, vec2 principal) {
  PRECISE vec3 p = vec3(float(x) + 0.5f - principal.x, float(y) + 0.5f - principal.y, 1.0f);
  return p;
}

// View depth where the pixel's ray meets the triangle's plane (orthographic: where the plane is
// over the pixel's position p.xy).
FN float depthAt(TrianglePlane t, vec3 p, uint projection) {
  if (projection == PROJECTION_ORTHOGRAPHIC) {
    PRECISE float zOrtho = divide(t.h0n - (p.x * t.n.x + p.y * t.n.y), t.n.z);
    return zOrtho;
  }
  PRECISE float z = divide(t.h0n, dot3(p, t.n));
  return z;
}

// The visibility key, (depth's float bits << 32) | triangle id: the smallest wins a pixel. A
// device with 64-bit integers and atomics holds it as a uint64_t; the 32-bit key path
// (PHONGVK_KEYS32: shaders built without any 64-bit integer, docs/DESIGN.md "Visibility") as
// uvec2(low word, high word), the same value, stored in the key buffer as the same 8 little-endian
// bytes, and ordered by keyLess as the 64-bit value is.
#ifdef PHONGVK_KEYS32
#define VisibilityKey uvec2
#define KEY_CLEAR uvec2(0xFFFFFFFFu, 0xFFFFFFFFu)
FN uvec2 keyOf(uint high, uint low) { return uvec2(low, high); }
FN uint keyLow(uvec2 k) { return k.x; }
FN uint keyHigh(uvec2 k) { return k.y; }
FN bool keyLess(uvec2 a, uvec2 b) { return a.y < b.y || (a.y == b.y && a.x < b.x); }
#else
#define VisibilityKey uint64_t
PHONGVK_CONST uint64_t KEY_CLEAR = 0xFFFFFFFFFFFFFFFFul;
FN uint64_t keyOf(uint high, uint low) { return (uint64_t(high) << 32) | uint64_t(low); }
FN uint keyLow(uint64_t k) { return uint(k & 0xFFFFFFFFul); }
FN uint keyHigh(uint64_t k) { return uint(k >> 32); }
FN bool keyLess(uint64_t a, uint64_t b) { return a < b; }
#endif

// The visibility key of a fragment at depth z of triangle `triangle`: depth's float bits above,
// the triangle id below; equal depths go to the lower triangle id. The depth is held to the depth range
// [zMin, zMax] of the clipped polygon: a pixel centre covered only thanks to snapping must not
// extrapolate an edge-on plane to a depth in front of the eye (or to NaN, which goes to zMin).
// Returns KEY_CLEAR for a fragment beyond the far plane.
FN VisibilityKey depthKey(float z, float zMin, float zMax, float farPlane, uint triangle) {
  float depth = z >= zMin ? (z <= zMax ? z : zMax) : zMin;
  if (depth > farPlane) return KEY_CLEAR;
  return keyOf(floatBitsToUint(depth), triangle);
}

// The key a triangle with this plane, depth range and id offers pixel (x, y), which it covers.
FN VisibilityKey planeKey(TrianglePlane plane, float zMin, float zMax, uint triangle, int x, int y, FrameData frame) {
  float z = depthAt(plane, pixelRay(x, y, frame.principal), frame.projection);
  return depthKey(z, zMin, zMax, frame.farPlane, triangle);
}

SHARED_END

#endif  // PHONGVK_DEPTH_H
