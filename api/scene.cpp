// scene.cpp — the public Scene: a handle on the validated model (scene/scene.h) and on the file's
// animation (scene/animate.h), which gives the other frames.
#include "phongvk/phongvk.h"

#include "api/scene_access.h"
#include "api/texture_access.h"
#include "api/triangle_mesh_access.h"
#include "api/scene_parts.h"
#include "prepare/memory_estimate.h"
#include "prepare/scene_data.h"
#include "shaders/phong.h"
#include "shaders/screen_quads.h"

#include "scene/animate.h"
#include "scene/camera.h"
#include "scene/mesh_arrays.h"
#include "scene/object_pose.h"
#include "scene/scene.h"
#include "scene/scene_write.h"

#include <atomic>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace phongvk {

namespace {

// A mesh given to addMesh, built once, with what it was added with (its material: the default, a
// name, or its own values): it follows the scene into its other frames (Scene::frame).
struct AddedMesh {
  ObjectId id;
  std::shared_ptr<const Mesh> mesh;
  scenejson::MaterialChoice material;
  bool closed = false;
  Matrix4 pose = IDENTITY_POSE;
  int32_t label = 0;  // its id in the object_id output (Scene::objectId)
  bool castShadows = true;  // its triangles block shadowed lights (Scene::setCastShadows)
};

// A light given to addLight: it follows the scene into its other frames, as added meshes do.
struct AddedLight {
  LightId id;
  Light light;
};

// Appends `added` to `spec` as a mesh object at its pose; `spec` is unchanged where it throws.
void appendAdded(SceneSpec& spec, const AddedMesh& added) {
  Object check;
  placeObject(check, added.pose);  // a bad pose throws before the scene changes
  addMeshObject(spec, added.mesh, added.material, added.closed);
  placeObject(spec.objects.back(), added.pose);
  spec.objects.back().label = added.label;
  spec.objects.back().castShadows = added.castShadows;
}

// `spec`'s lights with the added ones after them.
std::vector<Light> withAddedLights(const SceneSpec& spec, const std::vector<AddedLight>& added) {
  std::vector<Light> lights = lightsOf(spec);
  for (const AddedLight& light : added) lights.push_back(light.light);
  return lights;
}

// A light handle's tag beside its number: a scene's object and light handles never meet.
constexpr uint64_t LIGHT_HANDLE = uint64_t(1) << 31;

// Every scene's handles carry its serial, so that a handle one scene gave names nothing in another.
std::atomic<uint64_t> nextSerial{1};

}  // namespace

// A scene changes in place where no other scene shares its state (n adds take linear time); a
// scene that shares it (a copy, a derived scene) changes a copy of its own, and is another scene
// from then on, with a serial of its own.
struct Scene::State {
  std::shared_ptr<SceneSpec> spec;                // shared with other states until one changes it
  std::shared_ptr<const SceneSequence> sequence;  // where frame() comes from; none for one frame
  std::vector<AddedMesh> added;                   // in the order they were added: the spec's last objects
  std::vector<AddedLight> addedLights;            // likewise the spec's last lights
  uint64_t serial = nextSerial++;                 // a handle's upper 32 bits
  uint64_t nextObject = 1;                        // its lower 32 bits: each object's number in this scene
  uint64_t nextLight = 1;                         // each light's, beside LIGHT_HANDLE

  // `state` made its scene's own to change: as it is where no other scene shares it, else a copy
  // with a serial of its own.
  static State& own(std::shared_ptr<State>& state) {
    if (state.use_count() != 1) {
      state = std::make_shared<State>(*state);
      state->serial = nextSerial++;
    }
    return *state;
  }
  // `state`'s model replaced by `spec`: the same scene, its handles kept.
  static void replaceSpec(std::shared_ptr<State>& state, SceneSpec spec) {
    own(state).spec = std::make_shared<SceneSpec>(std::move(spec));
  }
  // The model, likewise this state's own to change.
  SceneSpec& ownSpec() {
    if (spec.use_count() != 1) spec = std::make_shared<SceneSpec>(*spec);
    return *spec;
  }

