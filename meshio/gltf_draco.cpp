// gltf_draco.cpp — see gltf_draco.h. Draco checks its own bitstream; what it hands back (attribute
// value indices, face indices) is checked here again before it is read.
#include "meshio/gltf_draco.h"

#include "phongvk/errors.h"

#include <draco/compression/decode.h>
#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <cmath>
#include <cstring>
#include <new>

namespace phongvk {
namespace {

constexpr const char* kExtension = "KHR_draco_mesh_compression";

// Throws SceneError "<where>: <path>: <primitive>: KHR_draco_mesh_compression: <why>".
struct Failure {
  std::string prefix;
  [[noreturn]] void operator()(const std::string& why) const { throw SceneError(prefix + why); }
};

// A non-negative whole number in the extension's JSON, or -1.
int64_t wholeNumber(const tinygltf::Value& value) {
  if (!value.IsNumber()) return -1;
  const double number = value.GetNumberAsDouble();
  return number >= 0 && number <= double(INT32_MAX) && number == std::floor(number) ? int64_t(number) : -1;
}

// The compressed bytes: the extension's buffer view, checked against its buffer.
draco::DecoderBuffer compressedBytes(const tinygltf::Model& model, const tinygltf::Value& extension, const Failure& fail) {
  const int64_t index = wholeNumber(extension.Get("bufferView"));
  if (index < 0) fail("bufferView is not a buffer view's index");
  if (size_t(index) >= model.bufferViews.size()) fail("bufferView " + std::to_string(index) + " does not exist");
  const tinygltf::BufferView& view = model.bufferViews[size_t(index)];
  if (view.buffer < 0 || size_t(view.buffer) >= model.buffers.size())
    fail("bufferViews[" + std::to_string(index) + "]'s buffer does not exist");
  const std::vector<unsigned char>& buffer = model.buffers[size_t(view.buffer)].data;
  if (view.byteOffset > buffer.size() || view.byteLength > buffer.size() - view.byteOffset)
    fail("bufferViews[" + std::to_string(index) + "] runs past the end of its buffer");
  draco::DecoderBuffer bytes;
  bytes.Init(reinterpret_cast<const char*>(buffer.data() + view.byteOffset), view.byteLength);
  return bytes;
}

// The attributes importGltf reads; the others (JOINTS_0, TANGENT, ...) are not decoded.
bool readsAttribute(const std::string& name) {
  return name == "POSITION" || name == "NORMAL" || name == "COLOR_0" || name.rfind("TEXCOORD_", 0) == 0;
}

// The largest value of a normalized integer accessor's component type (its values are fractions of
// it), or 0 where the values are read as they are.
double normalizedMax(const tinygltf::Accessor& accessor) {
  if (!accessor.normalized) return 0;
  switch (accessor.componentType) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 255.0;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 65535.0;
    case TINYGLTF_COMPONENT_TYPE_BYTE: return 127.0;
    case TINYGLTF_COMPONENT_TYPE_SHORT: return 32767.0;
    default: return 0;
  }
}

// One attribute's value at every point, as its accessor means it.
DracoPrimitive::Attribute decodeAttribute(const draco::Mesh& mesh, const draco::PointAttribute& attribute,
                                          const tinygltf::Accessor& accessor, const std::string& name, const Failure& fail) {
  DracoPrimitive::Attribute decoded;
  decoded.components = attribute.num_components();
  if (decoded.components < 1 || decoded.components > 4) fail(name + " has " + std::to_string(decoded.components) + " components");
  if (decoded.components != tinygltf::GetNumComponentsInType(uint32_t(accessor.type)))
    fail(name + " decodes to " + std::to_string(decoded.components) + " components a vertex, but its accessor's type says " +
         std::to_string(tinygltf::GetNumComponentsInType(uint32_t(accessor.type))));
  // Draco scales a normalized attribute itself; one stored as plain integers is scaled as the accessor says.
  const double max = attribute.normalized() ? 0.0 : normalizedMax(accessor);
  decoded.values.resize(size_t(mesh.num_points()) * size_t(decoded.components));
  float value[4];
  for (draco::PointIndex p(0); p < mesh.num_points(); ++p) {
    const draco::AttributeValueIndex at = attribute.mapped_index(p);
    if (at.value() >= attribute.size() || !attribute.ConvertValue<float>(at, int8_t(decoded.components), value))
      fail(name + ": vertex " + std::to_string(p.value()) + " cannot be decoded");
    for (int c = 0; c < decoded.components; ++c)
      decoded.values[size_t(p.value()) * size_t(decoded.components) + size_t(c)] =
          max > 0 ? float(std::fmax(double(value[c]) / max, -1.0)) : value[c];
  }
  return decoded;
}

// The mesh's triangles as indices, each checked against its points.
std::vector<uint32_t> decodeIndices(const draco::Mesh& mesh, const Failure& fail) {
  std::vector<uint32_t> indices;
  indices.reserve(size_t(mesh.num_faces()) * 3);
  for (draco::FaceIndex f(0); f < mesh.num_faces(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const uint32_t index = mesh.face(f)[k].value();
      if (index >= mesh.num_points())
        fail("triangle " + std::to_string(f.value()) + " has vertex index " + std::to_string(index) + ", but there are " +
             std::to_string(mesh.num_points()) + " vertices");
      indices.push_back(index);
    }
  }
  return indices;
}

std::unique_ptr<draco::Mesh> decodeMesh(draco::DecoderBuffer& bytes, const Failure& fail) {
  draco::Decoder decoder;
  try {
    draco::StatusOr<std::unique_ptr<draco::Mesh>> decoded = decoder.DecodeMeshFromBuffer(&bytes);
    if (!decoded.ok() || !decoded.value())
      fail("the compressed data cannot be decoded (Draco: " + decoded.status().error_msg_string() + ")");
    return std::move(decoded).value();
  } catch (const std::bad_alloc&) {  // counts in damaged data can ask for more than there is
    fail("the compressed data cannot be decoded (it asks for more memory than there is)");
  }
}

// The accessor attribute `name` of the primitive names; the extension may name only those.
const tinygltf::Accessor& accessorOf(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                                     const std::string& name, const Failure& fail) {
  const auto it = primitive.attributes.find(name);
  if (it == primitive.attributes.end()) fail("names " + name + ", which the primitive's attributes lack");
  if (it->second < 0 || size_t(it->second) >= model.accessors.size())
    fail(name + "'s accessor " + std::to_string(it->second) + " does not exist");
  return model.accessors[size_t(it->second)];
}

// The attributes the extension names that importGltf reads, decoded, each as many as the points.
void decodeAttributes(const tinygltf::Model& model, const tinygltf::Primitive& primitive, const tinygltf::Value& extension,
                      const draco::Mesh& mesh, DracoPrimitive& decoded, const Failure& fail) {
  const tinygltf::Value& attributes = extension.Get("attributes");
  if (!attributes.IsObject()) fail("attributes is not an object");
  for (const std::string& name : attributes.Keys()) {
    if (!readsAttribute(name)) continue;
    const tinygltf::Accessor& accessor = accessorOf(model, primitive, name, fail);
    const int64_t id = wholeNumber(attributes.Get(name));
    if (id < 0) fail(name + "'s attribute id is not a whole number");
    const draco::PointAttribute* attribute = mesh.GetAttributeByUniqueId(uint32_t(id));
    if (!attribute) fail(name + "'s attribute id " + std::to_string(id) + " is not in the compressed data");
    if (accessor.count != mesh.num_points())
      fail(name + " decodes to " + std::to_string(mesh.num_points()) + " vertices, but its accessor says " + std::to_string(accessor.count));
    decoded.attributes[name] = decodeAttribute(mesh, *attribute, accessor, name, fail);
  }
}

using Json = nlohmann::json;

// Gives each compressed primitive's indices accessor without a buffer view the compressed data's
// (giveCompressedIndicesViews); whether it gave any.
bool giveIndicesViews(Json& root) {
  const auto meshes = root.find("meshes");
  const auto accessors = root.find("accessors");
  const auto views = root.find("bufferViews");
  if (meshes == root.end() || !meshes->is_array() || accessors == root.end() || !accessors->is_array() || views == root.end() ||
      !views->is_array() || views->empty())
    return false;
  bool given = false;
  for (const Json& mesh : *meshes) {
    if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array()) continue;
    for (const Json& primitive : mesh["primitives"]) {
      if (!primitive.is_object() || !primitive.contains("indices") || !primitive["indices"].is_number_unsigned()) continue;
      const Json* extension = primitive.contains("extensions") && primitive["extensions"].is_object()
                                  ? &primitive["extensions"] : nullptr;
      if (!extension || !extension->contains(kExtension) || !(*extension)[kExtension].is_object()) continue;
      // The compressed data's view, or where that does not exist the first (decodeDracoPrimitive says so).
      const Json& named = (*extension)[kExtension].value("bufferView", Json());
      const Json view = named.is_number_unsigned() && named.get<uint64_t>() < views->size() ? named : Json(0);
      const uint64_t index = primitive["indices"].get<uint64_t>();
      if (index >= accessors->size()) continue;
      Json& accessor = (*accessors)[size_t(index)];
      if (!accessor.is_object() || accessor.contains("bufferView")) continue;
      accessor["bufferView"] = view;
      given = true;
    }
  }
  return given;
}

