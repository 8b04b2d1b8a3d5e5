// resolve.glsl — what the two resolve passes share (after bindings.glsl): both walk the touched
// bins (bindings.glsl), one workgroup per bin at a time (grid-stride): resolve_large the bins with
// large triangles, then resolve_small the tiles small triangles touched.
#include "color_slots.h"

layout(constant_id = SPEC_INTERPOLATION) const uint INTERPOLATION = INTERP_PERSPECTIVE;
layout(constant_id = SPEC_RESOLVE_OUTPUT) const uint OUTPUT = RESOLVE_OUTPUT_KEY_SLOTS;
// 0: resolve_large takes each bin's whole list of large triangles. N > 0 (frames whose lists are
// too long for the loop budget; gpu_layout.h LIST_CHUNK_FIRST): its keys build takes the next N
// entries of each list per dispatch, in rounds, keeping the smallest keys in the key buffer.
layout(constant_id = SPEC_LIST_CHUNK) const uint LIST_CHUNK = 0u;
// Flat and Phong shading (render.shading) light each pixel once, from its winning key (deferred):
// resolve_large's keys build leaves the keys, and resolve_lit lights every covered pixel.
layout(constant_id = SPEC_SHADING) const uint SHADING = SHADING_GOURAUD;
// The second resolve pass (resolve_keys.glsl): resolve_large left every winner's key (its keys
// build) instead of its colour, so every covered pixel of the touched bins is coloured.
// A scene with textures: every pixel is coloured by resolve_lit, which samples them (texture.h).
layout(constant_id = SPEC_TEXTURED) const bool TEXTURED = false;
const bool KEYS_ONLY = LIST_CHUNK != 0u || SHADING != SHADING_GOURAUD || TEXTURED;

// A touched bin: its first pixel, its flags (shared.h BIN_*), the head of its large-triangle list
// and its index in the bin grid.
struct Bin {
  uvec2 origin;
  uint flags;
  uint head;
  uint index;
};

Bin touchedBin(uint k) {
  uint packed = binData[2u * control.binCount + k];
  uvec2 bin = uvec2(packed & 0xFFFFu, packed >> 16);
  uint index = bin.y * control.binsX + bin.x;
  return Bin(bin * BIN_SIZE, binData[index], binData[control.binCount + index], index);
}

// The first pixel of the bin's tile t (row-major), and whether small triangles wrote keys in it.
uvec2 tileOrigin(Bin b, uint t) { return b.origin + uvec2(t % BIN_TILES, t / BIN_TILES) * TILE_SIZE; }

bool tileKeysWritten(Bin b, uint t) { return ((b.flags >> (BIN_KEYS_SHIFT + t)) & 1u) != 0u; }

bool inImage(int x, int y) { return x < int(frame.width) && y < int(frame.height); }

uint pixelIndex(int x, int y) { return uint(y) * frame.width + uint(x); }

// Pixel i's final colour, won by `key`, where OUTPUT says: into its key slot, or, for diffs, into
// the colour buffer as three bytes (shared.h BINDING_COLOR) with the final key kept.
void storeColor(uint i, uint color, VisibilityKey key) {
  if (OUTPUT == RESOLVE_OUTPUT_KEY_SLOTS) {
    storeKey(i, colorSlot(color));
    return;
  }
  storeKey(i, key);
  storeColorByte(3u * i, color & 0xFFu);
  storeColorByte(3u * i + 1u, (color >> 8) & 0xFFu);
  storeColorByte(3u * i + 2u, (color >> 16) & 0xFFu);
}

