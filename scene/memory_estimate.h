// memory_estimate.h — what a scene will take in memory, from the validated scene alone, checked
// before anything is built: a scene that cannot fit is an error naming the objects that take most
// of it, the estimate and the limit, not an allocation failure (or the OOM killer) minutes later.
#pragma once

#include "scene/scene.h"

#include <cstdint>
#include <string>

namespace phongvk {

// Peak memory per triangle while a scene is built, flattened and rendered: 106 B measured on
// lavapipe, where the device's buffers are host memory too (an icosphere at subdivide 9, 5.2M
// triangles: 555 MB; with the reference, 63 B); rounded up.
inline constexpr uint64_t BYTES_PER_TRIANGLE = 112;
// Per pixel: the image, the visibility keys and the GPU's colour and key buffers.
inline constexpr uint64_t BYTES_PER_PIXEL = 32;

// Triangles an object will have (mesh files: an upper bound from the file's size, 12 bytes a
// triangle at least in any format).
uint64_t estimatedTriangles(const Object& object);

// The memory a scene may use: the machine's physical memory, or PHONGVK_MAX_MEMORY_GB (a number of
// GiB, to raise or lower it), or what setSceneMemoryLimit set (0: back to those).
uint64_t memoryLimit();
void setSceneMemoryLimit(uint64_t bytes);

// Throws SceneError "<file>: the scene needs about N GiB (...), more than the M GiB limit; most
// of it: objects[2] (... triangles), ..." when the estimate exceeds memoryLimit().
void checkSceneMemory(const SceneSpec& scene, uint64_t pixels);

// Throws SceneError "<path>: <what> needs about N GiB (<detail>), more than the M GiB limit (...);
// <remedy>" when `bytes` exceed memoryLimit(): the one message for the scene and what is made
// beside it (a sequence's contact sheet).
void checkMemory(const std::string& path, const std::string& what, uint64_t bytes, const std::string& detail,
                 const std::string& remedy);

}  // namespace phongvk
