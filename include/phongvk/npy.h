// npy.h — images as NumPy .npy files (format 1.0): a depth in float32 metres, ids in int32, which
// numpy.load reads back as (height, width) arrays, and normals as (height, width, 3) float32.
#pragma once

#include "phongvk/errors.h"
#include "phongvk/export.h"

#include <cstdint>
#include <string>
#include <vector>

namespace phongvk {

// The file's bytes: the magic, version 1.0, the header dict ({'descr': '<f4' or '<i4',
// 'fortran_order': False, 'shape': (height, width)}, or (height, width, channels) for more than one
// channel) padded with spaces to a multiple of 64 bytes, then the values row by row (a pixel's
// channels together), little-endian. Throws ArgumentError when `values` does not hold
// width x height x channels values.
PHONGVK_API std::vector<uint8_t> encodeNpy(const std::vector<float>& values, int width, int height, int channels = 1);
PHONGVK_API std::vector<uint8_t> encodeNpy(const std::vector<int32_t>& values, int width, int height, int channels = 1);
// The file written atomically, as writePng writes (image.h PngEncoder::write). Throws OutputError.
PHONGVK_API void writeNpy(const std::string& path, const std::vector<float>& values, int width, int height,
                          int channels = 1);
PHONGVK_API void writeNpy(const std::string& path, const std::vector<int32_t>& values, int width, int height,
                          int channels = 1);

}  // namespace phongvk
