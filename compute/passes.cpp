// passes.cpp — a frame's passes and their specialization constants (passes.h).
#include "compute/passes.h"

namespace phongvk {

using namespace gpu;

namespace {

// The specialization constants shading with these materials and lights asks for (shared.h SPEC_*).
std::vector<SpecConstant> shadeSpecs(const std::vector<MaterialData>& materials, size_t lightCount) {
  bool specular = false, constantAttenuation = true;
  for (const MaterialData& m : materials) {
    specular = specular || m.ks != 0.0f;
    constantAttenuation = constantAttenuation && m.attenuation.y == 0.0f && m.attenuation.z == 0.0f;
  }
  return {{SPEC_LIGHT_COUNT, uint32_t(lightCount)}, {SPEC_SPECULAR, specular}, {SPEC_CONSTANT_ATTENUATION, constantAttenuation}};
}

}  // namespace

std::vector<PipelineRequest> passRequests(const PassChoices& choices, const std::vector<MaterialData>& materials,
                                          size_t lightCount, const FrameData& frame, bool withKeys) {
  const uint32_t output = withKeys ? RESOLVE_OUTPUT_KEEP_KEYS : RESOLVE_OUTPUT_KEY_SLOTS;
  const uint32_t interpolation = frame.interpolation;
  std::vector<PipelineRequest> requests = {
      // A scene drawn unlit throughout shades its vertices with no light: their colours are the same.
      {SHADE, shadeSpecs(materials, choices.unlit ? 0 : lightCount)},
      {RASTER, {}},
      {CLIP, {{SPEC_BIN_PASS, choices.binPass}, {SPEC_CLIP_POLYGONS, choices.clip}}},
      {RESOLVE_SMALL, {{SPEC_INTERPOLATION, interpolation}, {SPEC_RESOLVE_OUTPUT, output}}},
      {RESOLVE_LARGE,
       {{SPEC_INTERPOLATION, interpolation}, {SPEC_RESOLVE_TILES, choices.resolveTiles}, {SPEC_RESOLVE_OUTPUT, output}}},
  };
  // Only where they differ from the defaults: a Gouraud frame of whole lists keeps the pipelines
  // (and pipeline cache entries) it always had. requests[p] is pass p's request up to RESOLVE_LARGE.
  // Frames lit per pixel and scenes with textures colour every pixel in resolve_lit.
  const bool perPixel = frame.shading != SHADING_GOURAUD || choices.textured;
  if (choices.listChunk != 0u || perPixel) requests[RESOLVE_LARGE].code = RESOLVE_LARGE_KEYS;
  if (choices.listChunk != 0u) {
    for (Pass pass : {RESOLVE_SMALL, RESOLVE_LARGE}) requests[pass].specs.push_back({SPEC_LIST_CHUNK, choices.listChunk});
  }
  if (perPixel) requests[RESOLVE_SMALL].code = RESOLVE_LIT;
  if (frame.shading != SHADING_GOURAUD) {  // lit per pixel: resolve_lit as the second resolve, with the lights
    const std::vector<SpecConstant> lighting = shadeSpecs(materials, lightCount);
    requests[RESOLVE_SMALL].specs.insert(requests[RESOLVE_SMALL].specs.end(), lighting.begin(), lighting.end());
    for (Pass pass : {SHADE, RESOLVE_SMALL}) requests[pass].specs.push_back({SPEC_SHADING, frame.shading});
  }
  if (choices.textured) requests[RESOLVE_SMALL].specs.push_back({SPEC_TEXTURED, 1u});
  if (choices.shadows) {  // only where a light casts them: every other scene keeps its pipelines
    if (!choices.unlit) requests[SHADE].specs.push_back({SPEC_SHADOWS, 1u});
    if (perPixel) requests[RESOLVE_SMALL].specs.push_back({SPEC_SHADOWS, 1u});
  }
  if (frame.specular == SPECULAR_BLINN) {
    for (Pass pass : {SHADE, RESOLVE_SMALL}) requests[pass].specs.push_back({SPEC_BLINN, 1u});
  }
  if (choices.keys32) {  // the triangle and clip passes twice: depth words, then ids (raster_loops.glsl)
    requests.push_back({RASTER_IDS, {{SPEC_KEY_PASS, KEY_PASS_IDS}}, RASTER});
    if (choices.keptList) {  // a small scene's kept triangles as lists (gpu_layout.h keptList)
      requests.back().specs.push_back({SPEC_KEPT_LIST, 1u});
      for (Pass pass : {RASTER, CLIP}) requests[pass].specs.push_back({SPEC_KEPT_LIST, 1u});
    }
    requests.push_back({CLIP_IDS, requests[CLIP].specs, CLIP});
    requests.back().specs.push_back({SPEC_KEY_PASS, KEY_PASS_IDS});
    for (Pass pass : {RASTER, CLIP}) requests[pass].specs.push_back({SPEC_KEY_PASS, KEY_PASS_DEPTH});
  }
  if (choices.points) {  // the triangle shader as the point pass, with the triangle pass's constants
    requests.push_back({RASTER_POINTS, requests[RASTER].specs, RASTER});
    requests.back().specs.push_back({SPEC_POINT_PASS, 1u});
  }
  if (choices.binPass) requests.push_back({BIN_LARGE, {}});
  if (withKeys) requests.push_back({FILL, {}});  // the colour buffer's background
  if (packsColors(choices, withKeys)) requests.push_back({PACK, {}});
  if (frame.projection != PROJECTION_PERSPECTIVE) {  // as the others, only where not the default
    for (PipelineRequest& r : requests) r.specs.push_back({SPEC_PROJECTION, frame.projection});
  }
  if (choices.quads) {  // every pass that loads a record's corners or shades a vertex
    for (PipelineRequest& r : requests) r.specs.push_back({SPEC_QUADS, 1u});
  }
  return requests;
}

}  // namespace phongvk
