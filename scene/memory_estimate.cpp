// memory_estimate.cpp — see memory_estimate.h.
#include "scene/memory_estimate.h"

#include "scene/mesh.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <vector>

namespace phongvk {
namespace {

std::atomic<uint64_t> limitOverride{0};

uint64_t physicalMemory() {
  const long pages = ::sysconf(_SC_PHYS_PAGES), pageSize = ::sysconf(_SC_PAGE_SIZE);
  return pages > 0 && pageSize > 0 ? uint64_t(pages) * uint64_t(pageSize) : UINT64_MAX;
}

std::string gib(uint64_t bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f GiB", double(bytes) / double(uint64_t(1) << 30));
  return text;
}

}  // namespace

uint64_t estimatedTriangles(const Object& object) {
  uint64_t base = baseTriangles(object);
  if (object.shape == Shape::Polyhedron) base = 2 * object.points.size();
  if (object.shape == Shape::Mesh) base = object.arrays ? object.arrays->triangles.size() : object.fileVersion.bytes / 12;
  for (int level = 0; level < object.subdivide && base < (uint64_t(1) << 50); ++level) base *= 4;
  return base;
}

uint64_t memoryLimit() {
  if (const uint64_t set = limitOverride.load()) return set;
  if (const char* env = std::getenv("PHONGVK_MAX_MEMORY_GB")) {
    const double value = std::atof(env);
    if (value > 0 && std::isfinite(value)) return uint64_t(value * double(uint64_t(1) << 30));
  }
  return physicalMemory();
}

void setSceneMemoryLimit(uint64_t bytes) { limitOverride = bytes; }

void checkSceneMemory(const SceneSpec& scene, uint64_t pixels) {
  std::vector<std::pair<uint64_t, size_t>> objects;  // (triangles, index)
  uint64_t triangles = 0;
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    objects.push_back({estimatedTriangles(scene.objects[i]), i});
    triangles += objects.back().first;
  }
  const uint64_t bytes = triangles * BYTES_PER_TRIANGLE + pixels * BYTES_PER_PIXEL;
  if (bytes <= memoryLimit()) return;
  std::sort(objects.begin(), objects.end(), [](const auto& a, const auto& b) {
    return a.first != b.first ? a.first > b.first : a.second < b.second;  // the largest, in file order
  });
  std::string most;
  for (size_t k = 0; k < objects.size() && k < 3; ++k) {
    most += (k ? ", " : "") + scene.objects[objects[k].second].jsonPath + " (" + std::to_string(objects[k].first) + " triangles)";
  }
  checkMemory(scene.path, "the scene", bytes,
              std::to_string(triangles) + " triangles, " + std::to_string(pixels) + " pixels", "most of it: " + most);
}

void checkMemory(const std::string& path, const std::string& what, uint64_t bytes, const std::string& detail,
                 const std::string& remedy) {
  const uint64_t limit = memoryLimit();
  if (bytes <= limit) return;
  throw SceneError((path.empty() ? "" : path + ": ") + what + " needs about " + gib(bytes) + " (" + detail +
                   "), more than the " + gib(limit) +
                   " limit (by default the machine's memory; PHONGVK_MAX_MEMORY_GB or --max-memory-gb sets it); " + remedy);
}

}  // namespace phongvk
