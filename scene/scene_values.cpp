// scene_values.cpp — the value readers the scene file's sections share (scene_sections.h).
#include "scene/scene_sections.h"

#include <cmath>

namespace phongvk::scenejson {

float nonNegativeFloat(const Node& node) { return toFloat(node, atLeast(node, 0)); }
double floatComponent(const Node& node) { return toFloat(node, number(node)); }
double nonNegativeComponent(const Node& node) { return nonNegativeFloat(node); }
double unitComponent(const Node& node) { return inRange(node, 0, 1); }

glm::vec3 color(const Node& node) { return glm::vec3(vec3(node, nonNegativeComponent)); }
glm::vec3 unitColor(const Node& node) { return glm::vec3(vec3(node, unitComponent)); }

double coordinate(const Node& node) { return inRange(node, -MAX_COORDINATE, MAX_COORDINATE); }
glm::dvec3 point(const Node& node) { return vec3(node, coordinate); }

double length(const Node& node) {
  double value = positive(node);
  if (value > MAX_COORDINATE) {
    node.fail("must be <= " + formatNumber(MAX_COORDINATE) + ", got " + formatNumber(value));
  }
  return value;
}

glm::dvec3 usableDirection(const Node& node, glm::dvec3 direction) {
  double length = glm::length(direction);
  if (!std::isnormal(length)) {
    node.fail("must have a non-zero finite length, got length " + formatNumber(length));
  }
  return direction;
}

}  // namespace phongvk::scenejson
