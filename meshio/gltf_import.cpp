// gltf_import.cpp — see gltf_import.h. tinygltf parses the JSON and loads the buffers; every
// accessor read here is checked against its buffer view and buffer first, so that a file whose
// offsets, strides or counts lie is an error, not a read out of bounds.
#include "meshio/gltf_import.h"

#include "base/number_text.h"
#include "base/regular_file.h"
#include "image/texture_decode.h"
#include "meshio/gltf_lights.h"
#include "meshio/mesh_import.h"
#include "phongvk/errors.h"

// The implementation is compiled here, with hidden visibility like the rest of phongvk, rather than
// taken from Debian's libtinygltf.so: tinygltf is a header-only library, and another build of its
// symbols in a process (libdraco exports one) would otherwise serve whichever library met it first.
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>

#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <cmath>
#include <map>
#include <cstring>
#include <filesystem>
#include <optional>

namespace phongvk {
namespace {

constexpr int kMaxNodeDepth = 256;  // deeper node trees are refused
// How far from 1 a rotation quaternion's length may be: exporters write 6 to 9 digits.
constexpr double kUnitTolerance = 1e-3;

[[noreturn]] void fail(const std::string& where, const std::string& path, const std::string& why) {
  throw SceneError(where + ": " + path + ": " + why);
}

// Whether a file tinygltf looks for is there, of whatever kind: readRegularFile then says what is
// wrong with one that is not a regular file (tinygltf would say "not found").
bool fileExists(const std::string& path, void*) {
  std::error_code error;
  return std::filesystem::exists(path, error);
}

// The file itself and any buffer it names: regular files only (regular_file.h), read whole.
bool readRegularFile(std::vector<unsigned char>* out, std::string* error, const std::string& path, void*) {
  std::string why;
  const std::optional<RegularFile> file = RegularFile::open(path, why);
  if (!file) {
    if (error) *error += "'" + path + "': " + why + "\n";
    return false;
  }
  const std::string bytes = file->read();
  out->assign(bytes.begin(), bytes.end());
  return true;
}

// A data URI's image kept encoded: only the base-colour textures a primitive uses are decoded
// (Reader::texture). An image in a buffer view is read from the buffer then, with its range checked
// (tinygltf passes a buffer view's bytes unchecked: a view past its buffer's end would be read out
// of bounds), and an image file beside the glTF is read then too.
bool keepEncoded(tinygltf::Image* image, const int, std::string*, std::string*, int, int, const unsigned char* bytes,
                 int size, void*) {
  if (image->bufferView < 0) image->image.assign(bytes, bytes + size);
  return true;
}

// A sampler's wrap mode (glTF's GL enums) as gpu::TEXTURE_WRAP_*.
uint32_t wrapMode(int gl) {
  if (gl == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE) return gpu::TEXTURE_WRAP_CLAMP;
  if (gl == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT) return gpu::TEXTURE_WRAP_MIRROR;
  return gpu::TEXTURE_WRAP_REPEAT;
}

// Reads accessor elements as doubles, bounds checked once up front.
class Accessor {
 public:
  Accessor(const tinygltf::Model& model, int index, const std::string& what, const std::string& path, const std::string& where) {
    const auto bad = [&](const std::string& why) { fail(where, path, what + " (accessor " + std::to_string(index) + "): " + why); };
    if (index < 0 || size_t(index) >= model.accessors.size()) bad("does not exist");
    const tinygltf::Accessor& a = model.accessors[size_t(index)];
    if (a.sparse.isSparse) bad("sparse accessors are not supported");
    if (a.bufferView < 0 || size_t(a.bufferView) >= model.bufferViews.size()) bad("has no buffer view");
    const tinygltf::BufferView& view = model.bufferViews[size_t(a.bufferView)];
    if (view.buffer < 0 || size_t(view.buffer) >= model.buffers.size()) bad("its buffer does not exist");
    const std::vector<unsigned char>& buffer = model.buffers[size_t(view.buffer)].data;
    components_ = tinygltf::GetNumComponentsInType(uint32_t(a.type));
    componentSize_ = tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType));
    if (components_ <= 0 || componentSize_ <= 0) bad("unknown type or component type");
    componentType_ = a.componentType;
    normalized_ = a.normalized;
    count_ = a.count;
    const size_t element = size_t(components_) * size_t(componentSize_);
    stride_ = view.byteStride != 0 ? view.byteStride : element;
    if (stride_ < element) bad("its stride is smaller than an element");
    // Every sum and product below is checked before it is made: offsets and counts near 2^64
    // would otherwise wrap around and pass.
    if (view.byteOffset > buffer.size() || view.byteLength > buffer.size() - view.byteOffset)
      bad("its buffer view runs past the end of its buffer");
    if (a.byteOffset > view.byteLength) bad("runs past the end of its buffer view");
    const size_t room = view.byteLength - a.byteOffset;  // bytes from the accessor's start to the view's end
    if (count_ > 0 && (element > room || count_ - 1 > (room - element) / stride_))
      bad("runs past the end of its buffer view (" + std::to_string(count_) + " elements)");
    const size_t start = view.byteOffset + a.byteOffset;
    data_ = buffer.data() + start;
  }

