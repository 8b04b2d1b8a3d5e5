// png_write.cpp — PNG encoding (PngEncoder: 8-bit RGB and RGBA, 16-bit grey) and atomic PNG files.
// Every row is filtered "Sub" (each byte minus the same byte of the pixel to its left), which turns
// a frame's flat background and smooth shading into runs of zeros, then the whole image is deflated
// in one call: at level 1 by the run-only coder (deflate_runs.h), at the others by libdeflate (docs/DECISIONS.md "PNG levels").
#include "base/huge_pages.h"
#include "image/deflate_runs.h"
#include "image/output_file.h"
#include "phongvk/errors.h"
#include "phongvk/image.h"

#include <libdeflate.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <new>
#include <stdexcept>
#include <string>
#include <unistd.h>

namespace phongvk {

namespace {

constexpr uint8_t PNG_SIGNATURE[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
constexpr uint8_t FILTER_SUB = 1;
constexpr size_t MAX_CHUNK_BYTES = size_t(1) << 30;  // a chunk's length must stay below 2^31

void appendU32(std::vector<uint8_t>& out, uint32_t value) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(uint8_t(value >> shift));
}

// One chunk: length, type, data, and the CRC of type and data.
void appendChunk(std::vector<uint8_t>& out, const char (&type)[5], const uint8_t* data, size_t size) {
  appendU32(out, uint32_t(size));
  const size_t typeAt = out.size();
  out.insert(out.end(), type, type + 4);
  out.insert(out.end(), data, data + size);
  appendU32(out, uint32_t(libdeflate_crc32(0, out.data() + typeAt, size + 4)));
}

// What the encoder takes from each kind of image: its size, its pixels in PNG byte order and how
// the header names them.
struct PixelLayout {
  int width = 0;
  int height = 0;
  size_t bytesPerPixel = 0;
  uint8_t bitDepth = 8;
  uint8_t colourType = 0;
  const uint8_t* bytes = nullptr;
};

// No interlace.
void appendHeader(std::vector<uint8_t>& out, const PixelLayout& pixels) {
  std::vector<uint8_t> header;
  appendU32(header, uint32_t(pixels.width));
  appendU32(header, uint32_t(pixels.height));
  // bit depth, colour type, deflate, adaptive filters, no interlace
  header.insert(header.end(), {pixels.bitDepth, pixels.colourType, 0, 0, 0});
  appendChunk(out, "IHDR", header.data(), header.size());
}

// Each row as the PNG stream stores it: its filter type, then every byte minus the byte one pixel
// before (0 for the row's first pixel).
void filterRows(const PixelLayout& pixels, std::vector<uint8_t>& filtered) {
  const size_t step = pixels.bytesPerPixel;
  const size_t rowBytes = size_t(pixels.width) * step;
  const size_t bytes = (rowBytes + 1) * size_t(pixels.height);
  reserveLarge(filtered, bytes);  // fresh storage on huge pages
  filtered.resize(bytes);
  for (size_t y = 0; y < size_t(pixels.height); ++y) {
    const uint8_t* row = pixels.bytes + y * rowBytes;
    uint8_t* out = filtered.data() + y * (rowBytes + 1);
    out[0] = FILTER_SUB;
    for (size_t i = 0; i < rowBytes && i < step; ++i) out[1 + i] = row[i];
    for (size_t i = step; i < rowBytes; ++i) out[1 + i] = uint8_t(row[i] - row[i - step]);
  }
}

void checkSize(int width, int height, size_t samples, size_t samplesPerPixel) {
  if (width <= 0 || height <= 0 || samples != size_t(width) * size_t(height) * samplesPerPixel) {
    throw ArgumentError("cannot encode a " + std::to_string(width) + "x" + std::to_string(height) + " image holding " +
                        std::to_string(samples) + (samplesPerPixel == 1 ? " samples" : " bytes") + " as PNG");
  }
}

}  // namespace

struct PngEncoder::Pixels : PixelLayout {};  // the layout, named where the header can declare it

struct PngEncoder::State {
  libdeflate_compressor* compressor = nullptr;  // levels other than PNG_LEVEL_RUNS
  RunDeflater runs;
  std::vector<uint8_t> bigEndian;  // a 16-bit image's samples as PNG stores them
  std::vector<uint8_t> filtered;
  std::vector<uint8_t> deflated;
  std::vector<uint8_t> png;
};

PngEncoder::PngEncoder(int level) : state_(std::make_unique<State>()) {
  if (level < PNG_LEVEL_MIN || level > PNG_LEVEL_MAX) {
    throw ArgumentError("PNG level " + std::to_string(level) + " is out of range: " +
                                std::to_string(PNG_LEVEL_MIN) + " (no compression) to " +
                                std::to_string(PNG_LEVEL_MAX) + " (smallest files)");
  }
  if (level == PNG_LEVEL_RUNS) return;
  state_->compressor = libdeflate_alloc_compressor(level);
  if (state_->compressor == nullptr) throw std::bad_alloc();
}

PngEncoder::~PngEncoder() {
  if (state_) libdeflate_free_compressor(state_->compressor);  // accepts nullptr
}

PngEncoder::PngEncoder(PngEncoder&&) noexcept = default;
PngEncoder& PngEncoder::operator=(PngEncoder&& other) noexcept {
  if (this != &other) {
    if (state_) libdeflate_free_compressor(state_->compressor);
    state_ = std::move(other.state_);
  }
  return *this;
}

const std::vector<uint8_t>& PngEncoder::encode(const Image& image) {
  checkSize(image.width, image.height, image.rgb.size(), 3);
  return encodePixels(Pixels{{image.width, image.height, 3, 8, 2, image.rgb.data()}});
}

const std::vector<uint8_t>& PngEncoder::encode(const ImageRGBA& image) {
  checkSize(image.width, image.height, image.rgba.size(), 4);
  return encodePixels(Pixels{{image.width, image.height, 4, 8, 6, image.rgba.data()}});
}

const std::vector<uint8_t>& PngEncoder::encode(const ImageGrey16& image) {
  checkSize(image.width, image.height, image.grey.size(), 1);
  std::vector<uint8_t>& bytes = state_->bigEndian;
  bytes.resize(image.grey.size() * 2);
  for (size_t i = 0; i < image.grey.size(); ++i) {
    bytes[2 * i] = uint8_t(image.grey[i] >> 8);
    bytes[2 * i + 1] = uint8_t(image.grey[i]);
  }
  return encodePixels(Pixels{{image.width, image.height, 2, 16, 0, bytes.data()}});
}

const std::vector<uint8_t>& PngEncoder::encode(const ImageGrey8& image) {
  checkSize(image.width, image.height, image.grey.size(), 1);
  return encodePixels(Pixels{{image.width, image.height, 1, 8, 0, image.grey.data()}});
}

const std::vector<uint8_t>& PngEncoder::encodePixels(const Pixels& pixels) {
  State& s = *state_;
  filterRows(pixels, s.filtered);
  size_t deflatedBytes = 0;
  if (s.compressor == nullptr) {
    s.deflated.clear();
    s.runs.deflate(s.filtered.data(), s.filtered.size(), size_t(pixels.width) * pixels.bytesPerPixel + 1, s.deflated);
    deflatedBytes = s.deflated.size();
  } else {
    s.deflated.resize(libdeflate_zlib_compress_bound(s.compressor, s.filtered.size()));
    deflatedBytes = libdeflate_zlib_compress(s.compressor, s.filtered.data(), s.filtered.size(), s.deflated.data(),
                                             s.deflated.size());
    if (deflatedBytes == 0) throw Error("PNG encoding failed: deflate output exceeded its bound");
  }
  s.png.assign(std::begin(PNG_SIGNATURE), std::end(PNG_SIGNATURE));
  appendHeader(s.png, pixels);
  for (size_t at = 0; at < deflatedBytes; at += MAX_CHUNK_BYTES) {
    appendChunk(s.png, "IDAT", s.deflated.data() + at, std::min(MAX_CHUNK_BYTES, deflatedBytes - at));
  }
  appendChunk(s.png, "IEND", nullptr, 0);
  return s.png;
}

template <typename AnyImage>
void PngEncoder::writeImage(const std::string& path, const AnyImage& image) {
  const std::vector<uint8_t>* png = nullptr;
  try {
    png = &encode(image);
  } catch (const std::bad_alloc&) {
    throw OutputError("cannot write '" + path + "': no memory to encode its " + std::to_string(image.width) + " x " +
                      std::to_string(image.height) + " PNG");
  } catch (const std::exception& e) {
    throw OutputError("cannot write '" + path + "': " + e.what());
  }
  writeOutputFile(path, *png);
}

void PngEncoder::write(const std::string& path, const Image& image) { writeImage(path, image); }
void PngEncoder::write(const std::string& path, const ImageRGBA& image) { writeImage(path, image); }
void PngEncoder::write(const std::string& path, const ImageGrey16& image) { writeImage(path, image); }
void PngEncoder::write(const std::string& path, const ImageGrey8& image) { writeImage(path, image); }

std::vector<uint8_t> encodePng(const Image& image, int level) { return PngEncoder(level).encode(image); }

void writePng(const std::string& path, const Image& image, int level) { PngEncoder(level).write(path, image); }
std::vector<uint8_t> encodePng(const ImageRGBA& image, int level) { return PngEncoder(level).encode(image); }
void writePng(const std::string& path, const ImageRGBA& image, int level) { PngEncoder(level).write(path, image); }
std::vector<uint8_t> encodePng(const ImageGrey16& image, int level) { return PngEncoder(level).encode(image); }
void writePng(const std::string& path, const ImageGrey16& image, int level) { PngEncoder(level).write(path, image); }
std::vector<uint8_t> encodePng(const ImageGrey8& image, int level) { return PngEncoder(level).encode(image); }
void writePng(const std::string& path, const ImageGrey8& image, int level) { PngEncoder(level).write(path, image); }

void checkWritable(const std::string& path) { checkOutputPath(path); }

}  // namespace phongvk
