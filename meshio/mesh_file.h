// mesh_file.h — mesh objects' files: which format a file holds (by its content, checked against
// its extension) and the importer that reads it: OBJ through tinyobjloader (obj_import.h), glTF
// 2.0 through tinygltf (gltf_import.h), PLY and STL by phongvk's own readers (ply_file.h,
// stl_file.h; docs/DECISIONS.md "Mesh files" says why not assimp). Every importer gives a loaded
// mesh, which mesh_import.h finishes the same way whatever the format.
#pragma once

#include "geometry/mesh.h"

#include <optional>
#include <string>

namespace phongvk {

enum class MeshFormat { Obj, Ply, Stl, Gltf, Glb };

const char* formatName(MeshFormat format);

// The format of the file at `path`: by its content (PLY's "ply" line, GLB's "glTF" magic, a binary
// STL's size, an ASCII STL's "solid", glTF's JSON object), which must agree with a known extension
// (.obj .ply .stl .gltf .glb, any case); a text file of no other format is OBJ. Throws SceneError
// "<where>: <path>: <why>" for a file that cannot be read, or whose extension and content disagree.
MeshFormat meshFormat(const std::string& path, const std::string& where);

// The same without throwing: the format, or why there is none ("<path>: <why>").
struct DetectedFormat {
  std::optional<MeshFormat> format;
  std::string problem;
};
DetectedFormat detectMeshFormat(const std::string& path);

// The file as a loaded mesh (mesh_import.h). `baseColors`: a glTF primitive's base colour factor
// multiplies its vertex colours (the object then names no material of its own). Throws SceneError
// "<where>: <path>: <why>".
Mesh importMeshFile(const std::string& path, MeshFormat format, bool baseColors, const std::string& where);

// The triangles a mesh file of `bytes` will build, estimated before it is read, for the memory
// estimate: glTF and GLB count them from the JSON (gltf_import.h gltfTriangles: external buffers and
// instancing included); the other formats hold every triangle they build, 12 bytes a triangle at
// least, so their size bounds it.
uint64_t meshFileTriangles(const std::string& path, MeshFormat format, uint64_t bytes);

// The up axis a model in this format usually has: y for glTF (the format says so) and OBJ (most
// tools' export default), z for PLY and STL (scanners, CAD and 3D printing).
bool usuallyYUp(MeshFormat format);

}  // namespace phongvk
