// device.h — the physical devices, what each lacks, the choice among them, and the logical device
// with the features phongvk needs. Internal to host/: createContext (context.cpp) builds on it.
#pragma once

#include "vulkan/context.h"

#include <optional>
#include <vector>

namespace phongvk {

std::vector<VkPhysicalDevice> physicalDevices(VkInstance instance);

// Every device with what it lacks of phongvk's requirements (DeviceInfo::missing) and the key path
// it takes (DeviceInfo::keys32: its features, or PHONGVK_KEY_PATH where set; ArgumentError where
// that variable is neither 32 nor 64).
std::vector<DeviceInfo> inspectDevices(const std::vector<VkPhysicalDevice>& devices);

// The first compute queue family that can write timestamps, else the first compute family.
std::optional<uint32_t> findComputeFamily(VkPhysicalDevice device);

// PHONGVK_MAX_STORAGE_BUFFER_RANGE, a testing aid: the bytes it gives, or none where it is unset.
// ArgumentError where it is not a number of bytes. Read before any Vulkan object is made, so a bad
// value leaves nothing to release.
std::optional<uint64_t> storageRangeVariable();

// Fills the context's description of the chosen device: properties (with maxStorageBufferRange
// lowered to `storageRange` where that is smaller), memory, queue family, timestamps.
void describeDevice(VulkanContext& context, const DeviceInfo& info, std::optional<uint64_t> storageRange);

// The logical device with its key path's features (context.info.keys32: none) and its compute
// queue, loaded into volk.
void createDevice(VulkanContext& context);

}  // namespace phongvk
