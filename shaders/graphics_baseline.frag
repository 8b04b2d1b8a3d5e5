// Graphics-pipeline baseline (graphics/graphics_renderer.h), fragment stage: the Gouraud colour the
// hardware interpolated, clamped to [0, 1]; the R8G8B8A8_UNORM attachment rounds it to 8 bits.
#version 460
#extension GL_GOOGLE_include_directive : require
#include "shared.h"

// The vertex stage's mode and varying (graphics_baseline.vert).
layout(constant_id = SPEC_INTERPOLATION) const uint INTERPOLATION = INTERP_PERSPECTIVE;
layout(location = 0) in vec4 gouraud;
layout(location = 0) out vec4 outColor;

void main() {
  vec3 color = INTERPOLATION == INTERP_SCREEN ? gouraud.xyz / gouraud.w : gouraud.xyz;
  outColor = vec4(clamp(color, vec3(0.0f), vec3(1.0f)), 1.0f);
}
