// outputs.cpp — see outputs.h.
#include "api/outputs.h"

#include <bit>
#include <cstdint>
#include <limits>

namespace phongvk {
namespace {

constexpr uint64_t NO_KEY = ~uint64_t(0);  // the cleared key: no triangle

// The nearest of a pixel's samples and how many of them a triangle covers.
struct PixelKey {
  uint64_t key = NO_KEY;
  int covered = 0;
};

PixelKey pixelKey(const std::vector<uint64_t>& keys, int x, int y, int side, int sampleWidth) {
  PixelKey p;
  for (int j = 0; j < side; ++j) {
    for (int i = 0; i < side; ++i) {
      const uint64_t key = keys[size_t(y * side + j) * size_t(sampleWidth) + size_t(x * side + i)];
      p.covered += key != NO_KEY;
      p.key = std::min(p.key, key);
    }
  }
  return p;
}

}  // namespace

RenderedFrame outputsFromKeys(RenderOutput&& out, int side, const SceneData& data, const Outputs& outputs) {
  RenderedFrame frame;
  frame.image = std::move(out.image);
  const int width = frame.image.width, height = frame.image.height, samples = side * side;
  const size_t pixels = size_t(width) * size_t(height);
  if (outputs.alpha) frame.alpha.resize(pixels);
  if (outputs.depth) frame.depth.resize(pixels);
  if (outputs.objectIds) frame.objectIds.resize(pixels);
  if (outputs.triangleIds) frame.triangleIds.resize(pixels);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const size_t i = size_t(y) * size_t(width) + size_t(x);
      const PixelKey p = pixelKey(out.keys, x, y, side, width * side);
      const bool covered = p.key != NO_KEY;
      const uint32_t triangle = uint32_t(p.key);  // the whole scene's index (a share's keys are offset)
      if (outputs.alpha) frame.alpha[i] = uint8_t((255 * p.covered + samples / 2) / samples);
      if (outputs.depth)
        frame.depth[i] = covered ? std::bit_cast<float>(uint32_t(p.key >> 32)) : std::numeric_limits<float>::infinity();
      if (outputs.triangleIds) frame.triangleIds[i] = covered ? int32_t(triangle) : -1;
      if (outputs.objectIds) frame.objectIds[i] = covered ? int32_t(data.triangles[triangle - data.triangleBase].w) : -1;
    }
  }
  return frame;
}

}  // namespace phongvk
