// triangle_mesh.cpp — see include/phongvk/mesh.h (TriangleMesh).
#include "phongvk/phongvk.h"

#include "api/scene_access.h"
#include "api/triangle_mesh_access.h"
#include "prepare/memory_estimate.h"
#include "scene/mesh_arrays.h"
#include "scene/model_scene.h"
#include "scene/object_mesh.h"

namespace phongvk {

TriangleMesh::TriangleMesh(const MeshArrays& arrays) : mesh_(std::make_shared<const Mesh>(meshFromArrays(arrays))) {}

TriangleMesh::TriangleMesh(std::shared_ptr<const Mesh> mesh) : mesh_(std::move(mesh)) {}

namespace {

// The mesh of a model scene's only object, built as a render builds it; a message names the
// file and its inner line as a model rendered alone does ("m.ply: line 7: ...").
Mesh buildModel(const SceneSpec& spec, const std::string& path) {
  checkSceneMemory(spec, 0);
  const Object& object = spec.objects.at(0);
  try {
    return buildObjectMesh(object).mesh;
  } catch (const SceneError& error) {
    std::string why = error.what();
    const std::string inner = object.jsonPath + ".file: " + object.file + ": ";
    if (why.rfind(inner, 0) == 0) why.erase(0, inner.size());
    throw SceneError(path + ": " + why);
  }
}

}  // namespace

TriangleMesh TriangleMesh::fromFile(const std::string& path, ModelUp up) {
  if (!isModelFile(path))
    throw ArgumentError("path: expected a mesh file (.obj, .ply, .stl, .gltf or .glb), got '" + path + "'");
  const Scene model = loadScene(path, LoadOptions{up});
  return TriangleMesh(std::make_shared<const Mesh>(buildModel(SceneAccess::spec(model), path)));
}

size_t TriangleMesh::vertexCount() const { return mesh_->positions.size(); }
size_t TriangleMesh::triangleCount() const { return mesh_->triangles.size(); }

const std::shared_ptr<const Mesh>& TriangleMeshAccess::mesh(const TriangleMesh& mesh) { return mesh.mesh_; }

}  // namespace phongvk
