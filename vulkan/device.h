// device.h — the physical devices, what each lacks, the choice among them, and the logical device
// with the features phongvk needs. Internal to host/: createContext (context.cpp) builds on it.
#pragma once

#include "vulkan/context.h"

#include <optional>
#include <vector>

namespace phongvk {

std::vector<VkPhysicalDevice> physicalDevices(VkInstance instance);

// Every device with what it lacks of phongvk's requirements (DeviceInfo::missing).
std::vector<DeviceInfo> inspectDevices(const std::vector<VkPhysicalDevice>& devices);

// The first compute queue family that can write timestamps, else the first compute family.
std::optional<uint32_t> findComputeFamily(VkPhysicalDevice device);

// Fills the context's description of the chosen device: properties (PHONGVK_MAX_STORAGE_BUFFER_RANGE
// lowers maxStorageBufferRange; ArgumentError where it is not a number of bytes), memory, queue
// family, timestamps.
void describeDevice(VulkanContext& context, const DeviceInfo& info);

// The logical device with phongvk's features and its compute queue, loaded into volk.
void createDevice(VulkanContext& context);

}  // namespace phongvk
