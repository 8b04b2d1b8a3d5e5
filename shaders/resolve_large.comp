// First resolve pass: the touched bins with large triangles (resolve.glsl). A workgroup takes one
// 32x32 bin at a time, 8x8 tile by tile; each lane owns the 8 pixels of one column of a tile,
// 8 lanes a tile (one SIMD batch on a CPU device, so everything per tile is uniform there; a GPU
// workgroup takes several tiles at once, SPEC_RESOLVE_TILES). Per pixel: its key from the key
// buffer (where small triangles went by atomicMin, only in tiles they touched), then each of the
// bin's large triangles tested at the lane's 8 pixels (edge values stepped down the column), the
// smallest key kept in registers. There is no per-tile classification: lavapipe runs both sides of
// every branch, so skipping tiles or taking a cheaper path for covered ones only added work
// (fig1_cube 13.9 -> 12.7 ms without the covered-tile path, -> ~12 ms without classifying).
// Where a large triangle wins, its Gouraud colour (per pixel, from the winner's LargeShading, the
// constants the clip pass stored with its set-up: once per row instead of once per row and bin
// entry, fig1_cube -12%) -> packed RGBA8, stored by resolve.glsl storeColor; where a small one
// wins, the key stays for resolve_small.
//
// The 8 rows are spelled out by the FOR_ROWS macro instead of indexing per-lane arrays, which
// lavapipe may keep in memory.
#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_control_flow_attributes : require
#include "shared.h"
#include "raster.h"
#include "bindings.glsl"
#include "resolve.glsl"

layout(local_size_x = TILE_SIZE, local_size_y_id = SPEC_RESOLVE_TILES) in;

#define FOR_ROWS(DO) DO(0) DO(1) DO(2) DO(3) DO(4) DO(5) DO(6) DO(7)

// Per row r: the smallest key so far, and the set-up slot of the large triangle holding it
// (LIST_END: none does).
#define DECLARE_ROW(r)              \
  uint64_t best##r = KEY_CLEAR;     \
  uint slot##r = LIST_END;          \
  if (keysWritten && inImage(x, origin.y + r)) best##r = keys[pixelIndex(x, origin.y + r)];

// Row r against large triangle t (set-up slot `slot`), if it covers the pixel (its edge values,
// stepped down the lane's column row by row, decide); then the next row.
#define RASTER_ROW(r)                                                                              \
  if (columnCovers(c)) {                                                                           \
    uint64_t key = planeKey(t.plane, t.zMin, t.zMax, t.triangle, x, origin.y + r, frame);          \
    if (key < best##r) {                                                                           \
      best##r = key;                                                                               \
      slot##r = slot;                                                                              \
    }                                                                                              \
  }                                                                                                \
  c = nextRow(c);

// Row r, if a large triangle won it: the winner's Gouraud colour (from its set-up slot), stored
// (storeColor). A pixel won by a small triangle keeps its key for resolve_small; an uncovered one
// is left alone (the host gives it the background). lavapipe computes the colour of every row
// whoever won (both sides of a branch run), so the slot read is 0 unless a large triangle won:
// never a read past the set-ups.
#define FINISH_ROW(r)                                                                            \
  {                                                                                              \
    bool large = slot##r != LIST_END;                                                            \
    GouraudTriangle g = unpackShading(largeShading(large ? slot##r : 0u), INTERPOLATION);        \
    uint color = shadePixel(g, x, origin.y + r, frame, INTERPOLATION);                           \
    if (large && inImage(x, origin.y + r)) {                                                     \
      storeColor(pixelIndex(x, origin.y + r), color, best##r, keysWritten);                      \
    }                                                                                            \
  }

// This lane's column of the tile at `origin` (pixels) in a bin whose large-triangle list starts
// at `head`; `keysWritten` when small triangles wrote keys in the tile. Pixels no large triangle
// wins are left to resolve_small.
void resolveTile(ivec2 origin, uint head, bool keysWritten) {
  int column = int(gl_LocalInvocationID.x);
  int x = origin.x + column;
  FOR_ROWS(DECLARE_ROW)
  for (uint e = head; e != LIST_END;) {
    uvec2 entry = largeEntry(e);  // (set-up slot, next entry)
    uint slot = entry.x;
    LargeTriangle t = largeSetup(slot);
    ColumnEdges c = columnEdges(t, blockEdges(t, origin), column);
    FOR_ROWS(RASTER_ROW)
    e = entry.y;
  }
  FOR_ROWS(FINISH_ROW)
}

void main() {
  loadFrame();
  for (uint k = gl_WorkGroupID.x; k < binList.count; k += gl_NumWorkGroups.x) {
    Bin b = touchedBin(k);
    if (b.head == LIST_END) continue;  // resolve_small's
    [[dont_unroll]] for (uint t = gl_LocalInvocationID.y; t < BIN_TILES * BIN_TILES; t += gl_WorkGroupSize.y) {
      uvec2 origin = tileOrigin(b, t);
      if (origin.x < frame.width && origin.y < frame.height) resolveTile(ivec2(origin), b.head, tileKeysWritten(b, t));
    }
  }
  checkLoopBudget();
}
