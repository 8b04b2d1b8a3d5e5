// texture_access.h — the texels a Texture shares, for the library's own use (Scene::add hands them
// to the material that takes the texture).
#pragma once

#include "geometry/texture_image.h"
#include "phongvk/scene_parts.h"

#include <memory>

namespace phongvk {

struct TextureAccess {
  static const std::shared_ptr<const TextureImage>& image(const Texture& texture);
};

}  // namespace phongvk
