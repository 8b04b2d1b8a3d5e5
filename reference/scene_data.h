// scene_data.h — the scene flattened into the arrays both renderers consume (shaders/shared.h
// layouts), and the per-frame data derived from a camera view.
#pragma once

#include "camera.h"
#include "scene.h"
#include "shaders/shared.h"

#include <glm/glm.hpp>

#include <vector>

namespace phongvk {

// Built once per scene: meshes with normals, materials, lights. Uploaded once by the GPU path.
struct SceneData {
  std::vector<gpu::VertexIn> vertices;      // local to their object's origin
  std::vector<glm::uvec4> triangles;        // xyz: vertex indices; w: object index
  std::vector<glm::dvec3> objectOrigins;    // world, double: offsets are taken in double
  std::vector<gpu::ObjectData> objects;     // material and flags; offsets filled per frame
  std::vector<gpu::MaterialData> materials;
  std::vector<glm::dvec3> lightPositions;   // world, double
  std::vector<gpu::LightData> lights;       // intensity and colour; positions filled per frame
  glm::vec3 background{0.0f};
  glm::vec3 ambient{1.0f};
  uint32_t interpolation = gpu::INTERP_PERSPECTIVE;
};

// What changes with the camera: the frame constants and the eye-relative offsets.
struct FrameInputs {
  gpu::FrameData frame{};
  std::vector<gpu::ObjectData> objects;
  std::vector<gpu::LightData> lights;
};

// Builds every object's mesh and flattens the scene. Throws SceneError.
SceneData buildSceneData(const Scene& scene);

// The frame for `view`: camera basis, image size, and offsets from the eye computed in double.
FrameInputs makeFrame(const SceneData& data, const View& view);

}  // namespace phongvk
