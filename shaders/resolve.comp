// Resolve pass: an indirect dispatch over the touched bins (bindings.glsl). A workgroup takes one
// 32x32 bin at a time, tile by 8x8 tile; each lane owns ROWS pixels of one column of the tile
// (ROWS = 8 on CPU devices, where the 8 lanes of a workgroup are one SIMD batch and everything
// per tile is uniform; 1 on GPUs, a lane per pixel). Per pixel: its key from the key buffer
// (where small triangles went by atomicMin, only if the bin has any), then the bin's large
// triangles rasterized against the whole tile at once, the smallest key kept in registers; the
// winner's Gouraud colour -> packed RGBA8. Untouched bins keep the background the host filled in.
// Keys read are reset for the next frame (or left final, for diffs).
#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_control_flow_attributes : require
#include "shared.h"
#include "raster.h"
#include "bindings.glsl"

layout(local_size_x = TILE_SIZE, local_size_y_id = SPEC_RESOLVE_LANE_ROWS) in;
layout(constant_id = SPEC_INTERPOLATION) const uint INTERPOLATION = INTERP_PERSPECTIVE;
const int ROWS = int(TILE_SIZE / gl_WorkGroupSize.y);  // pixels per lane, down its column

// Lowers best[] (the keys of this lane's pixels, tile rows row0 + r) by large triangle t, bin
// entry e, over the tile at `origin`, noting in winner[] the entry that now holds each key. The
// tile is classified once; a tile wholly inside skips the edge tests. False if it is all outside.
bool rasterizeLarge(LargeTriangle t, uint e, ivec2 origin, int column, int row0,
                    INOUT_ARRAY(uint64_t, best, TILE_SIZE), INOUT_ARRAY(uint, winner, TILE_SIZE)) {
  BlockEdges edges = blockEdges(t, origin);
  int block = classifyBlock(t, edges, origin, int(TILE_SIZE));
  if (block == BLOCK_OUTSIDE) return false;
  [[unroll]] for (int r = 0; r < ROWS; ++r) {
    if (block == BLOCK_INSIDE || coversInBlock(t, edges, column, row0 + r)) {
      uint64_t key = planeKey(t.plane, t.zMin, t.zMax, t.triangle, origin.x + column, origin.y + row0 + r, frame);
      if (key < best[r]) {
        best[r] = key;
        winner[r] = e;
      }
    }
  }
  return true;
}

// Triangle `id`'s Gouraud constants (raster.h).
GouraudTriangle loadGouraud(uint id) {
  ShadedVertex a, b, c;
  loadTriangle(id, a, b, c);
  return gouraudTriangle(a, b, c);
}

// This lane's pixels of the tile at `origin` (pixels) in a bin whose large-triangle list starts
// at `head`; `keysWritten` when small triangles wrote keys in the tile. A tile that neither they
// nor a large triangle touched keeps the background (and its keys stay clear).
void resolveTile(ivec2 origin, uint head, bool keysWritten) {
  int column = int(gl_LocalInvocationID.x);
  int row0 = int(gl_LocalInvocationID.y) * ROWS;
  int x = origin.x + column;
  uint64_t best[TILE_SIZE];
  uint winner[TILE_SIZE];  // the bin entry whose large triangle holds best[r], or LIST_END
  uint color[TILE_SIZE];
  [[unroll]] for (int r = 0; r < ROWS; ++r) {
    int y = origin.y + row0 + r;
    best[r] = KEY_CLEAR;
    if (keysWritten && x < int(frame.width) && y < int(frame.height)) best[r] = keys[uint(y) * frame.width + uint(x)];
    winner[r] = LIST_END;
    color[r] = packColor(frame.background);
  }
  bool touched = keysWritten;
  for (uint e = head; e != LIST_END; e = largeEntries[e].y) {
    if (rasterizeLarge(largeSetups[largeEntries[e].x], e, origin, column, row0, best, winner)) touched = true;
  }
  if (!touched) return;
  // Pixels won by a large triangle: its vertices are loaded and set up once for the tile.
  for (uint e = head; e != LIST_END; e = largeEntries[e].y) {
    GouraudTriangle g = loadGouraud(largeSetups[largeEntries[e].x].triangle);
    [[unroll]] for (int r = 0; r < ROWS; ++r) {
      if (winner[r] == e) color[r] = shadePixel(g, x, origin.y + row0 + r, frame, INTERPOLATION);
    }
  }
  [[unroll]] for (int r = 0; r < ROWS; ++r) {
    int y = origin.y + row0 + r;
    if (x >= int(frame.width) || y >= int(frame.height)) continue;
    uint i = uint(y) * frame.width + uint(x);
    if (keysWritten) {
      if (winner[r] == LIST_END && best[r] != KEY_CLEAR) color[r] = shadePixel(loadGouraud(uint(best[r] & 0xFFFFFFFFul)), x, y, frame, INTERPOLATION);
      if (frame.keepKeys == 0u) keys[i] = KEY_CLEAR;
    }
    if (frame.keepKeys != 0u) keys[i] = best[r];
    colors[i] = color[r];
  }
}

void main() {
  for (uint k = gl_WorkGroupID.x; k < binList.count; k += gl_NumWorkGroups.x) {
    uint packed = binData[2u * frame.binCount + k];
    uvec2 bin = uvec2(packed & 0xFFFFu, packed >> 16);
    uint index = bin.y * frame.binsX + bin.x;
    uint flags = binData[index];
    uint head = binData[frame.binCount + index];
    [[dont_unroll]] for (uint tile = 0u; tile < BIN_TILES * BIN_TILES; ++tile) {
      uvec2 origin = (bin * BIN_TILES + uvec2(tile % BIN_TILES, tile / BIN_TILES)) * TILE_SIZE;
      if (origin.x < frame.width && origin.y < frame.height) resolveTile(ivec2(origin), head, ((flags >> (BIN_KEYS_SHIFT + tile)) & 1u) != 0u);
    }
  }
}
