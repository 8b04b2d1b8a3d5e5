// probe_float.comp — what the device's float division, square root and fma give, next to the
// corrected operations of exact_float.h, for inputs the host checks against its IEEE results
// (vulkan/float_probe.h). The host picks the renderer's passes' `_exact` builds from this.
//
// Probe i reads (a, b, c, x) and writes five bit patterns: a / b and sqrt(x) as the device does
// them, fma(a, b, c), and the first two corrected (correctedQuotient, correctedRoot).
#version 460
#extension GL_GOOGLE_include_directive : require

#include "exact_float.h"
#include "gpu_layout.h"

layout(local_size_x = FLOAT_PROBE_GROUP_SIZE) in;

layout(push_constant) uniform Params {
  uint count;
} params;

layout(std430, binding = 0) readonly buffer Inputs {
  vec4 inputs[];
};

layout(std430, binding = 1) writeonly buffer Outputs {
  uint outputs[];  // FLOAT_PROBE_RESULTS per probe
};

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= params.count) return;
  vec4 p = inputs[i];
  precise float quotient = p.x / p.y;
  precise float root = sqrt(p.w);
  precise float fused = fma(p.x, p.y, p.z);
  uint o = i * FLOAT_PROBE_RESULTS;
  outputs[o] = floatBitsToUint(quotient);
  outputs[o + 1] = floatBitsToUint(root);
  outputs[o + 2] = floatBitsToUint(fused);
  outputs[o + 3] = floatBitsToUint(correctedQuotient(p.x, p.y, quotient));
  outputs[o + 4] = floatBitsToUint(correctedRoot(p.w, root));
}
