// compare.h — pixel-wise comparison of two renders of one scene (what `phongvk diff` prints).
#pragma once

#include "phongvk/export.h"
#include "phongvk/image.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace phongvk {

struct DiffStats {
  int width = 0;
  int height = 0;
  uint64_t pixels = 0;
  uint64_t differing = 0;            // pixels with any channel different
  std::array<int, 3> maxAbs{};       // per channel, in 8-bit units
  std::array<double, 3> meanAbs{};   // per channel, over all pixels
  double psnr = 0;                   // dB over all channels; +inf when identical
  uint64_t triangleMismatch = 0;     // pixels whose winning key's triangle differs (or coverage)
  bool keysCompared = false;

  PHONGVK_API int maxChannelDiff() const;
  PHONGVK_API double identicalFraction() const;  // pixels bit-identical / pixels
};

// Compares images of equal size; keys (may be empty) also compare the winners: one per pixel, or
// with samples per pixel those of the sample grid (an image 2, 3 or 4 times wider and higher),
// a pixel counted once where any of its samples' winners differ.
// Throws ArgumentError when the sizes differ.
PHONGVK_API DiffStats compareImages(const Image& a, const Image& b, const std::vector<uint64_t>& keysA = {},
                                    const std::vector<uint64_t>& keysB = {});

// Where and how much a and b differ: black where equal, brighter with the largest channel
// difference (amplified 16x, at least 64 so a 1/255 difference is visible), and pure blue where
// the winning triangle differs.
PHONGVK_API Image diffHeatmap(const Image& a, const Image& b, const std::vector<uint64_t>& keysA = {},
                              const std::vector<uint64_t>& keysB = {});

// Human-readable report, one fact per line.
PHONGVK_API std::string formatDiff(const DiffStats& stats);

}  // namespace phongvk
