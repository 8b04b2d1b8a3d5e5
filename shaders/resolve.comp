// Resolve pass: one workgroup per 8x8 tile. A tile no triangle touched is skipped (the host
// filled the colours with the background). Otherwise, per pixel, the winning key's triangle ->
// Gouraud colour -> packed RGBA8, and the key and the tile are reset for the next frame.
#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#include "shared.h"
#include "raster.h"
#include "bindings.glsl"

layout(local_size_x = RESOLVE_GROUP_X, local_size_y = RESOLVE_GROUP_Y) in;
layout(constant_id = SPEC_INTERPOLATION) const uint INTERPOLATION = INTERP_PERSPECTIVE;

shared bool touched;

void main() {
  uint tile = gl_WorkGroupID.y * frame.tilesX + gl_WorkGroupID.x;
  if (gl_LocalInvocationIndex == 0u) touched = tiles[tile] != 0u;
  barrier();
  if (!touched) return;
  if (gl_LocalInvocationIndex == 0u) tiles[tile] = 0u;

  uvec2 pixel = gl_GlobalInvocationID.xy;
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