  // Where the handle `id` is in `list` (added or addedLights); RangeError for a handle this scene
  // does not hold, saying whether it was removed or belongs to another scene.
  template <typename Added, typename Id>
  size_t position(const std::vector<Added>& list, Id id, const char* kind) const {
    for (size_t i = 0; i < list.size(); ++i) {
      if (list[i].id == id) return i;
    }
    const std::string at = spec->path.empty() ? "" : spec->path + ": ";
    const std::string what = std::string(kind) + " " + std::to_string(id.value);
    if (id.value >> 32 == serial) throw RangeError(at + what + " was removed from this scene");
    throw RangeError(at + what + " belongs to another scene (or was removed before this scene was copied)");
  }
  size_t position(ObjectId id) const { return position(added, id, "object"); }
  size_t position(LightId id) const { return position(addedLights, id, "light"); }
  // The index in spec->objects of added[i], and in spec->lights of addedLights[i].
  size_t objectIndex(size_t i) const { return spec->objects.size() - added.size() + i; }
  size_t lightIndex(size_t i) const { return spec->lights.size() - addedLights.size() + i; }

  // Adds `mesh` with `material` as a scene file's "material"; unchanged where it throws. Its id in
  // the object_id output follows the scene's own objects, one number per add.
  ObjectId add(std::shared_ptr<const Mesh> mesh, const Matrix4& pose, scenejson::MaterialChoice material, bool closed) {
    const uint64_t ownObjects = spec->objects.size() - added.size();
    if (nextObject >= LIGHT_HANDLE || ownObjects + nextObject > LIGHT_HANDLE)
      throw ArgumentError("a scene gives at most 2^31 - 1 object ids");
    const ObjectId id{serial << 32 | nextObject};
    const auto label = int32_t(ownObjects + nextObject - 1);
    AddedMesh placed{id, std::move(mesh), std::move(material), closed, pose, label};
    appendAdded(ownSpec(), placed);
    added.push_back(std::move(placed));
    ++nextObject;
    return id;
  }

  // This scene with another model: the sequence and the added meshes stay.
  Scene with(std::shared_ptr<SceneSpec> other) const {
    auto state = std::make_shared<State>(*this);
    state->spec = std::move(other);
    state->serial = nextSerial++;
    return Scene(std::move(state));
  }
};

Scene::Scene(std::shared_ptr<State> state) : state_(std::move(state)) {}

Scene::Scene(int width, int height)
    : state_(std::make_shared<State>(State{std::make_shared<SceneSpec>(sceneInCode(width, height))})) {}

const SceneSpec& SceneAccess::spec(const Scene& scene) { return *scene.state_->spec; }

Scene SceneAccess::make(std::shared_ptr<SceneSpec> spec, std::shared_ptr<const SceneSequence> sequence) {
  return Scene(std::make_shared<Scene::State>(Scene::State{std::move(spec), std::move(sequence)}));
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
  return state_->with(std::make_shared<SceneSpec>(withRenderSettings(*state_->spec, settings)));
}

RenderSettings Scene::renderSettings() const { return scenejson::renderSettingsOf(*state_->spec); }

void Scene::setRenderSettings(const RenderSettings& settings) {
  State::replaceSpec(state_, withRenderSettings(*state_->spec, settings));
}

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
  scenejson::MaterialChoice choice;
  if (material) {
    choice = materialValues(*material, material->textureImage ? TextureAccess::image(*material->textureImage) : nullptr);
  }
  return State::own(state_).add(TriangleMeshAccess::mesh(mesh), pose, std::move(choice), closed);
}

ObjectId Scene::add(const TriangleMesh& mesh, const Matrix4& pose, const std::string& materialName, bool closed) {
  return State::own(state_).add(TriangleMeshAccess::mesh(mesh), pose, materialName, closed);
}

void Scene::setPose(ObjectId object, const Matrix4& pose) {
  const size_t i = state_->position(object);
  State& state = State::own(state_);
  placeObject(state.ownSpec().objects[state.objectIndex(i)], pose);  // unchanged where it throws
  state.added[i].pose = pose;
}

void Scene::remove(ObjectId object) {
  const size_t i = state_->position(object);
  State& state = State::own(state_);
  SceneSpec& spec = state.ownSpec();
  const size_t index = state.objectIndex(i);
  spec.objects.erase(spec.objects.begin() + ptrdiff_t(index));
  for (size_t k = index; k < spec.objects.size(); ++k) spec.objects[k].jsonPath = "objects[" + std::to_string(k) + "]";
  state.added.erase(state.added.begin() + ptrdiff_t(i));
}

