// gpu_pipelines.cpp — the passes a frame runs (passes.h), compiled once each, in parallel, and kept
// in the renderer's pipeline set (GpuPipelineSet).
#include "compute/gpu_renderer.h"

#include "shaders/bin_large.spv.h"
#include "shaders/bin_large_exact.spv.h"
#include "shaders/clip_triangles.spv.h"
#include "shaders/clip_triangles_exact.spv.h"
#include "shaders/fill_background.spv.h"
#include "shaders/fill_background_exact.spv.h"
#include "shaders/pack_colors.spv.h"
#include "shaders/pack_colors_exact.spv.h"
#include "shaders/raster_triangles.spv.h"
#include "shaders/raster_triangles_exact.spv.h"
#include "shaders/resolve_large.spv.h"
#include "shaders/resolve_large_exact.spv.h"
#include "shaders/resolve_large_keys.spv.h"
#include "shaders/resolve_large_keys_exact.spv.h"
#include "shaders/resolve_lit.spv.h"
#include "shaders/resolve_lit_exact.spv.h"
#include "shaders/resolve_small.spv.h"
#include "shaders/resolve_small_exact.spv.h"
#include "shaders/shade_vertices.spv.h"
#include "shaders/shade_vertices_exact.spv.h"
#include "shaders/bin_large_k32.spv.h"
#include "shaders/bin_large_k32_exact.spv.h"
#include "shaders/clip_triangles_k32.spv.h"
#include "shaders/clip_triangles_k32_exact.spv.h"
#include "shaders/fill_background_k32.spv.h"
#include "shaders/fill_background_k32_exact.spv.h"
#include "shaders/pack_colors_k32.spv.h"
#include "shaders/pack_colors_k32_exact.spv.h"
#include "shaders/raster_triangles_k32.spv.h"
#include "shaders/raster_triangles_k32_exact.spv.h"
#include "shaders/resolve_large_k32.spv.h"
#include "shaders/resolve_large_k32_exact.spv.h"
#include "shaders/resolve_large_keys_k32.spv.h"
#include "shaders/resolve_large_keys_k32_exact.spv.h"
#include "shaders/resolve_lit_k32.spv.h"
#include "shaders/resolve_lit_k32_exact.spv.h"
#include "shaders/resolve_small_k32.spv.h"
#include "shaders/resolve_small_k32_exact.spv.h"
#include "shaders/shade_vertices_k32.spv.h"
#include "shaders/shade_vertices_k32_exact.spv.h"

#include "shaders/bin_large_k32s.spv.h"
#include "shaders/bin_large_k32s_exact.spv.h"
#include "shaders/clip_triangles_k32s.spv.h"
#include "shaders/clip_triangles_k32s_exact.spv.h"
#include "shaders/fill_background_k32s.spv.h"
#include "shaders/fill_background_k32s_exact.spv.h"
#include "shaders/pack_colors_k32s.spv.h"
#include "shaders/pack_colors_k32s_exact.spv.h"
#include "shaders/raster_triangles_k32s.spv.h"
#include "shaders/raster_triangles_k32s_exact.spv.h"
#include "shaders/resolve_large_k32s.spv.h"
#include "shaders/resolve_large_k32s_exact.spv.h"
#include "shaders/resolve_large_keys_k32s.spv.h"
#include "shaders/resolve_large_keys_k32s_exact.spv.h"
#include "shaders/resolve_lit_k32s.spv.h"
#include "shaders/resolve_lit_k32s_exact.spv.h"
#include "shaders/resolve_small_k32s.spv.h"
#include "shaders/resolve_small_k32s_exact.spv.h"
#include "shaders/shade_vertices_k32s.spv.h"
#include "shaders/shade_vertices_k32s_exact.spv.h"

#include "vulkan/pipeline_cache.h"

#include <chrono>
#include <exception>
#include <future>

