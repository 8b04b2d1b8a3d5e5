// scene.cpp — the public Scene: a handle on the validated model (scene/scene.h) and on the file's
// animation (scene/animate.h), which gives the other frames.
#include "phongvk/phongvk.h"

#include "api/scene_access.h"

#include "scene/animate.h"
#include "scene/camera.h"
#include "scene/mesh_arrays.h"
#include "scene/scene.h"

#include <stdexcept>

namespace phongvk {

struct Scene::State {
  std::shared_ptr<const SceneSpec> spec;
  std::shared_ptr<const SceneSequence> sequence;  // where frame() comes from; none for one frame
};

Scene::Scene(std::shared_ptr<const State> state) : state_(std::move(state)) {}

const SceneSpec& SceneAccess::spec(const Scene& scene) { return *scene.state_->spec; }

Scene SceneAccess::make(std::shared_ptr<const SceneSpec> spec, std::shared_ptr<const SceneSequence> sequence) {
  return Scene(std::make_shared<const Scene::State>(Scene::State{std::move(spec), std::move(sequence)}));
}

const std::string& Scene::path() const { return state_->spec->path; }
int Scene::width() const { return makeView(state_->spec->camera).width; }
int Scene::height() const { return makeView(state_->spec->camera).height; }
size_t Scene::objectCount() const { return state_->spec->objects.size(); }
size_t Scene::lightCount() const { return state_->spec->lights.size(); }

Scene Scene::withImageSize(int width, int height) const {
  auto resized = std::make_shared<SceneSpec>(*state_->spec);
  resized->camera = phongvk::withImageSize(state_->spec->camera, width, height);
  makeView(resized->camera);  // throws SceneError for a size out of range
  return SceneAccess::make(std::move(resized), state_->sequence);
}

Scene Scene::withRender(const std::string& json) const {
  return SceneAccess::make(std::make_shared<SceneSpec>(withRenderOptions(*state_->spec, json)), state_->sequence);
}

Scene Scene::share(int part, int parts) const {
  if (parts < 1 || part < 0 || part >= parts) {
    throw SceneError(path() + ": share " + std::to_string(part) + " of " + std::to_string(parts) + " does not exist");
  }
  auto shared = std::make_shared<SceneSpec>(*state_->spec);
  shared->sharePart = part;
  shared->shareParts = parts;
  return SceneAccess::make(std::move(shared), state_->sequence);
}

void Scene::addMesh(const MeshArrays& mesh, const std::string& material, bool closed) {
  auto changed = std::make_shared<SceneSpec>(*state_->spec);
  addMeshObject(*changed, mesh, material, closed);
  state_ = std::make_shared<const State>(State{std::move(changed), state_->sequence});
}

int Scene::frameCount() const { return state_->sequence ? state_->sequence->frameCount() : 1; }

Scene Scene::frame(int index) const {
  if (index < 0 || index >= frameCount()) {
    throw RangeError((path().empty() ? "" : path() + ": ") + "frame " + std::to_string(index) +
                            " is out of range: the scene has " + std::to_string(frameCount()) + " frames");
  }
  if (!state_->sequence) return *this;
  return SceneAccess::make(std::make_shared<const SceneSpec>(state_->sequence->frame(index)), state_->sequence);
}

namespace {

// A scene file or text as its sequence (one frame without an "animate" block) and frame 0.
Scene firstFrame(std::shared_ptr<const SceneSequence> sequence) {
  auto spec = std::make_shared<const SceneSpec>(sequence->frame(0));
  return SceneAccess::make(std::move(spec), std::move(sequence));
}

}  // namespace

Scene loadScene(const std::string& path) { return firstFrame(std::make_shared<const SceneSequence>(SceneSequence::load(path))); }

Scene parseScene(const std::string& json, const std::string& name, const std::string& baseDir, bool objectsLater) {
  return firstFrame(
      std::make_shared<const SceneSequence>(scenejson::parseJson(json, name), name, baseDir, objectsLater));
}

}  // namespace phongvk
