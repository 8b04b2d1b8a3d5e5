// raster_loops.glsl — what the raster passes share (after bindings.glsl; needs
// GL_EXT_shader_atomic_int64): tile marking, span loops, handing large triangles to the large pass.

// Marks the tiles of pixel box (x0, y0, x1, y1) as touched: the first toucher of a tile appends
// it to the list (the plain read skips the atomic for tiles already taken).
void markTiles(ivec4 box) {
  for (int ty = box.y / int(TILE_SIZE); ty <= box.w / int(TILE_SIZE); ++ty) {
    for (int tx = box.x / int(TILE_SIZE); tx <= box.z / int(TILE_SIZE); ++tx) {
      uint tile = uint(ty) * frame.tilesX + uint(tx);
      if (tileData[tile] != 0u || atomicExchange(tileData[tile], 1u) != 0u) continue;
      uint k = atomicAdd(tileList.count, 1u);
      tileData[frame.tileCount + k] = uint(tx) | (uint(ty) << 16);  // resolve needs no division
      atomicMax(tileList.groupsX, min(k + 1u, frame.groupCap));
    }
  }
}

// Rasterizes rows [rowLo, rowHi] of sub-triangle s, row span by row span; the `lanes`
// invocations starting at `lane` share each span.
void rasterizeRows(TriangleSetup t, EdgeSetup s, int rowLo, int rowHi, int lane, int lanes) {
  for (int y = max(rowLo, s.bbox.y); y <= min(rowHi, s.bbox.w); ++y) {
    ivec2 span = rowSpan(s, y);
    for (int x = span.x + lane; x <= span.y; x += lanes) {
      atomicMin(keys[uint(y) * frame.width + uint(x)], coveredKey(t, x, y, frame));
    }
  }
}

// rasterizeRows for a small sub-triangle's 32-bit setup (raster.h EdgeSetup32), one invocation.
void rasterizeSmall(TriangleSetup t, EdgeSetup32 s) {
  for (int y = s.bbox.y; y <= s.bbox.w; ++y) {
    ivec2 span = rowSpan32(s, y);
    for (int x = span.x; x <= span.y; ++x) {
      atomicMin(keys[uint(y) * frame.width + uint(x)], coveredKey(t, x, y, frame));
    }
  }
}

// Stores the triangle's setup and appends its row chunks to the large list; false when either is
// full (then the caller draws it itself). A reservation that straddles the list's end still writes
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
