// memory_limit.cpp — the public API's memory limit (phongvk.h): set, read and checked against. No
// renderer here: scene_from_dict's converter (python/json_writer.h) bounds its values by the limit
// in builds without one (fuzz/dict_fuzzer.cpp).
#include <phongvk/phongvk.h>

#include "prepare/memory_estimate.h"
#include "shaders/shared.h"

namespace phongvk {

void setMemoryLimit(uint64_t bytes) { setSceneMemoryLimit(bytes); }

static_assert(MAX_TEXTURE_SIDE == gpu::TEXTURE_MAX_SIDE, "the public limit is the renderers' own");

void checkTextureSize(int64_t width, int64_t height, const std::string& what) {
  if (width < 1 || height < 1 || width > MAX_TEXTURE_SIDE || height > MAX_TEXTURE_SIDE) {
    throw ArgumentError(what + ": a texture is 1 to " + std::to_string(MAX_TEXTURE_SIDE) + " texels a side, got " +
                        std::to_string(width) + " x " + std::to_string(height));
  }
  const uint64_t texels = uint64_t(width) * uint64_t(height);
  checkMemory("", what, texels * 4, std::to_string(width) + " x " + std::to_string(height) + " texels, 4 bytes each",
              "a smaller texture fits");
}

uint64_t memoryLimit() { return sceneMemoryLimit(); }

}  // namespace phongvk
