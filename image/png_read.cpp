// png_read.cpp — PNG files read back as 8-bit RGB (stb_image), for diffs, tests and tools.
#include "phongvk/image.h"

#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb_image.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace phongvk {

Image readPng(const std::string& path) {
  int w = 0, h = 0, channels = 0;
  uint8_t* data = stbi_load(path.c_str(), &w, &h, &channels, 3);
  if (!data) throw Error("cannot read PNG '" + path + "': " + stbi_failure_reason());
  Image image(w, h);
  std::memcpy(image.rgb.data(), data, image.rgb.size());
  stbi_image_free(data);
  return image;
}

}  // namespace phongvk
