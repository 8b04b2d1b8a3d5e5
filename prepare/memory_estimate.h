// memory_estimate.h — what a scene will take in memory, from the validated scene alone, checked
// before anything is built: a scene that cannot fit is an error naming the objects that take most
// of it, the estimate and the limit, not an allocation failure (or the OOM killer) minutes later.
#pragma once

#include "base/memory_limit.h"
#include "scene/scene.h"

#include <cstdint>
#include <string>

namespace phongvk {

// Peak memory per triangle while a scene is built, flattened and rendered: 106 B measured on
// lavapipe, where the device's buffers are host memory too (an icosphere at subdivide 9, 5.2M
// triangles: 555 MB; with the reference, 63 B); rounded up.
inline constexpr uint64_t BYTES_PER_TRIANGLE = 112;
// Per triangle more with a light that casts shadows, counted from the arrays: the caster list (20 B),
// the tree's triangles on the host and the device (64 B each), its nodes (at most 2 x 32 B a
// triangle, on the host and the device) and the build's codes, order and centroids (28 B).
inline constexpr uint64_t SHADOW_BYTES_PER_TRIANGLE = 304;
// Per pixel: the image, the visibility keys and the GPU's colour and key buffers.
inline constexpr uint64_t BYTES_PER_PIXEL = 32;

// Triangles an object will have (mesh files: mesh_file.h meshFileTriangles, estimated when the
// scene was loaded).
uint64_t estimatedTriangles(const Object& object);

// Throws SceneError "<file>: the scene needs about N GiB (...), more than the M GiB limit; most
// of it: objects[2] (... triangles), ..." when the estimate exceeds sceneMemoryLimit(). `pixels`
// counts every sample.
void checkSceneMemory(const SceneSpec& scene, uint64_t pixels);

// The same for a scene whose meshes are built: `triangles` as built. Every frame is checked so
// (a renderer given the same geometry at a larger size or more samples, a sequence whose frames
// grow), and every build before its upload (a mesh file of large polygons builds more triangles
// than its size suggests). `textureBytes`: what the built scene's textures hold (SceneData's
// textureBytes), counted twice, the host's arrays and the device's copies.
void checkBuiltSceneMemory(const SceneSpec& scene, uint64_t triangles, uint64_t pixels, uint64_t textureBytes);

// Throws SceneError "<path>: <what> needs about N GiB (<detail>), more than the M GiB limit (...);
// <remedy>" when `bytes` exceed sceneMemoryLimit(): the one message for the scene and what is made
// beside it (a sequence's contact sheet).
void checkMemory(const std::string& path, const std::string& what, uint64_t bytes, const std::string& detail,
                 const std::string& remedy);

}  // namespace phongvk
