// Triangle pass: one invocation per triangle. Cull and snap (triangle_setup.h); a small one (32-bit edge
// functions suffice) is rasterized right here; one that crosses the near plane or the guard band,
// or is not small, goes to the clip list, and the clip pass (clip_triangles.comp) draws it or hands
// it to resolve. lavapipe runs both sides of every branch (masked; only loops really branch), so
// any code here costs every triangle: the large-triangle path, which few triangles take, lives in
// the clip pass (docs/PERFORMANCE.md, "Raster").
#version 460
#extension GL_GOOGLE_include_directive : require
#include "extensions.glsl"
#include "triangle_setup.h"
#include "small_triangles.h"
#include "bindings.glsl"
#include "raster_loops.glsl"

layout(local_size_x = SETUP_GROUP_SIZE) in;

// A small unclipped triangle, with 32-bit edges. On the 32-bit key path's depth pass, a triangle
// with a fragment that may still win a pixel (offerKey) is marked kept, for the ids pass.
void rasterizeSmallTriangle(TriangleSetup t) {
  EdgeSetup small;
  if (!setupSmallEdges(t.snapped[0], t.snapped[1], t.snapped[2], t.frontFacing != 0u, frame.width, frame.height, small)) {
    return;
  }
  if (!IDS_PASS) markBins(small.bbox);
  bool mayWin = rasterizeSmall(t, small);
#ifdef PHONGVK_KEYS32
  if (!IDS_PASS && mayWin) atomicOr(clipIds[control.triangleCount + t.triangle / 32u], 1u << (t.triangle % 32u));
#endif
}

// Triangle `id`: set up, then drawn here if small and unclipped, else listed for the clip pass.
void drawTriangle(uint id) {
  vec3 h0, h1, h2;
  bool cullBack;
  loadForSetup(id, h0, h1, h2, cullBack);
  TriangleSetup t;
  if (!setupPlane(h0, h1, h2, cullBack, id, frame, t)) return;
  bool inside = insideClipVolume(h0, h1, h2, frame.nearPlane, frame.projection);
  if (inside && !setupUnclipped(h0, h1, h2, frame, t)) return;
  if (inside && fitsSmallEdges(t.snapped[0], t.snapped[1], t.snapped[2])) {
    rasterizeSmallTriangle(t);
  } else if (!IDS_PASS) {
    uint k = atomicAdd(clipList.count, 1u);
    clipIds[k] = id;
    atomicMax(clipList.groupsX, min(k / CLIP_GROUP_SIZE + 1u, control.groupCap));
  }
}

// The ids pass of the 32-bit key path: only the triangles the depth pass kept, a word of 32 of
// them an invocation (gpu_layout.h keptWords). A triangle none of whose fragments may win cannot
// hold any pixel's least depth word, so leaving it out changes no pixel; on a grid of small
// triangles most are left out (back faces, no pixel centre covered, or beaten where they drew).
void redrawKept() {
  uint words = keptWords(control.triangleCount);
  for (uint w = gl_GlobalInvocationID.x; w < words; w += gl_NumWorkGroups.x * SETUP_GROUP_SIZE) {
    uint bits = clipIds[control.triangleCount + w];
    while (bits != 0u) {
      uint b = uint(findLSB(bits));
      bits &= bits - 1u;
      drawTriangle(w * 32u + b);
    }
  }
}

void main() {
  loadUniforms();
  if (IDS_PASS) {
    redrawKept();
  } else {
    // Grid-stride: the host caps the group count at control.groupCap.
    for (uint id = gl_GlobalInvocationID.x; id < control.triangleCount; id += gl_NumWorkGroups.x * SETUP_GROUP_SIZE) {
      drawTriangle(id);
    }
  }
  checkLoopBudget();
}
