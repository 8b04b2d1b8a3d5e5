// triangle_mesh.cpp — see include/phongvk/mesh.h (TriangleMesh).
#include "phongvk/phongvk.h"

#include "api/scene_access.h"
#include "api/triangle_mesh_access.h"
#include "prepare/memory_estimate.h"
#include "prepare/scene_data.h"
#include "scene/mesh_arrays.h"
#include "scene/model_scene.h"

namespace phongvk {

TriangleMesh::TriangleMesh(const MeshArrays& arrays) : mesh_(std::make_shared<const Mesh>(meshFromArrays(arrays))) {}

TriangleMesh::TriangleMesh(std::shared_ptr<const Mesh> mesh) : mesh_(std::move(mesh)) {}

TriangleMesh TriangleMesh::fromFile(const std::string& path, ModelUp up) {
  if (!isModelFile(path))
    throw ArgumentError("path: expected a mesh file (.obj, .ply, .stl, .gltf or .glb), got '" + path + "'");
  const Scene model = loadScene(path, LoadOptions{up});
  const SceneSpec& spec = SceneAccess::spec(model);
  checkSceneMemory(spec, 0);
  return TriangleMesh(std::make_shared<const Mesh>(buildSceneObject(spec, spec.objects.at(0)).mesh));
}

size_t TriangleMesh::vertexCount() const { return mesh_->positions.size(); }
size_t TriangleMesh::triangleCount() const { return mesh_->triangles.size(); }
size_t TriangleMesh::lineCount() const { return mesh_->lines.size(); }
size_t TriangleMesh::pointCount() const { return mesh_->points.size(); }

const std::shared_ptr<const Mesh>& TriangleMeshAccess::mesh(const TriangleMesh& mesh) { return mesh.mesh_; }

}  // namespace phongvk
