// image.h — 8-bit RGB images, what both renderers return; 8-bit RGBA and 16-bit grey images; PNG
// files of all three.
#pragma once

#include "phongvk/errors.h"
#include "phongvk/export.h"

#include <cstddef>
#include <cstdint>
#include <memory>
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

// 8-bit RGBA (a colour with its alpha, 255 opaque) and 16-bit grey (a depth in millimetres, an
// id): what PNG files hold besides RGB. Row 0 at the top, rows packed, samples in host order.
struct ImageRGBA {
  int width = 0;
  int height = 0;
  std::vector<uint8_t> rgba;  // 4 bytes per pixel
};
struct ImageGrey16 {
  int width = 0;
  int height = 0;
  std::vector<uint16_t> grey;  // 1 sample per pixel
};
// 8-bit grey: a mask (0 and 255), a coverage, an 8-bit id.
struct ImageGrey8 {
  int width = 0;
  int height = 0;
  std::vector<uint8_t> grey;  // 1 sample per pixel
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
// Throws ArgumentError when `out` has no keys (one per pixel).
PHONGVK_API Visibility visibilityOf(const RenderOutput& out);

// PNG deflate levels: 0 stores the pixels uncompressed; 1, the default, codes only runs (fastest
// on rendered frames: their filtered bytes are mostly runs of zeros); 2 to 12 are libdeflate's
// levels, from fast to the smallest files (6 is near zlib's default size). Every level decodes to
// the same pixels.
inline constexpr int PNG_LEVEL_MIN = 0;
inline constexpr int PNG_LEVEL_RUNS = 1;
inline constexpr int PNG_LEVEL_MAX = 12;
inline constexpr int PNG_LEVEL_DEFAULT = PNG_LEVEL_RUNS;

// Encodes images as PNG (every row filtered "Sub", then deflated at `level`), keeping its buffers
// from one image to the next: one per thread for a stream of frames. Not for use by two threads
// at once. Throws ArgumentError for a level outside PNG_LEVEL_MIN..PNG_LEVEL_MAX.
class PHONGVK_API PngEncoder {
 public:
  explicit PngEncoder(int level = PNG_LEVEL_DEFAULT);
  ~PngEncoder();
  PngEncoder(PngEncoder&&) noexcept;
  PngEncoder& operator=(PngEncoder&&) noexcept;

  // The PNG bytes, valid until the next call: colour type 2 (RGB), 6 (RGBA) or 0 (grey, 8 or 16
  // bits, 16-bit samples big-endian as PNG stores them). Throws ArgumentError for an image whose size and pixel
  // count disagree.
  const std::vector<uint8_t>& encode(const Image& image);
  const std::vector<uint8_t>& encode(const ImageRGBA& image);
  const std::vector<uint8_t>& encode(const ImageGrey16& image);
  const std::vector<uint8_t>& encode(const ImageGrey8& image);
  // Encodes and writes the file: atomically (a temporary file in the same folder, then a rename,
  // so a failed or interrupted write never leaves a partial file), through symbolic links, straight
  // into a character device such as /dev/null, to standard output for "-"; a FIFO, socket or block
  // device is refused, never replaced. Throws OutputError naming the path and the reason
  // (OutputWriteError when the writing itself fails).
  void write(const std::string& path, const Image& image);
  void write(const std::string& path, const ImageRGBA& image);
  void write(const std::string& path, const ImageGrey16& image);
  void write(const std::string& path, const ImageGrey8& image);

 private:
  struct State;
  struct Pixels;
  const std::vector<uint8_t>& encodePixels(const Pixels& pixels);
  template <typename AnyImage>
  void writeImage(const std::string& path, const AnyImage& image);
  std::unique_ptr<State> state_;
};

// One image's PNG bytes, or its PNG file written atomically (PngEncoder::write).
PHONGVK_API std::vector<uint8_t> encodePng(const Image& image, int level = PNG_LEVEL_DEFAULT);
PHONGVK_API void writePng(const std::string& path, const Image& image, int level = PNG_LEVEL_DEFAULT);
PHONGVK_API std::vector<uint8_t> encodePng(const ImageRGBA& image, int level = PNG_LEVEL_DEFAULT);
PHONGVK_API void writePng(const std::string& path, const ImageRGBA& image, int level = PNG_LEVEL_DEFAULT);
PHONGVK_API std::vector<uint8_t> encodePng(const ImageGrey16& image, int level = PNG_LEVEL_DEFAULT);
PHONGVK_API void writePng(const std::string& path, const ImageGrey16& image, int level = PNG_LEVEL_DEFAULT);
PHONGVK_API std::vector<uint8_t> encodePng(const ImageGrey8& image, int level = PNG_LEVEL_DEFAULT);
PHONGVK_API void writePng(const std::string& path, const ImageGrey8& image, int level = PNG_LEVEL_DEFAULT);

// Throws OutputError, naming the reason, when a file at `path` could not be written (its folder is
// missing, not a folder or not writable, or the path is a folder, FIFO, socket or block device);
// call it before long work. An empty path and "-" (standard output) are fine.
PHONGVK_API void checkWritable(const std::string& path);

// Reads a PNG as 8-bit RGB, as 8-bit RGBA (alpha 255 where the file has none), or as 16-bit grey
// (8-bit samples scaled by 257, colours as their luminance). Throws phongvk::Error naming the path.
PHONGVK_API Image readPng(const std::string& path);
PHONGVK_API ImageRGBA readPngRGBA(const std::string& path);
PHONGVK_API ImageGrey16 readPngGrey16(const std::string& path);

// `source` averaged down to width x height with a box filter: the source columns (and rows) are
// split into width (height) consecutive runs as even as integers allow, and each output pixel is
// the rounded mean of its run's pixels (how a render with samples is filtered down).
// Precondition: 1 <= width <= source.width, likewise height.
PHONGVK_API Image downscale(const Image& source, int width, int height);

}  // namespace phongvk
