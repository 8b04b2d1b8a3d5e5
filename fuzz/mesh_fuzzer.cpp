// mesh_fuzzer.cpp — libFuzzer target for the mesh file importers (scripts/fuzz.sh runs it).
//
// The first byte picks the extension (.ply, .stl, .glb, .obj, .gltf), the rest is the file. Any
// bytes must either give a mesh or throw SceneError: no crash, no sanitizer report, no hang, no
// other exception. A mesh that loads keeps the promises of mesh_import.h: finite positions, unit
// normals, indices in range, at least one triangle.
#include "scene/mesh_file.h"
#include "scene/mesh_import.h"

#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

namespace {

using namespace phongvk;

[[noreturn]] void broken(const std::string& what) {
  std::fprintf(stderr, "broken promise: %s\n", what.c_str());
  std::abort();
}

void checkMesh(const Mesh& mesh) {
  if (mesh.triangles.empty()) broken("a mesh without triangles");
  if (mesh.normals.size() != mesh.positions.size()) broken("normals do not match positions");
  for (const glm::vec3& p : mesh.positions)
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) broken("a non-finite position");
  for (const glm::vec3& n : mesh.normals)
    if (!(std::abs(glm::length(n) - 1.0f) < 1e-3f)) broken("a normal that is not unit length");
  for (const glm::uvec3& t : mesh.triangles)
    if (t.x >= mesh.positions.size() || t.y >= mesh.positions.size() || t.z >= mesh.positions.size())
      broken("an index out of range");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const char* kExtensions[] = {".ply", ".stl", ".glb", ".obj", ".gltf"};
  if (size < 1) return 0;
  const std::string path = "/tmp/phongvk_mesh_fuzz_" + std::to_string(getpid()) + kExtensions[data[0] % 5];
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data + 1), std::streamsize(size - 1));
  }
  try {
    const MeshFormat format = meshFormat(path, "objects[0].file");
    LinearTransform identity;
    checkMesh(finishLoadedMesh(importMeshFile(path, format, true, "objects[0].file"), identity, "objects[0].file"));
  } catch (const SceneError&) {
  }
  std::remove(path.c_str());
  return 0;
}
