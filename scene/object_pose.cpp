// object_pose.cpp — see object_pose.h.
#include "scene/object_pose.h"

#include "base/number_text.h"

#include <cmath>

namespace phongvk {

glm::dvec3 matrixColumn(const Matrix4& m, int c) { return {m[c], m[4 + c], m[8 + c]}; }

void checkAffine(const Matrix4& m, const std::string& what) {
  for (size_t i = 0; i < m.size(); ++i) {
    if (!std::isfinite(m[i]))
      throw ArgumentError(what + ": row " + std::to_string(i / 4) + " is not finite: " + formatNumber(m[i]));
  }
  if (m[12] != 0 || m[13] != 0 || m[14] != 0 || m[15] != 1) {
    throw ArgumentError(what + ": the last row must be 0 0 0 1, got " + formatNumber(m[12]) + " " +
                        formatNumber(m[13]) + " " + formatNumber(m[14]) + " " + formatNumber(m[15]));
  }
}

void placeObject(Object& object, const Matrix4& pose) {
  checkAffine(pose, "pose");
  glm::dmat3 linear;
  for (int c = 0; c < 3; ++c) linear[c] = matrixColumn(pose, c);  // glm: linear[column][row]
  for (int i = 0; i < 9; ++i) {
    if (std::abs(pose[4 * (i / 3) + i % 3]) > MAX_COORDINATE)  // as a file's scale factors
      throw ArgumentError("pose: row " + std::to_string(i / 3) + " has " + formatNumber(pose[4 * (i / 3) + i % 3]) +
                          ", beyond the " + formatNumber(MAX_COORDINATE) + " a pose's linear part may hold");
  }
  if (!(std::abs(glm::determinant(linear)) > 0)) throw ArgumentError("pose: the upper 3x3 block is not invertible");
  const glm::dmat3 inverse = glm::inverse(linear);  // the normals' map: finite, or the block is all but singular
  for (int c = 0; c < 3; ++c) {
    for (int r = 0; r < 3; ++r) {
      if (!(std::abs(inverse[c][r]) <= MAX_COORDINATE))
        throw ArgumentError("pose: the upper 3x3 block is too close to singular (its inverse holds " +
                            formatNumber(inverse[c][r]) + ")");
    }
  }
  const glm::dvec3 translation = {pose[3], pose[7], pose[11]};
  for (int axis = 0; axis < 3; ++axis) {
    if (std::abs(translation[axis]) > MAX_COORDINATE)
      throw ArgumentError("pose: the translation " + formatNumber(translation[axis]) + " is beyond the " +
                          formatNumber(MAX_COORDINATE) + " m a scene may use");
  }
  object.poseLinear = linear;
  object.rotation = glm::dmat3(1.0);
  object.scale = {1, 1, 1};
  object.translate = translation;
}

Matrix4 objectPose(const Object& object) {
  const glm::dmat3 linear = object.poseLinear.value_or(glm::dmat3(1.0));
  Matrix4 m = IDENTITY_POSE;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) m[4 * r + c] = linear[c][r];
    m[4 * r + 3] = object.translate[r];
  }
  return m;
}

}  // namespace phongvk
