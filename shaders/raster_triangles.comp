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

// A small unclipped triangle, with 32-bit edges. True where it drew a fragment that may still win
// a pixel (offerKey).
bool rasterizeSmallTriangle(TriangleSetup t) {
  EdgeSetup small;
  if (!setupSmallEdges(t.snapped[0], t.snapped[1], t.snapped[2], t.frontFacing != 0u, frame.width, frame.height, small)) {
    return false;
  }
  if (!IDS_PASS) markBins(small.bbox);
  return rasterizeSmall(t, small);
}

// Triangle `id`: set up, then drawn here if small and unclipped, else listed for the clip pass. On
// the 32-bit key path's depth pass, kept (raster_loops.glsl keepTriangle) where it may win a pixel.
void drawTriangle(uint id) {
  vec3 h0, h1, h2;
  bool cullBack;
  loadForSetup(id, h0, h1, h2, cullBack);
  TriangleSetup t;
  if (!setupPlane(h0, h1, h2, cullBack, id, frame, t)) return;
  bool inside = insideClipVolume(h0, h1, h2, frame.nearPlane, frame.projection);
  if (inside && !setupUnclipped(h0, h1, h2, frame, t)) return;
  if (inside && fitsSmallEdges(t.snapped[0], t.snapped[1], t.snapped[2])) {
    bool mayWin = rasterizeSmallTriangle(t);
#ifdef PHONGVK_KEYS32
    if (!IDS_PASS && mayWin) keepTriangle(id);
#endif
  } else if (!IDS_PASS) {
    uint k = atomicAdd(clipList.count, 1u);
    clipIds[k] = id;
    atomicMax(clipList.groupsX, min(k / CLIP_GROUP_SIZE + 1u, control.groupCap));
  }
}

void main() {
  loadUniforms();
#ifdef PHONGVK_KEYS32
  if (IDS_PASS) {  // the kept triangles only, a chunk of them an invocation
    uint span = keptSpan(control.triangleCount);
    uint chunks = keptChunks(control.triangleCount);
    for (uint c = gl_GlobalInvocationID.x; c < chunks; c += gl_NumWorkGroups.x * SETUP_GROUP_SIZE) {
      for (uint bits = keptChunkBits(c, span); bits != 0u; bits &= bits - 1u) drawTriangle(c * span + uint(findLSB(bits)));
    }
    checkLoopBudget();
    return;
  }
#endif
  // Grid-stride: the host caps the group count at control.groupCap.
  for (uint id = gl_GlobalInvocationID.x; id < control.triangleCount; id += gl_NumWorkGroups.x * SETUP_GROUP_SIZE) {
    drawTriangle(id);
  }
  checkLoopBudget();
}
