// image.h — 8-bit RGB images, what both renderers return, and PNG files.
#pragma once

#include "phongvk/export.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace phongvk {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<uint8_t> rgb;  // row 0 at the top, 3 bytes per pixel, rows packed

  Image() = default;
  Image(int w, int h) : width(w), height(h), rgb(static_cast<size_t>(w) * h * 3, 0) {}
  const uint8_t* pixel(int x, int y) const { return &rgb[(static_cast<size_t>(y) * width + x) * 3]; }
  uint8_t* pixel(int x, int y) { return &rgb[(static_cast<size_t>(y) * width + x) * 3]; }
};

// An image with its per-pixel visibility keys: (depth32 << 32) | triangle id, or all ones where no
// triangle covers the pixel. Keys are empty unless they were asked for (Renderer::renderWithKeys).
struct RenderOutput {
  Image image;
  std::vector<uint64_t> keys;
};

// The visibility buffer of a render with keys: per pixel, the winning triangle's index in the
// scene (objects in order, each object's triangles in order) or NO_TRIANGLE, and the winning
// fragment's view depth (+inf where nothing covers the pixel). Both come from the key
// (depth32 << 32) | triangle (docs/DESIGN.md "Visibility").
inline constexpr uint32_t NO_TRIANGLE = 0xFFFFFFFFu;
struct Visibility {
  int width = 0;
  int height = 0;
  std::vector<uint32_t> triangle;
  std::vector<float> depth;
};
// Throws std::invalid_argument when `out` has no keys (one per pixel).
PHONGVK_API Visibility visibilityOf(const RenderOutput& out);

// The image as PNG bytes (zlib deflate, every row filtered "Sub").
PHONGVK_API std::vector<uint8_t> encodePng(const Image& image);

// Encodes the image as PNG and writes it atomically: a temporary file in the same folder, then a rename, so a failed or
// interrupted write never leaves a partial file. Throws OutputError naming the path and the reason.
PHONGVK_API void writePng(const std::string& path, const Image& image);

// Throws OutputError, naming the reason, when a file at `path` could not be written (its folder is
// missing, not a folder or not writable, or the path is a folder); call it before long work. An
// empty path is fine (nothing to write).
PHONGVK_API void checkWritable(const std::string& path);

// Reads a PNG as 8-bit RGB. Throws std::runtime_error naming the path.
PHONGVK_API Image readPng(const std::string& path);

}  // namespace phongvk