  size_t count() const { return count_; }
  int components() const { return components_; }

  double at(size_t i, int c) const {
    const unsigned char* p = data_ + i * stride_ + size_t(c) * size_t(componentSize_);
    switch (componentType_) {
      case TINYGLTF_COMPONENT_TYPE_FLOAT: return read<float>(p);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return scaled(read<uint8_t>(p), 255.0);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return scaled(read<uint16_t>(p), 65535.0);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return read<uint32_t>(p);
      case TINYGLTF_COMPONENT_TYPE_BYTE: return scaled(read<int8_t>(p), 127.0);
      case TINYGLTF_COMPONENT_TYPE_SHORT: return scaled(read<int16_t>(p), 32767.0);
      default: return NAN;
    }
  }

  bool isInteger() const { return componentType_ != TINYGLTF_COMPONENT_TYPE_FLOAT && componentType_ != TINYGLTF_COMPONENT_TYPE_DOUBLE; }
  bool isUnsignedInteger() const {
    return componentType_ == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE || componentType_ == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
           componentType_ == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
  }

 private:
  template <typename T>
  static double read(const unsigned char* p) {
    T value;
    std::memcpy(&value, p, sizeof value);
    return double(value);
  }
  double scaled(double value, double max) const { return normalized_ ? std::fmax(value / max, -1.0) : value; }

  const unsigned char* data_ = nullptr;
  size_t count_ = 0, stride_ = 0;
  int components_ = 0, componentSize_ = 0, componentType_ = 0;
  bool normalized_ = false;
};

// The node's transform: its matrix, or translation, rotation and scale. Arrays of another length
// and rotations that are not unit quaternions are errors (the specification's rules), not a guess.
glm::dmat4 nodeMatrix(const tinygltf::Node& node, const std::string& name, const std::string& path, const std::string& where) {
  const auto needs = [&](const std::vector<double>& values, size_t size, const char* key) {
    if (!values.empty() && values.size() != size)
      fail(where, path, name + "." + key + " has " + std::to_string(values.size()) + " numbers, not " + std::to_string(size));
  };
  needs(node.matrix, 16, "matrix");
  needs(node.translation, 3, "translation");
  needs(node.rotation, 4, "rotation");
  needs(node.scale, 3, "scale");
  if (node.rotation.size() == 4) {
    const double length = glm::length(glm::dvec4(node.rotation[0], node.rotation[1], node.rotation[2], node.rotation[3]));
    if (!(std::abs(length - 1.0) <= kUnitTolerance))
      fail(where, path, name + ".rotation is not a unit quaternion (its length is " + formatNumber(length) + ")");
  }
  if (node.matrix.size() == 16) return glm::make_mat4(node.matrix.data());  // column-major, as glm
  glm::dmat4 m(1.0);
  if (node.translation.size() == 3) m = glm::translate(m, glm::dvec3(node.translation[0], node.translation[1], node.translation[2]));
  if (node.rotation.size() == 4)
    m = m * glm::mat4_cast(glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]));
  if (node.scale.size() == 3) m = glm::scale(m, glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
  return m;
}

uint32_t channel(double c) { return uint32_t(std::lround(std::fmin(std::fmax(std::isnan(c) ? 0.0 : c, 0.0), 1.0) * 255.0)); }

class Reader {
 public:
  Reader(const tinygltf::Model& model, bool baseColors, const std::string& path, const std::string& where)
      : model_(model), baseColors_(baseColors), path_(path), where_(where) {}

