// context.h — the Vulkan instance, the chosen device and its compute queue (volk-loaded, headless);
// built in instance.cpp (loader, instance, validation), device.cpp (choice, device) and context.cpp.
//
// phongvk needs Vulkan 1.2 and one queue family with compute. A device with shaderInt64 and
// shaderBufferInt64Atomics (visibility by 64-bit atomicMin on a storage buffer) and
// storageBuffer8BitAccess (resolve writes the colour buffer as RGB bytes) takes the 64-bit key path;
// any other the 32-bit one (DeviceInfo::keys32: two passes of 32-bit atomicMin, the colour bytes
// written through their words), which gives the same keys and bytes.
// Every device is checked against that list and the reasons it fails are kept, so "no device"
// errors and `phongvk devices` can say exactly why a device was rejected.
//
// volk keeps one global function table, loaded for the newest live context (listDevices and
// destroyContext put it back). Creating and destroying contexts takes one process-wide lock; code
// that may share the process with other threads' contexts (the public Renderer) holds a
// ContextLock while it calls Vulkan, which serializes their Vulkan work and loads its context's
// functions first.
#pragma once

#include "phongvk/devices.h"
#include "phongvk/errors.h"
#include "vulkan/vk_check.h"  // every user of a context checks Vulkan calls

#include <volk.h>

#include <atomic>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

namespace phongvk {

inline constexpr uint32_t STORAGE_ARRAYS_BELOW = 1u << 24;

struct ContextOptions {
  int deviceIndex = -1;   // -1: the best suitable device (discrete > integrated > virtual > CPU)
  bool validate = false;  // Khronos validation + synchronization validation; also env PHONGVK_VALIDATE=1
  bool pipelineCache = false;  // a VkPipelineCache kept across processes (pipeline_cache.h)
};

// Warnings and errors from the validation layers, collected so tests can assert there were none.
// Thread-safe: the layers may report from any thread.
class ValidationLog {
 public:
  void add(std::string message);
  size_t count() const;
  std::vector<std::string> messages() const;
  void clear();

 private:
  mutable std::mutex mutex_;
  std::vector<std::string> messages_;
};

// Device memory a context has allocated (kept by resources.cpp), so the renderer can report it.
struct MemoryUsage {
  std::atomic<VkDeviceSize> current{0};
  std::atomic<VkDeviceSize> peak{0};
};

struct VulkanContext {
  VkInstance instance = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;  // only when validating
  VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  VkQueue queue = VK_NULL_HANDLE;
  uint32_t queueFamily = 0;
  VkCommandPool commandPool = VK_NULL_HANDLE;  // for one-time command buffers; not thread-safe
  VkFence fence = VK_NULL_HANDLE;              // submitAndWait's, reset before each use; likewise
  VkPipelineCache pipelineCache = VK_NULL_HANDLE;  // ContextOptions::pipelineCache; every pipeline goes through it
  VkPhysicalDeviceProperties properties = {};
  VkPhysicalDeviceMemoryProperties memoryProperties = {};
  bool timestamps = false;          // the queue can write timestamps (see TimestampPool)
  uint32_t timestampValidBits = 0;  // of the queue family; timestamps wrap modulo 2^bits
  std::shared_ptr<ValidationLog> validation;  // null unless validating
  std::shared_ptr<MemoryUsage> memory = std::make_shared<MemoryUsage>();
  DeviceInfo info;                  // the chosen device
  // The 32-bit key path on a device with small texel buffers (maxTexelBufferElements below
  // STORAGE_ARRAYS_BELOW texels: SwiftShader's 65,536): the passes read the scene's arrays from
  // storage buffers (the _k32s builds, bindings.glsl TEXELS). Elsewhere texel buffers, which lavapipe
  // gathers in SIMD: the 1M-triangle grid's frame took 1.9x the 64-bit path's with storage buffers,
  // 1.2x with texels.
  bool storageArrays = false;
};

// Creates the instance, picks a device (options.deviceIndex or the best suitable one), creates the
// device with the features phongvk needs, a compute queue, a command pool and a fence.
// Throws NoDeviceError when no (or not the requested) device is usable, DeviceError when
// validation was asked for but the layer is not installed, VulkanError on any other failure.
VulkanContext createContext(const ContextOptions& options);

// The device createContext takes: `requested` if it is in range and suitable, else (requested = -1)
// the best-ranked suitable one, the first on ties. Throws NoDeviceError saying why each device was
// rejected. Public so its messages can be tested without the hardware that would produce them.
uint32_t chooseDevice(const std::vector<DeviceInfo>& reports, int requested);

// Destroys everything createContext made; safe on a default or already destroyed context.
// `validation` survives, so a caller holding it sees messages raised while tearing down
// (e.g. objects the caller forgot to destroy).
void destroyContext(VulkanContext& context);

// Held while this thread calls Vulkan on `context` where other threads may hold contexts of their
// own: one lock for the process (recursive), and volk's tables loaded for `context`.
class ContextLock {
 public:
  explicit ContextLock(const VulkanContext& context);

 private:
  std::unique_lock<std::recursive_mutex> lock_;
};

// A context destroyed when it goes out of scope.
class ScopedContext {
 public:
  explicit ScopedContext(const ContextOptions& options) : context(createContext(options)) {}
  ~ScopedContext() { destroyContext(context); }
  ScopedContext(const ScopedContext&) = delete;
  ScopedContext& operator=(const ScopedContext&) = delete;
  VulkanContext context;
};

// Throws DeviceError("scene too large for DEVICE: WHAT need NEED UNIT, more than
// LIMIT_NAME (LIMIT)") when need > limit, the renderers' one message for an exceeded device limit
// (`unit` may be empty).
void checkDeviceLimit(const VulkanContext& context, const std::string& what, uint64_t need, const std::string& unit,
                      const char* limitName, uint64_t limit);

}  // namespace phongvk
