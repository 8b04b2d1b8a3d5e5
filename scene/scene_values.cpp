// scene_values.cpp — the value readers the scene file's sections share (scene_sections.h).
#include "scene/scene_sections.h"

#include <cmath>

namespace phongvk::scenejson {

float nonNegativeFloat(double value, const Where& at) { return toFloat(atLeast(value, 0, at), at); }
double floatComponent(double value, const Where& at) { return toFloat(value, at); }
double nonNegativeComponent(double value, const Where& at) { return nonNegativeFloat(value, at); }
double unitComponent(double value, const Where& at) { return inRange(value, 0.0, 1.0, at); }
double coordinate(double value, const Where& at) { return inRange(value, -MAX_COORDINATE, MAX_COORDINATE, at); }

glm::vec3 color(const glm::dvec3& value, const Where& at) { return glm::vec3(checked3(value, nonNegativeComponent, at)); }
glm::vec3 unitColor(const glm::dvec3& value, const Where& at) { return glm::vec3(checked3(value, unitComponent, at)); }
glm::dvec3 point(const glm::dvec3& value, const Where& at) { return checked3(value, coordinate, at); }

float nonNegativeFloat(const Node& node) { return nonNegativeFloat(number(node), node.where()); }
double floatComponent(const Node& node) { return floatComponent(number(node), node.where()); }
double nonNegativeComponent(const Node& node) { return nonNegativeComponent(number(node), node.where()); }
double unitComponent(const Node& node) { return unitComponent(number(node), node.where()); }

glm::vec3 color(const Node& node) { return glm::vec3(vec3(node, nonNegativeComponent)); }
glm::vec3 unitColor(const Node& node) { return glm::vec3(vec3(node, unitComponent)); }

double coordinate(const Node& node) { return coordinate(number(node), node.where()); }
glm::dvec3 point(const Node& node) { return vec3(node, coordinate); }

double length(const Node& node) {
  double value = positive(node);
  if (value > MAX_COORDINATE) {
    node.fail("must be <= " + formatNumber(MAX_COORDINATE) + ", got " + formatNumber(value));
  }
  return value;
}

glm::dvec3 usableDirection(const glm::dvec3& direction, const Where& at) {
  double length = glm::length(direction);
  if (!std::isnormal(length)) at.fail("must have a non-zero finite length, got length " + formatNumber(length));
  return direction;
}

glm::dvec3 usableDirection(const Node& node, glm::dvec3 direction) { return usableDirection(direction, node.where()); }

}  // namespace phongvk::scenejson
