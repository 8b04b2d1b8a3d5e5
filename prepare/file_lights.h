// file_lights.h — the lights a model file places (glTF KHR_lights_punctual, meshio/gltf_lights.h)
// as lights of the scene: where the object that holds the file stands, in this contract's units
// (docs/DESIGN.md "Lights from files").
#pragma once

#include "geometry/mesh.h"
#include "scene/scene.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <optional>
#include <string>

namespace phongvk {

// A file's light and the object whose file placed it (its index in the scene's objects).
struct ObjectLight {
  uint32_t object = 0;
  MeshLight light;  // turned by the object's transform, about its origin (scene/object_mesh.h)
};

// The light where the object stands (`origin`, and its pose's linear part where posed), as a scene
// light: a point or spot light falls off with the inverse square of the distance (glTF's, windowed
// at its range), the intensity is glTF's candela or lux divided by pi (glTF's Lambert term is
// albedo / pi, this contract's kd C), the cones in degrees. `shadows`: it casts them (the object's
// "file_light_shadows").
LightSpec fileLightSpec(const MeshLight& light, const glm::dvec3& origin, const std::optional<glm::dmat3>& pose,
                        bool shadows);

}  // namespace phongvk
