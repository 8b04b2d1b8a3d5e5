// memory_estimate.cpp — see memory_estimate.h.
#include "prepare/memory_estimate.h"

#include "base/memory_text.h"
#include "prepare/scene_data.h"
#include "scene/object_mesh.h"

#include <algorithm>
#include <vector>

namespace phongvk {

uint64_t estimatedTriangles(const Object& object) {
  uint64_t base = baseTriangles(object);
  if (object.shape == Shape::Polyhedron) base = 2 * object.points.size();
  if (object.shape == Shape::Mesh) {  // a point's or a line's quad is two records
    base = object.arrays ? object.arrays->triangles.size() + 2 * (object.arrays->points.size() + object.arrays->lines.size())
                         : object.fileTriangles;
  }
  for (int level = 0; level < object.subdivide && base < (uint64_t(1) << 50); ++level) base *= 4;
  return base;
}

namespace {

uint64_t bytesPerTriangle(const SceneSpec& scene) {
  return BYTES_PER_TRIANGLE + (hasShadowedLights(scene) ? SHADOW_BYTES_PER_TRIANGLE : 0);
}

}  // namespace

void checkSceneMemory(const SceneSpec& scene, uint64_t pixels) {
  std::vector<std::pair<uint64_t, size_t>> objects;  // (triangles, index)
  uint64_t triangles = 0;
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    objects.push_back({estimatedTriangles(scene.objects[i]), i});
    triangles += objects.back().first;
  }
  const uint64_t bytes = triangles * bytesPerTriangle(scene) + pixels * BYTES_PER_PIXEL;
  if (bytes <= sceneMemoryLimit()) return;
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

void checkBuiltSceneMemory(const SceneSpec& scene, uint64_t triangles, uint64_t pixels, uint64_t textureBytes) {
  const std::string textures = textureBytes == 0 ? "" : ", " + std::to_string(textureBytes) + " bytes of textures";
  checkMemory(scene.path, "the scene", triangles * bytesPerTriangle(scene) + pixels * BYTES_PER_PIXEL + 2 * textureBytes,
              std::to_string(triangles) + " triangles as built, " + std::to_string(pixels) + " pixels" + textures,
              "a smaller image, fewer samples or simpler meshes fit");
}

void checkMemory(const std::string& path, const std::string& what, uint64_t bytes, const std::string& detail,
                 const std::string& remedy) {
  const uint64_t limit = sceneMemoryLimit();
  if (bytes > limit) throw SceneError(memoryMessage(path, what, bytes, limit, detail, remedy));
}

}  // namespace phongvk
