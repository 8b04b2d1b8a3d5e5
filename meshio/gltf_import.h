// gltf_import.h — glTF 2.0 files (.gltf with its buffers, .glb) through tinygltf
// (docs/DECISIONS.md "Mesh files").
#pragma once

#include "geometry/mesh.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace phongvk {

// Reads `path` (`binary`: a .glb) as a loaded mesh (mesh_import.h): every primitive (triangles,
// strips and fans; points; lines, line strips and loops) of the meshes the default scene's nodes
// place (the first scene where none is the default), with their node transforms (matrix or
// translation, rotation, scale); a primitive compressed with KHR_draco_mesh_compression decoded
// (gltf_draco.h). Normals where every triangle primitive has them; otherwise flat, as the
// specification asks; points and lines without them have (0, 0, 0), drawn unlit, as it asks too.
// COLOR_0 as 8 bits a channel; with `baseColors`, each primitive's base colour factor multiplies it
// (or is its colour). The lights its nodes place (KHR_lights_punctual, gltf_lights.h) in
// Mesh::lights. A file that requires an extension phongvk does not implement is refused by its
// name. Throws SceneError "<where>: <path>: <why>".
Mesh importGltf(const std::string& path, bool binary, bool baseColors, const std::string& where);

// The triangles importGltf will build from `path`, counted from the JSON alone (gltf_estimate.cpp):
// every primitive's index (or position) count, as often as the node tree places its mesh, whatever
// the size of the buffers; each point and line segment counts as two (its quad's two records). A compressed
// primitive's accessors give its decoded counts (gltf_draco.h refuses data that decodes to others).
// Nothing when the JSON cannot be read (importGltf then says why).
std::optional<uint64_t> gltfTriangles(const std::string& path, bool binary);

// The extensions the JSON of `path` requires (extensionsRequired), read without tinygltf
// (gltf_estimate.cpp): a file tinygltf cannot load is still refused by the extension it needs
// (EXT_meshopt_compression's buffers without a URI). Empty when the JSON cannot be read.
std::vector<std::string> gltfRequiredExtensions(const std::string& path, bool binary);

// What shows `path` to be a glTF 1.0 file that tinygltf could not load ("a GLB of version 1 (...)",
// "'accessors' is an object of named entries (...)"), read without tinygltf (gltf_estimate.cpp), so that its refusal says so; "" when
// nothing does. glTF 1.0's binary form has version 1 in its header, and its JSON keeps accessors,
// meshes and the other lists as objects of named entries, where glTF 2.0 has arrays.
std::string gltfVersionOneSign(const std::string& path, bool binary);

}  // namespace phongvk
