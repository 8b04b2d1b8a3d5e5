// context.cpp — instance, device choice (with the reasons each device is rejected), device, queue.
#include "host/context.h"

#include "host/vk_check.h"

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <optional>

#if defined(__SANITIZE_ADDRESS__)
#include <dlfcn.h>
#include <link.h>
#endif

namespace phongvk {

void ValidationLog::add(std::string message) {
  std::lock_guard lock(mutex_);
  messages_.push_back(std::move(message));
}

size_t ValidationLog::count() const {
  std::lock_guard lock(mutex_);
  return messages_.size();
}

std::vector<std::string> ValidationLog::messages() const {
  std::lock_guard lock(mutex_);
  return messages_;
}

void ValidationLog::clear() {
  std::lock_guard lock(mutex_);
  messages_.clear();
}

namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";
constexpr const char* kRequirements =
    "Vulkan 1.2, shaderInt64, shaderBufferInt64Atomics, storageBuffer8BitAccess and a compute queue";

void initializeLoader() {
  // volkInitialize dlopens libvulkan.so.1; once per process is enough.
  static const VkResult result = volkInitialize();
  if (result != VK_SUCCESS)
    throw NoDeviceError("no Vulkan loader found (libvulkan.so.1); install libvulkan1 and mesa-vulkan-drivers");
}

bool validationRequested(const ContextOptions& options) {
  const char* env = std::getenv("PHONGVK_VALIDATE");
  return options.validate || (env && std::string(env) == "1");
}

// volk has one global function table. Loading a temporary instance (listDevices, a createContext
// that fails) would leave a live context calling through the temporary's pointers — and an
// extension the temporary did not enable (vkDestroyDebugUtilsMessengerEXT) would be null.
// So the live contexts are remembered, and the newest one's tables are put back whenever a
// temporary instance or a context goes away. Contexts are created and destroyed on one thread.
struct LoadedContext {
  VkInstance instance;
  VkDevice device;
};

std::vector<LoadedContext>& liveContexts() {
  static std::vector<LoadedContext> contexts;
  return contexts;
}

void reloadNewestContext() {
  if (liveContexts().empty()) return;
  volkLoadInstanceOnly(liveContexts().back().instance);
  volkLoadDevice(liveContexts().back().device);
}

void forgetContext(VkDevice device) {
  std::vector<LoadedContext>& contexts = liveContexts();
  std::erase_if(contexts, [device](const LoadedContext& context) { return context.device == device; });
}

bool hasExtension(const std::vector<VkExtensionProperties>& extensions, const char* name) {
  for (const VkExtensionProperties& extension : extensions)
    if (std::string(extension.extensionName) == name) return true;
  return false;
}

std::vector<VkExtensionProperties> instanceExtensions(const char* layer) {
  uint32_t count = 0;
  VK_CHECK(vkEnumerateInstanceExtensionProperties(layer, &count, nullptr));
  std::vector<VkExtensionProperties> extensions(count);
  VK_CHECK(vkEnumerateInstanceExtensionProperties(layer, &count, extensions.data()));
  return extensions;
}

bool hasLayer(const char* name) {
  uint32_t count = 0;
  VK_CHECK(vkEnumerateInstanceLayerProperties(&count, nullptr));
  std::vector<VkLayerProperties> layers(count);
  VK_CHECK(vkEnumerateInstanceLayerProperties(&count, layers.data()));
  for (const VkLayerProperties& layer : layers)
    if (std::string(layer.layerName) == name) return true;
  return false;
}

VKAPI_ATTR VkBool32 VKAPI_CALL onValidationMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                   VkDebugUtilsMessageTypeFlagsEXT types,
                                                   const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
  // General messages come from the loader (a driver it could not load), the rest from the layers.
  const char* source = (types & VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT) ? "vulkan loader" : "validation";
  const char* level = severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT ? "error" : "warning";
  std::string message = std::string(source) + " " + level + ": " + (data->pMessage ? data->pMessage : "");
  std::fprintf(stderr, "phongvk: %s\n", message.c_str());
  static_cast<ValidationLog*>(user)->add(std::move(message));
  return VK_FALSE;  // never abort the call: the test that made it fails on the log instead
}

