// Colour pass (the colour buffer in host memory, a discrete GPU's): resolve has left every pixel's
// final colour in its key slot (color_slots.h colorSlot; KEY_CLEAR where nothing covered it, which gets
// the background); this pass packs them into the colour buffer's RGB bytes, one whole word per
// invocation, so a subgroup's stores are consecutive words (the next frame clears the slots).
// Resolve's own stores were three single bytes per pixel from scattered lanes into host memory
// over PCIe, which made a screen-filling floor's resolve slow on the H100; storing one byte per
// pixel instead of three made other scenes slower, not faster (partial lines there are what
// cost); three words per invocation, each subgroup store every third word, were as slow
// (docs/PERFORMANCE.md, "Readback").
#version 460
#extension GL_GOOGLE_include_directive : require
#include "extensions.glsl"

#include "gouraud.h"
#include "color_slots.h"
#include "bindings.glsl"

layout(local_size_x = PACK_GROUP_SIZE) in;

layout(std430, binding = BINDING_COLOR) writeonly buffer ColorWords { uint colorWords[]; };

// Pixel i's RGB (low three bytes); the background where nothing covered it or past the last pixel.
uint colorOf(uint i, uint pixels, uint background) {
  if (i >= pixels) return background;
  VisibilityKey slot = loadKey(i);
  return slot == KEY_CLEAR ? background : keyLow(slot) & 0xFFFFFFu;
}

void main() {
  loadUniforms();
  uint background = packColor(frame.background) & 0xFFFFFFu;
  uint pixels = frame.width * frame.height;
  uint words = (3u * pixels + 3u) / 4u;
  for (uint w = gl_GlobalInvocationID.x; w < words; w += gl_NumWorkGroups.x * PACK_GROUP_SIZE) {
    uint first = 4u * w / 3u;
    colorWords[w] = rgbWord(w, colorOf(first, pixels, background), colorOf(first + 1u, pixels, background));
  }
  checkLoopBudget();
}
