// gltf_lights.cpp — see gltf_lights.h.
#include "meshio/gltf_lights.h"

#include "base/number_text.h"
#include "phongvk/errors.h"

#include <tiny_gltf.h>

#include <cmath>

namespace phongvk {
namespace {

// The index of the light node `node` names in its KHR_lights_punctual extension, or -1.
int lightIndex(const tinygltf::Node& node, const std::string& fail) {
  const auto extension = node.extensions.find("KHR_lights_punctual");
  if (extension == node.extensions.end()) return -1;
  const tinygltf::Value& value = extension->second;
  if (!value.IsObject() || !value.Has("light") || !value.Get("light").IsNumber())
    throw SceneError(fail + "KHR_lights_punctual has no light index");
  const double index = value.Get("light").GetNumberAsDouble();
  if (!(index >= 0 && index < 1e9 && index == std::floor(index)))
    throw SceneError(fail + "KHR_lights_punctual.light is " + formatNumber(index) + ", not a light's index");
  return int(index);
}

void checkNumber(double value, double low, double high, const std::string& what, const std::string& fail) {
  if (!(value >= low && value <= high))
    throw SceneError(fail + what + " is " + formatNumber(value) + ", expected " + formatNumber(low) + " to " +
                     formatNumber(high));
}

// The light's type, colour, intensity, range and cones as a MeshLight (not yet placed).
MeshLight readLight(const tinygltf::Light& light, const std::string& fail) {
  MeshLight m;
  if (light.type == "point") m.kind = MeshLight::Kind::Point;
  else if (light.type == "spot") m.kind = MeshLight::Kind::Spot;
  else if (light.type == "directional") m.kind = MeshLight::Kind::Directional;
  else throw SceneError(fail + "type is '" + light.type + "', expected point, spot or directional");
  if (!light.color.empty()) {
    if (light.color.size() != 3) throw SceneError(fail + "color has " + std::to_string(light.color.size()) + " values, expected 3");
    for (int i = 0; i < 3; ++i) checkNumber(light.color[size_t(i)], 0, 1e6, "color[" + std::to_string(i) + "]", fail);
    m.color = {light.color[0], light.color[1], light.color[2]};
  }
  checkNumber(light.intensity, 0, 1e30, "intensity", fail);
  m.intensity = light.intensity;
  if (light.range != 0) checkNumber(light.range, 1e-6, 1e15, "range", fail);
  m.range = m.kind == MeshLight::Kind::Directional ? 0 : light.range;  // glTF: a directional light has none
  if (m.kind == MeshLight::Kind::Spot) {
    const double inner = light.spot.innerConeAngle, outer = light.spot.outerConeAngle;
    if (!(outer > 0 && outer <= M_PI / 2 + 1e-9))
      throw SceneError(fail + "spot.outerConeAngle is " + formatNumber(outer) + ", expected more than 0 and at most pi/2");
    if (!(inner >= 0 && inner < outer))
      throw SceneError(fail + "spot.innerConeAngle is " + formatNumber(inner) + ", expected 0 or more and less than outerConeAngle");
    m.innerCone = inner * 180 / M_PI;
    m.outerCone = std::min(outer * 180 / M_PI, 90.0);
  }
  return m;
}

}  // namespace

std::optional<MeshLight> gltfNodeLight(const tinygltf::Model& model, const tinygltf::Node& node,
                                       const std::string& nodeName, const glm::dmat4& transform,
                                       const std::string& path, const std::string& where) {
  const std::string file = where + ": " + path + ": ";
  const int index = lightIndex(node, file + nodeName + ": ");
  if (index < 0) return std::nullopt;
  const std::string name = "KHR_lights_punctual.lights[" + std::to_string(index) + "]";
  if (size_t(index) >= model.lights.size())
    throw SceneError(file + name + " does not exist (the file has " + std::to_string(model.lights.size()) + " lights)");
  MeshLight light = readLight(model.lights[size_t(index)], file + name + ": ");
  light.name = name;
  light.position = glm::dvec3(transform[3]);
  // The node's -Z axis; a node transform that collapses it leaves the light with no direction.
  const glm::dvec3 axis = -glm::dvec3(transform[2]);
  if (light.kind != MeshLight::Kind::Point && !(glm::length(axis) > 0 && std::isfinite(glm::length(axis))))
    throw SceneError(file + name + ": its node's transform leaves it no direction (a zero scale)");
  if (light.kind != MeshLight::Kind::Point) light.direction = glm::normalize(axis);
  for (int i = 0; i < 3; ++i) checkNumber(light.position[i], -MAX_COORDINATE, MAX_COORDINATE, "position", file + name + ": ");
  return light;
}

}  // namespace phongvk
