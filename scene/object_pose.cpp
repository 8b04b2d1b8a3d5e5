// object_pose.cpp — see object_pose.h.
#include "scene/object_pose.h"

#include "base/number_text.h"

#include <cmath>

namespace phongvk {

glm::dvec3 matrixColumn(const Matrix4& m, int c) { return {m[c], m[4 + c], m[8 + c]}; }

namespace {

std::string affineProblem(const Matrix4& m) {
  for (size_t i = 0; i < m.size(); ++i) {
    if (!std::isfinite(m[i])) return "row " + std::to_string(i / 4) + " is not finite: " + formatNumber(m[i]);
  }
  if (m[12] != 0 || m[13] != 0 || m[14] != 0 || m[15] != 1) {
    return "the last row must be 0 0 0 1, got " + formatNumber(m[12]) + " " + formatNumber(m[13]) + " " +
           formatNumber(m[14]) + " " + formatNumber(m[15]);
  }
  return "";
}

glm::dmat3 linearPart(const Matrix4& pose) {
  glm::dmat3 linear;
  for (int c = 0; c < 3; ++c) linear[c] = matrixColumn(pose, c);  // glm: linear[column][row]
  return linear;
}

}  // namespace

void checkAffine(const Matrix4& m, const std::string& what) {
  if (const std::string problem = affineProblem(m); !problem.empty()) throw ArgumentError(what + ": " + problem);
}

std::string poseProblem(const Matrix4& pose) {
  if (std::string problem = affineProblem(pose); !problem.empty()) return problem;
  for (int i = 0; i < 9; ++i) {
    const double entry = pose[4 * (i / 3) + i % 3];
    if (std::abs(entry) > MAX_COORDINATE)  // as a file's scale factors
      return "row " + std::to_string(i / 3) + " has " + formatNumber(entry) + ", beyond the " +
             formatNumber(MAX_COORDINATE) + " a pose's linear part may hold";
  }
  const glm::dmat3 linear = linearPart(pose);
  if (!(std::abs(glm::determinant(linear)) > 0)) return "the upper 3x3 block is not invertible";
  const glm::dmat3 inverse = glm::inverse(linear);  // the normals' map: finite, or the block is all but singular
  for (int c = 0; c < 3; ++c) {
    for (int r = 0; r < 3; ++r) {
      if (!(std::abs(inverse[c][r]) <= MAX_COORDINATE))
        return "the upper 3x3 block is too close to singular (its inverse holds " + formatNumber(inverse[c][r]) + ")";
    }
  }
  for (int axis = 0; axis < 3; ++axis) {
    const double t = pose[4 * axis + 3];
    if (std::abs(t) > MAX_COORDINATE)
      return "the translation " + formatNumber(t) + " is beyond the " + formatNumber(MAX_COORDINATE) + " m a scene may use";
  }
  return "";
}

void placeObject(Object& object, const Matrix4& pose) {
  if (const std::string problem = poseProblem(pose); !problem.empty()) throw ArgumentError("pose: " + problem);
  object.poseLinear = linearPart(pose);
  object.rotation = glm::dmat3(1.0);
  object.scale = {1, 1, 1};
  object.translate = {pose[3], pose[7], pose[11]};
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