  void node(int index, const glm::dmat4& parent, int depth) {
    const std::string name = "nodes[" + std::to_string(index) + "]";
    if (depth > kMaxNodeDepth) fail(where_, path_, "the node tree is deeper than " + std::to_string(kMaxNodeDepth));
    if (index < 0 || size_t(index) >= model_.nodes.size()) fail(where_, path_, "node " + std::to_string(index) + " does not exist");
    // The specification asks for a tree: a node reached twice (two parents, a cycle, or a root that
    // is also a child) would multiply the meshes below it, 2^40 times for 40 shared levels.
    if (visited_.empty()) visited_.assign(model_.nodes.size(), false);
    if (visited_[size_t(index)])
      fail(where_, path_, name + " is reached twice (nodes must form a tree: no node may have two parents or be its own ancestor)");
    visited_[size_t(index)] = true;
    const tinygltf::Node& n = model_.nodes[size_t(index)];
    const glm::dmat4 transform = parent * nodeMatrix(n, name, path_, where_);
    if (std::optional<MeshLight> light = gltfNodeLight(model_, n, name, transform, path_, where_)) lights_.push_back(*light);
    if (n.mesh >= 0) {
      if (size_t(n.mesh) >= model_.meshes.size()) fail(where_, path_, "node " + std::to_string(index) + " names a mesh that does not exist");
      for (const tinygltf::Primitive& p : model_.meshes[size_t(n.mesh)].primitives) primitive(p, transform);
    }
    for (int child : n.children) node(child, transform, depth + 1);
  }

  std::vector<MeshPart>& parts() { return parts_; }
  std::vector<MeshLight>& lights() { return lights_; }

 private:
  std::vector<uint32_t> indices(const tinygltf::Primitive& p, size_t vertices) const {
    std::vector<uint32_t> list;
    if (p.indices < 0) {
      for (size_t i = 0; i < vertices; ++i) list.push_back(uint32_t(i));
      return list;
    }
    const Accessor a(model_, p.indices, "indices", path_, where_);
    if (!a.isUnsignedInteger() || a.components() != 1)
      fail(where_, path_, "indices (accessor " + std::to_string(p.indices) + ") are not unsigned integers (5121, 5123 or 5125 scalars)");
    for (size_t i = 0; i < a.count(); ++i) {
      const double v = a.at(i, 0);
      if (!(v < double(vertices))) fail(where_, path_, "index " + std::to_string(i) + " is " + std::to_string(uint64_t(v)) + ", but there are " + std::to_string(vertices) + " vertices");
      list.push_back(uint32_t(v));
    }
    return list;
  }

  static std::vector<glm::uvec3> triangles(const std::vector<uint32_t>& i, int mode) {
    std::vector<glm::uvec3> t;
    if (mode == TINYGLTF_MODE_TRIANGLES)
      for (size_t k = 0; k + 2 < i.size(); k += 3) t.push_back({i[k], i[k + 1], i[k + 2]});
    if (mode == TINYGLTF_MODE_TRIANGLE_STRIP)
      for (size_t k = 0; k + 2 < i.size(); ++k) t.push_back(k % 2 ? glm::uvec3(i[k + 1], i[k], i[k + 2]) : glm::uvec3(i[k], i[k + 1], i[k + 2]));
    if (mode == TINYGLTF_MODE_TRIANGLE_FAN)
      for (size_t k = 1; k + 1 < i.size(); ++k) t.push_back({i[0], i[k], i[k + 1]});
    return t;
  }

  glm::dvec4 baseColor(const tinygltf::Primitive& p) const {
    if (!baseColors_ || p.material < 0 || size_t(p.material) >= model_.materials.size()) return glm::dvec4(1.0);
    const std::vector<double>& f = model_.materials[size_t(p.material)].pbrMetallicRoughness.baseColorFactor;
    return f.size() == 4 ? glm::dvec4(f[0], f[1], f[2], f[3]) : glm::dvec4(1.0);
  }

