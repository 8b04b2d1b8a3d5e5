// Triangle pass: one invocation per triangle. Clip, cull and snap (raster.h); a triangle whose
// pixel bounding box is small is rasterized right here, a large one is cut into row chunks that
// the large pass spreads over whole workgroups (raster_large.comp).
#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_shader_atomic_int64 : require
#include "shared.h"
#include "raster.h"
#include "bindings.glsl"
#include "raster_loops.glsl"

layout(local_size_x = SETUP_GROUP_SIZE) in;

// Stores the triangle's setup and appends its row chunks to the large list; false when either is
// full (then it is drawn right here). A reservation that straddles the list's end still writes
// the entries that fit, as skips: the large pass reads every entry below min(count, capacity),
// and none of them may be left over from an earlier frame.
bool deferToLargePass(TriangleSetup t) {
  uint slot = atomicAdd(large.setups, 1u);
  if (slot >= frame.largeSetupCapacity) return false;
  uint chunks = uint(chunkCount(t));
  uint first = atomicAdd(large.count, chunks);
  if (first + chunks > frame.largeCapacity) {
    for (uint e = first; e < frame.largeCapacity; ++e) largeEntries[e] = uvec2(LARGE_ENTRY_SKIP, 0u);
    return false;
  }
  largeSetups[slot] = t;
  for (uint c = 0u; c < chunks; ++c) largeEntries[first + c] = uvec2(slot, c);
  atomicMax(large.groupsX, min(first + chunks, frame.groupCap));
  return true;
}

void rasterizeHere(TriangleSetup t) {
  markTiles(t.bbox);
  EdgeSetup s;
  if (t.count == 3) {  // unclipped: no dynamic indexing (see setupUnclipped)
    if (fitsSmallEdges(t.snapped[0], t.snapped[1], t.snapped[2])) {  // 32-bit edges, same result
      EdgeSetup32 small;
      if (setupEdges32(t.snapped[0], t.snapped[1], t.snapped[2], t.frontFacing != 0u, frame.width, frame.height,
                       small)) {
        rasterizeSmall(t, small);
      }
      return;
    }
    if (setupSingle(t, frame, s)) rasterizeRows(t, s, s.bbox.y, s.bbox.w, 0, 1);
    return;
  }
  for (int k = 0; k + 2 < t.count; ++k) {
    if (setupFan(t, k, frame, s)) rasterizeRows(t, s, s.bbox.y, s.bbox.w, 0, 1);
  }
}

void main() {
  // Grid-stride: the host caps the group count at frame.groupCap.
  for (uint id = gl_GlobalInvocationID.x; id < frame.triangleCount; id += gl_NumWorkGroups.x * SETUP_GROUP_SIZE) {
    TriangleSetup t;
    if (!setupTriangleById(id, t)) continue;
    if (uint(boxPixels(t.bbox)) > SMALL_TRIANGLE_MAX_PIXELS && deferToLargePass(t)) continue;
    rasterizeHere(t);
  }
}
