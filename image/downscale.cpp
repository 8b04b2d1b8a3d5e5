// downscale.cpp — the box filter of image.h downscale.
#include "phongvk/image.h"

#include <cassert>
#include <cstdint>

namespace phongvk {
namespace {

// The run of source pixels [first, last) that output pixel `i` of `outSize` averages.
void boxRun(int i, int outSize, int inSize, int& first, int& last) {
  first = int(int64_t(i) * inSize / outSize);
  last = int(int64_t(i + 1) * inSize / outSize);
}

}  // namespace

Image downscale(const Image& source, int width, int height) {
  assert(width >= 1 && width <= source.width && height >= 1 && height <= source.height);
  Image out(width, height);
  for (int y = 0; y < height; ++y) {
    int y0, y1;
    boxRun(y, height, source.height, y0, y1);
    for (int x = 0; x < width; ++x) {
      int x0, x1;
      boxRun(x, width, source.width, x0, x1);
      const int count = (x1 - x0) * (y1 - y0);
      for (int c = 0; c < 3; ++c) {
        int sum = 0;
        for (int sy = y0; sy < y1; ++sy) {
          for (int sx = x0; sx < x1; ++sx) sum += source.pixel(sx, sy)[c];
        }
        out.pixel(x, y)[c] = static_cast<uint8_t>((sum + count / 2) / count);
      }
    }
  }
  return out;
}

}  // namespace phongvk
