// mesh.h — triangle meshes for the scene's objects: primitives, convex hull, mesh files,
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
  // One RGBA8 colour per position (red in the low byte) that multiplies the material's colour, or
  // none: white.
  std::vector<uint32_t> colors;
};

struct ObjectMesh {
  Mesh mesh;
  glm::dvec3 origin = {0, 0, 0};     // world position of the local frame's origin
  bool closed = true;                // back faces may be culled
};

// A primitive's triangle count before subdivision (64-bit: segments can be large); 0 for a
// polyhedron or a mesh, known once built.
uint64_t baseTriangles(const Object& object);

// Builds the object's mesh: primitive or hull or mesh file, then `subdivide` levels, then the
// object's transform (mesh_transform.h).
// Throws SceneError (naming object.jsonPath) for input that cannot make a mesh.
ObjectMesh buildObjectMesh(const Object& object);

}  // namespace phongvk
