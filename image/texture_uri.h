// texture_uri.h — a decoded texture written back as a data URI: how a scene written out
// (scene/scene_write.h) names a texture that came from inside a model file, so that reading the
// scene again decodes the same texels.
#pragma once

#include "geometry/texture_image.h"

#include <string>

namespace phongvk {

// "data:image/png;base64,..." of an 8-bit RGBA PNG of the texels, which decodeTexture reads back
// bit for bit (its wrap modes are not part of it).
std::string textureDataUri(const TextureImage& texture);

}  // namespace phongvk
