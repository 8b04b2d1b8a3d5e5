// selftest_wide_int.comp — the GLSL side of wide_int.h, on the device: invocation i takes the points
// a, b, p at inputs[3i..3i+2] and writes the edge function e of a, b, p, that plus a's x and
// floor(e / 256) as words (lo, hi), and floor(e / 256) and a.x + b.y held to [0, 2^32 - 1], which
// the host compares with int64_t (tests/wide_int_gpu_test.cpp). No 64-bit
// type: it runs where the 32-bit arithmetic is all there is.
#version 460
#extension GL_GOOGLE_include_directive : require

#include "wide_int.h"

layout(local_size_x = 64) in;

layout(push_constant) uniform Params {
  uint cases;
} params;

layout(std430, binding = 0) readonly buffer Inputs { ivec2 inputs[]; };
layout(std430, binding = 1) writeonly buffer Results { uvec2 results[]; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= params.cases) return;
  ivec2 a = inputs[3u * i], b = inputs[3u * i + 1u], p = inputs[3u * i + 2u];
  Wide e = wideEdgeFunction(a, b, p);
  Wide sum = wideAdd(e, wideOf(a.x));
  Wide eighth = wideFloorDiv256(e);
  results[4u * i] = uvec2(e.lo, e.hi);
  results[4u * i + 1u] = uvec2(sum.lo, sum.hi);
  results[4u * i + 2u] = uvec2(eighth.lo, eighth.hi);
  results[4u * i + 3u] = uvec2(wideClampToUint(eighth), wideClampToUint(wideAdd(wideOf(a.x), wideOf(b.y))));
}
