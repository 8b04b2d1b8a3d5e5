// memory_limit.cpp — see memory_limit.h.
#include "base/memory_limit.h"

#include "phongvk/errors.h"

#include <unistd.h>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace phongvk {
namespace {

std::atomic<uint64_t> limitOverride{0};

uint64_t physicalMemory() {
  const long pages = ::sysconf(_SC_PHYS_PAGES), pageSize = ::sysconf(_SC_PAGE_SIZE);
  return pages > 0 && pageSize > 0 ? uint64_t(pages) * uint64_t(pageSize) : UINT64_MAX;
}

}  // namespace

uint64_t parseMemoryLimit(const std::string& text, const std::string& what) {
  const auto bad = [&] {
    char least[32];
    std::snprintf(least, sizeof least, "%g", MIN_MEMORY_GIB);
    return SceneError(what + " is '" + text + "': expected a number of GiB, at least " + least + " (e.g. 4 or 0.5)");
  };
  const char* begin = text.c_str();
  char* end = nullptr;
  const double value = std::strtod(begin, &end);
  if (text.empty() || end != begin + text.size() || !std::isfinite(value) || !(value >= MIN_MEMORY_GIB)) throw bad();
  const double bytes = value * double(uint64_t(1) << 30);
  return bytes >= 18446744073709551615.0 ? UINT64_MAX : uint64_t(bytes);  // 1e11 GiB: no limit, not an overflow
}

uint64_t sceneMemoryLimit() {
  if (const uint64_t set = limitOverride.load()) return set;
  if (const char* env = std::getenv("PHONGVK_MAX_MEMORY_GB")) return parseMemoryLimit(env, "PHONGVK_MAX_MEMORY_GB");
  return physicalMemory();
}

void setSceneMemoryLimit(uint64_t bytes) { limitOverride = bytes; }

}  // namespace phongvk