VkDebugUtilsMessengerCreateInfoEXT messengerInfo(ValidationLog* log) {
  VkDebugUtilsMessengerCreateInfoEXT info = { VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT };
  // Warnings and errors only: info/verbose are the loader chatting about what it found.
  info.messageSeverity =
      VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                     VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  info.pfnUserCallback = onValidationMessage;
  info.pUserData = log;
  return info;
}

// Synchronization validation catches missing barriers between dispatches (a read of keys before
// the atomicMin pass is done), the bug class a compute renderer is most likely to have.
const VkValidationFeatureEnableEXT kValidationFeatures[] = {
    VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};

// Adds the Khronos layer, the messenger and synchronization validation to `info`; `messenger`
// and `features` are chained into it and must live until vkCreateInstance.
void enableValidation(VkInstanceCreateInfo& info, std::vector<const char*>& extensions,
                      VkDebugUtilsMessengerCreateInfoEXT& messenger, VkValidationFeaturesEXT& features) {
  if (!hasLayer(kValidationLayer))
    throw std::runtime_error(std::string("validation was requested but ") + kValidationLayer +
                             " is not installed; install vulkan-validationlayers");
  info.enabledLayerCount = 1;
  info.ppEnabledLayerNames = &kValidationLayer;
  extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  // Chained into the instance so vkCreateInstance and vkDestroyInstance are reported too.
  info.pNext = &messenger;
  if (hasExtension(instanceExtensions(kValidationLayer), VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME)) {
    extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);
    features.enabledValidationFeatureCount = static_cast<uint32_t>(std::size(kValidationFeatures));
    features.pEnabledValidationFeatures = kValidationFeatures;
    messenger.pNext = &features;
  }
}

// A Vulkan 1.2 instance, validated (messages to `log`) unless log is null; loaded into volk.
VkInstance createInstance(ValidationLog* log) {
  VkApplicationInfo app = { VK_STRUCTURE_TYPE_APPLICATION_INFO };
  app.pApplicationName = "phongvk";
  app.apiVersion = VK_API_VERSION_1_2;

  VkInstanceCreateInfo info = { VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO };
  info.pApplicationInfo = &app;

  std::vector<const char*> extensions;
  // Drivers that are not fully conformant (MoltenVK) are only listed when asked for.
  if (hasExtension(instanceExtensions(nullptr), VK_KHR_PORTABILITY_ENUMERATION_EXTENSION_NAME)) {
    extensions.push_back(VK_KHR_PORTABILITY_ENUMERATION_EXTENSION_NAME);
    info.flags |= VK_INSTANCE_CREATE_ENUMERATE_PORTABILITY_BIT_KHR;
  }
  VkDebugUtilsMessengerCreateInfoEXT messenger = messengerInfo(log);
  VkValidationFeaturesEXT features = { VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT };
  if (log) enableValidation(info, extensions, messenger, features);
  info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();

  VkInstance instance = VK_NULL_HANDLE;
  VkResult result = vkCreateInstance(&info, nullptr, &instance);
  // The loader answers VK_ERROR_INCOMPATIBLE_DRIVER when it finds no driver (ICD) at all.
  if (result == VK_ERROR_INCOMPATIBLE_DRIVER)
    throw NoDeviceError("no Vulkan driver found (vkCreateInstance: VK_ERROR_INCOMPATIBLE_DRIVER); "
                        "install mesa-vulkan-drivers");
  VK_CHECK(result);
  volkLoadInstanceOnly(instance);
  return instance;
}

std::vector<VkPhysicalDevice> physicalDevices(VkInstance instance) {
  uint32_t count = 0;
  VK_CHECK(vkEnumeratePhysicalDevices(instance, &count, nullptr));
  std::vector<VkPhysicalDevice> devices(count);
  VK_CHECK(vkEnumeratePhysicalDevices(instance, &count, devices.data()));
  return devices;
}

