// scene.cpp — a scene file as a whole (docs/DESIGN.md "Scene file"): its top-level keys, the render
// options, and loading. Each section has its own reader (scene_sections.h); the generic checks
// (types, ranges, paths in messages) live in scene_json.cpp.
#include "scene/scene.h"

#include "scene/animate.h"
#include "scene/scene_sections.h"
#include "base/number_text.h"
#include "shaders/screen_quads.h"

#include <array>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>

namespace phongvk {
namespace {

using namespace scenejson;

// "animate" is read by SceneSequence (animate.h), which hands readScene each frame without it.
const Keys kSceneKeys = {"camera",  "background", "ambient", "lights",
                         "materials", "objects",    "render",  "animate"};
const Keys kRenderKeys = {"interpolation", "shading", "specular", "samples", "texture_filter", "point_size", "line_width"};

// Samples per pixel: a square of 1 to 4 on a side.
int samplesPerPixel(int samples, const Where& at) {
  integerInRange(samples, 1, 16, at);
  const int side = int(std::lround(std::sqrt(double(samples))));
  if (side * side != samples) at.fail("must be 1, 4, 9 or 16 (a regular grid of samples per pixel), got " + std::to_string(samples));
  return samples;
}

// "render": interpolation, shading, specular model, samples per pixel and texture filter
// (docs/DESIGN.md), its keys and types checked, over the scene's own (the values are
// setRenderSettings').
void readRender(const Node& node, SceneSpec& scene) {
  requireObject(node);
  checkKeys(node, kRenderKeys);
  RenderSettings s = renderSettingsOf(scene);
  if (auto v = node.find("interpolation")) s.interpolation = choice<Interpolation>(*v, INTERPOLATION_NAMES);
  if (auto v = node.find("shading")) s.shading = choice<Shading>(*v, SHADING_NAMES);
  if (auto v = node.find("specular")) s.specular = choice<Specular>(*v, SPECULAR_NAMES);
  if (auto v = node.find("samples")) s.samples = integer(*v, 1, 16);
  if (auto v = node.find("texture_filter")) s.textureFilter = choice<TextureFilter>(*v, TEXTURE_FILTER_NAMES);
  if (auto v = node.find("point_size")) s.pointSize = number(*v);
  if (auto v = node.find("line_width")) s.lineWidth = number(*v);
  setRenderSettings(scene, s, node.where());
}

}  // namespace

namespace scenejson {

void setRenderSettings(SceneSpec& scene, const RenderSettings& s, const Where& at) {
  scene.interpolation = choice(s.interpolation, INTERPOLATION_NAMES, at.at("interpolation"));
  scene.shading = choice(s.shading, SHADING_NAMES, at.at("shading"));
  scene.specular = choice(s.specular, SPECULAR_NAMES, at.at("specular"));
  scene.samples = samplesPerPixel(s.samples, at.at("samples"));
  scene.textureFilter = choice(s.textureFilter, TEXTURE_FILTER_NAMES, at.at("texture_filter"));
  scene.pointSize = quadWidth(s.pointSize, at.at("point_size"));
  scene.lineWidth = quadWidth(s.lineWidth, at.at("line_width"));
}

double quadWidth(double pixels, const Where& at) {
  inRange(pixels, 0.0, double(gpu::QUAD_MAX_WIDTH), at);
  if (!(pixels * 256.0 >= 0.5)) at.fail("must be at least 1/256 pixel, got " + formatNumber(pixels));
  return pixels;
}

RenderSettings renderSettingsOf(const SceneSpec& scene) {
  const glm::vec3 b = scene.background;
  return {scene.shading, scene.specular, scene.interpolation, scene.samples, {b.x, b.y, b.z}, scene.textureFilter,
          scene.pointSize, scene.lineWidth};
}

SceneSpec readScene(const Node& root, const std::string& path, const std::string& baseDir, bool objectsLater) {
  requireObject(root);
  checkKeys(root, kSceneKeys);
  SceneSpec scene;
  scene.path = path;
  scene.camera = readCamera(root.require("camera"));
  if (auto background = root.find("background")) scene.background = unitColor(*background);
  if (auto ambient = root.find("ambient")) scene.ambient = color(*ambient);
  if (auto lights = root.find("lights")) scene.lights = readLights(*lights);
  MaterialTable materials(scene, baseDir);
  if (auto named = root.find("materials")) materials.readNamed(*named);
  scene.objects = readObjects(root.require("objects"), baseDir, materials, objectsLater);
  if (auto render = root.find("render")) readRender(*render, scene);
  return scene;
}

}  // namespace scenejson

FileVersion fileVersion(const std::string& path) {
  std::error_code error;
  FileVersion version;
  version.bytes = std::filesystem::file_size(path, error);
  const auto modified = std::filesystem::last_write_time(path, error);
  if (!error) version.modified = std::chrono::duration_cast<std::chrono::nanoseconds>(modified.time_since_epoch()).count();
  return version;
}

std::string readSceneText(const std::string& path) {
  std::string why;
  const std::optional<RegularFile> file = RegularFile::open(path, why);
  if (!file) throw SceneError(path + ": cannot read file: " + why);
  return file->read();
}

SceneSpec loadSceneSpec(const std::string& path) {
  return parseSceneSpec(readSceneText(path), path, std::filesystem::path(path).parent_path().string());
}

SceneSpec parseSceneSpec(const std::string& text, const std::string& path, const std::string& baseDir,
                         bool objectsLater) {
  // The sequence validates an "animate" block and reads frame 0's JSON (which has none).
  return SceneSequence(parseJson(text, path), path, baseDir, objectsLater).frame(0);
}

}  // namespace phongvk
