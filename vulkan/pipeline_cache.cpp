// pipeline_cache.cpp — the VkPipelineCache and its file (pipeline_cache.h).
#include "vulkan/pipeline_cache.h"

#include "vulkan/disk_cache.h"
#include "vulkan/vk_check.h"

#include <cstring>

namespace phongvk {
namespace {

std::string fileName(const VulkanContext& context) { return "pipelines-" + deviceCacheKey(context) + ".bin"; }

// Vulkan's own header (VkPipelineCacheHeaderVersionOne) names the device the data is for.
bool fitsDevice(const std::vector<uint8_t>& data, const VulkanContext& context) {
  if (data.size() < sizeof(VkPipelineCacheHeaderVersionOne)) return false;
  VkPipelineCacheHeaderVersionOne header;
  std::memcpy(&header, data.data(), sizeof header);
  const VkPhysicalDeviceProperties& p = context.properties;
  return header.headerSize >= sizeof header && header.headerSize <= data.size() &&
         header.headerVersion == VK_PIPELINE_CACHE_HEADER_VERSION_ONE && header.vendorID == p.vendorID &&
         header.deviceID == p.deviceID &&
         std::memcmp(header.pipelineCacheUUID, p.pipelineCacheUUID, VK_UUID_SIZE) == 0;
}

}  // namespace

VkPipelineCache loadPipelineCache(const VulkanContext& context) {
  std::optional<std::vector<uint8_t>> data = readCacheFile(fileName(context));
  if (data && !fitsDevice(*data, context)) data.reset();
  VkPipelineCacheCreateInfo info = {VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO};
  if (data) {
    info.initialDataSize = data->size();
    info.pInitialData = data->data();
  }
  VkPipelineCache cache = VK_NULL_HANDLE;
  VK_CHECK(vkCreatePipelineCache(context.device, &info, nullptr, &cache));
  return cache;
}

void savePipelineCache(const VulkanContext& context) {
  if (context.pipelineCache == VK_NULL_HANDLE) return;
  size_t size = 0;
  if (vkGetPipelineCacheData(context.device, context.pipelineCache, &size, nullptr) != VK_SUCCESS) return;
  std::vector<uint8_t> data(size);
  // VK_INCOMPLETE (the cache grew in between) leaves a shorter, still valid prefix; keep it.
  const VkResult result = vkGetPipelineCacheData(context.device, context.pipelineCache, &size, data.data());
  if (result != VK_SUCCESS && result != VK_INCOMPLETE) return;
  data.resize(size);
  if (fitsDevice(data, context)) writeCacheFile(fileName(context), data);
}

}  // namespace phongvk
