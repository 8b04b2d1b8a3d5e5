// mesh.h — triangle meshes for the scene's objects: primitives, convex hull, OBJ import,
// 1 -> 4 subdivision and vertex normals.
#pragma once

#include "scene/scene.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace phongvk {

// Positions are local to the object's origin (so far-away objects keep float precision);
// triangles wind counter-clockwise seen from outside (outward normal = cross(b - a, c - a)).
struct Mesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;    // unit length, one per position
  std::vector<glm::uvec3> triangles;
};

struct ObjectMesh {
  Mesh mesh;
  glm::dvec3 origin = {0, 0, 0};     // world position of the local frame's origin
  bool closed = true;                // back faces may be culled
};

// Builds the object's mesh: primitive or hull or OBJ, then `subdivide` levels, then normals.
// Throws SceneError (naming object.jsonPath) for input that cannot make a mesh.
ObjectMesh buildObjectMesh(const Object& object);

}  // namespace phongvk
