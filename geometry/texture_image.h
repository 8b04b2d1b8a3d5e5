// texture_image.h — a decoded base-colour texture as a mesh carries it (docs/DESIGN.md "Textures").
#pragma once

#include "shaders/shared.h"

#include <cstdint>
#include <string>
#include <vector>

namespace phongvk {

// RGBA8 texels (red in the low byte), row 0 at the image's top: texture coordinate (0, 0) is the
// top-left corner of texel 0, (1, 1) the bottom-right corner of the last. Each side is 1 to
// gpu::TEXTURE_MAX_SIDE texels. The wrap modes (gpu::TEXTURE_WRAP_*) say what a coordinate outside
// [0, 1] samples, across (u) and down (v).
struct TextureImage {
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<uint32_t> texels;
  uint32_t wrapU = gpu::TEXTURE_WRAP_REPEAT;
  uint32_t wrapV = gpu::TEXTURE_WRAP_REPEAT;
};

}  // namespace phongvk
