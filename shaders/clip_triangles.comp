// Clip pass: the triangles the triangle pass did not draw itself, those crossing the near plane or
// the guard band and those too large for its 32-bit edge functions. One inside the clip volume is
// set up as itself (triangle_setup.h setupUnclipped, as the triangle pass does); one crossing it is
// clipped to a polygon (setupClipped) whose fan sub-triangles become triangle setups of their
// own. Large ones go to resolve's bin lists, the others are rasterized here. Kept out of the
// triangle pass because on lavapipe code a pass merely contains costs every triangle it runs.
#version 460
#extension GL_GOOGLE_include_directive : require
#include "extensions.glsl"
#include "triangle_setup.h"
#include "bindings.glsl"
#include "raster_loops.glsl"

layout(local_size_x = CLIP_GROUP_SIZE) in;

// Whether this pass has the clipper (gpu_layout.h CLIP_*). Without it, the first triangle crossing
// the near plane or the guard band asks the host for a frame with it (STATUS_NEEDS_CLIPPING): code a
// pass merely contains costs lavapipe every triangle, and most scenes never clip
// (docs/DECISIONS.md, "The clipper only where a frame may need it").
layout(constant_id = SPEC_CLIP_POLYGONS) const uint CLIP_POLYGONS = CLIP_NONE;

// The fan's sub-triangles of a set-up polygon, rasterized or deferred to resolve. Without the
// clipper the polygon is the triangle itself. True where one drew a fragment that may still win.
bool drawFan(TriangleSetup t) {
  bool mayWin = false;
  for (int f = 0; f + 2 < t.count; ++f) {
    TriangleSetup sub = CLIP_POLYGONS == CLIP_ALL ? fanTriangle(t, f) : t;
    EdgeSetup s;
    if (setupSingle(sub, s)) mayWin = drawOrDefer(sub, s) || mayWin;
  }
  return mayWin;
}

// Every clip-listed triangle, or on the 32-bit key path's ids dispatch in a keptList scene only
// those its depth dispatch kept (raster_loops.glsl keepClipped), from their list by an indirect
// dispatch, so that its SIMD batches hold kept triangles only.
void main() {
  loadUniforms();
  bool keptOnly = IDS_PASS && KEPT_LIST;
  uint listed = keptOnly ? clipList.keptClipped : clipList.count;
  for (uint k = gl_GlobalInvocationID.x; k < listed; k += gl_NumWorkGroups.x * CLIP_GROUP_SIZE) {
    uint id = clipIds[keptOnly ? keptClippedIndex(k) : k];
    vec3 h0, h1, h2;
    bool cullBack;
    loadForSetup(id, h0, h1, h2, cullBack);
    TriangleSetup t;
    if (!setupPlane(h0, h1, h2, cullBack, id, frame, t)) continue;
    // Inside the clip volume (most here: not small): set up as itself, as the reference does. The
    // general clipper runs in a 0/1-trip loop (on lavapipe no cheaper than an if: a loop body runs
    // once, masked, even when no lane enters it).
    bool inside = insideClipVolume(h0, h1, h2, frame.nearPlane, frame.projection);
    if (!inside && CLIP_POLYGONS == CLIP_NONE) {
      atomicOr(status.flags, STATUS_NEEDS_CLIPPING);
      continue;
    }
    bool drawn = inside && setupUnclipped(h0, h1, h2, frame, t);
    if (CLIP_POLYGONS == CLIP_ALL) {
      for (uint clip = inside ? 1u : 0u; clip < 1u; ++clip) drawn = setupClipped(h0, h1, h2, frame, t);
    }
    if (drawn && drawFan(t) && !IDS_PASS && KEPT_LIST) keepClipped(id);
  }
  checkLoopBudget();
}
