// device.cpp — the physical devices and the reasons each is or is not usable, the choice among
// them, and the logical device with the features phongvk needs.
#include "vulkan/device.h"

#include "phongvk/errors.h"
#include "vulkan/instance.h"
#include "vulkan/vk_check.h"

#include <charconv>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <string>

namespace phongvk {
namespace {

constexpr const char* kRequirements = "Vulkan 1.2 and a compute queue";
constexpr const char* kKeyPathVariable = "PHONGVK_KEY_PATH";

// PHONGVK_KEY_PATH: 32 or 64 forces that key path (for tests and comparisons), unset lets each
// device's features decide; anything else is an ArgumentError naming the variable.
std::optional<int> keyPathVariable() {
  const char* text = std::getenv(kKeyPathVariable);
  if (!text) return std::nullopt;
  const std::string value = text;
  if (value == "32") return 32;
  if (value == "64") return 64;
  throw ArgumentError(std::string(kKeyPathVariable) + " is '" + value +
                      "': expected 32 (32-bit atomics, two passes) or 64 (64-bit atomics), or unset");
}

}  // namespace

std::vector<VkPhysicalDevice> physicalDevices(VkInstance instance) {
  uint32_t count = 0;
  VK_CHECK(vkEnumeratePhysicalDevices(instance, &count, nullptr));
  std::vector<VkPhysicalDevice> devices(count);
  VK_CHECK(vkEnumeratePhysicalDevices(instance, &count, devices.data()));
  return devices;
}

namespace {

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

}  // namespace

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

namespace {

DeviceInfo inspectDevice(VkPhysicalDevice device, uint32_t index, std::optional<int> keyPath) {
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
  if (!findComputeFamily(device)) report.missing.push_back("a compute queue");
  if (!features.features.shaderInt64) report.lacks64.push_back("shaderInt64");
  if (!vulkan12 || !features12.shaderBufferInt64Atomics) report.lacks64.push_back("shaderBufferInt64Atomics");
  if (!vulkan12 || !features12.storageBuffer8BitAccess) report.lacks64.push_back("storageBuffer8BitAccess");
  report.keys32 = keyPath ? *keyPath == 32 : !report.lacks64.empty();
  if (keyPath == 64) {
    for (const std::string& feature : report.lacks64)
      report.missing.push_back(feature + " (" + kKeyPathVariable + "=64)");
  }
  report.suitable = report.missing.empty();
  return report;
}

}  // namespace

std::vector<DeviceInfo> inspectDevices(const std::vector<VkPhysicalDevice>& devices) {
  const std::optional<int> keyPath = keyPathVariable();
  std::vector<DeviceInfo> reports;
  for (uint32_t i = 0; i < devices.size(); ++i) reports.push_back(inspectDevice(devices[i], i, keyPath));
  return reports;
}

namespace {

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

constexpr const char* kStorageRangeVariable = "PHONGVK_MAX_STORAGE_BUFFER_RANGE";

// The variable's value: a decimal number of bytes, at least 1 (one past 64 bits reads as the
// largest, which no device's limit reaches). Anything else is an ArgumentError naming it.
uint64_t parseStorageRange(const std::string& text) {
  uint64_t value = 0;
  const char* end = text.data() + text.size();
  const std::from_chars_result parsed = std::from_chars(text.data(), end, value);
  if (parsed.ec == std::errc::result_out_of_range && parsed.ptr == end) return UINT64_MAX;
  if (text.empty() || parsed.ec != std::errc() || parsed.ptr != end || value == 0)
    throw ArgumentError(std::string(kStorageRangeVariable) + " is '" + text +
                        "': expected a number of bytes, at least 1 (e.g. 134217728)");
  return value;
}

}  // namespace

// A testing aid: PHONGVK_MAX_STORAGE_BUFFER_RANGE lowers the device's maxStorageBufferRange (never
// raises it), so every check of that limit meets it as on a smaller device — a GPU's 4 GiB tested
// as lavapipe's 128 MiB, the least Vulkan allows.
std::optional<uint64_t> storageRangeVariable() {
  const char* text = std::getenv(kStorageRangeVariable);
  if (!text) return std::nullopt;
  return parseStorageRange(text);
}

// Everything about the chosen device that the rest of the port reads from the context.
void describeDevice(VulkanContext& context, const DeviceInfo& report, std::optional<uint64_t> storageRange) {
  context.info = report;
  vkGetPhysicalDeviceProperties(context.physicalDevice, &context.properties);
  uint32_t& limit = context.properties.limits.maxStorageBufferRange;
  if (storageRange && *storageRange < limit) limit = static_cast<uint32_t>(*storageRange);
  vkGetPhysicalDeviceMemoryProperties(context.physicalDevice, &context.memoryProperties);
  context.storageArrays = report.keys32 && context.properties.limits.maxTexelBufferElements < STORAGE_ARRAYS_BELOW;
  context.queueFamily = *findComputeFamily(context.physicalDevice);
  context.timestampValidBits = queueFamilies(context.physicalDevice)[context.queueFamily].timestampValidBits;
  context.timestamps = context.timestampValidBits > 0 && context.properties.limits.timestampPeriod > 0;
}

void createDevice(VulkanContext& context) {
  float priority = 1.0f;
  VkDeviceQueueCreateInfo queueInfo = { VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO };
  queueInfo.queueFamilyIndex = context.queueFamily;
  queueInfo.queueCount = 1;
  queueInfo.pQueuePriorities = &priority;

  VkPhysicalDeviceVulkan12Features features12 = { VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES };
  // The 64-bit key path's; the 32-bit path's shaders use none of them.
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
  info.pNext = context.info.keys32 ? nullptr : &features;
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queueInfo;
  info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  VK_CHECK(vkCreateDevice(context.physicalDevice, &info, nullptr, &context.device));
  loadContextFunctions(context.instance, context.device);
  vkGetDeviceQueue(context.device, context.queueFamily, 0, &context.queue);
}

std::vector<DeviceInfo> listDevices() {
  initializeLoader();
  const std::lock_guard lock(vulkanMutex());
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

std::string keyPathWords(const DeviceInfo& device) {
  if (!device.keys32) return "64-bit atomics";
  return "32-bit atomics, two passes" +
         (device.lacks64.empty() ? std::string(" (") + kKeyPathVariable + "=32)" : " (no " + joined(device.lacks64) + ")");
}

std::string formatDeviceList(const std::vector<DeviceInfo>& devices) {
  std::string text;
  for (const DeviceInfo& device : devices) {
    // Appended piece by piece: GCC 12 warns (-Wrestrict, a known false positive) on the chain
    // "[" + std::to_string(...) + ...
    text.append("[").append(std::to_string(device.index)).append("] ").append(device.name);
    text.append(" \u2014 ").append(device.type).append(", Vulkan ").append(device.apiVersion).append(" \u2014 ");
    text.append(device.suitable ? "usable \u2014 keys: " + keyPathWords(device) : "rejected: missing " + joined(device.missing));
    text.append("\n");
  }
  return text;
}

}  // namespace phongvk
