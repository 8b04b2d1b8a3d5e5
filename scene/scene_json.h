// scene_json.h — checked reading of JSON values for the scene loader. Every failure throws
// SceneError as "<file>: <json path>: <what is wrong>", e.g.
// "scenes/a.json: objects[2].material.ks: must be >= 0, got -1".
#pragma once

#include <array>
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "base/number_text.h"
#include "scene/scene.h"

namespace phongvk::scenejson {

// Ordered, so "materials" keeps its file order: named materials are indexed in that order.
using Json = nlohmann::ordered_json;
using Keys = std::vector<std::string_view>;

// Parses JSON text. A syntax error names its line and column; a number too large for a double
// and a duplicate key name their JSON path.
Json parseJson(const std::string& text, const std::string& file);

// Where a value sits: its JSON path and its file (none: empty). The checks of a scene's values
// take one, so a value read from a file and the same value given in code (scene_parts.h) fail
// with the same message: "<file>: <path>: <what is wrong>".
class Where {
 public:
  explicit Where(std::string path, std::string file = "") : path_(std::move(path)), file_(std::move(file)) {}
  const std::string& path() const { return path_; }
  Where at(std::string_view key) const;  // "camera" -> "camera.fov"
  Where element(size_t index) const;     // "camera.position" -> "camera.position[0]"
  [[noreturn]] void fail(const std::string& what) const;

 private:
  std::string path_;
  std::string file_;
};

// A JSON value together with where it sits, so every check can say where it failed.
class Node {
 public:
  Node(const Json& value, std::string path, const std::string& file);

  const Json& json() const { return *value_; }
  const std::string& path() const { return path_; }
  Where where() const { return Where(path_, *file_); }

  [[noreturn]] void fail(const std::string& what) const;
  // Fails at a member that may be absent, e.g. "camera.resolution" for an image size that
  // came from the default resolution.
  [[noreturn]] void failAt(std::string_view key, const std::string& what) const;

  // Members of an object (checked with requireObject first) and elements of an array.
  std::optional<Node> find(std::string_view key) const;
  Node require(std::string_view key) const;  // "missing required field 'key'"
  Node child(std::string_view key) const;    // precondition: the key exists
  Node element(size_t index) const;

 private:
  const Json* value_;
  std::string path_;
  const std::string* file_;
};

// "objects[2]" + "material" -> "objects[2].material"; the top level has the empty path.
std::string childPath(const std::string& parent, std::string_view key);

// `text`, or its first max - 3 characters and "..." where it is longer: values echoed in messages
// stay short whatever a file holds.
std::string shortened(std::string_view text, size_t max);

void requireObject(const Node& node);
void requireArray(const Node& node);

// Rejects keys outside `allowed`, listing the allowed ones. A key in `usedElsewhere` also gets
// `whyNotHere` ("not used by shape 'cube'"), so the reader learns it is valid, just not here.
void checkKeys(const Node& object, const Keys& allowed, const Keys& usedElsewhere = {},
               std::string_view whyNotHere = {});

// The checks of a number wherever it came from, failing at `at` (the Node forms below read a JSON
// number first and check it with these).
double atLeast(double value, double min, const Where& at);                  // >= min
double positive(double value, const Where& at);                             // > 0
double inRange(double value, double min, double max, const Where& at);      // min <= x <= max
double inOpenRange(double value, double min, double max, const Where& at);  // min < x < max
int integerInRange(int value, int min, int max, const Where& at);
float toFloat(double value, const Where& at);
// Each of v's three elements checked by `check` at at[i].
using ValueCheck = double (*)(double, const Where&);
glm::dvec3 checked3(const glm::dvec3& v, ValueCheck check, const Where& at);

// Numbers: JSON numbers only (no bools, no strings), always finite.
double number(const Node& node);
double atLeast(const Node& node, double min);                  // >= min
double positive(const Node& node);                             // > 0
double inRange(const Node& node, double min, double max);      // min <= x <= max
double inOpenRange(const Node& node, double min, double max);  // min < x < max
int integer(const Node& node, int min, int max);               // integral value in min..max
// Narrows a checked value to float, rejecting magnitudes a float cannot hold (they would
// become inf, and inf times a zero term is NaN downstream).
float toFloat(const Node& node, double value);

bool boolean(const Node& node);
std::string string(const Node& node);

// The value of an enumerated option: the index of `value` among `names` (joined for the message
// when it is none of them).
template <typename E, size_t N>
E choice(const std::string& value, const std::array<const char*, N>& names, const Where& at) {
  std::string list;
  for (size_t i = 0; i < N; ++i) {
    if (value == names[i]) return E(i);
    list += (i ? ", " : "") + std::string(names[i]);
  }
  at.fail("must be one of " + list + ", got '" + value + "'");
}
template <typename E, size_t N>
E choice(const Node& node, const std::array<const char*, N>& names) {
  return choice<E>(string(node), names, node.where());
}
// An enumerated option given in code: one of `names`' choices, else the file's message for a name
// that is none of them ("").
template <typename E, size_t N>
E choice(E value, const std::array<const char*, N>& names, const Where& at) {
  return choice<E>(size_t(value) < N ? std::string(names[size_t(value)]) : std::string(), names, at);
}

// An array of exactly 3 numbers, each read (and range checked) by `element`.
using ElementReader = double (*)(const Node&);
glm::dvec3 vec3(const Node& node, ElementReader element = number);

}  // namespace phongvk::scenejson
