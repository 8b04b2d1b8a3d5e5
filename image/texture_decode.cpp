// texture_decode.cpp — see texture_decode.h. The codecs are in png_decode.cpp and jpeg_decode.cpp.
#include "image/texture_decode.h"

#include "base/base64.h"
#include "base/memory_limit.h"
#include "base/memory_text.h"
#include "base/regular_file.h"
#include "image/texture_codecs.h"
#include "phongvk/errors.h"

#include <climits>
#include <algorithm>
#include <optional>
#include <string_view>

namespace phongvk {

namespace {

[[noreturn]] void fail(const std::string& what, const std::string& why) { throw SceneError(what + ": " + why); }

// Encoded images over 1 GiB are refused before decoding.
constexpr size_t MAX_ENCODED_BYTES = size_t(1) << 30;

// What the image's header says, before any pixel is decoded: a side within gpu::TEXTURE_MAX_SIDE,
// and its texels (width x height x 4 bytes) within the memory limit beside every texture the
// process already holds.
void checkSize(uint32_t width, uint32_t height, const std::string& what) {
  const uint32_t side = gpu::TEXTURE_MAX_SIDE;
  if (width == 0 || height == 0 || width > side || height > side) {
    fail(what, "the image is " + std::to_string(width) + "x" + std::to_string(height) + " pixels; a texture's sides are 1 to " +
                   std::to_string(side));
  }
  const uint64_t bytes = uint64_t(width) * height * 4, held = heldTexelBytes(), limit = sceneMemoryLimit();
  if (held + bytes > limit) {
    throw SceneError(memoryMessage(what, "a " + std::to_string(width) + "x" + std::to_string(height) + " texture", held + bytes,
                                   limit, std::to_string(bytes) + " bytes decoded, beside " + std::to_string(held) +
                                              " bytes of textures held already",
                                   "smaller or fewer textures fit"));
  }
}

// The first bytes of something that is not a PNG or JPEG, for the message.
std::string signatureOf(std::string_view bytes) {
  static const char* hex = "0123456789abcdef";
  std::string text;
  for (size_t i = 0; i < bytes.size() && i < 8; ++i) {
    text += std::string(i ? " " : "") + hex[uint8_t(bytes[i]) >> 4] + hex[uint8_t(bytes[i]) & 15];
  }
  return text.empty() ? "it is empty" : "it starts " + text;
}

}  // namespace

TextureRows textureRows(uint32_t width, uint32_t height) {
  TextureRows out;
  out.texture.width = width;
  out.texture.height = height;
  out.texture.texels.resize(size_t(width) * height);  // not zero-filled (texture_image.h)
  out.rows.resize(height);
  for (uint32_t y = 0; y < height; ++y) out.rows[y] = reinterpret_cast<unsigned char*>(out.texture.texels.data() + size_t(y) * width);
  return out;
}

TextureImage decodeTexture(const std::string& bytes, const std::string& what) {
  if (bytes.size() > MAX_ENCODED_BYTES || bytes.size() > size_t(INT_MAX)) fail(what, "the image file is over 1 GiB");
  const AcceptSize accept = [&](uint32_t width, uint32_t height) { checkSize(width, height, what); };
  if (isPng(bytes)) return decodePng(bytes, what, accept);
  if (isJpeg(bytes)) return decodeJpeg(bytes, what, accept);
  fail(what, "not a PNG or JPEG image (" + signatureOf(bytes) + ")");
}

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

TextureImage textureFromRows(uint32_t width, uint32_t height, const std::function<void(uint32_t, uint8_t*)>& fillRow,
                             const std::string& what) {
  checkSize(width, height, what);
  TextureRows out = textureRows(width, height);
  for (uint32_t y = 0; y < height; ++y) fillRow(y, out.rows[y]);
  return std::move(out.texture);
}

TextureImage readTextureFile(const std::string& path, const std::string& what) {
  std::string why;
  const std::optional<RegularFile> file = RegularFile::open(path, why);
  if (!file) fail(what, "cannot open '" + printablePath(path) + "': " + why);
  return decodeTexture(file->read(), what);
}

}  // namespace phongvk
