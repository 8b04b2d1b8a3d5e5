// resolve_large.glsl — the body of resolve_large.comp and resolve_large_keys.comp (see those).
#include "large_triangles.h"
#include "bindings.glsl"
#include "resolve.glsl"

// The keys build (resolve_large_keys.comp) leaves every winner's key for the second resolve pass:
// lists taken in rounds, and frames lit per pixel. The default build stores the colours where large
// triangles win and has none of that code.
#ifdef RESOLVE_LARGE_KEYS
#define LARGE_KEEPS_KEYS true
#else
#define LARGE_KEEPS_KEYS false
#endif


layout(local_size_x = TILE_SIZE, local_size_y_id = SPEC_RESOLVE_TILES) in;

// The 8 rows of a lane's column, spelled out (ROW(best, 3) is best3), or on the 32-bit key path a
// loop over arrays (ROW(best, r) is best[r]): SwiftShader's compiler took 269 s for the spelled-out
// pass and under a second for the loop (glsl_cpp.h UNROLL_KEYS64). ROW_TYPE(T) declares a row's
// variable where rows are spelled out; ROW_ARRAYS declares the arrays where they are not.
#ifdef PHONGVK_KEYS32
#define FOR_ROWS(DO) for (int r = 0; r < 8; ++r) { DO(r) }
#define ROW(name, r) name[r]
#define ROW_TYPE(T)
#define ROW_ARRAYS VisibilityKey best[8]; vec3 color[8]; bool won[8]; uint packed[8];
#else
#define FOR_ROWS(DO) DO(0) DO(1) DO(2) DO(3) DO(4) DO(5) DO(6) DO(7)
#define ROW(name, r) name##r
#define ROW_TYPE(T) T
#define ROW_ARRAYS
#endif

// Per row r: the smallest key so far, whether a large triangle holds it, and that triangle's
// colour there (unpacked).
#define DECLARE_ROW(r)              \
  ROW_TYPE(VisibilityKey) ROW(best, r) = KEY_CLEAR; \
  ROW_TYPE(vec3) ROW(color, r) = vec3(0.0f);        \
  ROW_TYPE(bool) ROW(won, r) = false;               \
  if ((keysWritten || LARGE_KEEPS_KEYS) && inImage(x, origin.y + r)) ROW(best, r) = loadKey(pixelIndex(x, origin.y + r));

// Row r against large triangle t (shading g), if it covers the pixel (its edge values, stepped
// down the lane's column row by row, decide); then the next row. lavapipe shades every row
// whether or not the triangle wins it (both sides of a branch run); the colour is packed once,
// for the winner (FINISH_ROW).
#define RASTER_ROW(r)                                                                              \
  if (columnCovers(c)) {                                                                           \
    VisibilityKey key = planeKey(t.plane, t.zMin, t.zMax, t.triangle, x, origin.y + r, frame);     \
    if (keyLess(key, ROW(best, r))) {                                                                   \
      ROW(best, r) = key;                                                                               \
      ROW(won, r) = true;                                                                               \
      ROW(color, r) = interpolateColor(g, pixelRay(x, origin.y + r, frame.principal), INTERPOLATION);   \
    }                                                                                              \
  }                                                                                                \
  c = nextRow(c);

// Row r, if a large triangle won it: its colour, stored (storeColor). A pixel won by a small
// triangle keeps its key for resolve_small; an uncovered one is left alone (the host gives it the
// background).
#define FINISH_ROW(r) \
  if (ROW(won, r) && inImage(x, origin.y + r)) storeColor(pixelIndex(x, origin.y + r), ROW(packed, r), ROW(best, r));

// Row r, if a large triangle (of this chunk) won it: its key, for the next round and the second resolve (keys build).
#define KEEP_ROW_KEY(r) \
  if (ROW(won, r) && inImage(x, origin.y + r)) storeKey(pixelIndex(x, origin.y + r), ROW(best, r));

// Row r's colour, packed (RGBA8), ORed into `packedBits` for keepVectors. That second use is what
// it is for: with one use, LLVM (in llvmpipe) moves the conversion and packing of each lane's
// colour into the per-lane loop that llvmpipe makes of the store, scalar code once per pixel
// instead of vector code once per row, which slows resolve (docs/PERFORMANCE.md, "Resolve").
#define PACK_ROW(r)                     \
  ROW_TYPE(uint) ROW(packed, r) = packColor(ROW(color, r)); \
  packedBits |= ROW(packed, r);

