// texture_decode.cpp — see texture_decode.h. stb_image's implementation is compiled in
// png_read.cpp (PNG and JPEG only).
#include "image/texture_decode.h"

#include "base/regular_file.h"
#include "phongvk/errors.h"

#include <stb_image.h>

#include <climits>
#include <cstring>
#include <memory>
#include <optional>
#include <string_view>

namespace phongvk {

namespace {

[[noreturn]] void fail(const std::string& what, const std::string& why) { throw SceneError(what + ": " + why); }

// Encoded images over 1 GiB are refused before decoding (stb_image takes an int size).
constexpr size_t MAX_ENCODED_BYTES = size_t(1) << 30;

}  // namespace

TextureImage decodeTexture(const std::string& bytes, const std::string& what) {
  if (bytes.size() > MAX_ENCODED_BYTES || bytes.size() > size_t(INT_MAX)) fail(what, "the image file is over 1 GiB");
  const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
  const int size = int(bytes.size());
  int width = 0, height = 0, channels = 0;
  if (!stbi_info_from_memory(data, size, &width, &height, &channels)) {
    fail(what, std::string("not a PNG or JPEG image (") + stbi_failure_reason() + ")");
  }
  const uint32_t side = gpu::TEXTURE_MAX_SIDE;
  if (width <= 0 || height <= 0 || uint32_t(width) > side || uint32_t(height) > side) {
    fail(what, "the image is " + std::to_string(width) + "x" + std::to_string(height) + " pixels; a texture's sides are 1 to " +
                   std::to_string(side));
  }
  std::unique_ptr<stbi_uc, void (*)(void*)> pixels(stbi_load_from_memory(data, size, &width, &height, &channels, 4),
                                                    stbi_image_free);
  if (!pixels) fail(what, std::string("cannot decode the image (") + stbi_failure_reason() + ")");
  TextureImage texture;
  texture.width = uint32_t(width);
  texture.height = uint32_t(height);
  texture.texels.resize(size_t(width) * size_t(height));
  std::memcpy(texture.texels.data(), pixels.get(), texture.texels.size() * 4);  // RGBA bytes: red in the low byte
  return texture;
}

namespace {

// RFC 4648 base64 (padding optional, no line breaks), or nothing for a character outside it.
std::optional<std::string> base64Decoded(std::string_view text) {
  std::string out;
  uint32_t bits = 0;
  int count = 0;
  for (char c : text) {
    int value = c >= 'A' && c <= 'Z' ? c - 'A' : c >= 'a' && c <= 'z' ? c - 'a' + 26 : c >= '0' && c <= '9' ? c - '0' + 52
              : c == '+' ? 62 : c == '/' ? 63 : c == '=' ? -2 : -1;
    if (value == -1) return std::nullopt;
    if (value == -2) break;
    bits = bits << 6 | uint32_t(value);
    if ((count += 6) >= 8) out += char((bits >> (count -= 8)) & 0xFF);
  }
  return out;
}

}  // namespace

TextureImage readTextureSource(const std::string& source, const std::string& what) {
  if (source.rfind("data:", 0) != 0) return readTextureFile(source, what);
  const size_t comma = source.find(',');
  const std::string header = source.substr(0, std::min(comma, source.size()));
  if (comma == std::string::npos || (header != "data:image/png;base64" && header != "data:image/jpeg;base64"))
    fail(what, "a data URI of a texture starts data:image/png;base64, or data:image/jpeg;base64,");
  const std::optional<std::string> bytes = base64Decoded(std::string_view(source).substr(comma + 1));
  if (!bytes) fail(what, "the data URI is not base64");
  return decodeTexture(*bytes, what);
}

TextureImage readTextureFile(const std::string& path, const std::string& what) {
  std::string why;
  const std::optional<RegularFile> file = RegularFile::open(path, why);
  if (!file) fail(what, "cannot open '" + path + "': " + why);
  return decodeTexture(file->read(), what);
}

}  // namespace phongvk
