// Background pass: fills the colour buffer (RGB bytes, shared.h BINDING_COLOR) with the frame's
// background before resolve writes the covered pixels; untouched bins are never resolved and keep
// it. Three bytes a pixel repeat every 12 bytes, which vkCmdFillBuffer's 4-byte pattern cannot
// express, so each invocation writes one whole word of the pattern (color_slots.h rgbWord, as the pack
// pass builds its words).
#version 460
#extension GL_GOOGLE_include_directive : require
#include "extensions.glsl"

#include "gouraud.h"
#include "color_slots.h"
#include "bindings.glsl"

layout(local_size_x = FILL_GROUP_SIZE) in;

layout(std430, binding = BINDING_COLOR) writeonly buffer ColorWords { uint colorWords[]; };

void main() {
  loadUniforms();
  uint rgb = packColor(frame.background);
  uint words = (3u * frame.width * frame.height + 3u) / 4u;
  for (uint w = gl_GlobalInvocationID.x; w < words; w += gl_NumWorkGroups.x * FILL_GROUP_SIZE) {
    colorWords[w] = rgbWord(w, rgb, rgb);
  }
  checkLoopBudget();
}
