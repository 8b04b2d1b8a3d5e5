#include "machine.h"

#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <thread>

namespace phongvk::bench {

namespace {

// The value of the first "key<spaces/tabs>: value" line of a /proc file, or "unknown".
std::string procField(const char* file, const std::string& key) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    if (line.compare(0, key.size(), key) != 0) continue;
    const size_t colon = line.find(':');
    const size_t start = line.find_first_not_of(" \t", colon + 1);
    if (colon != std::string::npos && start != std::string::npos) return line.substr(start);
  }
  return "unknown";
}

std::string memoryTotal() {
  const std::string kb = procField("/proc/meminfo", "MemTotal");  // "24558564 kB"
  char text[32];
  std::snprintf(text, sizeof text, "%.1f GiB", std::strtod(kb.c_str(), nullptr) / (1024.0 * 1024.0));
  return kb == "unknown" ? kb : text;
}

std::string driver(const VulkanContext& context) {
  VkPhysicalDeviceDriverProperties driver = {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
  VkPhysicalDeviceProperties2 properties = {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &driver};
  vkGetPhysicalDeviceProperties2(context.physicalDevice, &properties);
  return std::string(driver.driverName) + ", " + driver.driverInfo;
}

std::string utcNow() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%d %H:%M UTC", &utc);
  return text;
}

}  // namespace

Machine describeMachine(const VulkanContext& context) {
  Machine m;
  m.cpu = procField("/proc/cpuinfo", "model name");
  m.cores = std::thread::hardware_concurrency();
  m.memory = memoryTotal();
  const DeviceInfo& d = context.info;
  m.device = d.name + " (" + d.type + ", Vulkan " + d.apiVersion + ")";
  m.driver = driver(context);
  m.date = utcNow();
  return m;
}

unsigned cpuDeviceLanes(const VulkanContext& context) {
  if (context.properties.deviceType != VK_PHYSICAL_DEVICE_TYPE_CPU) return 0;
  VkPhysicalDeviceSubgroupProperties subgroup = {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES};
  VkPhysicalDeviceProperties2 properties = {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &subgroup};
  vkGetPhysicalDeviceProperties2(context.physicalDevice, &properties);
  return std::thread::hardware_concurrency() * subgroup.subgroupSize;
}

}  // namespace phongvk::bench
