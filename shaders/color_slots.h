// color_slots.h — how the GPU renderer hands colours over: a resolved pixel's colour kept in its
// key slot, and the RGB bytes of the colour buffer built a word at a time (not part of the
// contract: the reference writes its image directly).
#ifndef PHONGVK_COLOR_SLOTS_H
#define PHONGVK_COLOR_SLOTS_H

#include "glsl_cpp.h"
#include "shared.h"
#include "depth.h"

SHARED_BEGIN

// A resolved pixel's final colour kept in its key slot (RESOLVE_OUTPUT_KEY_SLOTS): this tag above,
// the packed RGBA8 below. The tag's upper word is a NaN's bits, so no depth key reaches it: every
// slot at or above the tag (KEY_CLEAR included) holds no key, and a pass skips it.
PHONGVK_CONST uint KEY_COLOR_TAG_HIGH = 0xFFFFFFFEu;

FN VisibilityKey colorSlot(uint color) { return keyOf(KEY_COLOR_TAG_HIGH, color); }

// Whether a slot holds a depth key (not a colour, not KEY_CLEAR).
FN bool slotHoldsKey(VisibilityKey slot) { return keyHigh(slot) < KEY_COLOR_TAG_HIGH; }

// Word w (bytes 4w..4w+3) of an image's RGB bytes, pixel k at bytes 3k..3k+2, from the packed
// colours (r in the low byte) of pixel 4w / 3, the first it reaches into, and the pixel after it:
// byte 4w + j is channel (4w + j) % 3 of pixel (4w + j) / 3.
FN uint rgbWord(uint w, uint first, uint next) {
  uint word = 0u;
  for (uint j = 0u; j < 4u; ++j) {
    uint k = 4u * w + j;
    uint color = k / 3u == 4u * w / 3u ? first : next;
    word |= ((color >> (8u * (k % 3u))) & 0xFFu) << (8u * j);
  }
  return word;
}

SHARED_END

#endif  // PHONGVK_COLOR_SLOTS_H
