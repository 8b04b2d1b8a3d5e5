// depth.h — depth and the 64-bit visibility key (docs/DESIGN.md "Visibility"). The depth of a pixel is
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

PHONGVK_CONST uint64_t KEY_CLEAR = 0xFFFFFFFFFFFFFFFFul;


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

// The key a triangle with this plane, depth range and id offers pixel (x, y), which it covers.
FN uint64_t planeKey(TrianglePlane plane, float zMin, float zMax, uint triangle, int x, int y, FrameData frame) {
  float z = depthAt(plane, pixelRay(x, y, frame.principal), frame.projection);
  return depthKey(z, zMin, zMax, frame.farPlane, triangle);
}

SHARED_END

#endif  // PHONGVK_DEPTH_H
