// gltf_lights.h — the lights a glTF file places (KHR_lights_punctual): each node that names one
// puts it where the node's transform says, pointing along the node's -Z axis.
#pragma once

#include "geometry/mesh.h"

#include <glm/glm.hpp>

#include <optional>
#include <string>

namespace tinygltf {
class Model;
struct Node;
}  // namespace tinygltf

namespace phongvk {

// The light node `node` (named `nodeName` in messages: "nodes[3]") names, placed by `transform` (the node's own and its ancestors'), or
// nothing when it names none. Throws SceneError "<where>: <path>: KHR_lights_punctual.lights[i]...:
// <why>" for a light that cannot be rendered: an unknown type, no such light, a negative or
// non-finite intensity or range, a colour outside [0, 1e6], cones outside 0 <= inner < outer <= pi/2.
std::optional<MeshLight> gltfNodeLight(const tinygltf::Model& model, const tinygltf::Node& node,
                                       const std::string& nodeName, const glm::dmat4& transform,
                                       const std::string& path, const std::string& where);

}  // namespace phongvk
