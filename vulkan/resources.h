// resources.h — storage buffers, their memory, and copying data in and out.
#pragma once

#include "vulkan/context.h"

#include <cstddef>
#include <vector>

namespace phongvk {

enum class MemoryKind {
  // Memory the GPU reads fastest. Never mapped — even where it is host visible (lavapipe, UMA,
  // resizable BAR) — so the CPU-only CI takes the same staging path as a discrete GPU.
  DeviceLocal,
  // Host visible and coherent, persistently mapped (prefers host-cached memory: fast readback).
  // For data the CPU writes or reads every frame.
  HostVisible,
  // Device local, host visible, coherent and cached, persistently mapped: memory that shaders and
  // the host both use at full speed, as a CPU or integrated device has (hasSharedMemory). For a
  // buffer the shaders work in and the host reads and resets in place.
  Shared,
};

// A buffer and its memory, freed when it goes (or by destroyBuffer before then). Move-only; the
// context that made it must outlive it.
struct Buffer {
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  void* mapped = nullptr;  // non-null for MemoryKind::HostVisible and Shared
  VkDeviceSize size = 0;   // the VkBuffer's size: the request rounded up to a multiple of 4, at least 4
  const VulkanContext* owner = nullptr;  // set by createBuffer

  Buffer() = default;
  Buffer(Buffer&& other) noexcept;
  Buffer& operator=(Buffer&& other) noexcept;
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;
  ~Buffer();
  // Forgets the handles without freeing them: for a buffer whose device is already gone.
  void disown();
};

// Vulkan forbids size 0, and vkCmdFillBuffer needs multiples of 4, so `size` is rounded up to a
// multiple of 4 (at least 4). DeviceLocal buffers also get TRANSFER_SRC | TRANSFER_DST usage, as
// uploadToBuffer / readFromBuffer reach them by copies. Throws VulkanError when out of memory.
void createBuffer(Buffer& result, const VulkanContext& context, VkDeviceSize size, VkBufferUsageFlags usage,
                  MemoryKind kind);

// Whether the device has MemoryKind::Shared memory. A discrete GPU's host-visible device-local
// memory (resizable BAR) is uncached for the host, so it does not count.
bool hasSharedMemory(const VulkanContext& context);

// Frees the buffer and its memory; safe on an empty or already destroyed Buffer.
void destroyBuffer(Buffer& buffer, const VulkanContext& context);

// Copies `bytes` from `data` into `dst` at `offset`: a memcpy when dst is mapped, otherwise through
// a staging buffer of at most 64 MiB and a one-time submission per part of that size.
// Throws std::out_of_range if the range does not fit.
void uploadToBuffer(const VulkanContext& context, Buffer& dst, const void* data, size_t bytes, VkDeviceSize offset = 0);

// Copies the first `bytes` of `src` to `out`, likewise. The GPU work that wrote src must have
// finished (submitAndWait, whose closing barrier makes the writes visible to the host).
void readFromBuffer(const VulkanContext& context, const Buffer& src, void* out, size_t bytes);

// A buffer the shaders read as RGBA32UI texels (a uniform texel buffer: bindings.glsl). texelFetch
// is gathered in SIMD by CPU devices (lavapipe), which load from a storage buffer lane by lane.
// Made without a view it is a storage buffer of uvec4s instead, as the compute port's 32-bit key
// path reads it (bindings.glsl TEXELS): such devices may allow few texels (SwiftShader: 65,536).
// Move-only like Buffer; the view goes with it.
struct TexelBuffer {
  Buffer buffer;
  VkBufferView view = VK_NULL_HANDLE;

  TexelBuffer() = default;
  TexelBuffer(TexelBuffer&& other) noexcept;
  TexelBuffer& operator=(TexelBuffer&& other) noexcept;
  ~TexelBuffer();
};
inline constexpr VkDeviceSize TEXEL_BYTES = 16;

// `bytes` (a multiple of TEXEL_BYTES; 0 still gets one texel) in a new texel buffer, a few texels
// longer than asked for where lavapipe needs it (resources.cpp texelBufferBytes), filled from
// `data` if it is not null; `usage` is added to UNIFORM_TEXEL_BUFFER (e.g. STORAGE for a pass that
// writes it). `view` false: a storage buffer without a texel view (above).
void createTexelBuffer(TexelBuffer& result, const VulkanContext& context, const void* data, VkDeviceSize bytes,
                       VkBufferUsageFlags usage, MemoryKind kind, bool view = true);

// createTexelBuffer filled from `data`, an array of std430 structs of whole texels.
template <typename T>
void createTexelBuffer(TexelBuffer& result, const VulkanContext& context, const std::vector<T>& data, MemoryKind kind,
                       bool view = true) {
  static_assert(sizeof(T) % TEXEL_BYTES == 0);
  createTexelBuffer(result, context, data.data(), data.size() * sizeof(T), 0, kind, view);
}

// Safe on an empty or already destroyed TexelBuffer.
void destroyTexelBuffer(TexelBuffer& texels, const VulkanContext& context);

// Device memory the context's buffers hold now, and the most they ever held at once.
VkDeviceSize deviceBytes(const VulkanContext& context);
VkDeviceSize peakDeviceBytes(const VulkanContext& context);

}  // namespace phongvk
