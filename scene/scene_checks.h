// scene_checks.h — the checks of a scene's typed sections (camera, lights, materials, render
// settings, ambient and background), the same for a value read from a scene file and one given in
// code (api/scene_parts.cpp): the file's readers (scene_sections.h) turn JSON into these values,
// checking only its types and keys, and both entries check the values here, so a file and a
// program fail with one message ("camera.fov: must be > 0 and < 180, got 200").
#pragma once

#include "phongvk/scene_parts.h"
#include "scene/scene.h"
#include "scene/scene_json.h"

#include <glm/glm.hpp>

#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace phongvk::scenejson {

// A camera as a scene file may say it: each key given or not (docs/DESIGN.md "Camera").
struct CameraValues {
  bool fit = false;
  std::optional<glm::dvec3> position, direction, lookAt, up;
  std::optional<double> fov, aspect, resolution, nearPlane, farPlane, fx, fy, cx, cy, orthoHeight;
  std::optional<int> width, height;
  bool orthographic = false;  // "projection": "orthographic"
};
CameraSpec cameraSpec(const CameraValues& camera, const Where& at);  // scene_camera.cpp

// Lights (scene_parts.h Light), each checked at at[i]; at most MAX_LIGHTS (scene_lighting.cpp).
LightSpec lightSpec(const Light& light, const Where& at);
std::vector<LightSpec> lightSpecs(const std::vector<Light>& lights, const Where& at);

// A material as given: a file's material object (the fields it leaves out at MaterialSpec's
// defaults) or a Material in code; its texture a file or data URI (resolved against baseDir), or
// an image held in memory (scene_lighting.cpp).
struct MaterialValues {
  double ka = MaterialSpec{}.ka, kd = MaterialSpec{}.kd, ks = MaterialSpec{}.ks, n = MaterialSpec{}.n;
  glm::dvec3 attenuation = glm::dvec3(MaterialSpec{}.attenuation);
  glm::dvec3 color = glm::dvec3(MaterialSpec{}.color);
  std::optional<std::string> texture;
  std::shared_ptr<const TextureImage> textureImage;
};
MaterialSpec materialSpec(const MaterialValues& material, const std::string& baseDir, const Where& at);

// An object's material: the scene's default (none), a name among the scene's materials, or its own.
using MaterialChoice = std::variant<std::monostate, std::string, MaterialValues>;

// `scene` with the render settings (its "render" section at `at`; scene.cpp).
void setRenderSettings(SceneSpec& scene, const RenderSettings& settings, const Where& at);
// A point's side or a line's width in pixels: above 0 (at least 1/256), at most QUAD_MAX_WIDTH.
double quadWidth(double pixels, const Where& at);

// The scene's render settings as a value (the background too).
RenderSettings renderSettingsOf(const SceneSpec& scene);

// Colours: ambient light (components >= 0) and background (components in 0..1).
glm::vec3 color(const glm::dvec3& value, const Where& at);
glm::vec3 unitColor(const glm::dvec3& value, const Where& at);

// Three numbers as the model holds them.
inline glm::dvec3 toVec(const Vec3& v) { return {v[0], v[1], v[2]}; }

}  // namespace phongvk::scenejson
