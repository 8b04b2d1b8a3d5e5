// texture_image.h — a decoded base-colour texture as a mesh carries it (docs/DESIGN.md "Textures").
#pragma once

#include "shaders/shared.h"

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>
#include <utility>
#include <vector>

namespace phongvk {

// The bytes of texels every TextureImage in the process holds now: a texture is refused before it
// is decoded when these and its own would pass the memory limit (image/texture_decode.h).
uint64_t heldTexelBytes();
void addHeldTexelBytes(int64_t bytes);

// Texel storage that counts what it holds in heldTexelBytes, and leaves new texels uninitialised:
// a decoder writes every one, and the pages of a huge texture whose decoding fails early are never
// touched.
template <typename T>
struct TexelAllocator {
  using value_type = T;
  TexelAllocator() = default;
  template <typename U>
  TexelAllocator(const TexelAllocator<U>&) noexcept {}
  T* allocate(size_t n) {
    T* p = std::allocator<T>().allocate(n);
    addHeldTexelBytes(int64_t(n * sizeof(T)));
    return p;
  }
  void deallocate(T* p, size_t n) noexcept {
    addHeldTexelBytes(-int64_t(n * sizeof(T)));
    std::allocator<T>().deallocate(p, n);
  }
  template <typename U>
  void construct(U* p) noexcept {
    ::new (static_cast<void*>(p)) U;  // default-initialised: no zero fill
  }
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
  template <typename U>
  bool operator==(const TexelAllocator<U>&) const noexcept { return true; }
};

using Texels = std::vector<uint32_t, TexelAllocator<uint32_t>>;

// RGBA8 texels (red in the low byte), row 0 at the image's top: texture coordinate (0, 0) is the
// top-left corner of texel 0, (1, 1) the bottom-right corner of the last. Each side is 1 to
// gpu::TEXTURE_MAX_SIDE texels. The wrap modes (gpu::TEXTURE_WRAP_*) say what a coordinate outside
// [0, 1] samples, across (u) and down (v).
struct TextureImage {
  uint32_t width = 0;
  uint32_t height = 0;
  Texels texels;
  uint32_t wrapU = gpu::TEXTURE_WRAP_REPEAT;
  uint32_t wrapV = gpu::TEXTURE_WRAP_REPEAT;
};

// `texture` with the wrap modes u and v: itself where it wraps so already, else a copy that does.
std::shared_ptr<const TextureImage> withWrap(std::shared_ptr<const TextureImage> texture, uint32_t u, uint32_t v);

}  // namespace phongvk
