#include "scene/scene_json.h"

#include <algorithm>
#include <cfloat>
#include <charconv>
#include <cmath>

namespace phongvk::scenejson {
namespace {

// Line and column (both 1-based, columns in bytes) of the character at `offset`; an offset at
// the end of the text points just past its last character.
std::pair<size_t, size_t> lineAndColumn(const std::string& text, size_t offset) {
  offset = std::min(offset, text.size());
  size_t line = 1;
  size_t lineStart = 0;
  for (size_t i = 0; i < offset; ++i) {
    if (text[i] == '\n') {
      ++line;
      lineStart = i + 1;
    }
  }
  return {line, offset - lineStart + 1};
}

// nlohmann's message, e.g. "[json.exception.parse_error.101] parse error at line 2, column 11:
// syntax error while parsing value - invalid literal; last read: '"a": tru,'", cut down to the
// reason ("invalid literal"). Its position is replaced by ours and the echoed input is dropped
// (it may hold raw newlines).
std::string syntaxReason(const std::string& message) {
  size_t dash = message.find(" - ");
  std::string reason = dash == std::string::npos ? message : message.substr(dash + 3);
  size_t lastRead = reason.find("; last read: ");
  if (lastRead != std::string::npos) {
    size_t expected = reason.find("; expected", lastRead);
    reason.erase(lastRead, expected == std::string::npos ? std::string::npos : expected - lastRead);
  }
  return reason;
}

// Builds the tree as nlohmann's own parser does, but knows the JSON path of the value it is
// about to add, so a duplicate key or an overflowing number can be named by path.
class TreeBuilder : public nlohmann::json_sax<Json> {
 public:
  TreeBuilder(const std::string& text, const std::string& file) : text_(text), file_(file) {}
  Json take() { return std::move(root_); }

  bool null() override { return add(nullptr); }
  bool boolean(bool value) override { return add(value); }
  bool number_integer(number_integer_t value) override { return add(value); }
  bool number_unsigned(number_unsigned_t value) override { return add(value); }
  bool number_float(number_float_t value, const string_t&) override { return add(value); }
  bool string(string_t& value) override { return add(std::move(value)); }
  bool binary(binary_t& value) override { return add(std::move(value)); }
  bool start_object(std::size_t) override { return open(Json::object()); }
  bool start_array(std::size_t) override { return open(Json::array()); }
  bool end_object() override { return close(); }
  bool end_array() override { return close(); }

  bool key(string_t& key) override {
    if (containers_.back()->contains(key)) fail(childPath(paths_.back(), key), "duplicate key");
    key_ = key;
    return true;
  }

  bool parse_error(std::size_t position, const std::string& lastToken,
                   const nlohmann::detail::exception& error) override {
    // Error 406 is a number that overflows a double ("1e999"); nlohmann reports it here.
    if (error.id == 406) fail(nextPath(), "must be finite, got " + lastToken);
    // `position` counts the characters read, so the offending one is at position - 1.
    auto [line, column] = lineAndColumn(text_, position == 0 ? 0 : position - 1);
    throw SceneError(file_ + ": JSON syntax error at line " + std::to_string(line) + ", column " +
                     std::to_string(column) + ": " + syntaxReason(error.what()));
  }

 private:
  [[noreturn]] void fail(const std::string& path, const std::string& what) const {
    Node(root_, path, file_).fail(what);
  }

  std::string nextPath() const {
    if (containers_.empty()) return "";
    const Json& parent = *containers_.back();
    if (parent.is_array()) return paths_.back() + "[" + std::to_string(parent.size()) + "]";
    return childPath(paths_.back(), key_);
  }

  // Adds a value to the innermost open container (or as the root). A container's storage only
  // grows while it is innermost, so pointers to the outer ones stay valid.
  Json& insert(Json value) {
    if (containers_.empty()) return root_ = std::move(value);
    Json& parent = *containers_.back();
    if (parent.is_array()) return parent.emplace_back(std::move(value));
    return parent[key_] = std::move(value);
  }

  bool add(Json value) {
    insert(std::move(value));
    return true;
  }

  bool open(Json container) {
    std::string path = nextPath();
    if (containers_.size() >= MAX_JSON_DEPTH)
      fail(path, "nested deeper than " + std::to_string(MAX_JSON_DEPTH) + " levels of objects and arrays");
    containers_.push_back(&insert(std::move(container)));
    paths_.push_back(std::move(path));
    return true;
  }

  bool close() {
    containers_.pop_back();
    paths_.pop_back();
    return true;
  }

