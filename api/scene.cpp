// scene.cpp — the public Scene and Sequence: handles on the validated model (scene/scene.h) and
// on the animation (scene/animate.h).
#include "phongvk/phongvk.h"

#include "scene/animate.h"
#include "scene/camera.h"
#include "scene/scene.h"

#include <stdexcept>

namespace phongvk {

Scene::Scene(std::shared_ptr<const SceneSpec> spec) : spec_(std::move(spec)) {}

const std::string& Scene::path() const { return spec_->path; }
int Scene::width() const { return makeView(spec_->camera).width; }
int Scene::height() const { return makeView(spec_->camera).height; }
size_t Scene::objectCount() const { return spec_->objects.size(); }
size_t Scene::lightCount() const { return spec_->lights.size(); }

Scene Scene::withImageSize(int width, int height) const {
  auto resized = std::make_shared<SceneSpec>(*spec_);
  resized->camera = phongvk::withImageSize(spec_->camera, width, height);
  makeView(resized->camera);  // throws SceneError for a size out of range
  return Scene(std::move(resized));
}

Scene loadScene(const std::string& path) { return Scene(std::make_shared<const SceneSpec>(loadSceneSpec(path))); }

Scene parseScene(const std::string& json, const std::string& name, const std::string& baseDir) {
  return Scene(std::make_shared<const SceneSpec>(parseSceneSpec(json, name, baseDir)));
}

Sequence::Sequence(std::shared_ptr<const SceneSequence> sequence) : sequence_(std::move(sequence)) {}

int Sequence::frameCount() const { return sequence_->frameCount(); }
const std::string& Sequence::path() const { return sequence_->path(); }
Scene Sequence::frame(int index) const {
  if (index < 0 || index >= frameCount()) {
    throw std::out_of_range(path() + ": frame " + std::to_string(index) + " is out of range: the sequence has " +
                            std::to_string(frameCount()) + " frames");
  }
  return Scene(std::make_shared<const SceneSpec>(sequence_->frame(index)));
}

Sequence loadSequence(const std::string& path) {
  return Sequence(std::make_shared<const SceneSequence>(SceneSequence::load(path)));
}

Sequence parseSequence(const std::string& json, const std::string& name, const std::string& baseDir) {
  return Sequence(std::make_shared<const SceneSequence>(scenejson::parseJson(json, name), name, baseDir));
}

}  // namespace phongvk
