// camera_fit.cpp — see camera_fit.h.
#include "prepare/camera_fit.h"

#include "scene/scene_json.h"

#include <algorithm>
#include <cmath>

namespace phongvk {
namespace {

constexpr double kMargin = 1.05;

std::string prefix(const std::string& file) { return file.empty() ? "" : file + ": "; }

// The tangent of the narrowest angle between the view axis and the image's sides.
double narrowestTangent(const CameraSpec& camera, const std::string& file) {
  if (!camera.intrinsics) {
    const double tanVertical = std::tan(glm::radians(camera.fov) / 2);
    return std::min(tanVertical, tanVertical * camera.aspect);
  }
  const double px = camera.cx + 0.5, py = camera.cy + 0.5;
  const double tangent = std::min(std::min(px, camera.width - px) / camera.fx, std::min(py, camera.height - py) / camera.fy);
  if (!(tangent > 0))
    throw SceneError(prefix(file) + "camera.fit: the principal point (cx, cy) = (" + formatNumber(camera.cx) + ", " +
                     formatNumber(camera.cy) + ") is not inside the image, so no view centred on it frames the scene");
  return tangent;
}

void fitCamera(CameraSpec& camera, const SceneData& data, const std::string& file) {
  const glm::dvec3 centre = (data.boundsMin + data.boundsMax) * 0.5;
  const double radius = std::max(glm::length(data.boundsMax - data.boundsMin) * 0.5, 1e-9);
  const double halfField = std::atan(narrowestTangent(camera, file));
  const double distance = kMargin * radius / std::sin(halfField);
  camera.position = centre - glm::normalize(camera.direction) * distance;
  camera.nearPlane = (distance - radius) / 2;
  camera.farPlane = 2 * (distance + radius);
  if (camera.orthographic) camera.orthoHeight = 2 * kMargin * radius / std::min(1.0, camera.aspect);
  const double reach = std::max({std::abs(camera.position.x), std::abs(camera.position.y), std::abs(camera.position.z),
                                 camera.farPlane});
  if (!(reach <= MAX_COORDINATE) || !(float(camera.nearPlane) >= 1.17549435e-38f))
    throw SceneError(prefix(file) + "camera.fit: the scene's bounds (radius " +
                     formatNumber(radius) + " m) put the camera beyond the coordinates a scene may use");
}

}  // namespace

bool needsFraming(const SceneSpec& scene) {
  return scene.camera.fit || std::any_of(scene.lights.begin(), scene.lights.end(), [](const LightSpec& l) { return l.atCamera; });
}

SceneSpec framedScene(const SceneSpec& scene, const SceneData& data) {
  SceneSpec framed = scene;
  if (framed.camera.fit) fitCamera(framed.camera, data, scene.path);
  for (LightSpec& light : framed.lights) {
    if (light.atCamera) light.position = framed.camera.position;
  }
  return framed;
}

}  // namespace phongvk
