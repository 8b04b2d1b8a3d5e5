// instance.h — the Vulkan loader (volk) and instances: loading the loader once, an instance with
// or without validation, and which context's function tables volk holds. Internal to host/:
// createContext (context.cpp) and listDevices (device.cpp) build on it.
#pragma once

#include "vulkan/context.h"

#include <mutex>
#include <vector>

namespace phongvk {

// Loads libvulkan.so.1 through volk, once per process. Throws NoDeviceError without a loader.
void initializeLoader();

// Validation asked for by the options or the environment (PHONGVK_VALIDATE=1).
bool validationRequested(const ContextOptions& options);

// A Vulkan 1.2 instance, with validation (messages to `log`) unless log is null; loaded into volk.
// Throws NoDeviceError without a driver, DeviceError when validation lacks its layer.
VkInstance createInstance(ValidationLog* log);

// The debug messenger of a validating context (its messages to context.validation).
void createMessenger(VulkanContext& context);

bool hasExtension(const std::vector<VkExtensionProperties>& extensions, const char* name);

// volk's tables belong to the newest live context; a temporary instance (listDevices) or a
// destroyed context hands them back with reloadNewestContext. Every load goes through these two,
// which also record what is loaded (ContextLock reloads only when another context's is).
void loadInstanceFunctions(VkInstance instance);
void loadContextFunctions(VkInstance instance, VkDevice device);
void rememberContext(const VulkanContext& context);
void forgetContext(VkDevice device);
void reloadNewestContext();

// Held while anything loads volk's tables or calls Vulkan through them (context.h ContextLock).
std::recursive_mutex& vulkanMutex();

// Keeps the driver and layer modules mapped for LeakSanitizer's report at exit.
// createInstance calls it, so a temporary instance (listDevices) and a context that fails to
// start are covered as well as a live one.
void keepVulkanModulesLoaded();

}  // namespace phongvk
