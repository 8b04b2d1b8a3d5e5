// file_lights.cpp — see file_lights.h.
#include "prepare/file_lights.h"

#include <numbers>

namespace phongvk {

LightSpec fileLightSpec(const MeshLight& light, const glm::dvec3& origin, const std::optional<glm::dmat3>& pose,
                        bool shadows) {
  LightSpec spec;
  const glm::dmat3 linear = pose ? *pose : glm::dmat3(1.0);
  spec.position = origin + linear * light.position;
  spec.direction = glm::normalize(linear * light.direction);
  spec.directional = light.kind == MeshLight::Kind::Directional;
  spec.spot = light.kind == MeshLight::Kind::Spot;
  spec.innerCone = light.innerCone;
  spec.outerCone = light.outerCone;
  spec.inverseSquare = !spec.directional;
  spec.range = light.range;
  spec.intensity = float(light.intensity / std::numbers::pi);
  spec.color = glm::vec3(light.color);
  spec.shadows = shadows;
  return spec;
}

}  // namespace phongvk