// The second use of the packed colours (PACK_ROW): never true (every packed colour has alpha 255,
// control.loopProbe is small), and a no-op if it were; the compiler cannot know either, so the
// packed values stay vectors.
void keepVectors(uint packedBits) {
  if (packedBits == control.loopProbe) atomicOr(status.flags, 0u);
}

// Where this dispatch stops in the list that starts at `head`: the end of the list, or with
// LIST_CHUNK the entry after the chunk's last (LIST_END when the chunk reaches the end).
uint chunkEnd(uint head) {
#ifdef RESOLVE_LARGE_KEYS
  if (LIST_CHUNK == 0u) return LIST_END;
  uint e = head;
  for (uint n = 0u; n < LIST_CHUNK && e != LIST_END; ++n) e = largeEntry(e).next;
  return e;
#else
  return LIST_END;
#endif
}

// From entry e of a bin's list on, before `end` (chunkEnd), the first whose tiles include `tile` (a
// bit of LargeEntry.tiles), as (set-up slot, next entry); (LIST_END, LIST_END) past the last. A
// loop, so lavapipe really skips the entries that miss the tile (it runs every side of a branch).
uvec2 nextEntryIn(uint e, uint end, uint tile) {
  uvec2 found = uvec2(LIST_END);
  while (e != end && found.x == LIST_END) {
    LargeEntry entry = largeEntry(e);
    if ((entry.tiles & tile) != 0u) found = uvec2(entry.slot, entry.next);
    e = entry.next;
  }
  return found;
}

// This lane's column of the tile at `origin` (pixels), bit `tile` of its bin's LargeEntry.tiles,
// against the entries of its bin's list from `head` to `end`; `keysWritten` when small triangles
// wrote keys in the tile. Pixels no large triangle wins are left to resolve_small.
void rasterizeTile(ivec2 origin, uint head, uint end, uint tile, bool keysWritten) {
  int column = int(gl_LocalInvocationID.x);
  int x = origin.x + column;
  ROW_ARRAYS
  FOR_ROWS(DECLARE_ROW)
  for (uvec2 entry = nextEntryIn(head, end, tile); entry.x != LIST_END; entry = nextEntryIn(entry.y, end, tile)) {
    uint slot = entry.x;
    LargeTriangle t = largeSetup(slot);
    GouraudTriangle g = unpackShading(largeShading(slot, INTERPOLATION), t.plane, frame.projection);
    ColumnEdges c = columnEdges(t, blockEdges(t, origin), column);
    FOR_ROWS(RASTER_ROW)
  }
#ifdef RESOLVE_LARGE_KEYS
  FOR_ROWS(KEEP_ROW_KEY)
  return;
#endif
  uint packedBits = 0u;
  FOR_ROWS(PACK_ROW)
  keepVectors(packedBits);
  FOR_ROWS(FINISH_ROW)
}

// Row r of a tile that the large triangle g owns: its colour, then packed (PACK_ROW).
#define SHADE_OWNED_ROW(r)                                                                      \
  ROW_TYPE(vec3) ROW(color, r) = interpolateColor(g, pixelRay(x, origin.y + r, frame.principal), INTERPOLATION); \
  PACK_ROW(r)

// Row r of an owned tile, stored where it is in the image (no key: keys are never kept with owned tiles).
#define STORE_OWNED_ROW(r) \
  if (inImage(x, origin.y + r)) storeColor(pixelIndex(x, origin.y + r), ROW(packed, r), KEY_CLEAR);

// This lane's column of the tile at `origin`, which the large triangle in set-up `slot` owns and
// nothing else reaches (no other large triangle, no small triangle's key): the triangle wins every
// pixel (each covered, at a depth short of the far plane), so only the colours are computed, the
// same as rasterizeTile would compute for them.
void shadeOwnedTile(ivec2 origin, uint slot) {
  int x = origin.x + int(gl_LocalInvocationID.x);
  GouraudTriangle g = unpackShading(largeShading(slot, INTERPOLATION), largeSetup(slot).plane, frame.projection);
  uint packedBits = 0u;
  ROW_ARRAYS
  FOR_ROWS(SHADE_OWNED_ROW)
  keepVectors(packedBits);
  FOR_ROWS(STORE_OWNED_ROW)
}

