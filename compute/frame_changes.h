// frame_changes.h — what the device holds from the frames sent so far, so that a frame uploads
// only the objects, materials and lights that changed, and its shade pass redoes only what is
// stale: vertex positions, vertex colours, or neither.
#pragma once

#include "prepare/scene_data.h"
#include "vulkan/resources.h"

#include <cstdint>
#include <vector>

namespace phongvk {

// Where the scene's per-frame arrays live on the device.
struct FrameArrays {
  Buffer& objects;
  Buffer& materials;
  Buffer& lights;
  Buffer& bvhNodes;         // the shadow rays' tree, built again where an object moved
  Buffer& shadowTriangles;
};

// What the shade pass recomputes this frame (PassControl shadeColors, shadePositions).
struct ShadeWork {
  bool colors = true;
  bool positions = true;
};

class FrameChanges {
 public:
  // A scene just uploaded with these arrays: the next frame recomputes everything. `unlit`: every
  // vertex is drawn unlit (everyVertexUnlit), so lights, the ambient and the eye leave their colours.
  void restart(const SceneData& data, bool unlit);

  // Uploads the frame's objects, materials and lights where they differ from the last frame's
  // and says what the shade pass must redo. Vertex colours are recomputed only when their inputs
  // changed: materials, lights, ambient, the shading mode or specular model, a posed object's
  // place, or the eye when some material is specular, or the shadow rays' tree (sent again when
  // it was built again: FrameInputs::shadowVersion), and in a scene drawn unlit only when the
  // materials or the mode changed; positions when the camera's basis, focal
  // length or an object's offsets changed. Throws ArgumentError when a count changes.
  ShadeWork send(const VulkanContext& context, const FrameArrays& arrays, const FrameInputs& in);

  // Frames so far whose per-vertex lighting was recomputed, and whose positions were transformed.
  uint64_t framesShaded() const { return framesShaded_; }
  uint64_t framesTransformed() const { return framesTransformed_; }

 private:
  std::vector<gpu::ObjectData> objects_;
  std::vector<gpu::MaterialData> materials_;
  std::vector<gpu::LightData> lights_;
  gpu::FrameData frame_{};
  uint64_t shadowVersion_ = 0;
  bool sent_ = false;  // frame_ holds a frame sent since the scene's upload
  bool unlit_ = false;
  uint64_t framesShaded_ = 0;
  uint64_t framesTransformed_ = 0;
};

}  // namespace phongvk
