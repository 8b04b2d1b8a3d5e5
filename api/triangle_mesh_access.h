// triangle_mesh_access.h — the built mesh a TriangleMesh shares, for the library's own use
// (Scene::add hands the same mesh to every object that adds it).
#pragma once

#include "geometry/mesh.h"
#include "phongvk/mesh.h"

#include <memory>

namespace phongvk {

struct TriangleMeshAccess {
  static const std::shared_ptr<const Mesh>& mesh(const TriangleMesh& mesh);
};

}  // namespace phongvk
