#include "image/packed_pixels.h"

#include <algorithm>

namespace phongvk {

Image imageFromPacked(std::span<const uint32_t> packed, int width, int height) {
  Image image(width, height);
  const size_t n = std::min(packed.size(), static_cast<size_t>(width) * height);
  const uint32_t* in = packed.data();
  size_t i = 0;
  for (; i + 4 <= n; i += 4) setPackedFour(image, i, in[i], in[i + 1], in[i + 2], in[i + 3]);
  for (; i < n; ++i) setPacked(image, i, in[i]);
  return image;
}

}  // namespace phongvk
