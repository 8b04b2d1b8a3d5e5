// object_mesh.h — an object's mesh, built from what the scene says: a primitive, a convex hull
// or a mesh file (geometry/, meshio/), then its subdivision and its transform.
#pragma once

#include "geometry/mesh.h"
#include "geometry/transform.h"
#include "scene/scene.h"

#include <glm/glm.hpp>

#include <cstdint>

namespace phongvk {

struct ObjectMesh {
  Mesh mesh;
  glm::dvec3 origin = {0, 0, 0};     // world position of the local frame's origin
  bool closed = true;                // back faces may be culled
  // The lights its mesh file places (glTF KHR_lights_punctual) unless the object says
  // "file_lights": false: turned by the object's transform, about its origin as the mesh is.
  std::vector<MeshLight> lights;
};

// R·S·U: U turns a Y-up file upright (y -> z, z -> -y), S scales per axis (a negative factor
// mirrors), R is `rotation` (scene.h Object).
LinearTransform objectTransform(const Object& object);

// A primitive's triangle count before subdivision (64-bit: segments can be large); 0 for a
// polyhedron or a mesh, known once built.
uint64_t baseTriangles(const Object& object);

// Builds the object's mesh: primitive or hull or mesh file, then `subdivide` levels, then the
// object's transform (objectTransform).
// Throws SceneError (naming object.jsonPath) for input that cannot make a mesh.
ObjectMesh buildObjectMesh(const Object& object);

}  // namespace phongvk
