// machine.h — what the numbers were measured on, for the report's header.
#pragma once

#include "vulkan/context.h"

#include <string>

namespace phongvk::bench {

struct Machine {
  std::string cpu;      // /proc/cpuinfo "model name"
  unsigned cores = 0;   // logical CPUs this process may use
  std::string memory;   // /proc/meminfo MemTotal, e.g. "23.4 GiB"
  std::string device;   // "llvmpipe (LLVM 15.0.6, 256 bits) (CPU, Vulkan 1.3.230)"
  std::string driver;   // "llvmpipe, Mesa 22.3.6 (LLVM 15.0.6)"
  std::string date;     // UTC, when the run started
};

Machine describeMachine(const VulkanContext& context);

// On a CPU device (lavapipe): the logical cores times the SIMD lanes of one (its subgroup size),
// the most work it can do at once, i.e. its best possible speedup over one scalar core. 0 on a GPU.
unsigned cpuDeviceLanes(const VulkanContext& context);

}  // namespace phongvk::bench
