// mesh_load.h — how fast mesh files load: a large file per format, written by the benchmark (a
// grid surface: binary PLY, OBJ, binary STL, GLB), loaded as a scene object would load it (the
// importer, then the transform, normals and checks of mesh_import.h), median of a few runs.
#pragma once

#include <string>
#include <vector>

namespace phongvk::bench {

// A 10M-triangle binary PLY and a 1M-triangle OBJ load within this many seconds.
inline constexpr double MESH_LOAD_TARGET_SECONDS = 1.0;

struct MeshLoadRun {
  std::string format;     // "binary PLY"
  std::string file;       // its name in the scratch folder
  size_t triangles = 0;   // as loaded
  double megabytes = 0;   // the file's size
  double seconds = 0;     // median load
  bool judged = false;    // has a target (PLY 10M, OBJ 1M)
  std::string failure;
  double megabytesPerSecond() const { return megabytes / seconds; }
};

// `quick`: small files, one run.
std::vector<MeshLoadRun> runMeshLoads(bool quick);

}  // namespace phongvk::bench
