// devices.h — the Vulkan devices on this machine and whether phongvk can use them.
#pragma once

#include "phongvk/export.h"

#include <cstdint>
#include <string>
#include <vector>

namespace phongvk {

// One physical device as phongvk sees it. phongvk needs Vulkan 1.2 and a compute queue. Where the
// device also has shaderInt64, shaderBufferInt64Atomics and storageBuffer8BitAccess, visibility
// takes 64-bit atomics; elsewhere (or with PHONGVK_KEY_PATH=32) 32-bit atomics in two passes, with
// the same keys and bytes (docs/DESIGN.md "Visibility").
struct DeviceInfo {
  uint32_t index = 0;                // position in vkEnumeratePhysicalDevices order: Renderer's `device`
  std::string name;                  // "llvmpipe (LLVM 15.0.6, 256 bits)"
  std::string type;                  // "discrete GPU", "integrated GPU", "virtual GPU", "CPU", "other"
  std::string apiVersion;            // "1.3.230"
  bool suitable = false;
  std::vector<std::string> missing;  // what it lacks: "Vulkan 1.2", "a compute queue" (or, with
                                     // PHONGVK_KEY_PATH=64, the 64-bit path's features)
  bool keys32 = false;               // the 32-bit key path
  std::vector<std::string> lacks64;  // which of the 64-bit path's features it lacks, if any
};

// The key path in words, as `phongvk devices` and the render summary print it: "64-bit atomics" or
// "32-bit atomics, two passes".
PHONGVK_API std::string keyPathWords(const DeviceInfo& device);

// Every Vulkan device with the reasons it is or is not usable. Throws NoDeviceError when there is
// no Vulkan loader or driver at all.
PHONGVK_API std::vector<DeviceInfo> listDevices();

// What `phongvk devices` prints, one line per device:
// "[0] llvmpipe (LLVM 15.0.6, 256 bits) — CPU, Vulkan 1.3.230 — usable — keys: 64-bit atomics"
PHONGVK_API std::string formatDeviceList(const std::vector<DeviceInfo>& devices);

}  // namespace phongvk
