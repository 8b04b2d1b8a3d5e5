// mesh_file.cpp — see mesh_file.h.
#include "meshio/mesh_file.h"

#include "base/mapped_file.h"
#include "base/regular_file.h"
#include "meshio/gltf_import.h"
#include "meshio/obj_import.h"
#include "meshio/ply_file.h"
#include "meshio/stl_file.h"
#include "phongvk/errors.h"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <optional>

namespace phongvk {
namespace {

std::optional<MeshFormat> formatOfExtension(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
  if (extension == ".obj") return MeshFormat::Obj;
  if (extension == ".ply") return MeshFormat::Ply;
  if (extension == ".stl") return MeshFormat::Stl;
  if (extension == ".gltf") return MeshFormat::Gltf;
  if (extension == ".glb") return MeshFormat::Glb;
  return std::nullopt;
}

bool startsWith(const std::string& bytes, const char* prefix) { return bytes.rfind(prefix, 0) == 0; }

// The format the first bytes and the size say, where they say one.
std::optional<MeshFormat> formatOfContent(const std::string& head, uint64_t size) {
  if (startsWith(head, "ply\n") || startsWith(head, "ply\r")) return MeshFormat::Ply;
  if (startsWith(head, "glTF")) return MeshFormat::Glb;
  if (head.size() >= 84) {  // binary STL: an 80-byte header, a triangle count, 50 bytes a triangle
    uint32_t count;
    std::memcpy(&count, head.data() + 80, 4);
    if (size == 84 + 50 * uint64_t(count)) return MeshFormat::Stl;
  }
  const size_t text = head.find_first_not_of(" \t\r\n");
  if (text == std::string::npos) return std::nullopt;
  if (head.compare(text, 5, "solid") == 0) return MeshFormat::Stl;
  if (head[text] == '{') return MeshFormat::Gltf;
  return std::nullopt;
}

}  // namespace

const char* formatName(MeshFormat format) {
  switch (format) {
    case MeshFormat::Obj: return "OBJ";
    case MeshFormat::Ply: return "PLY";
    case MeshFormat::Stl: return "STL";
    case MeshFormat::Gltf: return "glTF";
    case MeshFormat::Glb: return "GLB";
  }
  return "?";
}

uint64_t meshFileTriangles(const std::string& path, MeshFormat format, uint64_t bytes) {
  if (format == MeshFormat::Gltf || format == MeshFormat::Glb) {
    if (const std::optional<uint64_t> triangles = gltfTriangles(path, format == MeshFormat::Glb)) return *triangles;
  }
  return bytes / 12;
}

bool usuallyYUp(MeshFormat format) {
  return format == MeshFormat::Obj || format == MeshFormat::Gltf || format == MeshFormat::Glb;
}

DetectedFormat detectMeshFormat(const std::string& path) {
  const auto problem = [&](const std::string& why) { return DetectedFormat{std::nullopt, path + ": " + why}; };
  std::string unreadable;
  const std::optional<RegularFile> file = RegularFile::open(path, unreadable);
  if (!file) return problem("cannot open the file: " + unreadable);
  const std::string head = file->read(256);
  const uint64_t size = file->size();
  const std::optional<MeshFormat> byContent = formatOfContent(head, size);
  const std::optional<MeshFormat> byExtension = formatOfExtension(path);
  if (byContent && byExtension && *byContent != *byExtension)
    return problem(std::string("the extension says ") + formatName(*byExtension) + " but the content is " +
                   formatName(*byContent));
  if (byContent) return {byContent, ""};
  if (!byExtension || *byExtension == MeshFormat::Obj) return {MeshFormat::Obj, ""};  // text, parsed as OBJ
  std::string why = std::string("the extension says ") + formatName(*byExtension) + " but the content is not " +
                    formatName(*byExtension);
  if (*byExtension == MeshFormat::Stl && head.size() >= 84) {
    uint32_t count;
    std::memcpy(&count, head.data() + 80, 4);
    why += " (a binary STL of " + std::to_string(count) + " triangles has " + std::to_string(84 + 50 * uint64_t(count)) +
           " bytes, the file " + std::to_string(size) + ")";
  }
  return problem(why);
}

MeshFormat meshFormat(const std::string& path, const std::string& where) {
  const DetectedFormat detected = detectMeshFormat(path);
  if (!detected.format) throw SceneError(where + ": " + detected.problem);
  return *detected.format;
}

Mesh importMeshFile(const std::string& path, MeshFormat format, bool baseColors, const std::string& where) {
  if (format == MeshFormat::Obj) return importObj(path, where);
  if (format == MeshFormat::Gltf || format == MeshFormat::Glb) return importGltf(path, format == MeshFormat::Glb, baseColors, where);
  const MappedFile file(path, where);
  if (file.bytes().empty()) throw SceneError(where + ": " + path + ": the file is empty");
  return format == MeshFormat::Ply ? readPly(file.bytes(), path, where) : readStl(file.bytes(), path, where);
}

}  // namespace phongvk
