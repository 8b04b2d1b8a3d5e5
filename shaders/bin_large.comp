// Bin pass (GPU layout): links every large triangle into the lists of the bins it may cover, one
// invocation per (triangle, bin) pair. The clip pass reserved each triangle's entries (one per bin
// of its box, row-major) and wrote each as (set-up slot, LIST_END, 0, first entry of the
// triangle); this pass finds the entry's bin from its offset, computes the bin's tile mask and
// links it, or leaves it unlinked where the triangle misses the bin. On a GPU one invocation walking
// a screen-filling triangle's ~1,250 bins took most of a frame (docs/DECISIONS.md, "Binning"); on a
// CPU device the clip pass links them itself (WorkLayout::Cpu), and this pass is not run.
#version 460
#extension GL_GOOGLE_include_directive : require
#include "extensions.glsl"

#include "large_triangles.h"
#include "bindings.glsl"
#include "raster_loops.glsl"

layout(local_size_x = BIN_GROUP_SIZE) in;

void main() {
  loadUniforms();
  // An overflowing frame is rendered again; its lists may hold entries nobody wrote.
  if ((status.flags & STATUS_LARGE_OVERFLOW) != 0u) return;
  uint n = min(large.count, control.largeCapacity);
  for (uint e = gl_GlobalInvocationID.x; e < n; e += gl_NumWorkGroups.x * BIN_GROUP_SIZE) {
    LargeEntry entry = largeEntries[e];
    LargeTriangle record = largeSetup(entry.slot);
    ivec4 bins = binsOf(record.bbox);
    int i = int(e - entry.owned);  // the entry's place among its triangle's, row-major over the box's bins
    int columns = bins.z - bins.x + 1;
    linkEntry(e, entry.slot, record, ivec2(bins.x + i % columns, bins.y + i / columns));
  }
  checkLoopBudget();
}
