// texture_codecs.h — the PNG (libpng) and JPEG (libjpeg-turbo) decoders behind decodeTexture
// (texture_decode.h): each reads the header, asks `accept` about the size before any pixel is
// decoded, then decodes straight into the texture's RGBA8 texels, row by row. Every error of the
// codec is an error here, in the codec's words: a truncated or corrupt image never decodes to a
// partly blank texture.
#pragma once

#include "geometry/texture_image.h"

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace phongvk {

// Called with the image's size from its header, before any pixel is decoded; throws to refuse it.
using AcceptSize = std::function<void(uint32_t width, uint32_t height)>;

// A texture of `width` x `height` texels not yet written, and where each of its rows starts, for
// a codec to decode into.
struct TextureRows {
  TextureImage texture;
  std::vector<unsigned char*> rows;
};
TextureRows textureRows(uint32_t width, uint32_t height);

// Whether `bytes` start with the format's signature.
bool isPng(std::string_view bytes);
bool isJpeg(std::string_view bytes);

// The image in `bytes` as RGBA8 texels (grey, palette, 16-bit and alpha-less images converted;
// 16-bit samples keep their high byte). Throws SceneError "<what>: PNG: cannot read its header:
// <the codec's reason>" (or "cannot decode its pixels: ...", or "JPEG: ...").
TextureImage decodePng(std::string_view bytes, const std::string& what, const AcceptSize& accept);
TextureImage decodeJpeg(std::string_view bytes, const std::string& what, const AcceptSize& accept);

}  // namespace phongvk
