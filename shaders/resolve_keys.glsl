// resolve_keys.glsl — the loop resolve_small.comp and resolve_lit.comp share (after resolve.glsl):
// the tiles whose pixels still hold keys, in every touched bin, a lane per pixel; each such
// pixel's colour from its winning triangle by the includer's pixelColor(id, x, y), stored by
// resolve.glsl storeColor. Pixels nothing covered are left alone (the background: the host's or
// pack_colors.comp's in the key slots, fill_background.comp's in the colour buffer). It visits only
// the flagged tiles (a bit loop, not a test of all 16): on lavapipe even an empty iteration of a
// 64-lane group costs time, and a floor of large triangles touches every bin, so testing all tiles
// was a large part of its frame (docs/PERFORMANCE.md, "Resolve").

layout(local_size_x = TILE_SIZE, local_size_y = TILE_SIZE) in;

void resolvePixelOf(uvec2 origin) {
  int x = int(origin.x + gl_LocalInvocationID.x);
  int y = int(origin.y + gl_LocalInvocationID.y);
  if (!inImage(x, y)) return;
  uint i = pixelIndex(x, y);
  VisibilityKey key = loadKey(i);
  if (!slotHoldsKey(key)) return;  // uncovered, or resolved by resolve_large
  storeColor(i, pixelColor(keyLow(key), x, y), key);
}

void main() {
  loadUniforms();
  for (uint k = gl_WorkGroupID.x; k < binList.count; k += gl_NumWorkGroups.x) {
    Bin b = touchedBin(k);
    // The tiles small triangles wrote keys in, lowest first (none: only large triangles, resolve_large's);
    // every tile where resolve_large left keys instead of colours (KEYS_ONLY).
    uint keyTiles = KEYS_ONLY ? (1u << (BIN_TILES * BIN_TILES)) - 1u : b.flags >> BIN_KEYS_SHIFT;
    [[dont_unroll]] for (uint tiles = keyTiles; tiles != 0u; tiles &= tiles - 1u) {
      resolvePixelOf(tileOrigin(b, uint(findLSB(tiles))));
    }
  }
  checkLoopBudget();
}
