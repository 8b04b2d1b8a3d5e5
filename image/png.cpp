#include "phongvk/errors.h"
#include "phongvk/image.h"

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <unistd.h>

#include <zlib.h>

namespace {

// stb_image_write's deflate, replaced by zlib's at its default level: with the "Sub" row filter
// (below) a 1385x923 frame encodes in ~18 ms into ~53 KB, where stb's own deflate and per-row
// filter search took ~55 ms for ~102 KB. Returns a malloc'd buffer, as stb frees it with STBIW_FREE.
unsigned char* zlibCompress(unsigned char* data, int length, int* outLength, int /*quality*/) {
  uLongf size = compressBound(uLong(length));
  auto* out = static_cast<unsigned char*>(std::malloc(size));
  if (out == nullptr) return nullptr;
  if (compress2(out, &size, data, uLong(length), Z_DEFAULT_COMPRESSION) != Z_OK) {
    std::free(out);
    return nullptr;
  }
  *outLength = int(size);
  return out;
}

}  // namespace

#define STBIW_ZLIB_COMPRESS zlibCompress
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb_image.h>
#include <stb_image_write.h>

namespace phongvk {

namespace {

void appendBytes(void* context, void* data, int size) {
  auto* out = static_cast<std::vector<uint8_t>*>(context);
  auto* bytes = static_cast<uint8_t*>(data);
  out->insert(out->end(), bytes, bytes + size);
}

[[noreturn]] void fail(const std::string& path, const std::string& why) {
  throw OutputError("cannot write '" + path + "': " + why);
}

}  // namespace

std::vector<uint8_t> encodePng(const Image& image) {
  // "Sub" on every row: as small as stb's per-row filter search, far faster. Set once, race-free.
  static const bool subFilter = (stbi_write_force_png_filter = 1, true);
  (void)subFilter;
  std::vector<uint8_t> encoded;
  if (!stbi_write_png_to_func(appendBytes, &encoded, image.width, image.height, 3, image.rgb.data(),
                              image.width * 3)) {
    throw std::runtime_error("PNG encoding failed");
  }
  return encoded;
}

void writePng(const std::string& path, const Image& image) {
  std::vector<uint8_t> encoded;
  try {
    encoded = encodePng(image);
  } catch (const std::runtime_error& e) {
    fail(path, e.what());
  }
  const std::filesystem::path target(path);
  const std::filesystem::path temp =
      target.parent_path() / (target.filename().string() + ".tmp-" + std::to_string(getpid()));
  FILE* file = std::fopen(temp.c_str(), "wb");
  if (!file) fail(path, std::strerror(errno));
  const bool written = std::fwrite(encoded.data(), 1, encoded.size(), file) == encoded.size();
  const int writeErrno = errno;
  const bool closed = std::fclose(file) == 0;
  if (!written || !closed) {
    std::filesystem::remove(temp);
    fail(path, std::strerror(written ? errno : writeErrno));
  }
  std::error_code ec;
  std::filesystem::rename(temp, target, ec);
  if (ec) {
    std::filesystem::remove(temp);
    fail(path, ec.message());
  }
}

void checkWritable(const std::string& path) {
  if (path.empty()) return;
  std::filesystem::path folder = std::filesystem::path(path).parent_path();
  if (folder.empty()) folder = ".";
  if (std::filesystem::exists(folder) && !std::filesystem::is_directory(folder)) {
    throw OutputError("cannot write '" + path + "': '" + folder.string() + "' is a file, not a folder");
  }
  if (!std::filesystem::is_directory(folder)) {
    throw OutputError("cannot write '" + path + "': folder '" + folder.string() + "' does not exist");
  }
  if (access(folder.c_str(), W_OK) != 0) {
    throw OutputError("cannot write '" + path + "': folder '" + folder.string() + "' is not writable");
  }
  if (std::filesystem::is_directory(path)) throw OutputError("cannot write '" + path + "': it is a folder");
}

Image readPng(const std::string& path) {
  int w = 0, h = 0, channels = 0;
  uint8_t* data = stbi_load(path.c_str(), &w, &h, &channels, 3);
  if (!data) throw std::runtime_error("cannot read PNG '" + path + "': " + stbi_failure_reason());
  Image image(w, h);
  std::memcpy(image.rgb.data(), data, image.rgb.size());
  stbi_image_free(data);
  return image;
}

}  // namespace phongvk
