// gltf_import.cpp — see gltf_import.h. tinygltf parses the JSON and loads the buffers; every
// accessor read here is checked against its buffer view and buffer first (gltf_accessor.h), so
// that a file whose offsets, strides or counts lie is an error, not a read out of bounds.
#include "meshio/gltf_import.h"

#include "base/number_text.h"
#include "base/regular_file.h"
#include "image/texture_decode.h"
#include "meshio/gltf_accessor.h"
#include "meshio/gltf_draco.h"
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
      const std::vector<tinygltf::Primitive>& primitives = model_.meshes[size_t(n.mesh)].primitives;
      if (primitives.empty() && emptyMesh_.empty()) emptyMesh_ = "meshes[" + std::to_string(n.mesh) + "]";
      for (size_t p = 0; p < primitives.size(); ++p)
        primitive(primitives[p], transform, "meshes[" + std::to_string(n.mesh) + "].primitives[" + std::to_string(p) + "]");
    }
    for (int child : n.children) node(child, transform, depth + 1);
  }

  std::vector<MeshPart>& parts() { return parts_; }
  // The first mesh the nodes reach that has no primitives ("meshes[0]"; tinygltf leaves a
  // "primitives" that is not a list empty), or "": why a file that draws nothing does not.
  const std::string& emptyMesh() const { return emptyMesh_; }
  std::vector<MeshLight>& lights() { return lights_; }

 private:
  // Attribute `name` of the primitive: decoded where its Draco compression holds it, otherwise read
  // from its accessor; nothing when the primitive has none.
  std::optional<Accessor> attribute(const tinygltf::Primitive& p, const std::string& name) const {
    if (draco_) {
      const auto decoded = draco_->attributes.find(name);
      if (decoded != draco_->attributes.end())
        return Accessor(decoded->second.values.data(), draco_->vertices, decoded->second.components, GLTF_FLOAT);
    }
    const auto found = p.attributes.find(name);
    if (found == p.attributes.end()) return std::nullopt;
    return Accessor(model_, found->second, name, path_, where_);
  }

  std::vector<uint32_t> indices(const tinygltf::Primitive& p, size_t vertices) const {
    std::vector<uint32_t> list;
    if (p.indices < 0 && !draco_) {
      for (size_t i = 0; i < vertices; ++i) list.push_back(uint32_t(i));
      return list;
    }
    const Accessor a = draco_ ? Accessor(draco_->indices.data(), draco_->indices.size(), 1, GLTF_UNSIGNED_INT)
                              : Accessor(model_, p.indices, "indices", path_, where_);
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

  // The indices as what `mode` draws: points; lines (a strip's and a loop's segments, a loop of
  // three vertices or more closed by its last); triangles (strips and fans unrolled).
  static void addElements(std::vector<uint32_t> i, int mode, MeshPart& part) {
    const size_t n = i.size();
    if (mode == TINYGLTF_MODE_POINTS) part.points = std::move(i);
    if (mode == TINYGLTF_MODE_LINE)
      for (size_t k = 0; k + 1 < n; k += 2) part.lines.push_back({i[k], i[k + 1]});
    if (mode == TINYGLTF_MODE_LINE_STRIP || mode == TINYGLTF_MODE_LINE_LOOP)
      for (size_t k = 0; k + 1 < n; ++k) part.lines.push_back({i[k], i[k + 1]});
    if (mode == TINYGLTF_MODE_LINE_LOOP && n > 2) part.lines.push_back({i[n - 1], i[0]});
    if (mode >= TINYGLTF_MODE_TRIANGLES) part.triangles = triangles(i, mode);
  }

  glm::dvec4 baseColor(const tinygltf::Primitive& p) const {
    if (!baseColors_ || p.material < 0 || size_t(p.material) >= model_.materials.size()) return glm::dvec4(1.0);
    const std::vector<double>& f = model_.materials[size_t(p.material)].pbrMetallicRoughness.baseColorFactor;
    return f.size() == 4 ? glm::dvec4(f[0], f[1], f[2], f[3]) : glm::dvec4(1.0);
  }

  // Primitive `p` (named `name`, "meshes[0].primitives[1]") as a part: its vertices placed by
  // `transform`. Compressed (KHR_draco_mesh_compression), its decoded triangles (Draco's faces,
  // whether the mode says triangles or a strip) and attributes.
  void primitive(const tinygltf::Primitive& p, const glm::dmat4& transform, const std::string& name) {
    const int mode = p.mode;
    if (mode < TINYGLTF_MODE_POINTS || mode > TINYGLTF_MODE_TRIANGLE_FAN)
      fail(where_, path_, "a primitive's mode is " + std::to_string(mode) + ", not a glTF primitive mode (0 to 6)");
    draco_ = decodeDracoPrimitive(model_, p, name, path_, where_);
    const std::optional<Accessor> found = attribute(p, "POSITION");
    if (!found) fail(where_, path_, "a primitive has no POSITION");
    const Accessor& positions = *found;
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
    const bool drawsTriangles = mode >= TINYGLTF_MODE_TRIANGLES;
    normals(p, transform, drawsTriangles, part);
    colors(p, part);
    texturing(p, part);
    addElements(indices(p, positions.count()), draco_ ? TINYGLTF_MODE_TRIANGLES : mode, part);
    draco_.reset();
    parts_.push_back(std::move(part));
  }

  // The primitive's normals, turned by `transform`'s inverse transpose. On triangles, one of zero
  // length makes them unusable (the primitive is flat-shaded instead); on points and lines it is
  // (0, 0, 0), that vertex drawn unlit.
  void normals(const tinygltf::Primitive& p, const glm::dmat4& transform, bool drawsTriangles, MeshPart& part) const {
    const std::optional<Accessor> a = attribute(p, "NORMAL");
    if (!a) return;
    if (a->components() != 3 || a->count() != part.positions.size()) fail(where_, path_, "NORMAL is not one 3-vector a vertex");
    const glm::dmat3 m = glm::transpose(glm::inverse(glm::dmat3(transform)));
    for (size_t v = 0; v < a->count(); ++v) {
      const glm::dvec3 n = m * glm::dvec3(a->at(v, 0), a->at(v, 1), a->at(v, 2));
      const double length = glm::length(n);
      if (!std::isfinite(length) || (length == 0.0 && drawsTriangles)) {
        part.normals.clear();
        return;
      }
      part.normals.push_back(length == 0.0 ? glm::vec3(0.0f) : glm::vec3(n));
    }
  }

  void colors(const tinygltf::Primitive& p, MeshPart& part) const {
    const glm::dvec4 base = baseColor(p);
    const std::optional<Accessor> a = attribute(p, "COLOR_0");
    if (a) {
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
    const std::optional<Accessor> a = attribute(p, name);
    if (!a)
      fail(where_, path_, "materials[" + std::to_string(p.material) + "]'s base colour texture reads " + name + ", which a primitive lacks");
    if (a->components() != 2 || a->count() != part.positions.size()) fail(where_, path_, name + " is not one 2-vector a vertex");
    for (size_t v = 0; v < a->count(); ++v) part.uvs.push_back(glm::vec2(float(a->at(v, 0)), float(a->at(v, 1))));
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
  std::optional<DracoPrimitive> draco_;  // the primitive being read, decoded, where it is compressed
  std::vector<MeshLight> lights_;  // in the order the node tree reaches them
  std::vector<bool> visited_;  // nodes reached so far
  std::string emptyMesh_;
  std::map<int, std::shared_ptr<const TextureImage>> textures_;  // by texture index, once decoded
  std::map<int, std::shared_ptr<const TextureImage>> images_;    // by image index, once decoded
  std::vector<std::string> ignoredMaps_;  // the kinds of map seen that are not rendered
};

// The extensions phongvk implements: a file may require these and no others.
bool implemented(const std::string& extension) {
  return extension == "KHR_draco_mesh_compression" || extension == "KHR_lights_punctual";
}

// "requires the extension X, which phongvk does not implement" for the required extensions phongvk
// does not implement, or "" when it implements them all: a file that requires one (quantized
// positions, a texture transform) cannot be read right without it.
std::string unimplementedRequirement(const std::vector<std::string>& required) {
  std::vector<std::string> missing;
  for (const std::string& name : required) {
    if (!implemented(name)) missing.push_back(name);
  }
  if (missing.empty()) return "";
  std::string names;
  for (const std::string& name : missing) names += (names.empty() ? "" : ", ") + name;
  return "requires the extension" + std::string(missing.size() > 1 ? "s " : " ") + names + ", which phongvk does not implement";
}

// Why a glTF 1.0 file is refused, after what shows it to be one.
[[noreturn]] void failVersionOne(const std::string& where, const std::string& path, const std::string& sign) {
  fail(where, path, sign + "; phongvk reads glTF 2.0 files (convert a glTF 1.0 file to 2.0 first)");
}

// glTF 2.x (a later minor version is read as 2.0, as the specification allows), and no required
// extension phongvk does not implement.
void checkAsset(const tinygltf::Model& model, const std::string& path, const std::string& where) {
  const std::string& version = model.asset.version;
  if (version.rfind("2.", 0) != 0) failVersionOne(where, path, "asset.version is '" + version + "'");
  const std::string unimplemented = unimplementedRequirement(model.extensionsRequired);
  if (!unimplemented.empty()) fail(where, path, unimplemented);
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
  giveCompressedIndicesViews(bytes, true);
  return loader.LoadBinaryFromMemory(&model, &error, &warning, bytes.data(), unsigned(bytes.size()),
                                     tinygltf::GetBaseDir(path));
}

// A .gltf read once and parsed as tinygltf's LoadASCIIFromFile parses it (with its messages), its
// compressed primitives' indices given a buffer view first (gltf_draco.h).
bool loadGltf(tinygltf::TinyGLTF& loader, tinygltf::Model& model, std::string& error, std::string& warning,
              const std::string& path) {
  std::vector<unsigned char> bytes;
  std::string why;
  if (!readRegularFile(&bytes, &why, path, nullptr)) {
    error = "Failed to read file: " + path + ": " + why + "\n";
    return false;
  }
  if (bytes.empty()) {
    error = "Empty file.";
    return false;
  }
  giveCompressedIndicesViews(bytes, false);
  return loader.LoadASCIIFromString(&model, &error, &warning, reinterpret_cast<const char*>(bytes.data()),
                                    unsigned(bytes.size()), tinygltf::GetBaseDir(path));
}

}  // namespace

Mesh importGltf(const std::string& path, bool binary, bool baseColors, const std::string& where) {
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(keepEncoded, nullptr);
  loader.SetFsCallbacks({fileExists, tinygltf::ExpandFilePath, readRegularFile, tinygltf::WriteWholeFile, nullptr});
  tinygltf::Model model;
  std::string error, warning;
  const bool loaded = binary ? loadGlb(loader, model, error, warning, path, where) : loadGltf(loader, model, error, warning, path);
  if (!loaded) {
    const std::string unimplemented = unimplementedRequirement(gltfRequiredExtensions(path, binary));
    if (!unimplemented.empty()) fail(where, path, unimplemented);
    const std::string versionOne = gltfVersionOneSign(path, binary);
    if (!versionOne.empty()) failVersionOne(where, path, versionOne);
    fail(where, path, std::string("not a valid ") + (binary ? "GLB" : "glTF") + " file: " + error.substr(0, error.find('\n')));
  }
  checkAsset(model, path, where);
  if (model.scenes.empty()) fail(where, path, "no scene (its 'scenes' is missing or empty)");
  const int sceneIndex = model.defaultScene >= 0 ? model.defaultScene : 0;
  if (size_t(sceneIndex) >= model.scenes.size()) fail(where, path, "the default scene does not exist");
  Reader reader(model, baseColors, path, where);
  for (int n : model.scenes[size_t(sceneIndex)].nodes) reader.node(n, glm::dmat4(1.0), 0);
  if (reader.parts().empty() && !reader.emptyMesh().empty())
    fail(where, path, std::string(NOTHING_TO_DRAW) + ": " + reader.emptyMesh() + " has no primitives (glTF 2.0 asks for a list of one or more)");
  Mesh mesh = joinParts(reader.parts(), true, where + ": " + path);
  mesh.notice = reader.notice();
  mesh.lights = std::move(reader.lights());
  return mesh;
}

}  // namespace phongvk
