// texture_uri.cpp — see texture_uri.h.
#include "image/texture_uri.h"

#include "base/base64.h"
#include "phongvk/image.h"

#include <cstdint>
#include <string_view>

namespace phongvk {

std::string textureDataUri(const TextureImage& texture) {
  ImageRGBA image{int(texture.width), int(texture.height), std::vector<uint8_t>(texture.texels.size() * 4)};
  for (size_t i = 0; i < texture.texels.size(); ++i) {
    for (size_t c = 0; c < 4; ++c) image.rgba[4 * i + c] = uint8_t(texture.texels[i] >> (8 * c));  // red in the low byte
  }
  const std::vector<uint8_t> png = encodePng(image);
  return "data:image/png;base64," +
         base64Encoded(std::string_view(reinterpret_cast<const char*>(png.data()), png.size()));
}

}  // namespace phongvk