uint32_t readU32(const std::vector<unsigned char>& bytes, size_t at) {
  uint32_t value;
  std::memcpy(&value, bytes.data() + at, 4);
  return value;
}

void writeU32(std::vector<unsigned char>& bytes, size_t at, uint32_t value) { std::memcpy(bytes.data() + at, &value, 4); }

// The GLB with its JSON chunk replaced by `json` (padded with spaces to 4 bytes, as the format
// asks), its length and the file's changed to match.
void replaceJsonChunk(std::vector<unsigned char>& glb, std::string json) {
  json.resize((json.size() + 3) / 4 * 4, ' ');
  const uint32_t oldLength = readU32(glb, 12);
  const int64_t growth = int64_t(json.size()) - int64_t(oldLength);
  if (int64_t(readU32(glb, 8)) + growth > int64_t(UINT32_MAX)) return;  // beyond what a GLB can say: left to tinygltf
  std::vector<unsigned char> rebuilt(glb.begin(), glb.begin() + 20);
  rebuilt.insert(rebuilt.end(), json.begin(), json.end());
  rebuilt.insert(rebuilt.end(), glb.begin() + 20 + std::ptrdiff_t(oldLength), glb.end());
  writeU32(rebuilt, 8, uint32_t(int64_t(readU32(glb, 8)) + growth));
  writeU32(rebuilt, 12, uint32_t(json.size()));
  glb = std::move(rebuilt);
}

}  // namespace

