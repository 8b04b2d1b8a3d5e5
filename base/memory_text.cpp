// memory_text.cpp — see memory_text.h.
#include "base/memory_text.h"

#include <algorithm>
#include <cstdio>

namespace phongvk {
namespace {

// `bytes` in GiB with `decimals` decimals.
std::string gib(uint64_t bytes, int decimals) {
  char text[48];
  std::snprintf(text, sizeof text, "%.*f GiB", decimals, double(bytes) / double(uint64_t(1) << 30));
  return text;
}

// The fewest decimals at which `a` and `b` print differently, each with two significant digits at
// least, so that a message never says "0.1 GiB, more than the 0.1 GiB limit" or "the 0.0 GiB limit";
// ten decimals tell bytes apart.
int decimalsToTell(uint64_t a, uint64_t b) {
  const double smaller = double(std::min(a, b)) / double(uint64_t(1) << 30);
  int decimals = 1;
  for (double unit = 1; smaller > 0 && smaller < unit && decimals < 10; unit /= 10) ++decimals;
  while (decimals < 10 && gib(a, decimals) == gib(b, decimals)) ++decimals;
  return decimals;
}

}  // namespace

std::string memoryMessage(const std::string& path, const std::string& what, uint64_t bytes, uint64_t limit,
                          const std::string& detail, const std::string& remedy) {
  const int decimals = decimalsToTell(bytes, limit);
  return (path.empty() ? "" : path + ": ") + what + " needs about " + gib(bytes, decimals) + " (" + detail +
         "), more than the " + gib(limit, decimals) +
         " limit (by default the machine's memory; PHONGVK_MAX_MEMORY_GB or --max-memory-gb sets it); " + remedy;
}

}  // namespace phongvk
