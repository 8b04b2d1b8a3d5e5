// gltf_fuzzer.cpp — libFuzzer target for the glTF importer (gltf_import.h) with the files a model
// names beside it (scripts/fuzz.sh runs it).
//
// An input is a model and its external buffer:
//   byte 0        bit 0 picks the extension: 0 .gltf (JSON), 1 .glb
//   bytes 1..2    n, the model's length (little-endian; what is left when fewer bytes follow)
//   n bytes       the model, written as model.gltf or model.glb
//   the rest      written as buf.bin beside it, so that a buffer's "uri": "buf.bin" reads it
// Any bytes must either give a mesh or throw SceneError: no crash, no sanitizer report, no hang, no
// other exception. A mesh that loads keeps the promises of mesh_import.h (mesh_checks.h).
// fuzz/make_gltf_seeds.py writes the seeds (fuzz/gltf_corpus) in this framing.
#include "fuzz/mesh_checks.h"
#include "meshio/mesh_file.h"
#include "meshio/mesh_import.h"
#include "phongvk/errors.h"

#include <stdlib.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

using namespace phongvk;

// A folder of this process's own under the system's temporary folder, made once and removed with
// what is in it when the process exits normally (a crash leaves it behind).
class TempFolder {
 public:
  TempFolder() {
    std::string pattern = (std::filesystem::temp_directory_path() / "phongvk_gltf_fuzz_XXXXXX").string();
    if (!mkdtemp(pattern.data())) fuzz::broken("cannot make a temporary folder from " + pattern);
    path_ = pattern;
  }
  ~TempFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TempFolder(const TempFolder&) = delete;
  TempFolder& operator=(const TempFolder&) = delete;

  // Replaces the file `name` in the folder with `size` bytes; its path.
  std::string write(const std::string& name, const uint8_t* data, size_t size) const {
    const std::string path = (path_ / name).string();
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
    if (!out) fuzz::broken("cannot write " + path);
    return path;
  }

 private:
  std::filesystem::path path_;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const TempFolder folder;
  if (size < 3) return 0;
  const bool binary = data[0] & 1;
  const size_t modelSize = std::min(size_t(data[1]) | size_t(data[2]) << 8, size - 3);
  const uint8_t* model = data + 3;
  const std::string path = folder.write(binary ? "model.glb" : "model.gltf", model, modelSize);
  folder.write("buf.bin", model + modelSize, size - 3 - modelSize);
  try {
    const MeshFormat format = meshFormat(path, "objects[0].file");
    LinearTransform identity;
    fuzz::checkMesh(finishLoadedMesh(importMeshFile(path, format, true, "objects[0].file"), identity, "objects[0].file"));
  } catch (const SceneError&) {
    // rejected with a message: the expected outcome for most inputs
  }
  std::filesystem::remove(path);  // else the next input's model could name this one and read it
  return 0;
}
