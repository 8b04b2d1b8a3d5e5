// resources.h — storage buffers, their memory, and copying data in and out.
#pragma once

#include "host/context.h"

#include <cstddef>

namespace phongvk {

enum class MemoryKind {
  // Memory the GPU reads fastest. Never mapped — even where it is host visible (lavapipe, UMA,
  // resizable BAR) — so the CPU-only CI takes the same staging path as a discrete GPU.
  DeviceLocal,
  // Host visible and coherent, persistently mapped (prefers host-cached memory: fast readback).
  // For data the CPU writes or reads every frame.
  HostVisible,
};

struct Buffer {
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  void* mapped = nullptr;  // non-null for MemoryKind::HostVisible
  VkDeviceSize size = 0;   // the VkBuffer's size: the request rounded up to a multiple of 4, at least 4
};

// Vulkan forbids size 0, and vkCmdFillBuffer needs multiples of 4, so `size` is rounded up to a
// multiple of 4 (at least 4). DeviceLocal buffers also get TRANSFER_SRC | TRANSFER_DST usage, as
// uploadToBuffer / readFromBuffer reach them by copies. Throws VulkanError when out of memory.
void createBuffer(Buffer& result, const VulkanContext& context, VkDeviceSize size, VkBufferUsageFlags usage,
                  MemoryKind kind);

// Frees the buffer and its memory; safe on an empty or already destroyed Buffer.
void destroyBuffer(Buffer& buffer, const VulkanContext& context);

// Copies `bytes` from `data` into `dst` at `offset`: a memcpy when dst is mapped, otherwise through
// a temporary staging buffer and a one-time submission.
// Throws std::out_of_range if the range does not fit.
void uploadToBuffer(const VulkanContext& context, Buffer& dst, const void* data, size_t bytes, VkDeviceSize offset = 0);

// Copies the first `bytes` of `src` to `out`, likewise. The GPU work that wrote src must have
// finished (submitAndWait, whose closing barrier makes the writes visible to the host).
void readFromBuffer(const VulkanContext& context, const Buffer& src, void* out, size_t bytes);

// A view of `buffer` as texels of `format` (`texelBytes` each, which must divide the buffer's
// size), for a uniform texel buffer descriptor. Shaders read it with texelFetch, which SIMD CPU
// devices (lavapipe) gather several times faster than storage-buffer loads.
VkBufferView createTexelView(const VulkanContext& context, const Buffer& buffer, VkFormat format,
                             VkDeviceSize texelBytes);

// Safe on VK_NULL_HANDLE; leaves `view` null.
void destroyTexelView(VkBufferView& view, const VulkanContext& context);

// Device memory the context's buffers hold now, and the most they ever held at once.
VkDeviceSize deviceBytes(const VulkanContext& context);
VkDeviceSize peakDeviceBytes(const VulkanContext& context);

}  // namespace phongvk