  void primitive(const tinygltf::Primitive& p, const glm::dmat4& transform) {
    const int mode = p.mode;
    if (mode < TINYGLTF_MODE_POINTS || mode > TINYGLTF_MODE_TRIANGLE_FAN)
      fail(where_, path_, "a primitive's mode is " + std::to_string(mode) + ", not a glTF primitive mode (0 to 6)");
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN) return;
    const auto position = p.attributes.find("POSITION");
    if (position == p.attributes.end()) fail(where_, path_, "a primitive has no POSITION");
    const Accessor positions(model_, position->second, "POSITION", path_, where_);
    if (positions.components() != 3 || positions.isInteger()) fail(where_, path_, "POSITION is not 3 floats a vertex");
    MeshPart part;
    for (size_t v = 0; v < positions.count(); ++v) {
      const glm::dvec3 world(transform * glm::dvec4(positions.at(v, 0), positions.at(v, 1), positions.at(v, 2), 1.0));
      for (int axis = 0; axis < 3; ++axis) {
        if (!(std::abs(world[axis]) <= MAX_COORDINATE))
          fail(where_, path_, "vertex " + std::to_string(v) + " is not finite or beyond the coordinates a scene may use");
      }
      part.positions.push_back(glm::vec3(world));
    }
    normals(p, transform, part);
    colors(p, part);
    texturing(p, part);
    part.triangles = triangles(indices(p, positions.count()), mode);
    parts_.push_back(std::move(part));
  }

  void normals(const tinygltf::Primitive& p, const glm::dmat4& transform, MeshPart& part) const {
    const auto normal = p.attributes.find("NORMAL");
    if (normal == p.attributes.end()) return;
    const Accessor a(model_, normal->second, "NORMAL", path_, where_);
    if (a.components() != 3 || a.count() != part.positions.size()) fail(where_, path_, "NORMAL is not one 3-vector a vertex");
    const glm::dmat3 m = glm::transpose(glm::inverse(glm::dmat3(transform)));
    for (size_t v = 0; v < a.count(); ++v) {
      const glm::dvec3 n = m * glm::dvec3(a.at(v, 0), a.at(v, 1), a.at(v, 2));
      const double length = glm::length(n);
      if (!std::isfinite(length) || length == 0.0) {  // unusable: the primitive is flat-shaded instead
        part.normals.clear();
        return;
      }
      part.normals.push_back(glm::vec3(n));
    }
  }

  void colors(const tinygltf::Primitive& p, MeshPart& part) const {
    const glm::dvec4 base = baseColor(p);
    const auto color = p.attributes.find("COLOR_0");
    std::optional<Accessor> a;
    if (color != p.attributes.end()) {
      a.emplace(model_, color->second, "COLOR_0", path_, where_);
      if ((a->components() != 3 && a->components() != 4) || a->count() != part.positions.size())
        fail(where_, path_, "COLOR_0 is not one RGB or RGBA colour a vertex");
    } else if (base == glm::dvec4(1.0)) {
      return;
    }
    for (size_t v = 0; v < part.positions.size(); ++v) {
      glm::dvec4 c = base;
      if (a) c *= glm::dvec4(a->at(v, 0), a->at(v, 1), a->at(v, 2), a->components() == 4 ? a->at(v, 3) : 1.0);
      part.colors.push_back(channel(c.x) | channel(c.y) << 8 | channel(c.z) << 16 | channel(c.w) << 24);
    }
  }

  // The primitive's base-colour texture and its texture coordinates (TEXCOORD_n as the texture
  // names), if its material has one.
  void texturing(const tinygltf::Primitive& p, MeshPart& part) {
    if (p.material < 0 || size_t(p.material) >= model_.materials.size()) return;
    noteIgnoredMaps(model_.materials[size_t(p.material)]);
    const tinygltf::TextureInfo& info = model_.materials[size_t(p.material)].pbrMetallicRoughness.baseColorTexture;
    if (info.index < 0) return;
    const std::string name = "TEXCOORD_" + std::to_string(info.texCoord);
    const auto coordinates = p.attributes.find(name);
    if (coordinates == p.attributes.end())
      fail(where_, path_, "materials[" + std::to_string(p.material) + "]'s base colour texture reads " + name + ", which a primitive lacks");
    const Accessor a(model_, coordinates->second, name, path_, where_);
    if (a.components() != 2 || a.count() != part.positions.size()) fail(where_, path_, name + " is not one 2-vector a vertex");
    for (size_t v = 0; v < a.count(); ++v) part.uvs.push_back(glm::vec2(float(a.at(v, 0)), float(a.at(v, 1))));
    part.texture = texture(info.index);
  }

  // The material's maps phongvk does not render, named once each for the notice.
  void noteIgnoredMaps(const tinygltf::Material& m) {
    const std::pair<int, const char*> maps[] = {{m.normalTexture.index, "normal"},
                                                {m.occlusionTexture.index, "occlusion"},
                                                {m.emissiveTexture.index, "emissive"},
                                                {m.pbrMetallicRoughness.metallicRoughnessTexture.index, "metallic-roughness"}};
    for (const auto& [index, name] : maps) {
      if (index >= 0 && std::find(ignoredMaps_.begin(), ignoredMaps_.end(), name) == ignoredMaps_.end()) ignoredMaps_.push_back(name);
    }
  }

 public:
  // The notice for the maps the file's primitives use that are not rendered (Mesh::notice).
  std::string notice() const { return ignoredMapsNotice(path_, ignoredMaps_); }

 private:
  // Texture `index` (its image decoded, its sampler's wrap modes), decoded once per file.
  std::shared_ptr<const TextureImage> texture(int index) {
    const std::string name = "textures[" + std::to_string(index) + "]";
    if (size_t(index) >= model_.textures.size()) fail(where_, path_, name + " does not exist");
    std::shared_ptr<const TextureImage>& decoded = textures_[index];
    if (decoded) return decoded;
    const tinygltf::Texture& t = model_.textures[size_t(index)];
    if (t.source < 0 || size_t(t.source) >= model_.images.size()) fail(where_, path_, name + " has no image");
    decoded = image(t.source);
    if (t.sampler >= 0 && size_t(t.sampler) < model_.samplers.size()) {
      const tinygltf::Sampler& sampler = model_.samplers[size_t(t.sampler)];
      decoded = withWrap(decoded, wrapMode(sampler.wrapS), wrapMode(sampler.wrapT));
    }
    return decoded;
  }

  // Image `index`, decoded once however many textures use it.
  std::shared_ptr<const TextureImage> image(int index) {
    std::shared_ptr<const TextureImage>& decoded = images_[index];
    if (!decoded) decoded = std::make_shared<const TextureImage>(decodedImage(index));
    return decoded;
  }

  // The bytes of buffer view `index`, checked against its buffer.
  std::string bufferViewBytes(int index, const std::string& what) const {
    if (size_t(index) >= model_.bufferViews.size()) throw SceneError(what + ": its buffer view does not exist");
    const tinygltf::BufferView& view = model_.bufferViews[size_t(index)];
    if (view.buffer < 0 || size_t(view.buffer) >= model_.buffers.size()) throw SceneError(what + ": its buffer does not exist");
    const std::vector<unsigned char>& buffer = model_.buffers[size_t(view.buffer)].data;
    if (view.byteOffset > buffer.size() || view.byteLength > buffer.size() - view.byteOffset)
      throw SceneError(what + ": its buffer view runs past the end of its buffer");
    return std::string(buffer.begin() + std::ptrdiff_t(view.byteOffset), buffer.begin() + std::ptrdiff_t(view.byteOffset + view.byteLength));
  }

  // Image `index`: in a buffer view, a data URI (kept encoded by keepEncoded), or a file beside the glTF.
  TextureImage decodedImage(int index) const {
    const tinygltf::Image& image = model_.images[size_t(index)];
    const std::string what = where_ + ": " + path_ + ": images[" + std::to_string(index) + "]";
    if (image.bufferView >= 0) return decodeTexture(bufferViewBytes(image.bufferView, what), what);
    if (!image.image.empty()) return decodeTexture(std::string(image.image.begin(), image.image.end()), what);
    if (image.uri.empty()) throw SceneError(what + ": no image data");
    // Decoded as tinygltf decodes the file's buffer URIs, so one file's URIs follow one rule.
    const std::string file = texturePathBeside(tinygltf::dlib::urldecode(image.uri), path_);
    return readTextureFile(file, what + " ('" + image.uri + "')");
  }

  const tinygltf::Model& model_;
  bool baseColors_;
  const std::string& path_;
  const std::string& where_;
  std::vector<MeshPart> parts_;
  std::vector<MeshLight> lights_;  // in the order the node tree reaches them
  std::vector<bool> visited_;  // nodes reached so far
  std::map<int, std::shared_ptr<const TextureImage>> textures_;  // by texture index, once decoded
  std::map<int, std::shared_ptr<const TextureImage>> images_;    // by image index, once decoded
  std::vector<std::string> ignoredMaps_;  // the kinds of map seen that are not rendered
};