// Where resolve's work is in bin b (tile masks, bit t for tile t): the tiles to rasterize (x: some
// large triangle may cover them) and those to shade only (y: one large triangle owns the tile, and
// nothing else reaches it: no other large triangle, no small triangle's key). Owned tiles are
// rasterized too where keys are kept (phongvk diff), as the keys are wanted. One walk of the bin's
// list (to `end`, chunkEnd), with the entries' masks only. A list taken in chunks has no owned
// tiles (ownership is of the whole list), nor has a frame lit per pixel (owned tiles are shaded here).
uvec2 tileWork(Bin b, uint end) {
  uint seen = 0u;
  uint twice = 0u;
  uint owned = 0u;
  for (uint e = b.head; e != end;) {
    LargeEntry entry = largeEntry(e);
    twice |= seen & entry.tiles;
    seen |= entry.tiles;
    owned |= entry.owned;
    e = entry.next;
  }
  uint alone = OUTPUT == RESOLVE_OUTPUT_KEEP_KEYS || LARGE_KEEPS_KEYS ? 0u : owned & ~twice & ~(b.flags >> BIN_KEYS_SHIFT);
  return uvec2(seen & ~alone, alone);
}

// The GPU layout's workgroups take several tiles at once (SPEC_RESOLVE_TILES), the CPU layout's one.
const bool CPU_LAYOUT = gl_WorkGroupSize.y == 1u;

// Tile t of bin b, rasterized (against its list up to `end`) or (owned) only shaded, where it lies
// in the image.
void rasterizeBinTile(Bin b, uint end, uint t) {
  uvec2 origin = tileOrigin(b, t);
  if (origin.x < frame.width && origin.y < frame.height) rasterizeTile(ivec2(origin), b.head, end, 1u << t, tileKeysWritten(b, t));
}

void shadeOwnedBinTile(Bin b, uint t) {
  uvec2 origin = tileOrigin(b, t);
  if (origin.x < frame.width && origin.y < frame.height) shadeOwnedTile(ivec2(origin), nextEntryIn(b.head, LIST_END, 1u << t).x);
}

#ifdef RESOLVE_LARGE_KEYS
// LIST_CHUNK: once every tile of bin b has taken the chunk, the bin's list starts after it (all of
// the workgroup's invocations have read the old head), and another round is asked for if any is left.
void finishChunk(Bin b, uint end) {
  barrier();
  if (gl_LocalInvocationIndex != 0u) return;
  binData[control.binCount + b.index] = end;
  if (end != LIST_END) atomicOr(status.flags, STATUS_MORE_ROUNDS);
}
#endif

// On a CPU device the two kinds of tile are separate loops over their own tiles, not one loop
// with a branch: lavapipe would run both sides of the branch for every tile. A GPU rasterizes
// every tile: on the H100, walking each bin's list up front (tileWork) and shading owned tiles,
// with a branch per tile or these two loops, made resolve several times slower (the walks are
// chains of dependent loads; docs/PERFORMANCE.md, "History").
void main() {
  loadUniforms();
  for (uint k = gl_WorkGroupID.x; k < binList.count; k += gl_NumWorkGroups.x) {
    Bin b = touchedBin(k);
    if (b.head == LIST_END) continue;  // resolve_small's, or (LIST_CHUNK) done in an earlier round
    uint end = chunkEnd(b.head);
    if (CPU_LAYOUT) {
      uvec2 work = tileWork(b, end);
      [[dont_unroll]] for (uint tiles = work.x; tiles != 0u; tiles &= tiles - 1u) rasterizeBinTile(b, end, uint(findLSB(tiles)));
      [[dont_unroll]] for (uint tiles = work.y; tiles != 0u; tiles &= tiles - 1u) shadeOwnedBinTile(b, uint(findLSB(tiles)));
    } else {
      [[dont_unroll]] for (uint t = gl_LocalInvocationID.y; t < BIN_TILES * BIN_TILES; t += gl_WorkGroupSize.y) {
        rasterizeBinTile(b, end, t);
      }
    }
#ifdef RESOLVE_LARGE_KEYS
    if (LIST_CHUNK != 0u) finishChunk(b, end);
#endif
  }
  checkLoopBudget();
}
