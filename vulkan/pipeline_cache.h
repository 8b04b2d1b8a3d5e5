// pipeline_cache.h — the context's VkPipelineCache, kept across processes in the disk cache
// (disk_cache.h): read when a context that asks for it (ContextOptions::pipelineCache) is made,
// written back after a renderer compiles pipelines. The file's data is checked against the device
// (Vulkan's cache header: its version, vendor, device and UUID) before the driver sees it; data
// that does not match starts an empty cache. What a driver keeps in it is its own: NVIDIA's keeps
// compiled code; lavapipe 22.3's keeps nothing (its data is the 32-byte header), where Mesa's own
// shader cache under $XDG_CACHE_HOME/mesa_shader_cache holds the compiled code instead.
#pragma once

#include "vulkan/context.h"

namespace phongvk {

// A pipeline cache for the context, with the saved data when it fits the device.
VkPipelineCache loadPipelineCache(const VulkanContext& context);

// Saves the context's pipeline cache (if it has one) to the disk cache.
void savePipelineCache(const VulkanContext& context);

}  // namespace phongvk
