// png_read.cpp — PNG files read back as 8-bit RGB (stb_image), for diffs, tests and tools.
#include "phongvk/image.h"

#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb_image.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace phongvk {

Image readPng(const std::string& path) {
  int w = 0, h = 0, channels = 0;
  uint8_t* data = stbi_load(path.c_str(), &w, &h, &channels, 3);
  if (!data) throw std::runtime_error("cannot read PNG '" + path + "': " + stbi_failure_reason());
  Image image(w, h);
  std::memcpy(image.rgb.data(), data, image.rgb.size());
  stbi_image_free(data);
  return image;
}

bool pngIsComplete(const std::string& path, int width, int height) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) return false;
  std::ifstream in(path, std::ios::binary);
  unsigned char head[24] = {}, tail[12] = {};
  if (!in.read(reinterpret_cast<char*>(head), sizeof head)) return false;
  if (!in.seekg(-std::streamoff(sizeof tail), std::ios::end) || !in.read(reinterpret_cast<char*>(tail), sizeof tail)) {
    return false;
  }
  static const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  static const unsigned char iend[12] = {0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xAE, 0x42, 0x60, 0x82};
  auto bigEndian = [&](int at) {
    return uint32_t(head[at]) << 24 | uint32_t(head[at + 1]) << 16 | uint32_t(head[at + 2]) << 8 | uint32_t(head[at + 3]);
  };
  return std::memcmp(head, signature, 8) == 0 && std::memcmp(head + 12, "IHDR", 4) == 0 &&
         bigEndian(16) == uint32_t(width) && bigEndian(20) == uint32_t(height) && std::memcmp(tail, iend, 12) == 0;
}

}  // namespace phongvk
