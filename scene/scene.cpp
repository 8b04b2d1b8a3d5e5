// scene.cpp — a scene file as a whole (docs/DESIGN.md "Scene file"): its top-level keys, the render
// options, and loading. Each section has its own reader (scene_sections.h); the generic checks
// (types, ranges, paths in messages) live in scene_json.cpp.
#include "scene/scene.h"

#include "scene/animate.h"
#include "scene/scene_sections.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace phongvk {
namespace {

using namespace scenejson;

// "animate" is read by SceneSequence (animate.h), which hands readScene each frame without it.
const Keys kSceneKeys = {"camera",  "background", "ambient", "lights",
                         "materials", "objects",    "render",  "animate"};
const Keys kRenderKeys = {"interpolation"};

Interpolation readRender(const Node& node) {
  requireObject(node);
  checkKeys(node, kRenderKeys);
  auto interpolation = node.find("interpolation");
  if (!interpolation) return Interpolation::Perspective;
  std::string mode = string(*interpolation);
  if (mode == "perspective") return Interpolation::Perspective;
  if (mode == "screen") return Interpolation::Screen;
  interpolation->fail("must be one of perspective, screen, got '" + mode + "'");
}

}  // namespace

namespace scenejson {

SceneSpec readScene(const Node& root, const std::string& path, const std::string& baseDir, bool objectsLater) {
  requireObject(root);
  checkKeys(root, kSceneKeys);
  SceneSpec scene;
  scene.path = path;
  scene.camera = readCamera(root.require("camera"));
  if (auto background = root.find("background")) scene.background = unitColor(*background);
  if (auto ambient = root.find("ambient")) scene.ambient = color(*ambient);
  if (auto lights = root.find("lights")) scene.lights = readLights(*lights);
  MaterialTable materials(scene);
  if (auto named = root.find("materials")) materials.readNamed(*named);
  scene.objects = readObjects(root.require("objects"), baseDir, materials, objectsLater);
  if (auto render = root.find("render")) scene.interpolation = readRender(*render);
  return scene;
}

}  // namespace scenejson

std::string readSceneText(const std::string& path) {
  if (auto reason = unreadableReason(path)) {
    throw SceneError(path + ": cannot read file: " + *reason);
  }
  std::ifstream in(path, std::ios::binary);
  std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (!in.is_open()) throw SceneError(path + ": cannot read file: " + std::strerror(errno));
  return text;
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
