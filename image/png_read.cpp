// png_read.cpp — PNG files read back as 8-bit RGB or RGBA or 16-bit grey (stb_image), for diffs, tests
// and tools. stb_image is compiled here with its PNG and JPEG decoders (texture_decode.cpp decodes
// textures with it too).
#include "phongvk/image.h"

#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#include <stb_image.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace phongvk {

namespace {

// The file's pixels with `channels` samples each (stb_image converts), as T: uint8_t or uint16_t.
template <typename T>
std::vector<T> loadPixels(const std::string& path, int channels, int& width, int& height) {
  int fileChannels = 0;
  T* data = nullptr;
  if constexpr (sizeof(T) == 1) {
    data = stbi_load(path.c_str(), &width, &height, &fileChannels, channels);
  } else {
    data = stbi_load_16(path.c_str(), &width, &height, &fileChannels, channels);
  }
  if (!data) throw Error("cannot read PNG '" + path + "': " + stbi_failure_reason());
  std::vector<T> pixels(data, data + size_t(width) * size_t(height) * size_t(channels));
  stbi_image_free(data);
  return pixels;
}

}  // namespace

Image readPng(const std::string& path) {
  Image image;
  image.rgb = loadPixels<uint8_t>(path, 3, image.width, image.height);
  return image;
}

ImageRGBA readPngRGBA(const std::string& path) {
  ImageRGBA image;
  image.rgba = loadPixels<uint8_t>(path, 4, image.width, image.height);
  return image;
}

ImageGrey16 readPngGrey16(const std::string& path) {
  ImageGrey16 image;
  image.grey = loadPixels<uint16_t>(path, 1, image.width, image.height);
  return image;
}

}  // namespace phongvk
