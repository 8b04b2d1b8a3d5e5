// npy_write.cpp — NumPy .npy files, format 1.0 (numpy.lib.format): the header written here, the
// values as 32-bit little-endian words.
#include "image/output_file.h"
#include "phongvk/npy.h"

#include <bit>
#include <cstring>

namespace phongvk {
namespace {

constexpr uint8_t NPY_MAGIC[8] = {0x93, 'N', 'U', 'M', 'P', 'Y', 1, 0};  // and version 1.0
constexpr size_t NPY_ALIGNMENT = 64;

// `words` (float or int32 bit patterns) under a header naming `descr`.
template <typename T>
std::vector<uint8_t> encodeWords(const std::vector<T>& values, int width, int height, int channels, const char* descr) {
  static_assert(sizeof(T) == 4);
  if (width <= 0 || height <= 0 || channels <= 0 ||
      values.size() != size_t(width) * size_t(height) * size_t(channels)) {
    throw ArgumentError("cannot write a " + std::to_string(width) + "x" + std::to_string(height) +
                        (channels == 1 ? "" : "x" + std::to_string(channels)) + " array holding " +
                        std::to_string(values.size()) + " values as .npy");
  }
  const std::string shape = std::to_string(height) + ", " + std::to_string(width) +
                            (channels == 1 ? "" : ", " + std::to_string(channels));
  std::string dict = std::string("{'descr': '") + descr + "', 'fortran_order': False, 'shape': (" + shape + "), }";
  // magic and version, a 16-bit header length, the dict, spaces, and a newline ending the header
  const size_t unpadded = sizeof NPY_MAGIC + 2 + dict.size() + 1;
  dict.append((NPY_ALIGNMENT - unpadded % NPY_ALIGNMENT) % NPY_ALIGNMENT, ' ');
  dict.push_back('\n');
  std::vector<uint8_t> bytes(std::begin(NPY_MAGIC), std::end(NPY_MAGIC));
  bytes.insert(bytes.end(), {uint8_t(dict.size()), uint8_t(dict.size() >> 8)});
  bytes.insert(bytes.end(), dict.begin(), dict.end());
  for (const T& value : values) {
    const uint32_t word = std::bit_cast<uint32_t>(value);
    bytes.insert(bytes.end(), {uint8_t(word), uint8_t(word >> 8), uint8_t(word >> 16), uint8_t(word >> 24)});
  }
  return bytes;
}

template <typename T>
void writeWords(const std::string& path, const std::vector<T>& values, int width, int height, int channels) {
  std::vector<uint8_t> bytes;
  try {
    bytes = encodeNpy(values, width, height, channels);
  } catch (const std::exception& e) {
    throw OutputError("cannot write '" + path + "': " + e.what());
  }
  writeOutputFile(path, bytes);
}

}  // namespace

std::vector<uint8_t> encodeNpy(const std::vector<float>& values, int width, int height, int channels) {
  return encodeWords(values, width, height, channels, "<f4");
}

std::vector<uint8_t> encodeNpy(const std::vector<int32_t>& values, int width, int height, int channels) {
  return encodeWords(values, width, height, channels, "<i4");
}

void writeNpy(const std::string& path, const std::vector<float>& values, int width, int height, int channels) {
  writeWords(path, values, width, height, channels);
}

void writeNpy(const std::string& path, const std::vector<int32_t>& values, int width, int height, int channels) {
  writeWords(path, values, width, height, channels);
}

}  // namespace phongvk
