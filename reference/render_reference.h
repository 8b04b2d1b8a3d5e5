// render_reference.h — the CPU reference renderer: plain, single-threaded loops over the shared
// maths (shaders/phong.h, triangle_setup.h, gouraud.h, pixel_shading.h). It is the oracle every GPU image is
// diffed with.
#pragma once

#include "phongvk/image.h"
#include "prepare/scene_data.h"
#include "shaders/pixel_shading.h"
#include "shaders/screen_quads.h"

#include <array>
#include <cstdint>
#include <vector>

namespace phongvk {

// Per-vertex transform + Phong (the shade_vertices pass).
std::vector<gpu::ShadedVertex> shadeVertices(const SceneData& data, const FrameInputs& in);

// Rasterizes every triangle into the per-pixel minimum keys (the raster passes).
std::vector<uint64_t> rasterize(const SceneData& data, const std::vector<gpu::ShadedVertex>& shaded,
                                const gpu::FrameData& frame);

// The vertices whose attributes record `id` of data.triangles takes at its corners
// (shaders/screen_quads.h recordVertices).
inline glm::uvec3 cornerVertices(const SceneData& data, uint32_t id) {
  return gpu::recordVertices(data.triangles[id], isQuadRecord(data, id));
}

// Record `id`'s three shaded corners, as the GPU passes load them (bindings.glsl loadTriangle): a
// triangle's shaded vertices; a quad half's corners (screen_quads.h quadCorners) with its ends'
// colours. shadedOf(v) gives vertex v shaded.
template <typename ShadedOf>
std::array<gpu::ShadedVertex, 3> recordShaded(const SceneData& data, const gpu::FrameData& frame, uint32_t id,
                                              const ShadedOf& shadedOf) {
  const glm::uvec3 v = cornerVertices(data, id);
  std::array<gpu::ShadedVertex, 3> s = {shadedOf(v.x), shadedOf(v.y), shadedOf(v.z)};
  if (!isQuadRecord(data, id)) return s;
  gpu::vec3 h0, h1, h2;
  gpu::quadCorners(gpu::vec3(s[0].hpos), gpu::vec3(s[1].hpos), data.triangles[id].z, frame, h0, h1, h2);
  s[0].hpos = gpu::vec4(h0, 1.0f);
  s[1].hpos = gpu::vec4(h1, 1.0f);
  s[2].hpos = gpu::vec4(h2, 1.0f);
  return s;
}

// Flat or Phong shading's surface of record `id` at pixel (x, y) (shaders/pixel_shading.h): with
// flat shading the face's (a point's or a line's: flatQuadSurface), else the vertices' interpolated
// with the pixel's barycentrics among the record's shaded corners (their homogeneous positions).
gpu::SurfacePoint pixelSurface(const SceneData& data, const FrameInputs& in, uint32_t id,
                               const std::array<gpu::ShadedVertex, 3>& corners, int x, int y);

// Keys -> colours -> image (the resolve passes): the winner's Gouraud colour, or with flat and
// Phong shading its surface lit at the pixel (shaders/pixel_shading.h).
Image resolve(const SceneData& data, const FrameInputs& in, const std::vector<gpu::ShadedVertex>& shaded,
              const std::vector<uint64_t>& keys);

RenderOutput renderReference(const SceneData& data, const FrameInputs& in);

}  // namespace phongvk
