// screen_quads.h — points and line segments as the raster rules draw them (docs/DESIGN.md "Points
// and lines"): each is a quad a fixed number of pixels wide, stored as two records of the triangle
// array (its halves) whose three corners are made here from the shaded positions of its one or two
// vertices, so that culling, clipping, snapping, the top-left rule, the depth plane, the key and
// the colours are the triangles' own. Shared by the GPU passes, the reference and the host's
// outputs; see glsl_cpp.h for the dialect rules.
#ifndef PHONGVK_SCREEN_QUADS_H
#define PHONGVK_SCREEN_QUADS_H

#include "glsl_cpp.h"
#include "shared.h"
#include "edges.h"

SHARED_BEGIN

// A quad half's record in the triangle array: (vertex a, vertex b, code, object), where a point has
// a = b. The code (quadCode): bit 0 QUAD_SECOND_HALF for the second half, bit 1 QUAD_POINT for a
// point, and from bit 2 the quad's width (a point's side, a line's width) in 1/256 pixel of the image.
PHONGVK_CONST uint QUAD_SECOND_HALF = 1u;
PHONGVK_CONST uint QUAD_POINT = 2u;
PHONGVK_CONST uint QUAD_WIDTH_SHIFT = 2u;
// The widest point or line, in pixels: a quad's width in 1/256 pixel takes 14 bits.
PHONGVK_CONST float QUAD_MAX_WIDTH = 64.0f;

// A quad half's code, from its width in 1/256 pixel, whether it is a point's, and which half it is.
FN uint quadCode(uint width256, bool point, bool secondHalf) {
  return (width256 << QUAD_WIDTH_SHIFT) | (point ? QUAD_POINT : 0u) | (secondHalf ? QUAD_SECOND_HALF : 0u);
}
FN bool quadIsPoint(uint code) { return (code & QUAD_POINT) != 0u; }
FN bool quadIsSecondHalf(uint code) { return (code & QUAD_SECOND_HALF) != 0u; }
FN uint quadWidth256(uint code) { return code >> QUAD_WIDTH_SHIFT; }

// The vertices whose attributes (colour, normal, position for lighting, texture coordinate) a quad
// half's three corners take: half 0 is (a-, b-, b+), half 1 (a-, b+, a+), the corners at b on the
// quad's far side along it; a triangle's are its own. quad: the record is a quad half.
FN uvec3 recordVertices(uvec4 record, bool quad) {
  if (!quad) return uvec3(record.x, record.y, record.z);
  return uvec3(record.x, record.y, quadIsSecondHalf(record.z) ? record.x : record.y);
}

// Corner `corner` (0, 1, 2) of a quad half as (along, across) signs: -1 at a's end or side, +1 at b's.
FN vec2 quadCornerSigns(uint code, int corner) {
  bool second = quadIsSecondHalf(code);
  if (corner == 0) return vec2(-1.0f, -1.0f);
  if (corner == 1) return second ? vec2(1.0f, 1.0f) : vec2(1.0f, -1.0f);
  return second ? vec2(-1.0f, 1.0f) : vec2(1.0f, 1.0f);
}

// Half the quad's width in pixels of the frame drawn (frame.pixelScale of the image's pixels: more
// with samples per pixel): a multiple of 1/512 pixel times a small integer, exact in float.
FN float quadHalfWidth(uint code, FrameData frame) {
  PRECISE float w = float(quadWidth256(code)) * (1.0f / 512.0f) * frame.pixelScale;
  return w;
}

// The screen axes a quad's corners step along, as (along.x, along.y, across.x, across.y), and the
// along step's scale (0 for a line, whose quad has no caps). A point: x along, y across, both half
// its side. A line: across the screen axis its projection moves less along (x-major lines are
// widened in y, as Vulkan's and OpenGL's non-antialiased wide lines are), decided from the
// homogeneous positions without a division, so any W (a vertex behind the eye) gives the same axis
// as the visible part: |X_b W_a - X_a W_b| against |Y_b W_a - Y_a W_b|, the same at both ends.
FN vec4 quadAxes(vec3 ha, vec3 hb, uint code, uint projection) {
  if (quadIsPoint(code)) return vec4(1.0f, 0.0f, 0.0f, 1.0f);
  float wa = homogeneousW(ha, projection);
  float wb = homogeneousW(hb, projection);
  PRECISE float dx = hb.x * wa - ha.x * wb;
  PRECISE float dy = hb.y * wa - ha.y * wb;
  return abs(dx) >= abs(dy) ? vec4(0.0f, 0.0f, 0.0f, 1.0f) : vec4(0.0f, 0.0f, 1.0f, 0.0f);
}

// A quad corner in homogeneous pixel space: its end's position moved by the corner's signs times
// half the width along the axes, scaled by the end's W so that the step is that many pixels on
// screen. Linear in h, so a clipped quad keeps its width: the near plane's crossing of an edge
// from a- to b- is that crossing moved the same way.
FN vec3 quadCorner(vec3 h, vec2 signs, vec4 axes, float halfWidth, uint projection) {
  float w = homogeneousW(h, projection);
  PRECISE float scale = halfWidth * w;
  PRECISE vec2 step = vec2(signs.x * axes.x + signs.y * axes.z, signs.x * axes.y + signs.y * axes.w) * scale;
  PRECISE vec3 corner = vec3(h.x + step.x, h.y + step.y, h.z);
  return corner;
}

// The three homogeneous corners of a quad half with code `code` whose ends are ha (vertex a) and
// hb (vertex b).
FN void quadCorners(vec3 ha, vec3 hb, uint code, FrameData frame, OUT(vec3) h0, OUT(vec3) h1, OUT(vec3) h2) {
  vec4 axes = quadAxes(ha, hb, code, frame.projection);
  float halfWidth = quadHalfWidth(code, frame);
  vec2 s0 = quadCornerSigns(code, 0);
  vec2 s1 = quadCornerSigns(code, 1);
  vec2 s2 = quadCornerSigns(code, 2);
  h0 = quadCorner(s0.x < 0.0f ? ha : hb, s0, axes, halfWidth, frame.projection);
  h1 = quadCorner(s1.x < 0.0f ? ha : hb, s1, axes, halfWidth, frame.projection);
  h2 = quadCorner(s2.x < 0.0f ? ha : hb, s2, axes, halfWidth, frame.projection);
}

SHARED_END

#endif  // PHONGVK_SCREEN_QUADS_H
