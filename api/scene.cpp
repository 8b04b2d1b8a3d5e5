// scene.cpp — the public Scene: a handle on the validated model (scene/scene.h) and on the file's
// animation (scene/animate.h), which gives the other frames.
#include "phongvk/phongvk.h"

#include "api/scene_access.h"
#include "api/triangle_mesh_access.h"
#include "api/scene_parts.h"
#include "prepare/scene_data.h"

#include "scene/animate.h"
#include "scene/camera.h"
#include "scene/mesh_arrays.h"
#include "scene/scene.h"
#include "scene/scene_write.h"

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace phongvk {

namespace {

// A mesh given to addMesh, built once, with what it was added with (its material as a scene file's
// "material": a name or an object of fields): it follows the scene into its other frames
// (Scene::frame).
struct AddedMesh {
  ObjectId id;
  std::shared_ptr<const Mesh> mesh;
  scenejson::Json material;
  bool closed = false;
  Matrix4 pose = IDENTITY_POSE;
};

// Appends `added` to `spec` as a mesh object at its pose.
void appendAdded(SceneSpec& spec, const AddedMesh& added) {
  addMeshObject(spec, added.mesh, added.material, added.closed);
  placeObject(spec.objects.back(), added.pose);
}

}  // namespace

struct Scene::State {
  std::shared_ptr<const SceneSpec> spec;
  std::shared_ptr<const SceneSequence> sequence;  // where frame() comes from; none for one frame
  std::vector<AddedMesh> added;                   // in the order they were added: the spec's last objects
  unsigned long long nextId = 1;

  // Where `id` is in `added`; RangeError for a handle this scene does not hold.
  size_t position(ObjectId id, const std::string& path) const {
    for (size_t i = 0; i < added.size(); ++i) {
      if (added[i].id == id) return i;
    }
    throw RangeError((path.empty() ? "" : path + ": ") + "no object " + std::to_string(id.value) +
                     " (removed, or added to another scene)");
  }
  // The index in spec->objects of added[i].
  size_t objectIndex(size_t i) const { return spec->objects.size() - added.size() + i; }

  // Adds `mesh` to `scene` (whose state this is) with `material` as a scene file's "material".
  ObjectId add(Scene& scene, std::shared_ptr<const Mesh> mesh, const Matrix4& pose, scenejson::Json material,
               bool closed) const {
    const ObjectId id{nextId};
    const AddedMesh added{id, std::move(mesh), std::move(material), closed, pose};
    scene = changed([&](SceneSpec& spec, State& state) {
      appendAdded(spec, added);
      state.added.push_back(added);
      ++state.nextId;
    });
    return id;
  }

  // This scene with another model: the sequence and the added meshes stay.
  Scene with(std::shared_ptr<const SceneSpec> other) const {
    return Scene(std::make_shared<const State>(State{std::move(other), sequence, added, nextId}));
  }
  // This scene with a copy of its model and of this state changed by change(spec, state).
  template <typename Change>
  Scene changed(Change change) const {
    auto copy = std::make_shared<SceneSpec>(*spec);
    State next = *this;
    change(*copy, next);
    next.spec = std::move(copy);
    return Scene(std::make_shared<const State>(std::move(next)));
  }
};

Scene::Scene(std::shared_ptr<const State> state) : state_(std::move(state)) {}

Scene::Scene(int width, int height)
    : state_(std::make_shared<const State>(State{std::make_shared<const SceneSpec>(sceneInCode(width, height))})) {}

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
  return state_->with(std::move(resized));
}

Scene Scene::withRender(const RenderSettings& settings) const {
  return state_->with(std::make_shared<const SceneSpec>(withRenderSettings(*state_->spec, settings)));
}

RenderSettings Scene::renderSettings() const { return renderSettingsOf(*state_->spec); }

void Scene::setRenderSettings(const RenderSettings& settings) { *this = withRender(settings); }

Scene Scene::share(int part, int parts) const {
  if (parts < 1 || part < 0 || part >= parts) {
    throw SceneError(path() + ": share " + std::to_string(part) + " of " + std::to_string(parts) + " does not exist");
  }
  auto shared = std::make_shared<SceneSpec>(*state_->spec);
  shared->sharePart = part;
  shared->shareParts = parts;
  return state_->with(std::move(shared));
}

void Scene::addMesh(const MeshArrays& mesh, const std::optional<Material>& material, bool closed) {
  add(mesh, IDENTITY_POSE, material, closed);
}

void Scene::addMesh(const MeshArrays& mesh, const std::string& materialName, bool closed) {
  add(mesh, IDENTITY_POSE, materialName, closed);
}

ObjectId Scene::add(const MeshArrays& mesh, const Matrix4& pose, const std::optional<Material>& material,
                    bool closed) {
  return add(TriangleMesh(mesh), pose, material, closed);
}

ObjectId Scene::add(const MeshArrays& mesh, const Matrix4& pose, const std::string& materialName, bool closed) {
  return add(TriangleMesh(mesh), pose, materialName, closed);
}

ObjectId Scene::add(const TriangleMesh& mesh, const Matrix4& pose, const std::optional<Material>& material,
                    bool closed) {
  return state_->add(*this, TriangleMeshAccess::mesh(mesh), pose, material ? materialJson(*material) : scenejson::Json(),
                     closed);
}