std::vector<VkExtensionProperties> deviceExtensions(VkPhysicalDevice device) {
  uint32_t count = 0;
  VK_CHECK(vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr));
  std::vector<VkExtensionProperties> extensions(count);
  VK_CHECK(vkEnumerateDeviceExtensionProperties(device, nullptr, &count, extensions.data()));
  return extensions;
}

std::string versionString(uint32_t version) {
  return std::to_string(VK_API_VERSION_MAJOR(version)) + "." + std::to_string(VK_API_VERSION_MINOR(version)) + "." +
         std::to_string(VK_API_VERSION_PATCH(version));
}

// Names as `phongvk devices` prints them; rank: higher is preferred when no index is given.
struct DeviceType {
  VkPhysicalDeviceType type;
  const char* name;
  int rank;
};
constexpr DeviceType kDeviceTypes[] = {
    {VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU, "discrete GPU", 4},
    {VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU, "integrated GPU", 3},
    {VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU, "virtual GPU", 2},
    {VK_PHYSICAL_DEVICE_TYPE_CPU, "CPU", 1},
};

std::string deviceTypeName(VkPhysicalDeviceType type) {
  for (const DeviceType& known : kDeviceTypes)
    if (known.type == type) return known.name;
  return "other";
}

int deviceTypeRank(const std::string& name) {
  for (const DeviceType& known : kDeviceTypes)
    if (name == known.name) return known.rank;
  return 0;
}

std::vector<VkQueueFamilyProperties> queueFamilies(VkPhysicalDevice device) {
  uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
  return families;
}

// The first compute family that can write timestamps, else the first compute family.
std::optional<uint32_t> findComputeFamily(VkPhysicalDevice device) {
  std::vector<VkQueueFamilyProperties> families = queueFamilies(device);
  std::optional<uint32_t> found;
  for (uint32_t i = 0; i < families.size(); ++i) {
    if (!(families[i].queueFlags & VK_QUEUE_COMPUTE_BIT) || families[i].queueCount == 0) continue;
    if (families[i].timestampValidBits > 0) return i;
    if (!found) found = i;
  }
  return found;
}

DeviceInfo inspectDevice(VkPhysicalDevice device, uint32_t index) {
  VkPhysicalDeviceProperties properties;
  vkGetPhysicalDeviceProperties(device, &properties);

  DeviceInfo report;
  report.index = index;
  report.name = properties.deviceName;
  report.type = deviceTypeName(properties.deviceType);
  report.apiVersion = versionString(properties.apiVersion);

  // VkPhysicalDeviceVulkan12Features may only be queried from a 1.2 device.
  bool vulkan12 = properties.apiVersion >= VK_API_VERSION_1_2;
  VkPhysicalDeviceVulkan12Features features12 = { VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES };
  VkPhysicalDeviceFeatures2 features = { VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2 };
  features.pNext = vulkan12 ? &features12 : nullptr;
  vkGetPhysicalDeviceFeatures2(device, &features);

  if (!vulkan12) report.missing.push_back("Vulkan 1.2");
  if (!features.features.shaderInt64) report.missing.push_back("shaderInt64");
  if (vulkan12 && !features12.shaderBufferInt64Atomics) report.missing.push_back("shaderBufferInt64Atomics");
  if (vulkan12 && !features12.storageBuffer8BitAccess) report.missing.push_back("storageBuffer8BitAccess");
  if (!findComputeFamily(device)) report.missing.push_back("a compute queue");
  report.suitable = report.missing.empty();
  return report;
}

std::vector<DeviceInfo> inspectDevices(const std::vector<VkPhysicalDevice>& devices) {
  std::vector<DeviceInfo> reports;
  for (uint32_t i = 0; i < devices.size(); ++i) reports.push_back(inspectDevice(devices[i], i));
  return reports;
}

std::string joined(const std::vector<std::string>& items) {
  std::string text;
  for (const std::string& item : items) text += (text.empty() ? "" : ", ") + item;
  return text;
}

// "[0] llvmpipe (missing shaderBufferInt64Atomics); [1] ..."
std::string rejections(const std::vector<DeviceInfo>& reports) {
  std::string text;
  for (const DeviceInfo& report : reports)
    text += (text.empty() ? "[" : "; [") + std::to_string(report.index) + "] " + report.name + " (missing " +
            joined(report.missing) + ")";
  return text;
}

