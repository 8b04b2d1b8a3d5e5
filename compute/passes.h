// passes.h — which passes a frame of the compute port runs, with which shader builds and
// specialization constants: a function of the scene's materials and lights, the frame's modes and
// what the renderer settled on for the device and for earlier frames (PassChoices). Compiling and
// keeping the pipelines is gpu_pipelines.cpp's.
#pragma once

#include "shaders/gpu_layout.h"
#include "vulkan/pipelines.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace phongvk {

// The passes a frame records, then shader builds that stand in for one: RESOLVE_LIT runs
// RESOLVE_SMALL in frames lit per pixel (flat and Phong shading), RESOLVE_LARGE_KEYS runs
// RESOLVE_LARGE where it keeps only keys (those frames, and lists taken in rounds).
// On the 32-bit key path RASTER_IDS and CLIP_IDS run the triangle and clip shaders again, for the
// keys' low words (raster_loops.glsl KEY_PASS). RASTER_POINTS runs the triangle shader as the point
// pass, which draws the point quads (raster_triangles.comp POINT_PASS).
enum Pass { SHADE, RASTER, CLIP, RESOLVE_SMALL, RESOLVE_LARGE, BIN_LARGE, FILL, PACK, RESOLVE_LIT, RESOLVE_LARGE_KEYS,
            RASTER_IDS, CLIP_IDS, RASTER_POINTS, PASS_COUNT };

// A pass, the shader build that runs it (the pass's own, or a variant: RESOLVE_LIT,
// RESOLVE_LARGE_KEYS) and the specialization constants it is compiled with.
struct PipelineRequest {
  Pass pass;
  std::vector<SpecConstant> specs;
  Pass code = PASS_COUNT;  // PASS_COUNT: the pass's own shader
  Pass shader() const { return code == PASS_COUNT ? pass : code; }
};

// What the renderer settled on that shapes the passes: for the device (its work layout and key
// path, where colours go) and from earlier frames (the clipper, lists taken in chunks).
struct PassChoices {
  uint32_t resolveTiles = 1;         // SPEC_RESOLVE_TILES
  bool binPass = false;              // SPEC_BIN_PASS: the bin pass links the large triangles
  bool keys32 = false;               // the 32-bit key path: the triangle and clip passes twice
  bool keptList = false;             // SPEC_KEPT_LIST: on it, the kept triangles listed (gpu_layout.h keptList)
  bool colorsInKeys = false;         // the host reads the colours from the key slots (no pack pass)
  bool textured = false;             // the scene samples textures: resolve_lit colours every pixel
  bool shadows = false;              // SPEC_SHADOWS: some light casts shadows (shade and resolve_lit trace rays)
  bool quads = false;                // SPEC_QUADS: the scene has points or lines (shaders/screen_quads.h)
  bool points = false;               // the scene (its share) has whole point quads: the point pass draws them
  bool unlit = false;                // every vertex is drawn unlit (everyVertexUnlit): the shade pass lights none
  uint32_t clip = gpu::CLIP_NONE;    // SPEC_CLIP_POLYGONS
  uint32_t listChunk = 0;            // SPEC_LIST_CHUNK: 0, or the bins' lists taken this many a round
};

// Every pass's request for frames with these materials and lights and the frame's interpolation,
// shading, specular model and projection. Frames with keys (for diffs) keep the final keys and
// write the colour buffer after the background pass; without keys the colours go to the key
// slots, where the host reads them or the pack pass packs them into the colour buffer.
std::vector<PipelineRequest> passRequests(const PassChoices& choices, const std::vector<gpu::MaterialData>& materials,
                                          size_t lightCount, const gpu::FrameData& frame, bool withKeys);

// Whether the pack pass moves a frame's colours from the key slots into the colour buffer.
inline bool packsColors(const PassChoices& choices, bool withKeys) { return !withKeys && !choices.colorsInKeys; }

}  // namespace phongvk
