// Large-triangle pass: one workgroup per (triangle, row chunk) entry of the large list; its
// invocations stride over the chunk's pixels, so a triangle that fills the screen is spread over
// the whole device instead of serializing on one invocation.
#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_shader_atomic_int64 : require
#include "shared.h"
#include "raster.h"
#include "bindings.glsl"

layout(local_size_x = LARGE_GROUP_SIZE) in;

// Sub-triangle s's pixels within rows [rowLo, rowHi].
void rasterizeRows(TriangleSetup t, EdgeSetup s, uint id, int rowLo, int rowHi) {
  int y0 = max(rowLo, s.bbox.y);
  int y1 = min(rowHi, s.bbox.w);
  int width = s.bbox.z - s.bbox.x + 1;
  int count = (y1 - y0 + 1) * width;
  for (int i = int(gl_LocalInvocationID.x); i < count; i += int(LARGE_GROUP_SIZE)) {
    int y = y0 + i / width;
    int x = s.bbox.x + i % width;
    uint64_t key = fragmentKey(t, s, x, y, frame, id);
    if (key != KEY_CLEAR) atomicMin(keys[uint(y) * frame.width + uint(x)], key);
  }
}

void main() {
  uint entries = min(large.count, frame.largeCapacity);
  for (uint e = gl_WorkGroupID.x; e < entries; e += gl_NumWorkGroups.x) {
    uvec2 entry = largeEntries[e];
    TriangleSetup t;
    if (!setupTriangleById(entry.x, t)) continue;  // same inputs, same answer as the triangle pass
    int rows = rowsPerChunk(t.bbox);
    int rowLo = t.bbox.y + int(entry.y) * rows;
    for (int k = 0; k + 2 < t.count; ++k) {
      EdgeSetup s;
      if (setupFan(t, k, frame, s)) rasterizeRows(t, s, entry.x, rowLo, rowLo + rows - 1);
    }
  }
}
