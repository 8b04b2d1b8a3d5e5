// scene_access.h — the library's own way into a public Scene: the validated model it holds, and a
// Scene made from one. Nothing outside api/ includes it.
#pragma once

#include "phongvk/phongvk.h"
#include "scene/animate.h"
#include "scene/scene.h"

#include <memory>

namespace phongvk {

struct SceneAccess {
  static const SceneSpec& spec(const Scene& scene);
  static Scene make(std::shared_ptr<SceneSpec> spec, std::shared_ptr<const SceneSequence> sequence = nullptr);
};

}  // namespace phongvk
