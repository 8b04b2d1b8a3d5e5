// lights_reached.h — the lights output: how many of the frame's lights reach each pixel's surface
// point at its nearest sample (docs/DESIGN.md "Shadows"): every light without shadows, and each
// shadowed one whose ray from there is not blocked, by the same shared test the renderers shade with.
#pragma once

#include "prepare/scene_data.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace phongvk {

// Per pixel, the count for the triangle whose key `sampleKeys[nearest[i]]` names at that sample
// (its surface point as the frame's shading takes it: flat, the centroid; else the point under the
// sample); -1 where nearest[i] is NO_SAMPLE (normals.h).
std::vector<int32_t> lightsReached(const SceneData& data, const FrameInputs& in, const std::vector<uint64_t>& sampleKeys,
                                   const std::vector<size_t>& nearest);

}  // namespace phongvk
