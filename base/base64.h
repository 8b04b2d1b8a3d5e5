// base64.h — RFC 4648 base64, the encoding of the data URIs a scene names textures and glTF
// buffers by.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace phongvk {

// `bytes` in base64, padded with '=' to a multiple of four characters, without line breaks.
std::string base64Encoded(std::string_view bytes);

// The bytes `text` encodes (padding optional, no line breaks), or nothing for a character outside
// the alphabet.
std::optional<std::string> base64Decoded(std::string_view text);

}  // namespace phongvk
