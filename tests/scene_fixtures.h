// scene_fixtures.h — scene text the scene suites share: the smallest valid scene, edited copies of
// it, and parsing text as the file "a.json".
#pragma once

#include "scene/scene.h"

#include <functional>
#include <nlohmann/json.hpp>
#include <string>

namespace phongvk::test {

inline const char* kMinimalScene =
    R"({"camera": {"position": [0, 0, 0], "direction": [1, 0, 0]}, "objects": [{"shape": "sphere"}]})";

inline SceneSpec parse(const std::string& text) { return parseSceneSpec(text, "a.json", "."); }

// The minimal scene after `edit`.
inline nlohmann::ordered_json minimalWith(const std::function<void(nlohmann::ordered_json&)>& edit) {
  nlohmann::ordered_json scene = nlohmann::ordered_json::parse(kMinimalScene);
  edit(scene);
  return scene;
}

}  // namespace phongvk::test