int32_t Scene::objectId(ObjectId object) const { return state_->added[state_->position(object)].label; }

void Scene::setObjectId(ObjectId object, int32_t id) {
  if (id < 0) throw ArgumentError("object_id: must be in 0..2147483647, got " + std::to_string(id));
  const size_t i = state_->position(object);
  State& state = State::own(state_);
  state.ownSpec().objects[state.objectIndex(i)].label = id;
  state.added[i].label = id;
}

bool Scene::castsShadows(ObjectId object) const { return state_->added[state_->position(object)].castShadows; }

void Scene::setCastShadows(ObjectId object, bool casts) {
  const size_t i = state_->position(object);
  State& state = State::own(state_);
  state.ownSpec().objects[state.objectIndex(i)].castShadows = casts;
  state.added[i].castShadows = casts;
}

void Scene::setMesh(ObjectId object, const TriangleMesh& mesh) {
  const size_t i = state_->position(object);
  State& state = State::own(state_);
  state.added[i].mesh = TriangleMeshAccess::mesh(mesh);
  state.ownSpec().objects[state.objectIndex(i)].arrays = state.added[i].mesh;
}

LightId Scene::addLight(const Light& light) {
  if (state_->nextLight >= LIGHT_HANDLE) throw ArgumentError("a scene gives at most 2^31 - 1 light handles");
  std::vector<Light> lights = lightsOf(*state_->spec);
  lights.push_back(light);
  SceneSpec spec = withLights(*state_->spec, lights);  // throws before the scene changes
  State::replaceSpec(state_, std::move(spec));
  State& state = *state_;
  const LightId id{state.serial << 32 | LIGHT_HANDLE | state.nextLight++};
  state.addedLights.push_back({id, light});
  return id;
}

Light Scene::light(LightId light) const { return state_->addedLights[state_->position(light)].light; }

void Scene::setLight(LightId light, const Light& value) {
  setLightAt(state_->lightIndex(state_->position(light)), value);
}

void Scene::setLightAt(size_t index, const Light& value) {
  std::vector<Light> lights = lightsOf(*state_->spec);
  if (index >= lights.size()) {
    throw RangeError((path().empty() ? "" : path() + ": ") + "light " + std::to_string(index) +
                     " is out of range: the scene has " + std::to_string(lights.size()) + " lights");
  }
  lights[index] = value;
  State::replaceSpec(state_, withLights(*state_->spec, lights));
  State& state = *state_;
  const size_t own = lights.size() - state.addedLights.size();
  if (index >= own) state.addedLights[index - own].light = value;
}

void Scene::removeLight(LightId light) {
  const size_t i = state_->position(light);
  std::vector<Light> lights = lightsOf(*state_->spec);
  lights.erase(lights.begin() + ptrdiff_t(state_->lightIndex(i)));
  State::replaceSpec(state_, withLights(*state_->spec, lights));
  State& state = *state_;
  state.addedLights.erase(state.addedLights.begin() + ptrdiff_t(i));
}

namespace {

// The meshes of `spec` built as a renderer builds them, after the renderer's memory check (a frame of
// no pixels: nothing is rendered).
SceneData builtMeshes(const SceneSpec& spec) {
  checkSceneMemory(spec, 0);
  return buildSceneData(spec);
}

// What triangles() returns beside the built scene: positions and normals (3 floats each) a vertex,
// three int64 indices and an int32 object a triangle.
constexpr uint64_t RETURNED_BYTES_PER_VERTEX = 24;
constexpr uint64_t RETURNED_BYTES_PER_TRIANGLE = 28;

// Throws SceneError when the built scene `data` and the arrays triangles() makes of it need more
// than the memory limit, before they are made.
void checkTrianglesMemory(const SceneSpec& spec, const SceneData& data) {
  const uint64_t vertices = data.vertices.size(), triangles = data.triangles.size();
  checkMemory(spec.path, "Scene::triangles", triangles * (BYTES_PER_TRIANGLE + RETURNED_BYTES_PER_TRIANGLE) +
                                                 vertices * RETURNED_BYTES_PER_VERTEX,
              std::to_string(triangles) + " triangles and " + std::to_string(vertices) +
                  " vertices as built, and the arrays of them it returns",
              "simpler meshes fit");
}

}  // namespace

