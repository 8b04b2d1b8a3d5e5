// gouraud.h — Gouraud interpolation of the vertex colours at a pixel, perspective-correct or
// linear in screen space, and the 8-bit colour it becomes (docs/DESIGN.md "Gouraud"). Shared by the GPU
// passes and the reference; see glsl_cpp.h for the dialect rules.
#ifndef PHONGVK_GOURAUD_H
#define PHONGVK_GOURAUD_H

#include "glsl_cpp.h"
#include "exact_float.h"
#include "shared.h"
#include "depth.h"
#include "vector_math.h"

SHARED_BEGIN

// What Gouraud interpolation needs of one triangle, whatever the pixel: the plane normal n, the
// planes whose dot with the pixel ray give the barycentrics of vertices 1 and 2 (up to a common
// factor), the vertex colours as c0 + b1 dc1 + b2 dc2, and for screen-space interpolation
// dot(h0, n) and the vertices' W. With an orthographic camera the vertices are taken at W = 1, so
// the same formulas give barycentrics linear in screen space, as that projection has them, and
// n = (0, 0, n.z), dot(h0, n) = n.z exactly (depth.h facing).
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

FN GouraudTriangle gouraudTriangle(ShadedVertex a, ShadedVertex b, ShadedVertex c, uint projection) {
  vec3 h0 = vec3(a.hpos);
  vec3 h1 = vec3(b.hpos);
  vec3 h2 = vec3(c.hpos);
  if (projection == PROJECTION_ORTHOGRAPHIC) {
    h0.z = 1.0f;
    h1.z = 1.0f;
    h2.z = 1.0f;
  }
  PRECISE vec3 e1 = h1 - h0;
  PRECISE vec3 e2 = h2 - h0;
  GouraudTriangle g;
  g.n = cross3(e1, e2);
  g.det = dot3(h0, g.n);
  if (projection == PROJECTION_ORTHOGRAPHIC) {  // the same values, without zeros' signs
    g.n = vec3(0.0f, 0.0f, g.n.z);
    g.det = g.n.z;
  }
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

// The barycentrics of vertices 1 and 2 at pixel ray p, perspective-correct or linear in screen
// space, each held to [0, 1]: what Gouraud interpolates colours with, and Phong shading positions,
// normals and colours (pixel_shading.h).
FN vec2 barycentrics(GouraudTriangle g, vec3 p, uint mode) {
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
  return vec2(b1, b2);
}

// The colour interpolated with barycentrics b (barycentrics).
FN vec3 interpolateColorAt(GouraudTriangle g, vec2 b) {
  PRECISE vec3 c = g.c0 + b.x * g.dc1 + b.y * g.dc2;
  return c;
}

// The colour interpolated at pixel ray p, perspective-correct or linear in screen space.
FN vec3 interpolateColor(GouraudTriangle g, vec3 p, uint mode) { return interpolateColorAt(g, barycentrics(g, p, mode)); }

// Clamp to [0, 1], round(c * 255), pack as RGBA8 with opaque alpha.
FN uint packColor(vec3 c) {
  PRECISE vec3 q = floor(clamp(c, vec3(0.0f), vec3(1.0f)) * 255.0f + 0.5f);
  return uint(q.x) | (uint(q.y) << 8) | (uint(q.z) << 16) | (255u << 24);
}

// The final RGBA8 of pixel (x, y) won by triangle g; `mode` is frame.interpolation (a
// specialization constant in the shader).
FN uint shadePixel(GouraudTriangle g, int x, int y, FrameData frame, uint mode) {
  return packColor(interpolateColor(g, pixelRay(x, y, frame.principal), mode));
}

// shadePixel for the triangle with these vertices.
FN uint resolvePixel(ShadedVertex a, ShadedVertex b, ShadedVertex c, int x, int y, FrameData frame, uint mode) {
  return shadePixel(gouraudTriangle(a, b, c, frame.projection), x, y, frame, mode);
}

SHARED_END

#endif  // PHONGVK_GOURAUD_H
