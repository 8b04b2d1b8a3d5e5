// instance.cpp — the loader, instances with or without validation, the validation log, and which
// live context's function tables volk holds.
#include "vulkan/instance.h"

#include "vulkan/vk_check.h"

#include <dlfcn.h>
#include <link.h>

#include <cstdio>
#include <cstdlib>
#include <string>

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
namespace {

struct LoadedContext {
  VkInstance instance;
  VkDevice device;
};

std::vector<LoadedContext>& liveContexts() {
  static std::vector<LoadedContext> contexts;
  return contexts;
}

}  // namespace

void rememberContext(const VulkanContext& context) { liveContexts().push_back({context.instance, context.device}); }

namespace {

// What volk's tables hold now.
VkInstance loadedInstance = VK_NULL_HANDLE;
VkDevice loadedDevice = VK_NULL_HANDLE;

}  // namespace

void loadInstanceFunctions(VkInstance instance) {
  volkLoadInstanceOnly(instance);
  loadedInstance = instance;
  loadedDevice = VK_NULL_HANDLE;
}

void loadContextFunctions(VkInstance instance, VkDevice device) {
  volkLoadInstanceOnly(instance);
  volkLoadDevice(device);
  loadedInstance = instance;
  loadedDevice = device;
}

std::recursive_mutex& vulkanMutex() {
  static std::recursive_mutex mutex;
  return mutex;
}

ContextLock::ContextLock(const VulkanContext& context) : lock_(vulkanMutex()) {
  if (loadedInstance != context.instance || loadedDevice != context.device) {
    loadContextFunctions(context.instance, context.device);
  }
}

void reloadNewestContext() {
  if (liveContexts().empty()) return;
  loadContextFunctions(liveContexts().back().instance, liveContexts().back().device);
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

namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

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
    throw DeviceError(std::string("validation was requested but ") + kValidationLayer +
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

}  // namespace

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
  keepVulkanModulesLoaded();  // the driver is loaded now, whatever fails after
  loadInstanceFunctions(instance);
  return instance;
}

void createMessenger(VulkanContext& context) {
  VkDebugUtilsMessengerCreateInfoEXT info = messengerInfo(context.validation.get());
  VK_CHECK(vkCreateDebugUtilsMessengerEXT(context.instance, &info, nullptr, &context.messenger));
}

// LeakSanitizer reports at exit, after vkDestroyInstance has dlclose'd the driver and the layers,
// so their own leaks would show as "<unknown module>" and tests/lsan.supp could not name them.
// Marking them RTLD_NODELETE keeps them resolvable. Done in every build, not only ASan's, so that
// LeakSanitizer preloaded into a release build (LD_PRELOAD=liblsan.so.0) reads the same; a
// process that makes a second instance finds the driver loaded already.
void keepVulkanModulesLoaded() {
  auto pin = [](dl_phdr_info* info, size_t, void*) {
    std::string name = info->dlpi_name ? info->dlpi_name : "";
    if (name.find("libVkLayer_") != std::string::npos || name.find("libvulkan_") != std::string::npos)
      dlopen(name.c_str(), RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
    return 0;
  };
  dl_iterate_phdr(pin, nullptr);
}

}  // namespace phongvk
