// packed_pixels.h — pixels from the renderers' packed RGBA8 words (r in the low byte, as the
// shaders write them) into an Image's RGB bytes.
#pragma once

#include "phongvk/image.h"

#include <bit>
#include <cstdint>
#include <cstring>
#include <span>

namespace phongvk {

// Pixel i (row-major) from a packed word; alpha dropped.
inline void setPacked(Image& image, size_t i, uint32_t packed) {
  image.rgb[i * 3 + 0] = static_cast<uint8_t>(packed);
  image.rgb[i * 3 + 1] = static_cast<uint8_t>(packed >> 8);
  image.rgb[i * 3 + 2] = static_cast<uint8_t>(packed >> 16);
}

// Pixels i..i+3 from four packed words: two stores (8 + 4 bytes) instead of twelve byte stores,
// which reads an image faster (docs/PERFORMANCE.md, "Readback"). The words are built in registers:
// an array stored as three words and read back as two stalls store forwarding (slower than byte
// stores).
inline void setPackedFour(Image& image, size_t i, uint32_t p0, uint32_t p1, uint32_t p2, uint32_t p3) {
  static_assert(std::endian::native == std::endian::little, "the words hold r, g, b in byte order");
  const uint64_t first = (p0 & 0xFFFFFFull) | (uint64_t(p1 & 0xFFFFFFu) << 24) | (uint64_t(p2 & 0xFFFFu) << 48);
  const uint32_t last = ((p2 >> 16) & 0xFFu) | (p3 << 8);
  std::memcpy(&image.rgb[i * 3], &first, sizeof first);
  std::memcpy(&image.rgb[i * 3 + 8], &last, sizeof last);
}

// An image from one packed word per pixel.
Image imageFromPacked(std::span<const uint32_t> packed, int width, int height);

}  // namespace phongvk
