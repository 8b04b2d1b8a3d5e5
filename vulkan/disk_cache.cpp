// disk_cache.cpp — the cache folder and its files' framing (disk_cache.h).
#include "vulkan/disk_cache.h"

#include "vulkan/vk_check.h"

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <unistd.h>

namespace phongvk {
namespace {

// A file: MAGIC, the payload's size and FNV-1a checksum (little-endian u64 each), the payload.
constexpr char MAGIC[16] = "phongvk cache 1";
constexpr size_t HEADER_BYTES = sizeof(MAGIC) + 2 * sizeof(uint64_t);

void putU64(std::vector<uint8_t>& out, uint64_t value) {
  for (int i = 0; i < 8; ++i) out.push_back(uint8_t(value >> (8 * i)));
}

uint64_t getU64(const uint8_t* p) {
  uint64_t value = 0;
  for (int i = 7; i >= 0; --i) value = value << 8 | p[i];
  return value;
}

}  // namespace

std::filesystem::path cacheFolder() {
  const char* xdg = std::getenv("XDG_CACHE_HOME");
  if (xdg != nullptr && xdg[0] == '/') return std::filesystem::path(xdg) / "phongvk";
  const char* home = std::getenv("HOME");
  if (home != nullptr && home[0] != '\0') return std::filesystem::path(home) / ".cache" / "phongvk";
  return {};
}

std::string deviceCacheKey(const VulkanContext& context) {
  const VkPhysicalDeviceProperties& p = context.properties;
  // The driver's name and version text as well: lavapipe 22.3 reports driverVersion 1 and the
  // same UUID for every Mesa release, where driverInfo says "Mesa 22.3.6 (LLVM 15.0.6)".
  VkPhysicalDeviceDriverProperties driver = {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
  VkPhysicalDeviceProperties2 properties = {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
  properties.pNext = &driver;
  vkGetPhysicalDeviceProperties2(context.physicalDevice, &properties);
  uint64_t names = fnv1a(p.deviceName, std::strlen(p.deviceName));
  names = fnv1a(driver.driverName, std::strlen(driver.driverName), names);
  names = fnv1a(driver.driverInfo, std::strlen(driver.driverInfo), names);
  char key[160];
  int at = std::snprintf(key, sizeof key, "%x-%x-%x-%08llx-", p.vendorID, p.deviceID, p.driverVersion,
                         static_cast<unsigned long long>(names & 0xFFFFFFFFu));
  for (uint8_t byte : p.pipelineCacheUUID) at += std::snprintf(key + at, sizeof key - size_t(at), "%02x", byte);
  return key;
}

uint64_t fnv1a(const void* data, size_t size, uint64_t hash) {
  const auto* bytes = static_cast<const uint8_t*>(data);
  for (size_t i = 0; i < size; ++i) hash = (hash ^ bytes[i]) * 0x100000001b3ull;
  return hash;
}

std::optional<std::vector<uint8_t>> readCacheFile(const std::string& name) {
  const std::filesystem::path folder = cacheFolder();
  if (folder.empty()) return std::nullopt;
  std::ifstream file(folder / name, std::ios::binary);
  if (!file) return std::nullopt;
  const std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  if (bytes.size() < HEADER_BYTES || std::memcmp(bytes.data(), MAGIC, sizeof(MAGIC)) != 0) return std::nullopt;
  const uint64_t size = getU64(&bytes[sizeof(MAGIC)]);
  const uint64_t checksum = getU64(&bytes[sizeof(MAGIC) + 8]);
  if (size != bytes.size() - HEADER_BYTES || fnv1a(&bytes[HEADER_BYTES], size) != checksum) return std::nullopt;
  return std::vector<uint8_t>(bytes.begin() + HEADER_BYTES, bytes.end());
}

void writeCacheFile(const std::string& name, const std::vector<uint8_t>& payload) {
  const std::filesystem::path folder = cacheFolder();
  if (folder.empty()) return;
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error) return;
  std::vector<uint8_t> bytes(MAGIC, MAGIC + sizeof(MAGIC));
  putU64(bytes, payload.size());
  putU64(bytes, fnv1a(payload.data(), payload.size()));
  bytes.insert(bytes.end(), payload.begin(), payload.end());
  static std::atomic<uint64_t> writes{0};  // two threads of one process writing at once
  const std::filesystem::path temp =
      folder / (name + ".tmp-" + std::to_string(getpid()) + "-" + std::to_string(writes++));
  {
    std::ofstream file(temp, std::ios::binary);
    file.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    if (!file.flush()) {
      file.close();
      std::filesystem::remove(temp, error);
      return;
    }
  }
  std::filesystem::rename(temp, folder / name, error);
  if (error) std::filesystem::remove(temp, error);
}

}  // namespace phongvk
