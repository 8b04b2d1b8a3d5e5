// selftest_atomic64.comp — proves the device's 64-bit buffer atomicMin is exact before the renderer
// trusts it with its depth|triangle keys (docs/DESIGN.md "Visibility").
//
// Invocation i folds key(i) = (depth(i) << 32) | i into keys[i % SLOT_COUNT] with atomicMin.
// depth(i) keeps only the top 8 bits of a hash, so many invocations share a depth and the winner
// is decided by the low word (the renderer's equal-depth tie-break), and half of the depths have
// bit 63 set (a signed compare would pick them). The host computes the same minima.
#version 460
#extension GL_EXT_shader_atomic_int64 : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_GOOGLE_include_directive : require

#include "shared.h"

layout(local_size_x = 64) in;

// Slots the invocations are spread over; specialized by the test to exercise SpecConstant (the
// id is shared.h's SPEC_SELFTEST_SLOTS).
layout(constant_id = SPEC_SELFTEST_SLOTS) const uint SLOT_COUNT = 4;

layout(push_constant) uniform Params {
  uint invocations;
} params;

layout(std430, binding = 0) buffer Keys {
  uint64_t keys[];
};

// lowbias32 (Chris Wellons): a well-mixed 32-bit hash; the host has the same function.
uint hash(uint x) {
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= params.invocations) return;
  uint depth = hash(i) & 0xff000000u;
  atomicMin(keys[i % SLOT_COUNT], (uint64_t(depth) << 32) | uint64_t(i));
}