// glTF 2.x (a later minor version is read as 2.0, as the specification allows), and no required
// extension: phongvk implements none, and a file that requires one (Draco compression, quantized
// positions) cannot be read right without it.
void checkAsset(const tinygltf::Model& model, const std::string& path, const std::string& where) {
  const std::string& version = model.asset.version;
  if (version.rfind("2.", 0) != 0)
    fail(where, path, "asset.version is '" + version + "'; phongvk reads glTF 2.0 files (convert a glTF 1.0 file to 2.0 first)");
  if (!model.extensionsRequired.empty()) {
    std::string names;
    for (const std::string& name : model.extensionsRequired) names += (names.empty() ? "" : ", ") + name;
    fail(where, path, "requires the extension" + std::string(model.extensionsRequired.size() > 1 ? "s " : " ") + names +
                          ", which phongvk does not implement");
  }
}

// Where a GLB's BIN chunk would end, past the file's own length: tinygltf checks the chunk's length
// against the file without the chunk's 8-byte header, so a chunk that claims up to 8 bytes more
// than the file holds would be copied out of bounds. Nothing when the file has no BIN chunk, or
// tinygltf's own checks refuse it first (too short, a JSON chunk past the end).
std::optional<uint64_t> binChunkOverrun(const std::vector<unsigned char>& bytes) {
  if (bytes.size() < 20) return std::nullopt;
  uint32_t length, jsonLength;
  std::memcpy(&length, bytes.data() + 8, 4);
  std::memcpy(&jsonLength, bytes.data() + 12, 4);
  const uint64_t binAt = 20ull + jsonLength;
  if (length > bytes.size() || binAt + 8 > length) return std::nullopt;
  uint32_t binLength;
  std::memcpy(&binLength, bytes.data() + binAt, 4);
  const uint64_t end = binAt + 8 + binLength;
  return end > length ? std::optional<uint64_t>(end) : std::nullopt;
}

