// base64.cpp — see base64.h.
#include "base/base64.h"

#include <cstdint>

namespace phongvk {

namespace {

constexpr char ALPHABET[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

// A character's six bits, -2 for the padding '=', -1 outside the alphabet.
int sextet(char c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return c - 'a' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  if (c == '+') return 62;
  if (c == '/') return 63;
  return c == '=' ? -2 : -1;
}

}  // namespace

std::string base64Encoded(std::string_view bytes) {
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (size_t i = 0; i < bytes.size(); i += 3) {
    const size_t left = bytes.size() - i;
    uint32_t v = uint32_t(uint8_t(bytes[i])) << 16;
    if (left > 1) v |= uint32_t(uint8_t(bytes[i + 1])) << 8;
    if (left > 2) v |= uint8_t(bytes[i + 2]);
    out += ALPHABET[v >> 18];
    out += ALPHABET[(v >> 12) & 63];
    out += left > 1 ? ALPHABET[(v >> 6) & 63] : '=';
    out += left > 2 ? ALPHABET[v & 63] : '=';
  }
  return out;
}

std::optional<std::string> base64Decoded(std::string_view text) {
  std::string out;
  out.reserve(text.size() / 4 * 3);
  uint32_t bits = 0;
  int count = 0;
  for (char c : text) {
    const int value = sextet(c);
    if (value == -1) return std::nullopt;
    if (value == -2) break;
    bits = bits << 6 | uint32_t(value);
    if ((count += 6) >= 8) out += char((bits >> (count -= 8)) & 0xFF);
  }
  return out;
}

}  // namespace phongvk
