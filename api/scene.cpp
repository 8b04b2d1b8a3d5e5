// scene.cpp — the public Scene: a handle on the validated model (scene/scene.h) and on the file's
// animation (scene/animate.h), which gives the other frames.
#include "phongvk/phongvk.h"

#include "scene/animate.h"
#include "scene/camera.h"
#include "scene/mesh_arrays.h"
#include "scene/scene.h"

#include <stdexcept>

namespace phongvk {

Scene::Scene(std::shared_ptr<const SceneSpec> spec, std::shared_ptr<const SceneSequence> sequence)
    : spec_(std::move(spec)), sequence_(std::move(sequence)) {}

const std::string& Scene::path() const { return spec_->path; }
int Scene::width() const { return makeView(spec_->camera).width; }
int Scene::height() const { return makeView(spec_->camera).height; }
size_t Scene::objectCount() const { return spec_->objects.size(); }
size_t Scene::lightCount() const { return spec_->lights.size(); }

Scene Scene::withImageSize(int width, int height) const {
  auto resized = std::make_shared<SceneSpec>(*spec_);
  resized->camera = phongvk::withImageSize(spec_->camera, width, height);
  makeView(resized->camera);  // throws SceneError for a size out of range
  return Scene(std::move(resized), sequence_);
}

Scene Scene::withRender(const std::string& json) const {
  return Scene(std::make_shared<SceneSpec>(withRenderOptions(*spec_, json)), sequence_);
}

Scene Scene::share(int part, int parts) const {
  if (parts < 1 || part < 0 || part >= parts) {
    throw SceneError(path() + ": share " + std::to_string(part) + " of " + std::to_string(parts) + " does not exist");
  }
  auto shared = std::make_shared<SceneSpec>(*spec_);
  shared->sharePart = part;
  shared->shareParts = parts;
  return Scene(std::move(shared), sequence_);
}

void Scene::addMesh(const MeshArrays& mesh, const std::string& material, bool closed) {
  auto changed = std::make_shared<SceneSpec>(*spec_);
  addMeshObject(*changed, mesh, material, closed);
  spec_ = std::move(changed);
}

int Scene::frameCount() const { return sequence_ ? sequence_->frameCount() : 1; }

Scene Scene::frame(int index) const {
  if (index < 0 || index >= frameCount()) {
    throw RangeError((path().empty() ? "" : path() + ": ") + "frame " + std::to_string(index) +
                            " is out of range: the scene has " + std::to_string(frameCount()) + " frames");
  }
  if (!sequence_) return *this;
  return Scene(std::make_shared<const SceneSpec>(sequence_->frame(index)), sequence_);
}

namespace {

// A scene file or text as its sequence (one frame without an "animate" block) and frame 0.
Scene firstFrame(std::shared_ptr<const SceneSequence> sequence) {
  auto spec = std::make_shared<const SceneSpec>(sequence->frame(0));
  return Scene(std::move(spec), std::move(sequence));
}

}  // namespace

Scene loadScene(const std::string& path) { return firstFrame(std::make_shared<const SceneSequence>(SceneSequence::load(path))); }

Scene parseScene(const std::string& json, const std::string& name, const std::string& baseDir, bool objectsLater) {
  return firstFrame(
      std::make_shared<const SceneSequence>(scenejson::parseJson(json, name), name, baseDir, objectsLater));
}

}  // namespace phongvk
