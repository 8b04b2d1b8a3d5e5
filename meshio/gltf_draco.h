// gltf_draco.h — glTF primitives compressed with KHR_draco_mesh_compression, decoded by Draco
// (Debian's libdraco) into the values their accessors stand for.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace tinygltf {
class Model;
struct Primitive;
}  // namespace tinygltf

namespace phongvk {

// What a compressed primitive decodes to: the attributes phongvk reads (POSITION, NORMAL, COLOR_0,
// TEXCOORD_n) that the extension names, as floats in the meaning of their accessors (a normalized
// integer as a fraction of its largest value), and the triangles' indices, three a triangle.
struct DracoPrimitive {
  struct Attribute {
    int components = 0;
    std::vector<float> values;  // `components` a vertex
  };
  std::map<std::string, Attribute> attributes;  // by the primitive's attribute name
  size_t vertices = 0;
  std::vector<uint32_t> indices;
};

// The primitive decoded, or nothing when it names no KHR_draco_mesh_compression. `name` is the
// primitive in messages ("meshes[0].primitives[1]"). Throws SceneError "<where>: <path>: <name>:
// KHR_draco_mesh_compression: <why>" for a mode other than triangles or a triangle strip, a buffer
// view that does not exist or runs past its buffer, an attribute id the compressed data lacks or
// an attribute the primitive does not name, data Draco cannot decode, and decoded counts that
// differ from what the accessors say (the memory estimate counts those).
std::optional<DracoPrimitive> decodeDracoPrimitive(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                                                   const std::string& name, const std::string& path, const std::string& where);

// tinygltf 2.7 refuses a primitive whose indices accessor has no buffer view, and a compressed
// primitive's has none (its indices are in the compressed data). `file` (a .gltf's text, or a GLB)
// with each such accessor given the compressed data's buffer view (the first view, where the
// extension names none that exists: decodeDracoPrimitive then says so), so that tinygltf loads it;
// nothing reads that view as indices (decodeDracoPrimitive decodes them). Unchanged where no
// primitive is compressed, or where the JSON cannot be read (tinygltf then says why).
void giveCompressedIndicesViews(std::vector<unsigned char>& file, bool binary);

}  // namespace phongvk
