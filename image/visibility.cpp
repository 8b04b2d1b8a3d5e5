// visibility.cpp — the visibility buffer (include/phongvk/image.h Visibility) from the keys.
#include "phongvk/image.h"

#include <bit>
#include <limits>
#include <stdexcept>

namespace phongvk {

Visibility visibilityOf(const RenderOutput& out) {
  const size_t pixels = size_t(out.image.width) * out.image.height;
  if (out.keys.size() != pixels) {
    throw ArgumentError("a visibility buffer needs the render's keys (renderWithKeys), one per pixel");
  }
  Visibility v;
  v.width = out.image.width;
  v.height = out.image.height;
  v.triangle.resize(pixels);
  v.depth.resize(pixels);
  for (size_t i = 0; i < pixels; ++i) {
    const uint64_t key = out.keys[i];
    const bool covered = key != ~0ull;  // the cleared key: no triangle
    v.triangle[i] = covered ? uint32_t(key) : NO_TRIANGLE;
    v.depth[i] = covered ? std::bit_cast<float>(uint32_t(key >> 32)) : std::numeric_limits<float>::infinity();
  }
  return v;
}

}  // namespace phongvk
