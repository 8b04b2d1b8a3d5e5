// devices.h — the Vulkan devices on this machine and whether phongvk can use them.
#pragma once

#include "phongvk/export.h"

#include <cstdint>
#include <string>
#include <vector>

namespace phongvk {

// One physical device as phongvk sees it. phongvk needs Vulkan 1.2, shaderInt64,
// shaderBufferInt64Atomics, storageBuffer8BitAccess and a compute queue.
struct DeviceInfo {
  uint32_t index = 0;                // position in vkEnumeratePhysicalDevices order: Renderer's `device`
  std::string name;                  // "llvmpipe (LLVM 15.0.6, 256 bits)"
  std::string type;                  // "discrete GPU", "integrated GPU", "virtual GPU", "CPU", "other"
  std::string apiVersion;            // "1.3.230"
  bool suitable = false;
  std::vector<std::string> missing;  // what it lacks: "Vulkan 1.2", "shaderInt64", ..., "a compute queue"
};

// Every Vulkan device with the reasons it is or is not usable. Throws NoDeviceError when there is
// no Vulkan loader or driver at all.
PHONGVK_API std::vector<DeviceInfo> listDevices();

// What `phongvk devices` prints, one line per device:
// "[0] llvmpipe (LLVM 15.0.6, 256 bits) — CPU, Vulkan 1.3.230 — usable"
PHONGVK_API std::string formatDeviceList(const std::vector<DeviceInfo>& devices);

}  // namespace phongvk
