// render_reference.h — the CPU reference renderer: plain, single-threaded loops over the shared
// maths (shaders/phong.h, triangle_setup.h, gouraud.h, pixel_shading.h). It is the oracle every GPU image is
// diffed with.
#pragma once

#include "phongvk/image.h"
#include "prepare/scene_data.h"
#include "shaders/pixel_shading.h"

#include <cstdint>
#include <vector>

namespace phongvk {

// Per-vertex transform + Phong (the shade_vertices pass).
std::vector<gpu::ShadedVertex> shadeVertices(const SceneData& data, const FrameInputs& in);

// Rasterizes every triangle into the per-pixel minimum keys (the raster passes).
std::vector<uint64_t> rasterize(const SceneData& data, const std::vector<gpu::ShadedVertex>& shaded,
                                const gpu::FrameData& frame);

// Flat or Phong shading's surface of triangle `tri` at pixel (x, y) (shaders/pixel_shading.h): with
// flat shading the face's, else the vertices' interpolated with the pixel's barycentrics among the
// triangle's shaded vertices s0, s1, s2 (their homogeneous positions).
gpu::SurfacePoint pixelSurface(const SceneData& data, const FrameInputs& in, glm::uvec4 tri, const gpu::ShadedVertex& s0,
                               const gpu::ShadedVertex& s1, const gpu::ShadedVertex& s2, int x, int y);

// Keys -> colours -> image (the resolve passes): the winner's Gouraud colour, or with flat and
// Phong shading its surface lit at the pixel (shaders/pixel_shading.h).
Image resolve(const SceneData& data, const FrameInputs& in, const std::vector<gpu::ShadedVertex>& shaded,
              const std::vector<uint64_t>& keys);

RenderOutput renderReference(const SceneData& data, const FrameInputs& in);

}  // namespace phongvk
