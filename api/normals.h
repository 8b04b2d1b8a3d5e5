// normals.h — the normals output: each pixel's shading normal at its nearest sample, as the
// renderers shade that sample (flat: the face normal; Gouraud and Phong: the vertex normals
// interpolated with the sample's barycentrics, normalized), rotated into camera space.
#pragma once

#include "prepare/scene_data.h"
#include "shaders/pixel_shading.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace phongvk {

// Marks a pixel without a sample (no triangle covers it) in the nearest-sample list.
inline constexpr size_t NO_SAMPLE = ~size_t(0);

// The unit shading normal of triangle `triangle` (its index in data.triangles) at sample (x, y)
// of the frame `in` (in the view the frame was rendered in, samples included), in camera space:
// x right, y up, z forward (the frame's right, up and forward rows; depth runs along z). Zero
// where the surface has no normal (a degenerate face, vertex normals cancelling). The stored
// normal, not flipped toward the eye on a back face: the shading lights it as stored.
glm::vec3 cameraNormal(const SceneData& data, const FrameInputs& in, uint32_t triangle, int x, int y);

// The surface point the frame's shading lights at sample (x, y) of triangle `triangle` (its index
// in data.triangles): render_reference.h pixelSurface, as the renderers shade it.
gpu::SurfacePoint sampleSurface(const SceneData& data, const FrameInputs& in, uint32_t triangle, int x, int y);

// Per pixel, three floats: cameraNormal of the triangle whose key `sampleKeys[nearest[i]]` names
// (the whole scene's index: a share's keys are offset by data.triangleBase) at that sample; 0, 0, 0
// where nearest[i] is NO_SAMPLE.
std::vector<float> normalsOfSamples(const SceneData& data, const FrameInputs& in, const std::vector<uint64_t>& sampleKeys,
                                    const std::vector<size_t>& nearest);

}  // namespace phongvk
