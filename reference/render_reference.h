// render_reference.h — the CPU reference renderer: plain, single-threaded loops over the shared
// maths (shaders/phong.h, triangle_setup.h, gouraud.h). It is the oracle every GPU image is
// diffed with.
#pragma once

#include "phongvk/image.h"
#include "scene/scene_data.h"

#include <cstdint>
#include <vector>

namespace phongvk {

// Per-vertex transform + Phong (the shade_vertices pass).
std::vector<gpu::ShadedVertex> shadeVertices(const SceneData& data, const FrameInputs& in);

// Rasterizes every triangle into the per-pixel minimum keys (the raster passes).
std::vector<uint64_t> rasterize(const SceneData& data, const std::vector<gpu::ShadedVertex>& shaded,
                                const gpu::FrameData& frame);

// Keys -> Gouraud colours -> image (the resolve pass).
Image resolve(const SceneData& data, const std::vector<gpu::ShadedVertex>& shaded,
              const std::vector<uint64_t>& keys, const gpu::FrameData& frame);

RenderOutput renderReference(const SceneData& data, const FrameInputs& in);

}  // namespace phongvk
