// gltf_estimate.cpp — see gltf_import.h gltfTriangles: what a glTF file will build, read from its
// JSON before its buffers, so that the memory estimate (memory_estimate.h) sees a small .gltf with
// a large external buffer, or a mesh placed by many nodes, for what it is.
#include "meshio/gltf_import.h"

#include "base/regular_file.h"

#include <nlohmann/json.hpp>

#include <cstring>
#include <vector>

namespace phongvk {
namespace {

using Json = nlohmann::json;

constexpr uint64_t kSaturated = UINT64_MAX / 4;  // sums stop growing here (the estimate multiplies)

uint64_t saturatingAdd(uint64_t a, uint64_t b) { return a > kSaturated - std::min(b, kSaturated) ? kSaturated : a + b; }

// The triangle-array records of `quads` points or line segments: two each.
uint64_t quadRecords(uint64_t quads) { return saturatingAdd(quads, quads); }

// The JSON of a .gltf (the whole file) or of a .glb (its first chunk).
std::string jsonText(const RegularFile& file, bool binary) {
  if (!binary) return file.read();
  const std::string header = file.read(20);  // magic, version, length; the first chunk's length and type
  if (header.size() < 20 || header.compare(16, 4, "JSON") != 0) return "";
  uint32_t length;
  std::memcpy(&length, header.data() + 12, 4);
  const std::string head = file.read(20 + uint64_t(length));
  return head.size() > 20 ? head.substr(20) : "";
}

uint64_t unsignedAt(const Json& object, const char* key) {
  const auto it = object.find(key);
  return it != object.end() && it->is_number_unsigned() ? it->get<uint64_t>() : 0;
}

// An array element by index, or null.
const Json* element(const Json& root, const char* key, const Json& index) {
  const auto array = root.find(key);
  if (array == root.end() || !array->is_array() || !index.is_number_unsigned()) return nullptr;
  const uint64_t i = index.get<uint64_t>();
  return i < array->size() ? &(*array)[size_t(i)] : nullptr;
}

// The triangles a primitive makes, by its mode, from its indices' (or positions') count: a point or a
// line segment counts as two, the records of the triangle array its quad takes (screen_quads.h), as
// the built scene counts them (memory_estimate.h).
uint64_t primitiveTriangles(const Json& root, const Json& primitive) {
  const uint64_t mode = primitive.contains("mode") ? unsignedAt(primitive, "mode") : 4;
  const Json* accessor = nullptr;
  if (const auto indices = primitive.find("indices"); indices != primitive.end()) {
    accessor = element(root, "accessors", *indices);
  } else if (const auto attributes = primitive.find("attributes"); attributes != primitive.end() && attributes->is_object()) {
    if (const auto position = attributes->find("POSITION"); position != attributes->end())
      accessor = element(root, "accessors", *position);
  }
  const uint64_t count = accessor && accessor->is_object() ? unsignedAt(*accessor, "count") : 0;
  switch (mode) {
    case 0: return quadRecords(count);                          // points
    case 1: return quadRecords(count / 2);                      // lines
    case 2: return quadRecords(count > 2 ? count : count / 2);  // a line loop, closed from 3 vertices
    case 3: return quadRecords(count > 1 ? count - 1 : 0);      // a line strip
    case 4: return count / 3;
    case 5: case 6: return count > 2 ? count - 2 : 0;
    default: return 0;
  }
}

uint64_t meshTriangles(const Json& root, const Json& meshIndex) {
  const Json* mesh = element(root, "meshes", meshIndex);
  if (!mesh || !mesh->is_object()) return 0;
  const auto primitives = mesh->find("primitives");
  if (primitives == mesh->end() || !primitives->is_array()) return 0;
  uint64_t triangles = 0;
  for (const Json& p : *primitives)
    if (p.is_object()) triangles = saturatingAdd(triangles, primitiveTriangles(root, p));
  return triangles;
}

// The file's JSON, or null when it cannot be read or parsed.
Json rootOf(const std::string& path, bool binary) {
  std::string why;
  const std::optional<RegularFile> file = RegularFile::open(path, why);
  if (!file) return Json();
  const Json root = Json::parse(jsonText(*file, binary), nullptr, false);
  return root.is_object() ? root : Json();
}

}  // namespace

std::vector<std::string> gltfRequiredExtensions(const std::string& path, bool binary) {
  const Json root = rootOf(path, binary);
  std::vector<std::string> names;
  if (!root.is_object() || !root.contains("extensionsRequired") || !root["extensionsRequired"].is_array()) return names;
  for (const Json& name : root["extensionsRequired"])
    if (name.is_string()) names.push_back(name.get<std::string>());
  return names;
}

std::string gltfVersionOneSign(const std::string& path, bool binary) {
  if (binary) {
    std::string why;
    const std::optional<RegularFile> file = RegularFile::open(path, why);
    const std::string header = file ? file->read(8) : "";
    return header.size() == 8 && header.compare(0, 4, "glTF") == 0 && header.compare(4, 4, std::string("\x01\0\0\0", 4)) == 0
               ? "a GLB of version 1 (glTF 1.0's binary form)"
               : "";
  }
  const Json root = rootOf(path, binary);
  if (!root.is_object()) return "";
  for (const char* key : {"accessors", "bufferViews", "buffers", "meshes", "nodes", "materials"}) {
    if (root.contains(key) && root[key].is_object()) return "'" + std::string(key) + "' is an object of named entries (glTF 1.0's form)";
  }
  return "";
}

std::optional<uint64_t> gltfTriangles(const std::string& path, bool binary) {
  const Json root = rootOf(path, binary);
  if (!root.is_object()) return std::nullopt;
  const Json* scene = element(root, "scenes", root.contains("scene") ? root["scene"] : Json(uint64_t(0)));  // unsigned, as element asks
  if (!scene || !scene->is_object() || !scene->contains("nodes") || !(*scene)["nodes"].is_array()) return 0;
  // Each node once (the importer refuses a node reached twice), walked without recursion.
  std::vector<bool> seen(root.contains("nodes") && root["nodes"].is_array() ? root["nodes"].size() : 0, false);
  std::vector<const Json*> stack;
  for (const Json& n : (*scene)["nodes"]) stack.push_back(&n);
  uint64_t triangles = 0;
  while (!stack.empty()) {
    const Json& index = *stack.back();
    stack.pop_back();
    const Json* node = element(root, "nodes", index);
    if (!node || !node->is_object() || seen[size_t(index.get<uint64_t>())]) continue;
    seen[size_t(index.get<uint64_t>())] = true;
    if (const auto mesh = node->find("mesh"); mesh != node->end()) triangles = saturatingAdd(triangles, meshTriangles(root, *mesh));
    if (const auto children = node->find("children"); children != node->end() && children->is_array())
      for (const Json& child : *children) stack.push_back(&child);
  }
  return triangles;
}

}  // namespace phongvk