// A GLB read once, refused where binChunkOverrun finds its BIN chunk past its end, then parsed as
// tinygltf's LoadBinaryFromFile parses it.
bool loadGlb(tinygltf::TinyGLTF& loader, tinygltf::Model& model, std::string& error, std::string& warning,
             const std::string& path, const std::string& where) {
  std::vector<unsigned char> bytes;
  if (!readRegularFile(&bytes, &error, path, nullptr)) return false;
  if (const std::optional<uint64_t> end = binChunkOverrun(bytes)) {
    uint32_t length;
    std::memcpy(&length, bytes.data() + 8, 4);
    fail(where, path, "not a valid GLB file: its BIN chunk would end at byte " + std::to_string(*end) +
                          ", past the file's length of " + std::to_string(length) + " bytes");
  }
  return loader.LoadBinaryFromMemory(&model, &error, &warning, bytes.data(), unsigned(bytes.size()),
                                     tinygltf::GetBaseDir(path));
}

}  // namespace

Mesh importGltf(const std::string& path, bool binary, bool baseColors, const std::string& where) {
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(keepEncoded, nullptr);
  loader.SetFsCallbacks({fileExists, tinygltf::ExpandFilePath, readRegularFile, tinygltf::WriteWholeFile, nullptr});
  tinygltf::Model model;
  std::string error, warning;
  const bool loaded = binary ? loadGlb(loader, model, error, warning, path, where)
                             : loader.LoadASCIIFromFile(&model, &error, &warning, path);
  if (!loaded) fail(where, path, std::string("not a valid ") + (binary ? "GLB" : "glTF") + " file: " + error.substr(0, error.find('\n')));
  checkAsset(model, path, where);
  if (model.scenes.empty()) fail(where, path, "no scene");
  const int sceneIndex = model.defaultScene >= 0 ? model.defaultScene : 0;
  if (size_t(sceneIndex) >= model.scenes.size()) fail(where, path, "the default scene does not exist");
  Reader reader(model, baseColors, path, where);
  for (int n : model.scenes[size_t(sceneIndex)].nodes) reader.node(n, glm::dmat4(1.0), 0);
  Mesh mesh = joinParts(reader.parts(), true, where + ": " + path);
  mesh.notice = reader.notice();
  mesh.lights = std::move(reader.lights());
  return mesh;
}

}  // namespace phongvk
