// frame_changes.cpp — a frame's uploads of only what changed (frame_changes.h).
#include "compute/frame_changes.h"

#include "phongvk/errors.h"

#include <cstddef>
#include <cstring>
#include <string>

namespace phongvk {

using namespace gpu;

namespace {

template <typename T>
bool sameBytes(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

// Uploads `next` into `buffer` unless it equals what was sent last time; true if it changed.
template <typename T>
bool uploadIfChanged(const VulkanContext& context, Buffer& buffer, const std::vector<T>& next, std::vector<T>& last,
                     const char* what) {
  if (sameBytes(next, last)) return false;
  if (next.size() != last.size() && !last.empty()) {
    throw ArgumentError(std::string("a frame may not change the number of ") + what);
  }
  if (!next.empty()) uploadToBuffer(context, buffer, next.data(), next.size() * sizeof(T));
  last = next;
  return true;
}

}  // namespace

void FrameChanges::restart(const SceneData& data, bool unlit) {
  unlit_ = unlit;
  objects_ = data.objects;
  materials_ = data.materials;
  lights_ = data.lights;
  shadowVersion_ = data.shadowVersion;
  sent_ = false;
}

ShadeWork FrameChanges::send(const VulkanContext& context, const FrameArrays& arrays, const FrameInputs& in) {
  const bool materialsChanged = uploadIfChanged(context, arrays.materials, in.materials, materials_, "materials");
  const bool lightsChanged = uploadIfChanged(context, arrays.lights, in.lights, lights_, "lights");
  const bool objectsMoved = !sameLightingPlaces(in.objects, objects_);  // a posed object moved
  const bool objectsChanged = uploadIfChanged(context, arrays.objects, in.objects, objects_, "objects");
  const bool shadowsMoved = in.shadows && in.shadowVersion != shadowVersion_;
  if (shadowsMoved) {
    uploadToBuffer(context, arrays.bvhNodes, in.shadows->nodes.data(), in.shadows->nodes.size() * sizeof(BvhNode));
    uploadToBuffer(context, arrays.shadowTriangles, in.shadows->triangles.data(),
                   in.shadows->triangles.size() * sizeof(ShadowTriangle));
    shadowVersion_ = in.shadowVersion;
  }
  const FrameData& f = in.frame;
  const bool first = !sent_;
  // Positions follow the camera basis, the focal length and the objects' offsets (toHomogeneous).
  const bool positionsStale = first || objectsChanged || f.right != frame_.right || f.up != frame_.up ||
                              f.forward != frame_.forward || f.focalX != frame_.focalX || f.focalY != frame_.focalY;
  const bool eyeMoved = first || f.eye != frame_.eye;
  const bool ambientChanged = first || f.ambient != frame_.ambient;
  // Frames lit per pixel leave the vertex colours as they were; the specular model changes them.
  const bool modelChanged = first || f.shading != frame_.shading || f.specular != frame_.specular;
  // An unlit vertex's colour is its material's times its own: only the materials and the mode
  // (frames lit per pixel leave the colours unwritten) change it, not the lights, the ambient, the
  // eye or a pose (which keeps a zero normal zero).
  const bool lightingChanged = lightsChanged || ambientChanged || objectsMoved || shadowsMoved ||
                               (eyeMoved && !lightingIsViewIndependent(in));
  const bool colorsStale = first || materialsChanged || modelChanged || (!unlit_ && lightingChanged);
  frame_ = f;
  sent_ = true;
  framesShaded_ += colorsStale;
  framesTransformed_ += positionsStale;
  return {colorsStale, positionsStale};
}

}  // namespace phongvk
