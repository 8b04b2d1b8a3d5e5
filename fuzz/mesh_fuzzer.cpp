// mesh_fuzzer.cpp — libFuzzer target for the mesh file importers (scripts/fuzz.sh runs it).
//
// The first byte picks the extension (.ply, .stl, .glb, .obj, .gltf), the rest is the file. Any
// bytes must either give a mesh or throw SceneError: no crash, no sanitizer report, no hang, no
// other exception. A mesh that loads keeps the promises of mesh_import.h (mesh_checks.h).
#include "fuzz/mesh_checks.h"
#include "meshio/mesh_file.h"
#include "meshio/mesh_import.h"
#include "phongvk/errors.h"

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>

using namespace phongvk;

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
    fuzz::checkMesh(finishLoadedMesh(importMeshFile(path, format, true, "objects[0].file"), identity, "objects[0].file"));
  } catch (const SceneError&) {
  }
  std::remove(path.c_str());
  return 0;
}