ObjectId Scene::add(const TriangleMesh& mesh, const Matrix4& pose, const std::string& materialName, bool closed) {
  return state_->add(*this, TriangleMeshAccess::mesh(mesh), pose, scenejson::Json(materialName), closed);
}

void Scene::setPose(ObjectId object, const Matrix4& pose) {
  const size_t i = state_->position(object, path());
  *this = state_->changed([&](SceneSpec& spec, State& state) {
    placeObject(spec.objects[state.objectIndex(i)], pose);
    state.added[i].pose = pose;
  });
}

void Scene::remove(ObjectId object) {
  const size_t i = state_->position(object, path());
  *this = state_->changed([&](SceneSpec& spec, State& state) {
    const size_t index = state.objectIndex(i);
    spec.objects.erase(spec.objects.begin() + ptrdiff_t(index));
    for (size_t k = index; k < spec.objects.size(); ++k) spec.objects[k].jsonPath = "objects[" + std::to_string(k) + "]";
    state.added.erase(state.added.begin() + ptrdiff_t(i));
  });
}

std::array<Vec3, 2> Scene::bounds() const {
  const SceneData data = buildSceneData(*state_->spec);
  return {Vec3{data.boundsMin.x, data.boundsMin.y, data.boundsMin.z}, Vec3{data.boundsMax.x, data.boundsMax.y, data.boundsMax.z}};
}

SceneTriangles Scene::triangles() const {
  const SceneData data = buildSceneData(*state_->spec);
  SceneTriangles out;
  out.mesh.positions.reserve(data.vertices.size() * 3);
  out.mesh.normals.reserve(data.vertices.size() * 3);
  for (const gpu::VertexIn& v : data.vertices) {
    const glm::dvec3 world = data.objectOrigins[v.object] + glm::dvec3(v.position);
    out.mesh.positions.insert(out.mesh.positions.end(), {float(world.x), float(world.y), float(world.z)});
    out.mesh.normals.insert(out.mesh.normals.end(), {v.normal.x, v.normal.y, v.normal.z});
  }
  out.mesh.triangles.reserve(data.triangles.size() * 3);
  out.objects.reserve(data.triangles.size());
  for (const glm::uvec4& t : data.triangles) {
    out.mesh.triangles.insert(out.mesh.triangles.end(), {int64_t(t.x), int64_t(t.y), int64_t(t.z)});
    out.objects.push_back(int32_t(t.w));
  }
  return out;
}

Camera Scene::camera() const { return cameraOf(*state_->spec); }

void Scene::setCamera(const Camera& camera) {
  *this = state_->with(std::make_shared<const SceneSpec>(withCamera(*state_->spec, camera)));
}

std::vector<Light> Scene::lights() const { return lightsOf(*state_->spec); }

void Scene::setLights(const std::vector<Light>& lights) {
  *this = state_->with(std::make_shared<const SceneSpec>(withLights(*state_->spec, lights)));
}

Vec3 Scene::ambient() const { return ambientOf(*state_->spec); }

void Scene::setAmbient(const Vec3& ambient) {
  *this = state_->with(std::make_shared<const SceneSpec>(withAmbient(*state_->spec, ambient)));
}

std::string Scene::toJson() const { return sceneJson(*state_->spec).dump(2); }

int Scene::frameCount() const { return state_->sequence ? state_->sequence->frameCount() : 1; }

Scene Scene::frame(int index) const {
  if (index < 0 || index >= frameCount()) {
    throw RangeError((path().empty() ? "" : path() + ": ") + "frame " + std::to_string(index) +
                            " is out of range: the scene has " + std::to_string(frameCount()) + " frames");
  }
  if (!state_->sequence) return *this;
  auto spec = std::make_shared<SceneSpec>(state_->sequence->frame(index));
  for (const AddedMesh& added : state_->added) appendAdded(*spec, added);
  return state_->with(std::move(spec));
}

namespace {

// A scene file or text as its sequence (one frame without an "animate" block) and frame 0.
Scene firstFrame(std::shared_ptr<const SceneSequence> sequence) {
  auto spec = std::make_shared<const SceneSpec>(sequence->frame(0));
  return SceneAccess::make(std::move(spec), std::move(sequence));
}

}  // namespace

ModelUp parseModelUp(const std::string& name) {
  if (name == "y") return ModelUp::Y;
  if (name == "z") return ModelUp::Z;
  throw ArgumentError("up: expected 'y' or 'z', got '" + name + "'");
}

bool parseOrthographic(const std::string& projection) {
  if (projection == "perspective") return false;
  if (projection == "orthographic") return true;
  throw ArgumentError("projection: expected 'perspective' or 'orthographic', got '" + projection + "'");
}

Scene loadScene(const std::string& path, const LoadOptions& options) {
  ModelView view;
  if (options.up != ModelUp::Usual) view.up = options.up == ModelUp::Y ? UpAxis::Y : UpAxis::Z;
  view.orthographic = options.orthographic;
  return firstFrame(std::make_shared<const SceneSequence>(SceneSequence::load(path, view)));
}

Scene parseScene(const std::string& json, const std::string& name, const std::string& baseDir, bool objectsLater) {
  return firstFrame(
      std::make_shared<const SceneSequence>(scenejson::parseJson(json, name), name, baseDir, objectsLater));
}

}  // namespace phongvk
