// texture_decode.cpp — see texture_decode.h. stb_image's implementation is compiled in
// png_read.cpp (PNG and JPEG only).
#include "image/texture_decode.h"

#include "base/regular_file.h"
#include "phongvk/errors.h"

#include <stb_image.h>

#include <climits>
#include <cstring>
#include <memory>

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

TextureImage readTextureFile(const std::string& path, const std::string& what) {
  std::string why;
  const std::optional<RegularFile> file = RegularFile::open(path, why);
  if (!file) fail(what, "cannot open '" + path + "': " + why);
  return decodeTexture(file->read(), what);
}

}  // namespace phongvk