std::array<Vec3, 2> Scene::bounds() const {
  const SceneData data = builtMeshes(*state_->spec);
  return {Vec3{data.boundsMin.x, data.boundsMin.y, data.boundsMin.z}, Vec3{data.boundsMax.x, data.boundsMax.y, data.boundsMax.z}};
}

SceneTriangles Scene::triangles() const {
  const SceneData data = builtMeshes(*state_->spec);
  checkTrianglesMemory(*state_->spec, data);
  SceneTriangles out;
  out.mesh.positions.reserve(data.vertices.size() * 3);
  out.mesh.normals.reserve(data.vertices.size() * 3);
  for (const gpu::VertexIn& stored : data.vertices) {
    const gpu::VertexIn v = gpu::posedVertex(stored, data.objects[stored.object]);  // as the renderers turn it
    const glm::dvec3 world = data.objectOrigins[v.object] + glm::dvec3(v.position);
    out.mesh.positions.insert(out.mesh.positions.end(), {float(world.x), float(world.y), float(world.z)});
    out.mesh.normals.insert(out.mesh.normals.end(), {v.normal.x, v.normal.y, v.normal.z});
  }
  out.mesh.triangles.reserve(size_t(data.quadBase) * 3);
  out.objects.reserve(data.quadBase);
  for (uint32_t id = 0; id < data.triangles.size(); ++id) {
    const glm::uvec4& t = data.triangles[id];
    if (!isQuadRecord(data, id)) {
      out.mesh.triangles.insert(out.mesh.triangles.end(), {int64_t(t.x), int64_t(t.y), int64_t(t.z)});
      out.objects.push_back(int32_t(t.w));
    } else if (gpu::quadIsSecondHalf(t.z)) {
      continue;  // a quad's first half stands for it
    } else if (gpu::quadIsPoint(t.z)) {
      out.mesh.points.push_back(int64_t(t.x));
      out.pointObjects.push_back(int32_t(t.w));
    } else {
      out.mesh.lines.insert(out.mesh.lines.end(), {int64_t(t.x), int64_t(t.y)});
      out.lineObjects.push_back(int32_t(t.w));
    }
  }
  return out;
}

Camera Scene::camera() const { return cameraOf(*state_->spec); }

void Scene::setCamera(const Camera& camera) {
  State::replaceSpec(state_, withCamera(*state_->spec, camera));
}

std::vector<Light> Scene::lights() const { return lightsOf(*state_->spec); }

void Scene::setLights(const std::vector<Light>& lights) {
  State::replaceSpec(state_, withLights(*state_->spec, lights));
  state_->addedLights.clear();  // every light handle retired
}

Vec3 Scene::ambient() const { return ambientOf(*state_->spec); }

void Scene::setAmbient(const Vec3& ambient) {
  State::replaceSpec(state_, withAmbient(*state_->spec, ambient));
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
  if (!state_->addedLights.empty()) *spec = withLights(*spec, withAddedLights(*spec, state_->addedLights));
  return state_->with(std::move(spec));
}

namespace {

// A scene file or text as its sequence (one frame without an "animate" block) and frame 0.
Scene firstFrame(std::shared_ptr<const SceneSequence> sequence) {
  auto spec = std::make_shared<SceneSpec>(sequence->frame(0));
  return SceneAccess::make(std::move(spec), std::move(sequence));
}

}  // namespace

Scene loadScene(const std::string& path, const LoadOptions& options) {
  ModelView view;
  if (options.up != ModelUp::Usual) view.up = options.up == ModelUp::Y ? UpAxis::Y : UpAxis::Z;
  view.orthographic = options.orthographic;
  view.fileLights = options.fileLights;
  view.fileLightShadows = options.fileLightShadows;
  return firstFrame(std::make_shared<const SceneSequence>(SceneSequence::load(path, view)));
}

Scene parseScene(const std::string& json, const std::string& name, const std::string& baseDir, bool objectsLater) {
  return firstFrame(
      std::make_shared<const SceneSequence>(scenejson::parseJson(json, name), name, baseDir, objectsLater));
}

}  // namespace phongvk
