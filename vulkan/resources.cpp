// resources.cpp — buffers, memory type choice, staging copies, memory accounting.
#include "vulkan/resources.h"

#include "base/huge_pages.h"
#include "vulkan/submit.h"
#include "vulkan/vk_check.h"

#include <algorithm>
#include <cassert>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

namespace phongvk {
namespace {

std::optional<uint32_t> findMemoryType(const VkPhysicalDeviceMemoryProperties& properties, uint32_t typeBits,
                                       VkMemoryPropertyFlags flags) {
  for (uint32_t i = 0; i < properties.memoryTypeCount; ++i)
    if ((typeBits & (1u << i)) && (properties.memoryTypes[i].propertyFlags & flags) == flags) return i;
  return std::nullopt;
}

// The first type with `required | preferred`, else the first with `required`.
uint32_t chooseMemoryType(const VulkanContext& context, uint32_t typeBits, VkMemoryPropertyFlags required,
                          VkMemoryPropertyFlags preferred) {
  std::optional<uint32_t> type = findMemoryType(context.memoryProperties, typeBits, required | preferred);
  if (!type) type = findMemoryType(context.memoryProperties, typeBits, required);
  if (!type)
    throw VulkanError("no memory type with property flags " + std::to_string(required) + " for a buffer (type bits " +
                          std::to_string(typeBits) + ")",
                      VK_ERROR_OUT_OF_DEVICE_MEMORY);
  return *type;
}

constexpr VkMemoryPropertyFlags SHARED_MEMORY = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT |
                                                VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT |
                                                VK_MEMORY_PROPERTY_HOST_COHERENT_BIT | VK_MEMORY_PROPERTY_HOST_CACHED_BIT;

uint32_t memoryTypeFor(const VulkanContext& context, uint32_t typeBits, MemoryKind kind) {
  if (kind == MemoryKind::DeviceLocal)
    return chooseMemoryType(context, typeBits, 0, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  if (kind == MemoryKind::Shared) return chooseMemoryType(context, typeBits, SHARED_MEMORY, 0);
  return chooseMemoryType(context, typeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT,
                          VK_MEMORY_PROPERTY_HOST_CACHED_BIT);
}

void countAllocation(const VulkanContext& context, VkDeviceSize bytes) {
  VkDeviceSize now = context.memory->current += bytes;
  VkDeviceSize peak = context.memory->peak.load();
  while (now > peak && !context.memory->peak.compare_exchange_weak(peak, now)) {
  }
}

void checkRange(const Buffer& buffer, VkDeviceSize offset, size_t bytes) {
  if (offset > buffer.size || bytes > buffer.size - offset)
    throw RangeError("buffer access of " + std::to_string(bytes) + " bytes at offset " + std::to_string(offset) +
                            " exceeds the buffer's " + std::to_string(buffer.size) + " bytes");
}

void copyBuffer(const VulkanContext& context, VkBuffer src, VkDeviceSize srcOffset, VkBuffer dst,
                VkDeviceSize dstOffset, VkDeviceSize bytes) {
  VkCommandBuffer cmd = beginOneTimeCommands(context);
  VkBufferCopy region = {srcOffset, dstOffset, bytes};
  vkCmdCopyBuffer(cmd, src, dst, 1, &region);
  submitAndWait(context, cmd);  // its closing barrier publishes the copy to shaders and the host
}

// The most a copy stages at once: a large array goes through in parts, so the host never holds a
// whole second copy of it beside the array and the device's (on a CPU device, host memory too).
constexpr size_t STAGING_BYTES = size_t(64) << 20;

// A host-visible buffer for one copy, destroyed on every path out of the copy.
struct StagingBuffer {
  StagingBuffer(const VulkanContext& context, size_t bytes, VkBufferUsageFlags usage) : context(context) {
    createBuffer(buffer, context, bytes, usage, MemoryKind::HostVisible);
  }
  ~StagingBuffer() { destroyBuffer(buffer, context); }
  StagingBuffer(const StagingBuffer&) = delete;
  StagingBuffer& operator=(const StagingBuffer&) = delete;

  const VulkanContext& context;
  Buffer buffer;
};

// On a CPU device (lavapipe) device memory is the process's own, fresh from the allocator and not
// yet touched: ask for 2 MiB pages for it (base/huge_pages.h), as for large meshes. A frame's
// key buffer alone is 10 MB at 1385x923, which 4 KiB pages fault in 2,500 times on the first
// frame (later frames measure the same either way). Elsewhere device memory is the driver's.
void adviseHugeDeviceMemory(const VulkanContext& context, const Buffer& buffer, VkDeviceSize bytes) {
  if (context.properties.deviceType != VK_PHYSICAL_DEVICE_TYPE_CPU || bytes < (VkDeviceSize(2) << 20)) return;
  void* mapped = buffer.mapped;
  if (!mapped && vkMapMemory(context.device, buffer.memory, 0, VK_WHOLE_SIZE, 0, &mapped) != VK_SUCCESS) return;
  adviseHugePages(mapped, size_t(bytes));
  if (!buffer.mapped) vkUnmapMemory(context.device, buffer.memory);
}

}  // namespace

void createBuffer(Buffer& result, const VulkanContext& context, VkDeviceSize size, VkBufferUsageFlags usage,
                  MemoryKind kind) {
  result = {};
  VkBufferCreateInfo info = { VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO };
  info.size = size == 0 ? 4 : (size + 3) & ~VkDeviceSize(3);
  // Unmapped buffers are filled and read only by copies, so they always allow them.
  info.usage = usage;
  if (kind == MemoryKind::DeviceLocal)
    info.usage |= VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  VK_CHECK(vkCreateBuffer(context.device, &info, nullptr, &result.buffer));
  result.size = info.size;
  result.owner = &context;

  try {
    VkMemoryRequirements requirements;
    vkGetBufferMemoryRequirements(context.device, result.buffer, &requirements);
    VkMemoryAllocateInfo allocateInfo = { VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO };
    allocateInfo.allocationSize = requirements.size;
    allocateInfo.memoryTypeIndex = memoryTypeFor(context, requirements.memoryTypeBits, kind);
    VK_CHECK(vkAllocateMemory(context.device, &allocateInfo, nullptr, &result.memory));
    countAllocation(context, requirements.size);
    VK_CHECK(vkBindBufferMemory(context.device, result.buffer, result.memory, 0));
    if (kind != MemoryKind::DeviceLocal)
      VK_CHECK(vkMapMemory(context.device, result.memory, 0, VK_WHOLE_SIZE, 0, &result.mapped));
    adviseHugeDeviceMemory(context, result, requirements.size);
  } catch (...) {
    destroyBuffer(result, context);
    throw;
  }
}

namespace {

// The size a texel buffer of `bytes` is made with: padded by up to 17 texels so that neither is it
// a power of two nor are its bits 8-15 all zero. lavapipe (llvmpipe, Mesa 22.3) keys the machine
// code it generates for a pipeline on what it reads of each bound texel buffer's size, and those
// two properties of it are what moved the key: unpadded, a scene whose counts made one of them
// differ paid seconds of code generation on its first frame, although every pipeline was one it
// had compiled before (docs/DECISIONS.md, "One machine code for every scene").
// Never past the device's texel limit (the padding is only for lavapipe's sake).
VkDeviceSize texelBufferBytes(VkDeviceSize bytes, const VulkanContext& context) {
  VkDeviceSize size = std::max(bytes, TEXEL_BYTES);
  while ((size & (size - 1)) == 0 || ((size >> 8) & 0xFF) == 0) size += TEXEL_BYTES;
  const VkDeviceSize limit = VkDeviceSize(context.properties.limits.maxTexelBufferElements) * TEXEL_BYTES;
  return size <= limit ? size : std::max(bytes, TEXEL_BYTES);
}

}  // namespace

void createTexelBuffer(TexelBuffer& result, const VulkanContext& context, const void* data, VkDeviceSize bytes,
                       VkBufferUsageFlags usage, MemoryKind kind, bool view) {
  assert(bytes % TEXEL_BYTES == 0);
  result = {};
  createBuffer(result.buffer, context, texelBufferBytes(bytes, context),
               usage | (view ? VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT : VK_BUFFER_USAGE_STORAGE_BUFFER_BIT), kind);
  try {
    if (data && bytes) uploadToBuffer(context, result.buffer, data, bytes);
    if (!view) return;
    VkBufferViewCreateInfo info = {VK_STRUCTURE_TYPE_BUFFER_VIEW_CREATE_INFO};
    info.buffer = result.buffer.buffer;
    info.format = VK_FORMAT_R32G32B32A32_UINT;
    info.range = VK_WHOLE_SIZE;
    VK_CHECK(vkCreateBufferView(context.device, &info, nullptr, &result.view));
  } catch (...) {
    destroyTexelBuffer(result, context);
    throw;
  }
}

void destroyTexelBuffer(TexelBuffer& texels, const VulkanContext& context) {
  if (texels.view) vkDestroyBufferView(context.device, texels.view, nullptr);
  texels.view = VK_NULL_HANDLE;
  destroyBuffer(texels.buffer, context);
}

void destroyBuffer(Buffer& buffer, const VulkanContext& context) {
  if (buffer.memory) {
    VkMemoryRequirements requirements;
    vkGetBufferMemoryRequirements(context.device, buffer.buffer, &requirements);
    context.memory->current -= requirements.size;
    vkFreeMemory(context.device, buffer.memory, nullptr);  // also unmaps
  }
  if (buffer.buffer) vkDestroyBuffer(context.device, buffer.buffer, nullptr);
  buffer.disown();
}

void Buffer::disown() {
  buffer = VK_NULL_HANDLE;
  memory = VK_NULL_HANDLE;
  mapped = nullptr;
  size = 0;
  owner = nullptr;
}

Buffer::Buffer(Buffer&& other) noexcept
    : buffer(other.buffer), memory(other.memory), mapped(other.mapped), size(other.size), owner(other.owner) {
  other.disown();
}

Buffer& Buffer::operator=(Buffer&& other) noexcept {
  if (this == &other) return *this;
  if (owner) destroyBuffer(*this, *owner);
  buffer = other.buffer;
  memory = other.memory;
  mapped = other.mapped;
  size = other.size;
  owner = other.owner;
  other.disown();
  return *this;
}

Buffer::~Buffer() {
  if (owner) destroyBuffer(*this, *owner);
}

TexelBuffer::TexelBuffer(TexelBuffer&& other) noexcept : buffer(std::move(other.buffer)), view(other.view) {
  other.view = VK_NULL_HANDLE;
}

TexelBuffer& TexelBuffer::operator=(TexelBuffer&& other) noexcept {
  if (this == &other) return *this;
  if (buffer.owner) destroyTexelBuffer(*this, *buffer.owner);
  buffer = std::move(other.buffer);
  view = other.view;
  other.view = VK_NULL_HANDLE;
  return *this;
}

TexelBuffer::~TexelBuffer() {
  if (buffer.owner) destroyTexelBuffer(*this, *buffer.owner);
}

void uploadToBuffer(const VulkanContext& context, Buffer& dst, const void* data, size_t bytes, VkDeviceSize offset) {
  checkRange(dst, offset, bytes);
  if (bytes == 0) return;
  if (dst.mapped) {
    std::memcpy(static_cast<char*>(dst.mapped) + offset, data, bytes);  // coherent: no flush needed
    return;
  }
  StagingBuffer staging(context, std::min(bytes, STAGING_BYTES), VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
  for (size_t done = 0; done < bytes; done += STAGING_BYTES) {
    const size_t part = std::min(bytes - done, STAGING_BYTES);
    std::memcpy(staging.buffer.mapped, static_cast<const char*>(data) + done, part);
    copyBuffer(context, staging.buffer.buffer, 0, dst.buffer, offset + done, part);
  }
}

void readFromBuffer(const VulkanContext& context, const Buffer& src, void* out, size_t bytes) {
  checkRange(src, 0, bytes);
  if (bytes == 0) return;
  if (src.mapped) {
    std::memcpy(out, src.mapped, bytes);
    return;
  }
  StagingBuffer staging(context, std::min(bytes, STAGING_BYTES), VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  for (size_t done = 0; done < bytes; done += STAGING_BYTES) {
    const size_t part = std::min(bytes - done, STAGING_BYTES);
    copyBuffer(context, src.buffer, done, staging.buffer.buffer, 0, part);
    std::memcpy(static_cast<char*>(out) + done, staging.buffer.mapped, part);
  }
}

bool hasSharedMemory(const VulkanContext& context) {
  return findMemoryType(context.memoryProperties, ~0u, SHARED_MEMORY).has_value();
}

VkDeviceSize deviceBytes(const VulkanContext& context) { return context.memory->current; }

VkDeviceSize peakDeviceBytes(const VulkanContext& context) { return context.memory->peak; }

}  // namespace phongvk
