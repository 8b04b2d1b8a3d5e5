// scene_parts.cpp — see scene_parts.h and include/phongvk/scene_parts.h.
#include "api/scene_parts.h"

#include "base/number_text.h"
#include "scene/camera.h"
#include "scene/object_pose.h"
#include "scene/scene_json.h"

#include <array>
#include <cmath>

namespace phongvk {
namespace {

using scenejson::Json;

void requireFinite(double value, const std::string& what) {
  if (!std::isfinite(value)) throw ArgumentError(what + ": must be finite, got " + formatNumber(value));
}

Json vec3Json(const Vec3& v, const std::string& what) {
  for (int i = 0; i < 3; ++i) requireFinite(v[i], what + "[" + std::to_string(i) + "]");
  return Json::array({v[0], v[1], v[2]});
}

// A camera pose's rotation block must be a rotation: orthonormal columns (within 1e-6) and no mirror.
void checkRotation(const Matrix4& m) {
  const glm::dvec3 x = matrixColumn(m, 0), y = matrixColumn(m, 1), z = matrixColumn(m, 2);
  const double worst = std::max({std::abs(glm::dot(x, x) - 1), std::abs(glm::dot(y, y) - 1),
                                 std::abs(glm::dot(z, z) - 1), std::abs(glm::dot(x, y)), std::abs(glm::dot(y, z)),
                                 std::abs(glm::dot(z, x))});
  if (worst > 1e-6)
    throw ArgumentError("pose: the upper 3x3 block is not a rotation (its columns are not orthonormal within 1e-6)");
  if (glm::dot(glm::cross(x, y), z) < 0) throw ArgumentError("pose: the upper 3x3 block mirrors (determinant -1)");
}

}  // namespace

Camera cameraFromPose(const Matrix4& m, PoseConvention convention, double fov, int width, int height) {
  checkAffine(m, "pose");
  checkRotation(m);
  const glm::dvec3 position = {m[3], m[7], m[11]};
  const glm::dvec3 forward = convention == PoseConvention::OpenGL ? -matrixColumn(m, 2) : matrixColumn(m, 2);
  const glm::dvec3 up = convention == PoseConvention::OpenGL ? matrixColumn(m, 1) : -matrixColumn(m, 1);
  Camera camera;
  camera.position = {position.x, position.y, position.z};
  camera.lookAt = {position.x + forward.x, position.y + forward.y, position.z + forward.z};
  camera.up = {up.x, up.y, up.z};
  camera.fov = fov;
  camera.width = width;
  camera.height = height;
  return camera;
}

Camera cameraFromIntrinsics(double fx, double fy, double cx, double cy, int width, int height,
                            const Matrix4& cameraToWorld, PoseConvention convention) {
  if (width < 1 || height < 1)
    throw ArgumentError("intrinsics: the image size must be at least 1x1, got " + std::to_string(width) + "x" +
                        std::to_string(height));
  for (const auto& [value, name] : {std::pair{fx, "fx"}, {fy, "fy"}}) {
    if (!(std::isfinite(value) && value > 0))
      throw ArgumentError(std::string(name) + ": must be a positive focal length in pixels, got " + formatNumber(value));
  }
  Camera camera = cameraFromPose(cameraToWorld, convention, Camera{}.fov, width, height);
  camera.intrinsics = Intrinsics{fx, fy, cx, cy};
  return camera;
}

namespace {

// `camera` at width x height as a scene file's "camera".
Json cameraJson(const Camera& camera, int width, int height) {
  requireFinite(camera.fov, "camera.fov");
  requireFinite(camera.nearPlane, "camera.near");
  requireFinite(camera.farPlane, "camera.far");
  Json json = {{"position", vec3Json(camera.position, "camera.position")},
               {"look_at", vec3Json(camera.lookAt, "camera.look_at")},
               {"up", vec3Json(camera.up, "camera.up")},
               {"width", width},
               {"height", height},
               {"near", camera.nearPlane},
               {"far", camera.farPlane}};
  if (camera.orthoHeight) {
    if (camera.intrinsics) throw ArgumentError("camera: intrinsics describe a pinhole camera, not an orthographic one");
    requireFinite(*camera.orthoHeight, "camera.ortho_height");
    json["projection"] = "orthographic";
    json["ortho_height"] = *camera.orthoHeight;
    return json;
  }
  if (!camera.intrinsics) {
    json["fov"] = camera.fov;
    return json;
  }
  const Intrinsics& k = *camera.intrinsics;
  for (const auto& [value, name] : {std::pair{k.fx, "fx"}, {k.fy, "fy"}, {k.cx, "cx"}, {k.cy, "cy"}})
    requireFinite(value, std::string("camera.") + name);
  json["fx"] = k.fx;
  json["fy"] = k.fy;
  json["cx"] = k.cx;
  json["cy"] = k.cy;
  return json;
}

}  // namespace

SceneSpec withCamera(const SceneSpec& scene, const Camera& camera) {
  const View current = makeView(scene.camera);
  const bool sized = camera.width > 0 || camera.height > 0;  // else the scene's own size
  const Json json = cameraJson(camera, sized ? camera.width : current.width, sized ? camera.height : current.height);
  return withSection(scene, "camera", json.dump());
}

Camera cameraOf(const SceneSpec& scene) {
  const CameraSpec& c = scene.camera;
  const View view = makeView(c);
  Camera camera;
  camera.position = {c.position.x, c.position.y, c.position.z};
  camera.lookAt = {c.position.x + c.direction.x, c.position.y + c.direction.y, c.position.z + c.direction.z};
  camera.up = {c.up.x, c.up.y, c.up.z};
  camera.fov = c.fov;
  camera.width = view.width;
  camera.height = view.height;
  camera.nearPlane = c.nearPlane;
  camera.farPlane = c.farPlane;
  if (c.intrinsics) camera.intrinsics = Intrinsics{c.fx, c.fy, c.cx, c.cy};
  if (c.orthographic) camera.orthoHeight = c.orthoHeight;
  return camera;
}

SceneSpec withLights(const SceneSpec& scene, const std::vector<Light>& lights) {
  Json json = Json::array();
  for (size_t i = 0; i < lights.size(); ++i) {
    const Light& light = lights[i];
    const std::string at = "lights[" + std::to_string(i) + "]";
    requireFinite(light.intensity, at + ".intensity");
    Json entry = {{"intensity", light.intensity}, {"color", vec3Json(light.color, at + ".color")}};
    if (light.directional) {
      entry["direction"] = vec3Json(light.direction, at + ".direction");
    } else {
      entry["position"] = light.atCamera ? Json("camera") : vec3Json(light.position, at + ".position");
    }
    json.push_back(std::move(entry));
  }
  return withSection(scene, "lights", json.dump());
}

std::vector<Light> lightsOf(const SceneSpec& scene) {
  std::vector<Light> lights;
  for (const LightSpec& l : scene.lights) {
    lights.push_back({{l.position.x, l.position.y, l.position.z}, l.intensity, {l.color.x, l.color.y, l.color.z},
                      l.atCamera, l.directional, {l.direction.x, l.direction.y, l.direction.z}});
  }
  return lights;
}

SceneSpec withAmbient(const SceneSpec& scene, const Vec3& ambient) {
  return withSection(scene, "ambient", vec3Json(ambient, "ambient").dump());
}

Vec3 ambientOf(const SceneSpec& scene) { return {scene.ambient.x, scene.ambient.y, scene.ambient.z}; }

Json materialJson(const Material& m) {
  for (const auto& [value, key] : {std::pair{m.ka, "ka"}, {m.kd, "kd"}, {m.ks, "ks"}, {m.n, "n"}})
    requireFinite(value, std::string("material.") + key);
  Json json = {{"ka", m.ka},
               {"kd", m.kd},
               {"ks", m.ks},
               {"n", m.n},
               {"attenuation", vec3Json(m.attenuation, "material.attenuation")},
               {"color", vec3Json(m.color, "material.color")}};
  if (!m.texture.empty() && m.textureImage)
    throw ArgumentError("material: a texture file (texture) or one held in memory (textureImage), not both");
  if (!m.texture.empty()) json["texture"] = m.texture;
  return json;
}

SceneSpec withRenderSettings(const SceneSpec& scene, const RenderSettings& settings) {
  const Json render = {{"shading", shadingName(settings.shading)},
                       {"specular", specularName(settings.specular)},
                       {"interpolation", interpolationName(settings.interpolation)},
                       {"samples", settings.samples},
                       {"texture_filter", textureFilterName(settings.textureFilter)}};
  const Json background = vec3Json(settings.background, "background");
  return withSection(withSection(scene, "render", render.dump()), "background", background.dump());
}

RenderSettings renderSettingsOf(const SceneSpec& scene) {
  const glm::vec3 b = scene.background;
  return {scene.shading, scene.specular, scene.interpolation, scene.samples, {b.x, b.y, b.z}, scene.textureFilter};
}

SceneSpec sceneInCode(int width, int height) {
  const SceneSpec camera = withSection(SceneSpec{}, "camera", cameraJson(Camera{}, width, height).dump());
  SceneSpec spec = withLights(camera, {Light{.atCamera = true}});
  spec.materials.push_back(noFallOffMaterial());  // the default material (Scene(width, height))
  spec.defaultMaterial = int(spec.materials.size()) - 1;
  return spec;
}

namespace {

// The name of choice `value` among `names`; "" (which no scene file's reader takes) for a value
// outside the enum.
template <typename E, size_t N>
const char* nameOf(E value, const std::array<const char*, N>& names) {
  const size_t index = size_t(value);
  return index < N ? names[index] : "";
}

// The choice `name` stands for, read as a scene file's render.KEY.
SceneSpec renderOption(const char* key, const std::string& name) {
  return withSection(SceneSpec{}, "render", Json{{key, name}}.dump());
}

}  // namespace

const char* shadingName(Shading shading) { return nameOf(shading, SHADING_NAMES); }
const char* specularName(Specular specular) { return nameOf(specular, SPECULAR_NAMES); }
const char* interpolationName(Interpolation interpolation) { return nameOf(interpolation, INTERPOLATION_NAMES); }
Shading parseShading(const std::string& name) { return renderOption("shading", name).shading; }
Specular parseSpecular(const std::string& name) { return renderOption("specular", name).specular; }
Interpolation parseInterpolation(const std::string& name) {
  return renderOption("interpolation", name).interpolation;
}
const char* textureFilterName(TextureFilter filter) { return nameOf(filter, TEXTURE_FILTER_NAMES); }
TextureFilter parseTextureFilter(const std::string& name) { return renderOption("texture_filter", name).textureFilter; }

}  // namespace phongvk
