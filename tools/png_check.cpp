// png_check.cpp — see png_check.h.
#include "tools/png_check.h"

#include <libdeflate.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace phongvk {

namespace {

uint32_t bigEndian(const unsigned char* p) { return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | uint32_t(p[3]); }

}  // namespace

// Whole, as written: the signature, an IHDR of the size asked for first, then chunks each of whose
// CRC matches its type and data, up to an IEND that ends the file. A frame whose bytes were cut,
// zeroed or overwritten anywhere fails a CRC (or the walk), and is rendered again.
bool pngIsComplete(const std::string& path, int width, int height) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) return false;
  std::ifstream in(path, std::ios::binary);
  const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const auto* p = reinterpret_cast<const unsigned char*>(bytes.data());
  static const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  if (bytes.size() < 8 + 25 || std::memcmp(p, signature, 8) != 0) return false;
  if (std::memcmp(p + 12, "IHDR", 4) != 0 || bigEndian(p + 16) != uint32_t(width) || bigEndian(p + 20) != uint32_t(height))
    return false;
  for (size_t at = 8; bytes.size() - at >= 12;) {  // length, type, data, CRC
    const uint32_t length = bigEndian(p + at);
    if (length > bytes.size() - at - 12) return false;
    if (uint32_t(libdeflate_crc32(0, p + at + 4, size_t(length) + 4)) != bigEndian(p + at + 8 + length)) return false;
    const bool end = std::memcmp(p + at + 4, "IEND", 4) == 0;
    at += 12 + size_t(length);
    if (end) return at == bytes.size();
  }
  return false;
}

}  // namespace phongvk
