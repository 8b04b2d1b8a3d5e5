// Large-triangle pass: one workgroup per (triangle, row chunk) entry of the large list; the
// chunk's rows split the invocations, so a triangle that fills the screen is spread over the
// whole device instead of serializing on one invocation.
#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_shader_atomic_int64 : require
#include "shared.h"
#include "raster.h"
#include "bindings.glsl"
#include "raster_loops.glsl"

layout(local_size_x = LARGE_GROUP_SIZE) in;

void main() {
  uint entries = min(large.count, frame.largeCapacity);
  int lane = int(gl_LocalInvocationID.x);
  for (uint e = gl_WorkGroupID.x; e < entries; e += gl_NumWorkGroups.x) {
    uvec2 entry = largeEntries[e];
    if (entry.x == LARGE_ENTRY_SKIP) continue;  // part of a reservation that did not fit
    TriangleSetup t = largeSetups[entry.x];  // set up once, by the triangle or clip pass
    // The chunk's rows split the lanes: each lane walks its own row's span with its row-mates.
    int rows = rowsPerChunk(t);
    int lanesPerRow = int(LARGE_GROUP_SIZE) / rows;
    int rowLo = t.bbox.y + int(entry.y) * rows;
    int y = rowLo + lane / lanesPerRow;
    if (lane == 0) markTiles(ivec4(t.bbox.x, rowLo, t.bbox.z, min(rowLo + rows - 1, t.bbox.w)));
    EdgeSetup s;  // every stored setup is a single triangle (the clip pass splits fans)
    if (setupSingle(t, frame, s)) rasterizeRows(t, s, y, y, lane % lanesPerRow, lanesPerRow);
  }
}
