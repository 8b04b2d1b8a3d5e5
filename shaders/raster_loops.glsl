// raster_loops.glsl — the loops both raster passes share (after bindings.glsl; needs
// GL_EXT_shader_atomic_int64).

// Marks the tiles of pixel box (x0, y0, x1, y1) as touched. Every writer stores the same value,
// so the unsynchronised stores are benign.
void markTiles(ivec4 box) {
  for (int ty = box.y / int(TILE_SIZE); ty <= box.w / int(TILE_SIZE); ++ty) {
    for (int tx = box.x / int(TILE_SIZE); tx <= box.z / int(TILE_SIZE); ++tx) {
      tiles[uint(ty) * frame.tilesX + uint(tx)] = 1u;
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
