// texture.cpp — see include/phongvk/scene_parts.h (Texture).
#include "phongvk/phongvk.h"

#include "api/texture_access.h"
#include "image/texture_decode.h"

#include <cstring>

namespace phongvk {

Texture::Texture(std::shared_ptr<const TextureImage> image) : image_(std::move(image)) {}

Texture Texture::fromRows(int width, int height, const std::function<void(int y, uint8_t* rgba)>& fillRow,
                          const std::string& what) {
  const auto fill = [&](uint32_t y, uint8_t* rgba) { fillRow(int(y), rgba); };
  return Texture(std::make_shared<const TextureImage>(
      textureFromRows(uint32_t(std::max(width, 0)), uint32_t(std::max(height, 0)), fill, what)));
}

Texture Texture::fromImage(const ImageRGBA& image, const std::string& what) {
  if (image.rgba.size() != size_t(std::max(image.width, 0)) * size_t(std::max(image.height, 0)) * 4)
    throw ArgumentError(what + ": an RGBA image of " + std::to_string(image.width) + " x " + std::to_string(image.height) +
                        " pixels holds " + std::to_string(image.rgba.size()) + " bytes, not 4 a pixel");
  const size_t rowBytes = size_t(image.width) * 4;
  return fromRows(image.width, image.height,
                  [&](int y, uint8_t* rgba) { std::memcpy(rgba, image.rgba.data() + size_t(y) * rowBytes, rowBytes); }, what);
}

int Texture::width() const { return int(image_->width); }
int Texture::height() const { return int(image_->height); }

const std::shared_ptr<const TextureImage>& TextureAccess::image(const Texture& texture) { return texture.image_; }

}  // namespace phongvk
