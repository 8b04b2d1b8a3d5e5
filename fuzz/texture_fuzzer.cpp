// texture_fuzzer.cpp — libFuzzer target for the texture decoder (image/texture_decode.h), the one
// entry every texture goes through: a material's file or data URI, an OBJ's map_Kd, a PLY's
// TextureFile and a glTF image (scripts/fuzz.sh runs it). An input is the image's bytes, PNG or
// JPEG headers and segments in any state. Any bytes must either give a texture whose texels fill
// its sides or throw SceneError: no crash, no sanitizer report, no hang, no other exception, and no
// more memory than the limit set here allows. Seeds: fuzz/texture_corpus (small PNGs of every
// colour type, interlaced, 16-bit; baseline and progressive JPEGs).
#include "base/memory_limit.h"
#include "image/texture_decode.h"
#include "phongvk/errors.h"

#include <cstdint>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace phongvk;
  // 64 MiB of texels at most: a header that asks for more is refused before decoding, as a scene's is.
  setSceneMemoryLimit(uint64_t(64) << 20);
  try {
    const TextureImage texture = decodeTexture(std::string(reinterpret_cast<const char*>(data), size), "fuzz");
    if (texture.width == 0 || texture.height == 0 || texture.texels.size() != size_t(texture.width) * texture.height) std::abort();
  } catch (const SceneError&) {
  }
  return 0;
}