void createDevice(VulkanContext& context) {
  float priority = 1.0f;
  VkDeviceQueueCreateInfo queueInfo = { VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO };
  queueInfo.queueFamilyIndex = context.queueFamily;
  queueInfo.queueCount = 1;
  queueInfo.pQueuePriorities = &priority;

  VkPhysicalDeviceVulkan12Features features12 = { VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES };
  features12.shaderBufferInt64Atomics = VK_TRUE;  // atomicMin of the 64-bit depth|triangle key
  features12.storageBuffer8BitAccess = VK_TRUE;   // resolve writes the colour buffer's RGB bytes
  VkPhysicalDeviceFeatures2 features = { VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2 };
  features.pNext = &features12;
  features.features.shaderInt64 = VK_TRUE;        // uint64_t keys and int64 edge functions

  // A portability (non-conformant) driver requires its subset extension to be enabled.
  std::vector<const char*> extensions;
  if (hasExtension(deviceExtensions(context.physicalDevice), "VK_KHR_portability_subset"))
    extensions.push_back("VK_KHR_portability_subset");

  VkDeviceCreateInfo info = { VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO };
  info.pNext = &features;
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queueInfo;
  info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  VK_CHECK(vkCreateDevice(context.physicalDevice, &info, nullptr, &context.device));
  volkLoadDevice(context.device);
  vkGetDeviceQueue(context.device, context.queueFamily, 0, &context.queue);
}

void createCommandPool(VulkanContext& context) {
  VkCommandPoolCreateInfo info = { VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO };
  info.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;  // one-time command buffers, freed after each submit
  info.queueFamilyIndex = context.queueFamily;
  VK_CHECK(vkCreateCommandPool(context.device, &info, nullptr, &context.commandPool));
  // One fence for every submitAndWait, reset before each use: on the H100 creating and destroying
  // a fence per submission cost 0.5 ms (265 + 232 us), more than a small frame's device time.
  VkFenceCreateInfo fenceInfo = { VK_STRUCTURE_TYPE_FENCE_CREATE_INFO };
  VK_CHECK(vkCreateFence(context.device, &fenceInfo, nullptr, &context.fence));
}

void createMessenger(VulkanContext& context) {
  VkDebugUtilsMessengerCreateInfoEXT info = messengerInfo(context.validation.get());
  VK_CHECK(vkCreateDebugUtilsMessengerEXT(context.instance, &info, nullptr, &context.messenger));
}

// Everything about the chosen device that the rest of the port reads from the context.
void describeDevice(VulkanContext& context, const DeviceInfo& report) {
  context.info = report;
  vkGetPhysicalDeviceProperties(context.physicalDevice, &context.properties);
  vkGetPhysicalDeviceMemoryProperties(context.physicalDevice, &context.memoryProperties);
  context.queueFamily = *findComputeFamily(context.physicalDevice);
  context.timestampValidBits = queueFamilies(context.physicalDevice)[context.queueFamily].timestampValidBits;
  context.timestamps = context.timestampValidBits > 0 && context.properties.limits.timestampPeriod > 0;
}

// ASan builds only. LeakSanitizer reports at exit, after vkDestroyInstance has dlclose'd the
// driver and the layers, so their own leaks would show as "<unknown module>" and
// tests/lsan.supp could not name them. Marking them RTLD_NODELETE keeps them resolvable.
void keepVulkanModulesLoaded() {
#if defined(__SANITIZE_ADDRESS__)
  auto pin = [](dl_phdr_info* info, size_t, void*) {
    std::string name = info->dlpi_name ? info->dlpi_name : "";
    if (name.find("libVkLayer_") != std::string::npos || name.find("libvulkan_") != std::string::npos)
      dlopen(name.c_str(), RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
    return 0;
  };
  dl_iterate_phdr(pin, nullptr);
#endif
}

}  // namespace

