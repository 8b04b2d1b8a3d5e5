// disk_cache.h — what phongvk keeps across processes for a device: its compiled pipelines
// (pipeline_cache.h) and what the float probe found (float_probe.h). Files live in
// $XDG_CACHE_HOME/phongvk, or ~/.cache/phongvk without it, named after the device and its driver
// (deviceCacheKey), so another GPU or a driver update finds no file of its own and starts over. Each file carries a header with its payload's size and
// checksum: a truncated, corrupt or foreign file is ignored (and replaced when next written). A
// cache never fails a render: a folder that cannot be made or a file that cannot be written only
// means the next process does the work again.
#pragma once

#include "vulkan/context.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace phongvk {

// $XDG_CACHE_HOME/phongvk (an absolute XDG_CACHE_HOME only, as the XDG spec asks), else
// $HOME/.cache/phongvk; empty when neither variable is set.
std::filesystem::path cacheFolder();

// "10005-0-1-<8 hex digits>-<32 hex digits>": the part of a cache file's name that names the
// device and driver: vendor, device id, driver version, a hash of the device's name and the
// driver's name and version text, the pipeline-cache UUID.
std::string deviceCacheKey(const VulkanContext& context);

// 64-bit FNV-1a: stable across runs and builds, for names and checksums.
uint64_t fnv1a(const void* data, size_t size, uint64_t hash = 0xcbf29ce484222325ull);

// The payload of cacheFolder()/name, if the file is there and whole; nullopt otherwise.
std::optional<std::vector<uint8_t>> readCacheFile(const std::string& name);

// Writes cacheFolder()/name atomically (a temporary file, then a rename): processes writing the
// same file at once leave one of their versions, never a mix. Failures are ignored.
void writeCacheFile(const std::string& name, const std::vector<uint8_t>& payload);

}  // namespace phongvk
