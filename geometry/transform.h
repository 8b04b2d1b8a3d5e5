// transform.h — a linear transform of a mesh about its origin (an object's is built by
// objectTransform, scene/object_mesh.h): positions mapped in double, normals by the inverse
// transpose, winding reversed by a mirroring transform so that front faces stay counter-clockwise
// seen from outside.
#pragma once

#include "geometry/mesh.h"

#include <string>

#include <glm/glm.hpp>

namespace phongvk {

struct LinearTransform {
  glm::dmat3 matrix{1.0};
  glm::dmat3 normalMatrix{1.0};  // inverse transpose of matrix
  bool identity = true;
  bool keepsDirections = true;   // a positive uniform scale (or none): normals stay as they are
  bool mirrors = false;          // det < 0: triangles are rewound
};

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