  const std::string& text_;
  const std::string& file_;
  Json root_;
  std::vector<Json*> containers_;   // open objects and arrays, innermost last
  std::vector<std::string> paths_;  // their JSON paths
  std::string key_;                 // the key of the next value in the innermost object
};

[[noreturn]] void failType(const Node& node, std::string_view expected) {
  node.fail("must be " + std::string(expected) + ", got " + node.json().type_name());
}

// A finite JSON number; `expected` names what the field wants, for the message.
double numberAs(const Node& node, std::string_view expected) {
  if (!node.json().is_number()) failType(node, expected);
  double value = node.json().get<double>();
  // The parser already rejects overflowing literals; this keeps the promise for any other Json.
  if (!std::isfinite(value)) node.fail("must be finite, got " + formatNumber(value));
  return value;
}

std::string joinKeys(const Keys& keys) {
  std::string text;
  for (std::string_view key : keys) text += (text.empty() ? "" : ", ") + std::string(key);
  return text;
}

bool contains(const Keys& keys, std::string_view key) {
  return std::find(keys.begin(), keys.end(), key) != keys.end();
}

}  // namespace

Json parseJson(const std::string& text, const std::string& file) {
  TreeBuilder builder(text, file);
  Json::sax_parse(text, &builder);  // errors throw from TreeBuilder::parse_error
  return builder.take();
}

Node::Node(const Json& value, std::string path, const std::string& file)
    : value_(&value), path_(std::move(path)), file_(&file) {}

Where Where::at(std::string_view key) const { return Where(childPath(path_, key), file_); }

Where Where::element(size_t index) const { return Where(path_ + "[" + std::to_string(index) + "]", file_); }

void Where::fail(const std::string& what) const {
  throw SceneError((file_.empty() ? "" : file_ + ": ") + (path_.empty() ? "top level" : path_) + ": " +
                   shortened(what, 1000));
}

void Node::fail(const std::string& what) const { where().fail(what); }

void Node::failAt(std::string_view key, const std::string& what) const { where().at(key).fail(what); }

std::optional<Node> Node::find(std::string_view key) const {
  auto it = value_->find(std::string(key));
  if (it == value_->end()) return std::nullopt;
  return Node(*it, childPath(path_, key), *file_);
}

Node Node::require(std::string_view key) const {
  if (auto node = find(key)) return *node;
  fail("missing required field '" + std::string(key) + "'");
}

Node Node::child(std::string_view key) const { return *find(key); }

Node Node::element(size_t index) const {
  return Node((*value_)[index], path_ + "[" + std::to_string(index) + "]", *file_);
}

std::string shortened(std::string_view text, size_t max) {
  if (text.size() <= max) return std::string(text);
  return std::string(text.substr(0, max - 3)) + "...";
}

std::string childPath(const std::string& parent, std::string_view key) {
  const std::string shown = shortened(key, 64);  // a megabyte key is not echoed whole
  return parent.empty() ? shown : parent + "." + shown;
}

void requireObject(const Node& node) {
  if (!node.json().is_object()) failType(node, "an object");
}

void requireArray(const Node& node) {
  if (!node.json().is_array()) failType(node, "an array");
}

void checkKeys(const Node& object, const Keys& allowed, const Keys& usedElsewhere,
               std::string_view whyNotHere) {
  for (const auto& [key, value] : object.json().items()) {
    if (contains(allowed, key)) continue;
    std::string why = contains(usedElsewhere, key) ? ", " + std::string(whyNotHere) : "";
    object.failAt(key, "unknown key" + why + " (allowed: " + joinKeys(allowed) + ")");
  }
}

double number(const Node& node) { return numberAs(node, "a number"); }

double atLeast(double value, double min, const Where& at) {
  if (value < min) at.fail("must be >= " + formatNumber(min) + ", got " + formatNumber(value));
  return value;
}

double positive(double value, const Where& at) {
  if (value <= 0) at.fail("must be > 0, got " + formatNumber(value));
  return value;
}

double inRange(double value, double min, double max, const Where& at) {
  if (value < min || value > max) {
    at.fail("must be between " + formatNumber(min) + " and " + formatNumber(max) + ", got " + formatNumber(value));
  }
  return value;
}

double inOpenRange(double value, double min, double max, const Where& at) {
  if (value <= min || value >= max) {
    at.fail("must be > " + formatNumber(min) + " and < " + formatNumber(max) + ", got " + formatNumber(value));
  }
  return value;
}

int integerInRange(int value, int min, int max, const Where& at) {
  if (value < min || value > max) {
    at.fail("must be between " + std::to_string(min) + " and " + std::to_string(max) + ", got " +
            std::to_string(value));
  }
  return value;
}

float toFloat(double value, const Where& at) {
  if (std::abs(value) > FLT_MAX) at.fail("too large for a 32-bit float, got " + formatNumber(value));
  return static_cast<float>(value);
}

glm::dvec3 checked3(const glm::dvec3& v, ValueCheck check, const Where& at) {
  return {check(v.x, at.element(0)), check(v.y, at.element(1)), check(v.z, at.element(2))};
}

double atLeast(const Node& node, double min) { return atLeast(number(node), min, node.where()); }
double positive(const Node& node) { return positive(number(node), node.where()); }
double inRange(const Node& node, double min, double max) { return inRange(number(node), min, max, node.where()); }
double inOpenRange(const Node& node, double min, double max) {
  return inOpenRange(number(node), min, max, node.where());
}

int integer(const Node& node, int min, int max) {
  double value = numberAs(node, "an integer");
  // 32.0 is accepted: JSON does not tell integers from reals, only the value matters.
  if (std::floor(value) != value) node.fail("must be an integer, got " + formatNumber(value));
  if (value < min || value > max) {
    node.fail("must be between " + std::to_string(min) + " and " + std::to_string(max) + ", got " +
              formatNumber(value));
  }
  return static_cast<int>(value);
}

float toFloat(const Node& node, double value) { return toFloat(value, node.where()); }

bool boolean(const Node& node) {
  if (!node.json().is_boolean()) failType(node, "true or false");
  return node.json().get<bool>();
}

std::string string(const Node& node) {
  if (!node.json().is_string()) failType(node, "a string");
  return node.json().get<std::string>();
}

glm::dvec3 vec3(const Node& node, ElementReader element) {
  if (!node.json().is_array()) failType(node, "an array of 3 numbers");
  if (node.json().size() != 3) {
    node.fail("must be an array of 3 numbers, got " + std::to_string(node.json().size()) +
              " elements");
  }
  return {element(node.element(0)), element(node.element(1)), element(node.element(2))};
}

}  // namespace phongvk::scenejson
