#include "phongvk/compare.h"
#include "phongvk/errors.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <stdexcept>

namespace phongvk {

namespace {

bool keysDiffer(const std::vector<uint64_t>& a, const std::vector<uint64_t>& b, size_t i) {
  // The triangle id is the low word; a cleared pixel (all ones) differs from any covered one.
  return static_cast<uint32_t>(a[i]) != static_cast<uint32_t>(b[i]) || ((a[i] == ~0ull) != (b[i] == ~0ull));
}

// How many keys a side the images' pixels have: 1, or with samples per pixel (render.samples) the
// side of their grid, the keys then those of an image `side` times wider and higher; 0 when the
// keys cannot be compared (none, or counts that fit neither).
int keySide(const Image& a, const std::vector<uint64_t>& keysA, const std::vector<uint64_t>& keysB) {
  const size_t n = static_cast<size_t>(a.width) * a.height;
  for (size_t side = 1; side <= 4 && keysA.size() == keysB.size(); ++side) {
    if (keysA.size() == n * side * side) return int(side);
  }
  return 0;
}

// Whether any sample of pixel i has another winner in a than in b.
bool pixelKeysDiffer(const std::vector<uint64_t>& a, const std::vector<uint64_t>& b, size_t i, int width, int side) {
  if (side == 1) return keysDiffer(a, b, i);
  const size_t x = i % size_t(width), y = i / size_t(width), rowKeys = size_t(width) * side;
  for (size_t j = 0; j < size_t(side); ++j) {
    for (size_t k = 0; k < size_t(side); ++k) {
      if (keysDiffer(a, b, (y * side + j) * rowKeys + x * side + k)) return true;
    }
  }
  return false;
}

}  // namespace

int DiffStats::maxChannelDiff() const { return *std::max_element(maxAbs.begin(), maxAbs.end()); }

double DiffStats::identicalFraction() const {
  return pixels == 0 ? 1.0 : static_cast<double>(pixels - differing) / static_cast<double>(pixels);
}

DiffStats compareImages(const Image& a, const Image& b, const std::vector<uint64_t>& keysA,
                        const std::vector<uint64_t>& keysB) {
  if (a.width != b.width || a.height != b.height) {
    throw ArgumentError("images differ in size: " + std::to_string(a.width) + "x" + std::to_string(a.height) +
                                " vs " + std::to_string(b.width) + "x" + std::to_string(b.height));
  }
  DiffStats s;
  s.width = a.width;
  s.height = a.height;
  s.pixels = static_cast<uint64_t>(a.width) * a.height;
  const int side = keySide(a, keysA, keysB);
  s.keysCompared = side != 0;
  std::array<uint64_t, 3> sum{};
  double squared = 0;
  for (size_t i = 0; i < s.pixels; ++i) {
    bool differs = false;
    for (int c = 0; c < 3; ++c) {
      const int d = std::abs(int(a.rgb[i * 3 + c]) - int(b.rgb[i * 3 + c]));
      differs = differs || d != 0;
      s.maxAbs[c] = std::max(s.maxAbs[c], d);
      sum[c] += d;
      squared += double(d) * d;
    }
    s.differing += differs;
    if (s.keysCompared && pixelKeysDiffer(keysA, keysB, i, a.width, side)) ++s.triangleMismatch;
  }
  for (int c = 0; c < 3; ++c) s.meanAbs[c] = s.pixels ? double(sum[c]) / double(s.pixels) : 0.0;
  const double mse = s.pixels ? squared / (3.0 * double(s.pixels)) : 0.0;
  s.psnr = mse == 0 ? std::numeric_limits<double>::infinity() : 10.0 * std::log10(255.0 * 255.0 / mse);
  return s;
}

Image diffHeatmap(const Image& a, const Image& b, const std::vector<uint64_t>& keysA,
                  const std::vector<uint64_t>& keysB) {
  compareImages(a, b);  // size check
  Image heat(a.width, a.height);
  const int side = keySide(a, keysA, keysB);
  for (size_t i = 0; i < static_cast<size_t>(a.width) * a.height; ++i) {
    int d = 0;
    for (int c = 0; c < 3; ++c) d = std::max(d, std::abs(int(a.rgb[i * 3 + c]) - int(b.rgb[i * 3 + c])));
    const uint8_t level = d == 0 ? 0 : static_cast<uint8_t>(std::min(255, std::max(64, d * 16)));
    const bool wrongTriangle = side != 0 && pixelKeysDiffer(keysA, keysB, i, a.width, side);
    heat.rgb[i * 3 + 0] = wrongTriangle ? 0 : level;
    heat.rgb[i * 3 + 1] = wrongTriangle ? 0 : level;
    heat.rgb[i * 3 + 2] = wrongTriangle ? 255 : level;
  }
  return heat;
}

std::string formatDiff(const DiffStats& s) {
  char buffer[1024];
  std::snprintf(buffer, sizeof buffer,
                "image size:          %dx%d\n"
                "pixels compared:     %llu\n"
                "pixels differing:    %llu (%.4f%% identical)\n"
                "max abs difference:  R %d  G %d  B %d (of 255)\n"
                "mean abs difference: R %.5f  G %.5f  B %.5f\n"
                "PSNR:                %s\n",
                s.width, s.height, static_cast<unsigned long long>(s.pixels),
                static_cast<unsigned long long>(s.differing), 100.0 * s.identicalFraction(), s.maxAbs[0],
                s.maxAbs[1], s.maxAbs[2], s.meanAbs[0], s.meanAbs[1], s.meanAbs[2],
                std::isinf(s.psnr) ? "inf dB (identical)" : (std::to_string(s.psnr) + " dB").c_str());
  std::string text = buffer;
  if (s.keysCompared) {
    text += "winning triangle differs: " + std::to_string(s.triangleMismatch) + " pixels\n";
  }
  return text;
}

}  // namespace phongvk
