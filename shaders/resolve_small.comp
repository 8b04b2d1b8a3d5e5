// Second resolve pass (resolve.glsl): the tiles small triangles touched, in every bin, a lane per
// pixel. Per pixel whose key is still set (resolve_large took the pixels large triangles won):
// the winning key's triangle -> Gouraud colour -> packed RGBA8, stored by resolve.glsl
// storeColor. Pixels nothing covered are left alone (the background: the host's or
// pack_colors.comp's in the key slots, fill_background.comp's in the colour buffer).
// Kept apart from resolve_large.comp because on lavapipe the mere presence of that pass's code
// makes this simple path several times slower. It visits only the flagged tiles (a bit loop, not
// a test of all 16): on lavapipe each empty iteration of a 64-lane group costs ~0.1 us, and a
// floor of large triangles touches every bin, so testing all tiles took ~5 ms of a 17 ms frame.
#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_control_flow_attributes : require
#include "gouraud.h"
#include "bindings.glsl"
#include "resolve.glsl"

layout(local_size_x = TILE_SIZE, local_size_y = TILE_SIZE) in;

void resolvePixelOf(uvec2 origin) {
  int x = int(origin.x + gl_LocalInvocationID.x);
  int y = int(origin.y + gl_LocalInvocationID.y);
  if (!inImage(x, y)) return;
  uint i = pixelIndex(x, y);
  uint64_t key = keys[i];
  if (key >= KEY_COLOR_TAG) return;  // uncovered, or resolved by resolve_large
  storeColor(i, shadePixel(loadGouraud(uint(key & 0xFFFFFFFFul)), x, y, frame, INTERPOLATION), key);
}

void main() {
  loadUniforms();
  for (uint k = gl_WorkGroupID.x; k < binList.count; k += gl_NumWorkGroups.x) {
    Bin b = touchedBin(k);
    // The tiles small triangles wrote keys in, lowest first (none: only large triangles, resolve_large's);
    // every tile where resolve_large left keys instead of colours (LIST_CHUNK).
    uint keyTiles = LIST_CHUNK == 0u ? b.flags >> BIN_KEYS_SHIFT : (1u << (BIN_TILES * BIN_TILES)) - 1u;
    [[dont_unroll]] for (uint tiles = keyTiles; tiles != 0u; tiles &= tiles - 1u) {
      resolvePixelOf(tileOrigin(b, uint(findLSB(tiles))));
    }
  }
  checkLoopBudget();
}
