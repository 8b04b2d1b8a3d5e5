// context.cpp — a context from its parts (instance.h, device.h): instance, chosen device, queue,
// command pool and fence; and its destruction in the right order.
#include "vulkan/context.h"

#include "vulkan/device.h"
#include "vulkan/instance.h"
#include "vulkan/pipeline_cache.h"
#include "vulkan/vk_check.h"

#include <string>

namespace phongvk {
namespace {

void createCommandPool(VulkanContext& context) {
  VkCommandPoolCreateInfo info = { VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO };
  info.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;  // one-time command buffers, freed after each submit
  info.queueFamilyIndex = context.queueFamily;
  VK_CHECK(vkCreateCommandPool(context.device, &info, nullptr, &context.commandPool));
  // One fence for every submitAndWait, reset before each use: on the H100 creating and destroying
  // a fence per submission cost more than a small frame's device time (docs/DECISIONS.md, "One
  // fence per context").
  VkFenceCreateInfo fenceInfo = { VK_STRUCTURE_TYPE_FENCE_CREATE_INFO };
  VK_CHECK(vkCreateFence(context.device, &fenceInfo, nullptr, &context.fence));
}

}  // namespace

VulkanContext createContext(const ContextOptions& options) {
  initializeLoader();
  const std::lock_guard lock(vulkanMutex());
  const std::optional<uint64_t> storageRange = storageRangeVariable();
  VulkanContext context;
  if (validationRequested(options)) context.validation = std::make_shared<ValidationLog>();
  try {
    context.instance = createInstance(context.validation.get());
    if (context.validation) createMessenger(context);
    std::vector<VkPhysicalDevice> devices = physicalDevices(context.instance);
    std::vector<DeviceInfo> reports = inspectDevices(devices);
    uint32_t chosen = chooseDevice(reports, options.deviceIndex);
    context.physicalDevice = devices[chosen];
    describeDevice(context, reports[chosen], storageRange);
    createDevice(context);
    createCommandPool(context);
    if (options.pipelineCache) context.pipelineCache = loadPipelineCache(context);
  } catch (...) {
    destroyContext(context);  // also reloads the tables of a context that was live before
    throw;
  }
  rememberContext(context);
  return context;
}

void destroyContext(VulkanContext& context) {
  // Destroy through this context's own function tables (another context may be loaded now),
  // then hand volk back to the newest context still alive.
  const std::lock_guard lock(vulkanMutex());
  if (context.instance) loadInstanceFunctions(context.instance);
  if (context.device) {
    loadContextFunctions(context.instance, context.device);
    // Whatever is still in flight must finish before its pool and device go. The result is
    // ignored on purpose: a lost device must still be destroyed.
    (void)vkDeviceWaitIdle(context.device);
    if (context.fence) vkDestroyFence(context.device, context.fence, nullptr);
    if (context.commandPool) vkDestroyCommandPool(context.device, context.commandPool, nullptr);
    if (context.pipelineCache) vkDestroyPipelineCache(context.device, context.pipelineCache, nullptr);
    vkDestroyDevice(context.device, nullptr);
    forgetContext(context.device);
  }
  if (context.messenger) vkDestroyDebugUtilsMessengerEXT(context.instance, context.messenger, nullptr);
  if (context.instance) vkDestroyInstance(context.instance, nullptr);
  reloadNewestContext();

  std::shared_ptr<ValidationLog> validation = std::move(context.validation);
  context = VulkanContext{};
  context.validation = std::move(validation);
}

void checkDeviceLimit(const VulkanContext& context, const std::string& what, uint64_t need, const std::string& unit,
                      const char* limitName, uint64_t limit) {
  if (need <= limit) return;
  throw DeviceError("scene too large for " + context.info.name + ": " + what + " need " +
                           std::to_string(need) + (unit.empty() ? "" : " " + unit) + ", more than " + limitName +
                           " (" + std::to_string(limit) + ")");
}

}  // namespace phongvk
