// Resolve pass: per pixel, the winning key's triangle -> Gouraud colour -> packed RGBA8.
#version 460
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#include "shared.h"
#include "raster.h"
#include "bindings.glsl"

layout(local_size_x = RESOLVE_GROUP_X, local_size_y = RESOLVE_GROUP_Y) in;

void main() {
  uvec2 pixel = gl_GlobalInvocationID.xy;
  if (pixel.x >= frame.width || pixel.y >= frame.height) return;
  uint i = pixel.y * frame.width + pixel.x;
  uint64_t key = keys[i];
  if (key == KEY_CLEAR) {
    colors[i] = packColor(frame.background);
    return;
  }
  ShadedVertex a, b, c;
  loadTriangle(uint(key & 0xFFFFFFFFul), a, b, c);
  colors[i] = resolvePixel(a, b, c, int(pixel.x), int(pixel.y), frame);
}