namespace phongvk {

using namespace gpu;

namespace {

struct ShaderCode {
  const uint32_t* spirv;
  size_t bytes;
};

#define SHADER(name) {spirv_##name, sizeof(spirv_##name)}
#define BUILDS(name)                                                                                     \
  {{SHADER(name), SHADER(name##_exact)}, {SHADER(name##_k32), SHADER(name##_k32_exact)}, \
   {SHADER(name##_k32s), SHADER(name##_k32s_exact)}}

// Per pass (passes.h Pass order), for the 64-bit key path, the 32-bit one, and the 32-bit one
// reading its arrays from storage buffers (VulkanContext::storageArrays): the build with the
// device's own division and sqrt, and the `_exact` build that corrects them (shaders/exact_float.h),
// for devices whose own are off.
constexpr ShaderCode SHADERS[][3][2] = {
    BUILDS(shade_vertices), BUILDS(raster_triangles), BUILDS(clip_triangles), BUILDS(resolve_small),
    BUILDS(resolve_large), BUILDS(bin_large), BUILDS(fill_background), BUILDS(pack_colors),
    BUILDS(resolve_lit), BUILDS(resolve_large_keys),
};

#undef BUILDS
#undef SHADER

// A set serves renderers of one build (exact or not) in practice; the key says which all the same.
std::vector<uint32_t> pipelineKey(uint32_t pass, bool exact, const std::vector<SpecConstant>& specs) {
  std::vector<uint32_t> key = {pass, exact};
  for (const SpecConstant& s : specs) key.insert(key.end(), {s.id, s.value});
  return key;
}

}  // namespace

// Compiles the requested pipelines not compiled before, all at once on threads of their own (a
// CPU device compiles each on the calling thread, and on lavapipe the raster, clip and
// large-resolve passes take the longest: docs/PERFORMANCE.md, "Start-up"), and keeps them: a
// sequence that toggles a feature (a ks sweep through 0) compiles each variant once. Every thread
// is joined before any error is rethrown.
// New pipelines go into the pipeline cache on disk (pipeline_cache.h).
void GpuRenderer::compilePipelines(const std::vector<PipelineRequest>& requests) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::pair<std::vector<uint32_t>, std::future<ComputePipeline>>> pending;
  for (const PipelineRequest& r : requests) {
    std::vector<uint32_t> key = pipelineKey(r.shader(), exactFloats_, r.specs);
    if (pipelines_->byKey_.count(key) != 0) continue;
    const int path = context_.storageArrays ? 2 : (context_.info.keys32 ? 1 : 0);
    const ShaderCode code = SHADERS[r.shader()][path][exactFloats_ ? 1 : 0];
    // Only the shade pass has push constants: the chunk of vertices a dispatch shades (ShadeChunk).
    const uint32_t pushBytes = r.shader() == SHADE ? sizeof(ShadeChunk) : 0;
    pending.emplace_back(std::move(key), std::async(std::launch::async, [this, code, pushBytes, specs = r.specs] {
                           return createComputePipeline(context_, code.spirv, code.bytes, bindings_, pushBytes, specs);
                         }));
  }
  std::exception_ptr failure;
  for (auto& [key, compiled] : pending) {
    try {
      pipelines_->byKey_[key] = compiled.get();
    } catch (...) {
      if (!failure) failure = std::current_exception();
    }
  }
  if (failure) std::rethrow_exception(failure);
  if (pending.empty()) return;
  savePipelineCache(context_);
  pipelines_->compileMs_ += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// The pipeline compilePipelines made for `request`.
const ComputePipeline& GpuRenderer::pipeline(const PipelineRequest& request) const {
  return pipelines_->byKey_.at(pipelineKey(request.shader(), exactFloats_, request.specs));
}

void GpuRenderer::selectPipelines(const FrameInputs& in) {
  choices_.clip = std::max(retry_.clipFloor(), in.clip);
  choices_.listChunk = retry_.listChunk();
  const std::vector<PipelineRequest> requests = passRequests(choices_, in.materials, in.lights.size(), in.frame, withKeys_);
  compilePipelines(requests);
  for (const PipelineRequest& r : requests) current_[r.pass] = pipeline(r);
}

}  // namespace phongvk
