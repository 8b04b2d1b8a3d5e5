// gpu_readback.cpp — the frame's image, read where resolve (or the pack pass) left it: the key
// slots on a device that shares memory with the host, the RGB colour buffer elsewhere.
#include "compute/gpu_renderer.h"

#include "base/huge_pages.h"
#include "image/packed_pixels.h"
#include "shaders/color_slots.h"
#include "shaders/gouraud.h"

#include <span>

namespace phongvk {

using namespace gpu;

namespace {

// The image in the key slots resolve left (RESOLVE_OUTPUT_KEY_SLOTS), into `image` (sized to
// them): a slot's colour, or the background where resolve left KEY_CLEAR; every slot is reset to
// KEY_CLEAR for the next frame.
void imageFromKeySlots(std::span<uint64_t> slots, uint32_t background, Image& image) {
  auto take = [&](size_t i) {
    const uint64_t slot = slots[i];
    if (slot == KEY_CLEAR) return background;
    slots[i] = KEY_CLEAR;
    return uint32_t(slot);
  };
  size_t i = 0;
  for (; i + 4 <= slots.size(); i += 4) setPackedFour(image, i, take(i), take(i + 1), take(i + 2), take(i + 3));
  for (; i < slots.size(); ++i) setPacked(image, i, take(i));
}

}  // namespace

// The frame's image, read where resolve wrote it (host-visible, coherent; submitAndWait's closing
// barrier made the writes visible to the host): no copy first. Into `image`'s storage, which is
// not zero-filled first when it is already large enough: a sequence that reuses its image pays
// neither a new image's zero fill nor the page faults of its fresh memory (docs/PERFORMANCE.md,
// "Readback").
Image GpuRenderer::readImage(Image image) {
  const size_t pixels = size_t(width_) * height_;
  image.width = int(width_);
  image.height = int(height_);
  reserveLarge(image.rgb, 3 * pixels);  // fresh storage on huge pages (a one-frame render's image)
  if (!frameColorsInKeys_) {
    // Resolve wrote the image's own layout: one copy (assign reuses the capacity).
    const auto* bytes = static_cast<const uint8_t*>(image_.colors.mapped);
    image.rgb.assign(bytes, bytes + 3 * pixels);
    return image;
  }
  image.rgb.resize(3 * pixels);
  imageFromKeySlots({static_cast<uint64_t*>(image_.keys.mapped), pixels}, packColor(frame_.background), image);
  keysDirty_ = false;
  return image;
}

}  // namespace phongvk
