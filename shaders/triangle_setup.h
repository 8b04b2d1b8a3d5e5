// triangle_setup.h — one triangle from its shaded vertices to what the raster loops need: culled
// (off screen, edge-on, back face), clipped and snapped, fanned into sub-triangles, and the key it
// offers a pixel (docs/DESIGN.md "Rasterization", "Visibility"). Coverage uses the triangle clipped
// against the near plane and the guard band, snapped to 1/256 pixel; depth and colour use the
// original triangle's plane. Shared by the GPU passes and the reference; see glsl_cpp.h.
#ifndef PHONGVK_TRIANGLE_SETUP_H
#define PHONGVK_TRIANGLE_SETUP_H

#include "glsl_cpp.h"
#include "shared.h"
#include "clip.h"
#include "depth.h"
#include "edges.h"

SHARED_BEGIN

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



// The rest of setupTriangle for a triangle that needs no clipping (nearly all of them): the same
// operations in the same order as the general path, but only constant indices, so a SIMD CPU
// keeps everything in registers instead of per-lane arrays in memory.
FN bool setupUnclipped(vec3 h0, vec3 h1, vec3 h2, FrameData frame, INOUT(TriangleSetup) t) {
  t.count = 3;
  t.zMin = min(min(h0.z, h1.z), h2.z);
  t.zMax = max(max(h0.z, h1.z), h2.z);
  ivec2 v0 = snapToSubpixel(h0, frame.principal, frame.projection);
  ivec2 v1 = snapToSubpixel(h1, frame.principal, frame.projection);
  ivec2 v2 = snapToSubpixel(h2, frame.principal, frame.projection);
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
  float side = facing(t.plane, frame.projection);
  if (side == 0.0f) return false;
  t.frontFacing = side < 0.0f ? 1u : 0u;
  if (cullBack && t.frontFacing == 0u) return false;
  t.triangle = triangle;
  return true;
}

// The rest of the setup for a triangle that crosses the near plane or the guard band: clip, snap
// the polygon. False when nothing is left in front of the near plane or no pixel centre is in the
// bounding box. (The GPU runs this in a pass of its own, clip_triangles.comp: on a SIMD CPU code a
// pass merely contains costs every triangle it runs.) Indexed with constants once the loop unrolls,
// as clipTriangle is.
FN bool setupClipped(vec3 h0, vec3 h1, vec3 h2, FrameData frame, INOUT(TriangleSetup) t) {
  vec3 poly[MAX_CLIP_VERTICES];
  t.count = clipTriangle(h0, h1, h2, frame.nearPlane, frame.projection, poly);
  if (t.count == 0) return false;
  t.zMin = poly[0].z;
  t.zMax = poly[0].z;
  ivec2 lo = snapToSubpixel(poly[0], frame.principal, frame.projection);
  ivec2 hi = lo;
  t.snapped[0] = lo;
  UNROLL for (int i = 1; i < int(MAX_CLIP_VERTICES); ++i) {
    if (i < t.count) {
      t.zMin = min(t.zMin, poly[i].z);
      t.zMax = max(t.zMax, poly[i].z);
      ivec2 v = snapToSubpixel(poly[i], frame.principal, frame.projection);
      t.snapped[i] = v;
      lo = min(lo, v);
      hi = max(hi, v);
    }
  }
  t.bbox = pixelBounds(lo, hi, frame.width, frame.height);
  return !isEmpty(t.bbox);
}

// Culls, clips and snaps a triangle for rasterization. False: it draws nothing.
FN bool setupTriangle(vec3 h0, vec3 h1, vec3 h2, bool cullBack, uint triangle, FrameData frame, OUT(TriangleSetup) t) {
  if (!setupPlane(h0, h1, h2, cullBack, triangle, frame, t)) return false;
  if (insideClipVolume(h0, h1, h2, frame.nearPlane, frame.projection)) return setupUnclipped(h0, h1, h2, frame, t);
  return setupClipped(h0, h1, h2, frame, t);
}

// Sub-triangle k (0 <= k < count - 2) of a set-up triangle's fan.
FN bool setupFan(TriangleSetup t, int k, FrameData frame, OUT(EdgeSetup) s) {
  return setupEdges(t.snapped[0], t.snapped[k + 1], t.snapped[k + 2], t.frontFacing != 0u, frame.width, frame.height, s);
}

FN VisibilityKey coveredKey(TriangleSetup t, int x, int y, FrameData frame) {
  return planeKey(t.plane, t.zMin, t.zMax, t.triangle, x, y, frame);
}

FN VisibilityKey fragmentKey(TriangleSetup t, EdgeSetup s, int x, int y, FrameData frame) {
  if (!covers(s, pixelCentre(x, y))) return KEY_CLEAR;
  return coveredKey(t, x, y, frame);
}

SHARED_END

#endif  // PHONGVK_TRIANGLE_SETUP_H
