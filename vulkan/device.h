// device.h — the physical devices, what each lacks, the choice among them, and the logical device
// with the features phongvk needs. Internal to host/: createContext (context.cpp) builds on it.
#pragma once

#include "vulkan/context.h"

#include <optional>
#include <vector>

namespace phongvk {

std::vector<VkPhysicalDevice> physicalDevices(VkInstance instance);

// Every device with what it lacks of phongvk's requirements (DeviceInfo::missing). With
// `computeOnly`, a compute queue is all a device needs (ContextOptions::computeOnly).
std::vector<DeviceInfo> inspectDevices(const std::vector<VkPhysicalDevice>& devices, bool computeOnly = false);

// The first compute queue family that can write timestamps, else the first compute family.
std::optional<uint32_t> findComputeFamily(VkPhysicalDevice device);

// PHONGVK_MAX_STORAGE_BUFFER_RANGE, a testing aid: the bytes it gives, or none where it is unset.
// ArgumentError where it is not a number of bytes. Read before any Vulkan object is made, so a bad
// value leaves nothing to release.
std::optional<uint64_t> storageRangeVariable();

// Fills the context's description of the chosen device: properties (with maxStorageBufferRange
// lowered to `storageRange` where that is smaller), memory, queue family, timestamps.
void describeDevice(VulkanContext& context, const DeviceInfo& info, std::optional<uint64_t> storageRange);

// The logical device with phongvk's features (none with `computeOnly`) and its compute queue,
// loaded into volk.
void createDevice(VulkanContext& context, bool computeOnly = false);

}  // namespace phongvk
