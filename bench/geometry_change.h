// geometry_change.h — what a new mesh each frame costs (a deforming mesh, a dataset of models,
// driven from code): the public Renderer given a new geometry of the same triangle count every
// frame, against frames of fixed geometry, interleaved.
#pragma once

#include <string>
#include <vector>

namespace phongvk::bench {

// A frame with a new mesh, less the mesh's build, within this factor of a frame of fixed geometry.
inline constexpr double GEOMETRY_CHANGE_TARGET = 1.5;
// Interleaved rounds, each of this many frames each way (the medians are over all of them).
inline constexpr int GEOMETRY_CHANGE_ROUNDS = 5, GEOMETRY_CHANGE_FRAMES = 10;

struct GeometryChangeRun {
  std::string name;         // "gpu, 1250 triangles"
  std::string backend;      // "gpu" or "cpu"
  size_t triangles = 0;
  int width = 0, height = 0;
  double fixedMs = 0;       // a frame of fixed geometry (relit: the specular model alternates), median
  double newMeshMs = 0;     // a frame with a new mesh of the same size, median, the mesh's build included
  double buildMs = 0;       // of which the mesh's build (RendererStats::buildMs), median
  double pipelinesMs = 0;   // pipelines compiled during the new-mesh frames (0: none compiled twice)
  std::string failure;
  double ratio() const { return (newMeshMs - buildMs) / fixedMs; }
};

// `quick`: the small mesh only, one round.
std::vector<GeometryChangeRun> runGeometryChanges(bool quick);

}  // namespace phongvk::bench
