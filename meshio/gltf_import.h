// gltf_import.h — glTF 2.0 files (.gltf with its buffers, .glb) through tinygltf
// (docs/DECISIONS.md "Mesh files").
#pragma once

#include "geometry/mesh.h"

#include <cstdint>
#include <optional>
#include <string>

namespace phongvk {

// Reads `path` (`binary`: a .glb) as a loaded mesh (mesh_import.h): every triangle primitive
// (triangles, strips, fans; points and lines are skipped) of the meshes the default scene's nodes
// place (the first scene where none is the default), with their node transforms (matrix or
// translation, rotation, scale). Normals where every primitive has them; otherwise flat, as the
// specification asks. COLOR_0 as 8 bits a channel; with `baseColors`, each primitive's base
// colour factor multiplies it (or is its colour). The lights its nodes place (KHR_lights_punctual,
// gltf_lights.h) in Mesh::lights. Throws SceneError "<where>: <path>: <why>".
Mesh importGltf(const std::string& path, bool binary, bool baseColors, const std::string& where);

// The triangles importGltf will build from `path`, counted from the JSON alone (gltf_estimate.cpp):
// every primitive's index (or position) count, as often as the node tree places its mesh, whatever
// the size of the buffers. Nothing when the JSON cannot be read (importGltf then says why).
std::optional<uint64_t> gltfTriangles(const std::string& path, bool binary);

}  // namespace phongvk