std::vector<DeviceInfo> listDevices() {
  initializeLoader();
  VkInstance instance = createInstance(nullptr);
  std::vector<DeviceInfo> reports;
  std::exception_ptr failure;
  try {
    reports = inspectDevices(physicalDevices(instance));
  } catch (...) {
    failure = std::current_exception();
  }
  vkDestroyInstance(instance, nullptr);
  reloadNewestContext();  // loading the temporary instance replaced a live context's tables
  if (failure) std::rethrow_exception(failure);
  return reports;
}

uint32_t chooseDevice(const std::vector<DeviceInfo>& reports, int requested) {
  if (reports.empty())
    throw NoDeviceError("no Vulkan device found: the Vulkan driver lists none; install mesa-vulkan-drivers");
  if (requested >= 0) {
    if (static_cast<size_t>(requested) >= reports.size())
      throw NoDeviceError("Vulkan device index " + std::to_string(requested) + " is out of range; the devices are:\n" +
                          formatDeviceList(reports));
    const DeviceInfo& report = reports[requested];
    if (!report.suitable)
      throw NoDeviceError("Vulkan device " + std::to_string(requested) + " (" + report.name +
                          ") is not usable: missing " + joined(report.missing));
    return report.index;
  }
  std::optional<uint32_t> best;
  int bestRank = -1;
  for (const DeviceInfo& report : reports) {
    int rank = deviceTypeRank(report.type);
    if (report.suitable && rank > bestRank) {
      best = report.index;
      bestRank = rank;
    }
  }
  if (!best) throw NoDeviceError(std::string("no usable Vulkan device (phongvk needs ") + kRequirements +
                                 "): " + rejections(reports));
  return *best;
}

VulkanContext createContext(const ContextOptions& options) {
  initializeLoader();
  VulkanContext context;
  if (validationRequested(options)) context.validation = std::make_shared<ValidationLog>();
  try {
    context.instance = createInstance(context.validation.get());
    if (context.validation) createMessenger(context);
    std::vector<VkPhysicalDevice> devices = physicalDevices(context.instance);
    std::vector<DeviceInfo> reports = inspectDevices(devices);
    uint32_t chosen = chooseDevice(reports, options.deviceIndex);
    context.physicalDevice = devices[chosen];
    describeDevice(context, reports[chosen]);
    createDevice(context);
    createCommandPool(context);
  } catch (...) {
    destroyContext(context);  // also reloads the tables of a context that was live before
    throw;
  }
  liveContexts().push_back({context.instance, context.device});
  keepVulkanModulesLoaded();
  return context;
}

void destroyContext(VulkanContext& context) {
  // Destroy through this context's own function tables (another context may be loaded now),
  // then hand volk back to the newest context still alive.
  if (context.instance) volkLoadInstanceOnly(context.instance);
  if (context.device) {
    volkLoadDevice(context.device);
    // Whatever is still in flight must finish before its pool and device go. The result is
    // ignored on purpose: a lost device must still be destroyed.
    (void)vkDeviceWaitIdle(context.device);
    if (context.fence) vkDestroyFence(context.device, context.fence, nullptr);
    if (context.commandPool) vkDestroyCommandPool(context.device, context.commandPool, nullptr);
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

std::string formatDeviceList(const std::vector<DeviceInfo>& devices) {
  std::string text;
  for (const DeviceInfo& device : devices) {
    // Appended piece by piece: GCC 12 warns (-Wrestrict, a known false positive) on the chain
    // "[" + std::to_string(...) + ...
    text.append("[").append(std::to_string(device.index)).append("] ").append(device.name);
    text.append(" \u2014 ").append(device.type).append(", Vulkan ").append(device.apiVersion).append(" \u2014 ");
    text.append(device.suitable ? "usable" : "rejected: missing " + joined(device.missing)).append("\n");
  }
  return text;
}

void checkDeviceLimit(const VulkanContext& context, const std::string& what, uint64_t need, const std::string& unit,
                      const char* limitName, uint64_t limit) {
  if (need <= limit) return;
  throw std::runtime_error("scene too large for " + context.info.name + ": " + what + " need " +
                           std::to_string(need) + (unit.empty() ? "" : " " + unit) + ", more than " + limitName +
                           " (" + std::to_string(limit) + ")");
}

}  // namespace phongvk
