// devices.cpp — `phongvk devices`: every Vulkan device and, for each one phongvk cannot use, why.
#include "cli/cli_support.h"

#include <cstdio>

namespace phongvk::cli {

int runDevices() {
  return guarded([] {
    std::printf("%s", formatDeviceList(listDevices()).c_str());
    return int(EXIT_OK);
  });
}

}  // namespace phongvk::cli
