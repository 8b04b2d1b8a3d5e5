// texture_image.cpp — see texture_image.h.
#include "geometry/texture_image.h"

#include <algorithm>

namespace phongvk {
namespace {

std::atomic<int64_t> held{0};

}  // namespace

uint64_t heldTexelBytes() { return uint64_t(std::max<int64_t>(held.load(), 0)); }

void addHeldTexelBytes(int64_t bytes) { held += bytes; }

std::shared_ptr<const TextureImage> withWrap(std::shared_ptr<const TextureImage> texture, uint32_t u, uint32_t v) {
  if (texture->wrapU == u && texture->wrapV == v) return texture;
  auto wrapped = std::make_shared<TextureImage>(*texture);
  wrapped->wrapU = u;
  wrapped->wrapV = v;
  return wrapped;
}

}  // namespace phongvk
