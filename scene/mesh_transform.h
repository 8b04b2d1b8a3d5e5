// mesh_transform.h — an object's linear transform (up axis, then scale, then rotation, about the
// object's origin; docs/DESIGN.md "Scene file") and what it does to a mesh: positions mapped in
// double, normals by the inverse transpose, winding reversed by a mirroring scale so that front
// faces stay counter-clockwise seen from outside.
#pragma once

#include "scene/mesh.h"
#include "scene/scene.h"

#include <glm/glm.hpp>

namespace phongvk {

struct LinearTransform {
  glm::dmat3 matrix{1.0};
  glm::dmat3 normalMatrix{1.0};  // inverse transpose of matrix
  bool identity = true;
  bool keepsDirections = true;   // a positive uniform scale (or none): normals stay as they are
  bool mirrors = false;          // det < 0: triangles are rewound
};

// R·S·U: U turns a Y-up file upright (y -> z, z -> -y), S scales per axis (a negative factor
// mirrors), R is `rotation` (scene.h Object).
LinearTransform objectTransform(const Object& object);

// The rotation for "rotate": [x, y, z] degrees about the world axes, x first, then y, then z.
glm::dmat3 rotationXYZ(glm::dvec3 degrees);
// The rotation by `degrees` about `axis` (non-zero), counter-clockwise looking down the axis.
glm::dmat3 rotationAxisAngle(glm::dvec3 axis, double degrees);

glm::dvec3 transformPoint(const LinearTransform& t, glm::vec3 p);
// A unit normal (normalised in double) from a normal of any non-zero length.
glm::vec3 transformNormal(const LinearTransform& t, glm::vec3 n);

// Applies `t` to the positions (and the winding) of a mesh; nothing for the identity. Throws
// SceneError "<where>: ..." when a position leaves the coordinates a scene may use.
void transformPositions(Mesh& mesh, const LinearTransform& t, const std::string& where);

// transformPositions, and the normals of a built mesh turned with them.
void transformMesh(Mesh& mesh, const LinearTransform& t, const std::string& where);

}  // namespace phongvk
