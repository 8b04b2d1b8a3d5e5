// object_pose.h — an object placed by a 4x4 pose (Scene::add, a scene file's "pose"): the checks
// every pose gets, and the object's origin and linear part from it. The mesh of such an object is
// built in its own coordinates and the pose's linear part is applied per vertex by both renderers
// (shaders/phong.h posedVertex), so moving it builds nothing again.
#pragma once

#include "phongvk/scene_parts.h"
#include "scene/scene.h"

#include <glm/glm.hpp>

#include <string>

namespace phongvk {

// Column `c` of the upper 3x3 block of a row-major 4x4 matrix.
glm::dvec3 matrixColumn(const Matrix4& m, int c);

// ArgumentError naming `what` for a matrix that is not affine: a value that is not finite, or a
// last row other than 0 0 0 1.
void checkAffine(const Matrix4& m, const std::string& what);

// Why `pose` cannot place an object, without the "pose: " a message leads with; "" when it can.
// Not an affine map (non-finite, last row not 0 0 0 1), a linear part with an entry beyond
// MAX_COORDINATE or not invertible or whose inverse has one, a translation beyond the coordinates
// a scene may use.
std::string poseProblem(const Matrix4& pose);

// `object` placed by `pose`: its origin the pose's translation, its linear part the pose's upper
// 3x3 block (Object::poseLinear), its own scale and rotation none. ArgumentError "pose: <the
// problem>" for a pose poseProblem refuses; `object` unchanged then.
void placeObject(Object& object, const Matrix4& pose);

// The pose `object` was placed by, as a row-major 4x4 matrix (its poseLinear and translate).
Matrix4 objectPose(const Object& object);

}  // namespace phongvk
