// Resolve pass: an indirect dispatch over the touched tiles (bindings.glsl), a workgroup being one
// 8x8 tile at a time; untouched tiles keep the background the host filled in. Per pixel, the
// winning key's triangle -> Gouraud colour -> packed RGBA8, and the key and the tile's flag are
// reset for the next frame.
#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#include "shared.h"
#include "raster.h"
#include "bindings.glsl"

layout(local_size_x = RESOLVE_GROUP_X, local_size_y = RESOLVE_GROUP_Y) in;
layout(constant_id = SPEC_INTERPOLATION) const uint INTERPOLATION = INTERP_PERSPECTIVE;

// This invocation's pixel of the tile at `tile` (in tiles).
void resolveTile(uvec2 tile) {
  uvec2 pixel = tile * TILE_SIZE + gl_LocalInvocationID.xy;
  if (pixel.x >= frame.width || pixel.y >= frame.height) return;
  uint i = pixel.y * frame.width + pixel.x;
  uint64_t key = keys[i];
  if (key == KEY_CLEAR) {
    colors[i] = packColor(frame.background);
    return;
  }
  keys[i] = KEY_CLEAR;
  ShadedVertex a, b, c;
  loadTriangle(uint(key & 0xFFFFFFFFul), a, b, c);
  colors[i] = resolvePixel(a, b, c, int(pixel.x), int(pixel.y), frame, INTERPOLATION);
}

void main() {
  for (uint k = gl_WorkGroupID.x; k < tileList.count; k += gl_NumWorkGroups.x) {
    uint packed = tileData[frame.tileCount + k];
    uvec2 tile = uvec2(packed & 0xFFFFu, packed >> 16);
    if (gl_LocalInvocationIndex == 0u) tileData[tile.y * frame.tilesX + tile.x] = 0u;  // only this one reads it
    resolveTile(tile);
  }
}