void giveCompressedIndicesViews(std::vector<unsigned char>& file, bool binary) {
  size_t begin = 0, end = file.size();
  if (binary) {  // the JSON chunk: its length at byte 12, its type at 16, its text from 20
    if (file.size() < 20 || std::memcmp(file.data() + 16, "JSON", 4) != 0 || readU32(file, 12) > file.size() - 20) return;
    begin = 20;
    end = 20 + readU32(file, 12);
  }
  const std::string_view text(reinterpret_cast<const char*>(file.data()) + begin, end - begin);
  if (text.find(kExtension) == std::string_view::npos) return;  // the common case: no JSON parsed twice
  Json root = Json::parse(text, nullptr, false);
  if (!root.is_object() || !giveIndicesViews(root)) return;
  const std::string json = root.dump(-1, ' ', false, Json::error_handler_t::replace);
  if (binary) {
    replaceJsonChunk(file, json);
  } else {
    file.assign(json.begin(), json.end());
  }
}

std::optional<DracoPrimitive> decodeDracoPrimitive(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                                                   const std::string& name, const std::string& path, const std::string& where) {
  const auto found = primitive.extensions.find(kExtension);
  if (found == primitive.extensions.end()) return std::nullopt;
  const Failure fail{where + ": " + path + ": " + name + ": " + kExtension + ": "};
  const tinygltf::Value& extension = found->second;
  if (!extension.IsObject()) fail("not an object");
  if (primitive.mode != TINYGLTF_MODE_TRIANGLES && primitive.mode != TINYGLTF_MODE_TRIANGLE_STRIP)
    fail("the primitive's mode is " + std::to_string(primitive.mode) + "; compressed primitives are triangles (4) or a triangle strip (5)");
  draco::DecoderBuffer bytes = compressedBytes(model, extension, fail);
  const std::unique_ptr<draco::Mesh> mesh = decodeMesh(bytes, fail);
  DracoPrimitive decoded;
  decoded.vertices = mesh->num_points();
  decodeAttributes(model, primitive, extension, *mesh, decoded, fail);
  decoded.indices = decodeIndices(*mesh, fail);
  if (primitive.indices >= 0 && size_t(primitive.indices) < model.accessors.size() &&
      model.accessors[size_t(primitive.indices)].count != decoded.indices.size())
    fail("the triangles decode to " + std::to_string(decoded.indices.size()) + " indices, but the indices accessor says " +
         std::to_string(model.accessors[size_t(primitive.indices)].count));
  return decoded;
}

}  // namespace phongvk
