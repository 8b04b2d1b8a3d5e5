// texture_decode.h — a PNG or JPEG texture decoded to RGBA8 (libpng, libjpeg-turbo), or pixels
// held in memory, checked against the texture limits before any texel is allocated.
#pragma once

#include "geometry/texture_image.h"

#include <cstdint>
#include <functional>
#include <string>

namespace phongvk {

// The image in `bytes` (PNG or JPEG, any channel count: grey, grey + alpha, RGB, RGBA; 16-bit PNGs
// reduced to 8 bits) as a texture with repeat wrapping. Throws SceneError "<what>: <why>" for an
// image that is not PNG or JPEG, is corrupt or truncated, or has a side over gpu::TEXTURE_MAX_SIDE.
TextureImage decodeTexture(const std::string& bytes, const std::string& what);

// The texture a scene names by `source`: a PNG or JPEG file, or a data URI of one
// ("data:image/png;base64,..." or "data:image/jpeg;base64,...", as glTF embeds images and
// phongvk.Material writes an array). Throws SceneError "<what>: <why>".
TextureImage readTextureSource(const std::string& source, const std::string& what);

// A texture of `width` x `height` texels that `fillRow(y, rgba)` writes, row y (0 at the top) as
// `width` RGBA8 texels: pixels held in memory (phongvk::Texture). Checked as a decoded image's
// header is, before anything is allocated: SceneError "<what>: ..." for a side outside
// 1..gpu::TEXTURE_MAX_SIDE, or texels that would pass the memory limit beside those held already.
TextureImage textureFromRows(uint32_t width, uint32_t height, const std::function<void(uint32_t, uint8_t*)>& fillRow,
                             const std::string& what);

// decodeTexture of the regular file at `path`; `what` names it in the errors, and a missing or
// unreadable file is one ("<what>: cannot open ...").
TextureImage readTextureFile(const std::string& path, const std::string& what);

}  // namespace phongvk
