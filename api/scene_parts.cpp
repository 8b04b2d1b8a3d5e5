// scene_parts.cpp — see scene_parts.h and include/phongvk/scene_parts.h.
#include "api/scene_parts.h"

#include "base/number_text.h"
#include "scene/camera.h"
#include "scene/object_pose.h"
#include "scene/scene_checks.h"

#include <array>
#include <cmath>

namespace phongvk {
namespace {

using scenejson::toVec;
using scenejson::Where;

// A value given in code that no scene file can hold (JSON has no NaN or infinity): ArgumentError,
// before the file's checks.
double requireFinite(double value, const std::string& what) {
  if (!std::isfinite(value)) throw ArgumentError(what + ": must be finite, got " + formatNumber(value));
  return value;
}

glm::dvec3 finite3(const Vec3& v, const std::string& what) {
  for (int i = 0; i < 3; ++i) requireFinite(v[i], what + "[" + std::to_string(i) + "]");
  return toVec(v);
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

// `camera` at width x height as the values a scene file's "camera" would give.
scenejson::CameraValues cameraValues(const Camera& camera, int width, int height) {
  scenejson::CameraValues c;
  c.position = finite3(camera.position, "camera.position");
  c.lookAt = finite3(camera.lookAt, "camera.look_at");
  c.up = finite3(camera.up, "camera.up");
  c.width = width;
  c.height = height;
  c.nearPlane = requireFinite(camera.nearPlane, "camera.near");
  c.farPlane = requireFinite(camera.farPlane, "camera.far");
  requireFinite(camera.fov, "camera.fov");
  if (camera.orthoHeight) {
    if (camera.intrinsics) throw ArgumentError("camera: intrinsics describe a pinhole camera, not an orthographic one");
    c.orthographic = true;
    c.orthoHeight = requireFinite(*camera.orthoHeight, "camera.ortho_height");
  } else if (camera.intrinsics) {
    const Intrinsics& k = *camera.intrinsics;
    c.fx = requireFinite(k.fx, "camera.fx");
    c.fy = requireFinite(k.fy, "camera.fy");
    c.cx = requireFinite(k.cx, "camera.cx");
    c.cy = requireFinite(k.cy, "camera.cy");
  } else {
    c.fov = camera.fov;
  }
  return c;
}

}  // namespace

SceneSpec withCamera(const SceneSpec& scene, const Camera& camera) {
  const View current = makeView(scene.camera);
  const bool sized = camera.width > 0 || camera.height > 0;  // else the scene's own size
  SceneSpec changed = scene;
  changed.camera = scenejson::cameraSpec(
      cameraValues(camera, sized ? camera.width : current.width, sized ? camera.height : current.height),
      Where("camera", scene.path));
  return changed;
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
  for (size_t i = 0; i < lights.size(); ++i) {
    const std::string at = "lights[" + std::to_string(i) + "]";
    requireFinite(lights[i].intensity, at + ".intensity");
    finite3(lights[i].color, at + ".color");
    if (lights[i].directional || lights[i].spot) finite3(lights[i].direction, at + ".direction");
    if (!lights[i].directional && !lights[i].atCamera) finite3(lights[i].position, at + ".position");  // at the camera: not used
  }
  SceneSpec changed = scene;
  changed.lights = scenejson::lightSpecs(lights, Where("lights", scene.path));
  return changed;
}

std::vector<Light> lightsOf(const SceneSpec& scene) {
  std::vector<Light> lights;
  for (const LightSpec& l : scene.lights) {
    lights.push_back({{l.position.x, l.position.y, l.position.z}, l.intensity, {l.color.x, l.color.y, l.color.z},
                      l.atCamera, l.directional, {l.direction.x, l.direction.y, l.direction.z}, l.spot, l.innerCone,
                      l.outerCone, l.inverseSquare, l.range, l.shadows});
  }
  return lights;
}

SceneSpec withAmbient(const SceneSpec& scene, const Vec3& ambient) {
  SceneSpec changed = scene;
  changed.ambient = scenejson::color(finite3(ambient, "ambient"), Where("ambient", scene.path));
  return changed;
}

Vec3 ambientOf(const SceneSpec& scene) { return {scene.ambient.x, scene.ambient.y, scene.ambient.z}; }

scenejson::MaterialValues materialValues(const Material& m, std::shared_ptr<const TextureImage> textureImage) {
  scenejson::MaterialValues values;
  values.ka = requireFinite(m.ka, "material.ka");
  values.kd = requireFinite(m.kd, "material.kd");
  values.ks = requireFinite(m.ks, "material.ks");
  values.n = requireFinite(m.n, "material.n");
  values.attenuation = finite3(m.attenuation, "material.attenuation");
  values.color = finite3(m.color, "material.color");
  if (!m.texture.empty() && textureImage)
    throw ArgumentError("material: a texture file (texture) or one held in memory (textureImage), not both");
  if (!m.texture.empty()) values.texture = m.texture;
  values.textureImage = std::move(textureImage);
  return values;
}

SceneSpec withRenderSettings(const SceneSpec& scene, const RenderSettings& settings) {
  SceneSpec changed = scene;
  scenejson::setRenderSettings(changed, settings, Where("render", scene.path));
  changed.background = scenejson::unitColor(finite3(settings.background, "background"), Where("background", scene.path));
  return changed;
}

SceneSpec sceneInCode(int width, int height) {
  SceneSpec spec;
  spec.camera = scenejson::cameraSpec(cameraValues(Camera{}, width, height), Where("camera"));
  spec.lights = scenejson::lightSpecs({Light{.atCamera = true}}, Where("lights"));
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

// The choice `name` stands for, checked as a scene file's render.KEY.
template <typename E, size_t N>
E renderOption(const char* key, const std::string& name, const std::array<const char*, N>& names) {
  return scenejson::choice<E>(name, names, Where(std::string("render.") + key));
}

}  // namespace

const char* shadingName(Shading shading) { return nameOf(shading, SHADING_NAMES); }
const char* specularName(Specular specular) { return nameOf(specular, SPECULAR_NAMES); }
const char* interpolationName(Interpolation interpolation) { return nameOf(interpolation, INTERPOLATION_NAMES); }
Shading parseShading(const std::string& name) { return renderOption<Shading>("shading", name, SHADING_NAMES); }
Specular parseSpecular(const std::string& name) { return renderOption<Specular>("specular", name, SPECULAR_NAMES); }
Interpolation parseInterpolation(const std::string& name) {
  return renderOption<Interpolation>("interpolation", name, INTERPOLATION_NAMES);
}
const char* textureFilterName(TextureFilter filter) { return nameOf(filter, TEXTURE_FILTER_NAMES); }
TextureFilter parseTextureFilter(const std::string& name) {
  return renderOption<TextureFilter>("texture_filter", name, TEXTURE_FILTER_NAMES);
}

}  // namespace phongvk
