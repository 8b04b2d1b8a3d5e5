// texture_decode.h — a PNG or JPEG texture decoded to RGBA8 (stb_image), checked against the
// texture limits before any pixel is decoded.
#pragma once

#include "geometry/texture_image.h"

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

// decodeTexture of the regular file at `path`; `what` names it in the errors, and a missing or
// unreadable file is one ("<what>: cannot open ...").
TextureImage readTextureFile(const std::string& path, const std::string& what);

}  // namespace phongvk
