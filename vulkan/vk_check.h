// vk_check.h — every Vulkan result is checked, in release builds too.
//
//   VK_CHECK(vkCreateBuffer(device, &info, nullptr, &buffer));
//
// throws VulkanError("vulkan/resources.cpp:42: vkCreateBuffer(device, &info, nullptr, &buffer) failed:
// VK_ERROR_OUT_OF_DEVICE_MEMORY"), so a failure names the place, the call and the reason.
#pragma once

#include "phongvk/errors.h"

#include <volk.h>

#include <stdexcept>
#include <string>

namespace phongvk {

// A Vulkan call returned something other than VK_SUCCESS. `result` keeps the code for callers
// that react to a specific one (VK_ERROR_DEVICE_LOST, VK_TIMEOUT).
class VulkanError : public DeviceError {
 public:
  VulkanError(const std::string& message, VkResult result) : DeviceError(message), result(result) {}
  VkResult result;
};

// The enumerant's name, e.g. "VK_ERROR_OUT_OF_DEVICE_MEMORY"; unknown codes print as a number.
inline std::string vkResultName(VkResult result) {
  switch (result) {
#define PHONGVK_RESULT_NAME(name) \
  case name:                      \
    return #name;
    PHONGVK_RESULT_NAME(VK_SUCCESS)
    PHONGVK_RESULT_NAME(VK_NOT_READY)
    PHONGVK_RESULT_NAME(VK_TIMEOUT)
    PHONGVK_RESULT_NAME(VK_EVENT_SET)
    PHONGVK_RESULT_NAME(VK_EVENT_RESET)
    PHONGVK_RESULT_NAME(VK_INCOMPLETE)
    PHONGVK_RESULT_NAME(VK_ERROR_OUT_OF_HOST_MEMORY)
    PHONGVK_RESULT_NAME(VK_ERROR_OUT_OF_DEVICE_MEMORY)
    PHONGVK_RESULT_NAME(VK_ERROR_INITIALIZATION_FAILED)
    PHONGVK_RESULT_NAME(VK_ERROR_DEVICE_LOST)
    PHONGVK_RESULT_NAME(VK_ERROR_MEMORY_MAP_FAILED)
    PHONGVK_RESULT_NAME(VK_ERROR_LAYER_NOT_PRESENT)
    PHONGVK_RESULT_NAME(VK_ERROR_EXTENSION_NOT_PRESENT)
    PHONGVK_RESULT_NAME(VK_ERROR_FEATURE_NOT_PRESENT)
    PHONGVK_RESULT_NAME(VK_ERROR_INCOMPATIBLE_DRIVER)
    PHONGVK_RESULT_NAME(VK_ERROR_TOO_MANY_OBJECTS)
    PHONGVK_RESULT_NAME(VK_ERROR_FORMAT_NOT_SUPPORTED)
    PHONGVK_RESULT_NAME(VK_ERROR_FRAGMENTED_POOL)
    PHONGVK_RESULT_NAME(VK_ERROR_UNKNOWN)
    PHONGVK_RESULT_NAME(VK_ERROR_OUT_OF_POOL_MEMORY)
    PHONGVK_RESULT_NAME(VK_ERROR_INVALID_EXTERNAL_HANDLE)
    PHONGVK_RESULT_NAME(VK_ERROR_FRAGMENTATION)
    PHONGVK_RESULT_NAME(VK_ERROR_INVALID_OPAQUE_CAPTURE_ADDRESS)
    PHONGVK_RESULT_NAME(VK_PIPELINE_COMPILE_REQUIRED)
    PHONGVK_RESULT_NAME(VK_ERROR_VALIDATION_FAILED_EXT)
    PHONGVK_RESULT_NAME(VK_ERROR_INVALID_SHADER_NV)
#undef PHONGVK_RESULT_NAME
    default:
      return "VkResult(" + std::to_string(static_cast<int>(result)) + ")";
  }
}

[[noreturn]] inline void throwVulkanError(VkResult result, const char* file, int line, const char* call) {
  throw VulkanError(std::string(file) + ":" + std::to_string(line) + ": " + call + " failed: " + vkResultName(result),
                    result);
}

}  // namespace phongvk

// Anything but VK_SUCCESS is a failure: the positive codes (VK_TIMEOUT, VK_INCOMPLETE) mean the
// call did not do what the caller asked, and callers that expect them test the result themselves.
#define VK_CHECK(call)                                                             \
  do {                                                                             \
    VkResult vkCheckResult_ = (call);                                              \
    if (vkCheckResult_ != VK_SUCCESS)                                              \
      ::phongvk::throwVulkanError(vkCheckResult_, __FILE__, __LINE__, #call);      \
  } while (0)
