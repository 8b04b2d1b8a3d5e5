// grids.h — the benchmark's wavy grid meshes (a new mesh each frame, a moving object, shadows).
#pragma once

#include "phongvk/phongvk.h"

namespace phongvk::bench {

// A wavy n x n grid (2n² triangles) a metre across, about its centre, its wave shifted by `phase`:
// another mesh for every phase.
MeshArrays waveGrid(int n, float phase);

}  // namespace phongvk::bench
