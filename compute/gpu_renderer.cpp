// gpu_renderer.cpp — the compute port's frame loop: upload what changed, record the passes, submit,
// render again if the frame ran out of room or loop iterations, read the image. Its parts live in
// gpu_pipelines.cpp (which passes, compiled how), gpu_buffers.cpp (buffers, uploads, what changed),
// gpu_recording.cpp (the command buffer) and gpu_readback.cpp (the image).
#include "compute/gpu_renderer.h"

#include "vulkan/float_probe.h"
#include "vulkan/vk_check.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace phongvk {

using namespace gpu;

namespace {

// The most workgroups one pass launches on this device (gpu_layout.h: CPU_DISPATCH_GROUPS).
uint32_t groupCapFor(const VulkanContext& context) {
  return context.properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU ? CPU_DISPATCH_GROUPS : MAX_DISPATCH_GROUPS;
}

}  // namespace

GpuPipelineSet::~GpuPipelineSet() = default;  // each pipeline frees itself (ComputePipeline)

GpuRenderer::GpuRenderer(const VulkanContext& context, const SceneData& data, const GpuRendererOptions& options)
    : context_(context),
      options_(options),
      exactFloats_(options.exactFloats ? *options.exactFloats : probeFloatOps(context).useExact()),
      retry_(groupCapFor(context), options.firstGroupCap, options.firstListChunk),
      pipelines_(options.pipelines ? options.pipelines : std::make_shared<GpuPipelineSet>(context)),
      bindings_(sharedBindings(context)) {
  const bool cpu = context_.properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
  const bool cpuLayout = options.layout == WorkLayout::Cpu || (options.layout == WorkLayout::Auto && cpu);
  choices_.resolveTiles = cpuLayout ? 1u : 8u;
  choices_.binPass = !cpuLayout || context_.storageArrays;  // the _k32s clip pass never links (raster_loops.glsl)
  choices_.keys32 = context_.info.keys32;
  if (options.output == ColorOutput::InKeySlots && !hasSharedMemory(context_)) {
    throw ArgumentError("colours in the key slots need memory that is device local and host cached");
  }
  choices_.colorsInKeys = options.output == ColorOutput::InKeySlots ||
                          (options.output == ColorOutput::Auto && hasSharedMemory(context_));
  choices_.clip = options.clip;
  try {
    checkSceneFits(data);
    compileSceneModes(data);
    createTimestampPool(timestamps_, context_, TIMESTAMP_SLOTS);
    createFrameBuffers();
    uploadScene(data);
  } catch (...) {
    release();
    throw;
  }
}

GpuRenderer::~GpuRenderer() { release(); }

// What the scene's frames will use, compiled all at once; the raster pass's set layout serves
// every pass (updateDescriptors).
void GpuRenderer::compileSceneModes(const SceneData& data) {
  FrameData modes{};
  modes.interpolation = data.interpolation;
  modes.shading = data.shading;
  modes.specular = data.specular;
  modes.projection = data.projection;
  choices_.textured = !data.uvs.empty();
  choices_.shadows = data.shadowed;
  choices_.quads = hasQuads(data);
  const glm::uvec2 points = pointQuadRange(data);
  choices_.points = points.x < points.y;
  choices_.unlit = everyVertexUnlit(data);
  choices_.keptList = choices_.keys32 && keptList(uint32_t(data.triangles.size()));
  const std::vector<PipelineRequest> requests = passRequests(choices_, data.materials, data.lights.size(), modes, false);
  compilePipelines(requests);
  current_[RASTER] = pipeline(requests[RASTER]);
}

void GpuRenderer::replaceScene(const SceneData& data, uint32_t clip) {
  checkSceneFits(data);  // before anything is released
  scene_ = {};  // the old meshes go before the new ones are allocated
  choices_.clip = std::max(retry_.clipFloor(), clip);
  retry_.restart();
  compileSceneModes(data);
  uploadScene(data);
  if (width_ != 0) createLargeBuffersFor(VkDeviceSize(width_) * height_);  // sized for this scene's triangles
  keysDirty_ = true;
  updateDescriptors();
}

void GpuRenderer::release() {
  scene_ = {};
  image_ = {};
  perFrame_ = {};
  timestamps_.reset();
  arena_.reset();
  arenaSets_ = 0;
}

RenderOutput GpuRenderer::render(const FrameInputs& in, bool withKeys, Image storage) {
  withKeys_ = withKeys;
  ensureImageBuffers(in.frame.width, in.frame.height);
  const VkDeviceSize pixels = VkDeviceSize(width_) * height_;
  if (withKeys && image_.keyReadback.buffer == VK_NULL_HANDLE) {
    createBuffer(image_.keyReadback, context_, pixels * sizeof(uint64_t), VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                 MemoryKind::HostVisible);
  }
  uploadFrame(in);
  selectPipelines(in);
  if (!frameColorsInKeys_) ensureColorBuffer(true);
  while (!renderAttempt()) selectPipelines(in);  // the clip pass may now clip, the lists be taken in chunks

  RenderOutput out;
  out.image = readImage(std::move(storage));
  if (withKeys) {
    out.keys.resize(pixels);
    readFromBuffer(context_, image_.keyReadback, out.keys.data(), pixels * sizeof(uint64_t));
  }
  return out;
}

// Renders the uploaded frame once; false when it must be rendered again (prepareRetry has grown
// what it lacked). With the bins' lists taken in chunks (RetryPolicy::listChunk), the first submission ends
// after resolve_large's first round; the rounds it asks for (STATUS_MORE_ROUNDS) are submitted one
// by one, then the rest of the frame.
bool GpuRenderer::renderAttempt() {
  auto* status = static_cast<FrameStatus*>(perFrame_.status.mapped);
  *status = {};  // coherent memory: the device sees it at submission
  VkCommandBuffer cmd = beginOneTimeCommands(context_);
  recordFrame(cmd);  // as uploaded (bin counts included); clears keysDirty_ keys first
  // What this frame leaves in the key slots for the next to clear: its final keys (withKeys), or
  // its colours, unless the host resets those as it reads them (readImage; the pack pass does not).
  keysDirty_ = true;
  submitAndWait(context_, cmd);
  if (choices_.listChunk != 0u) {
    while (status->flags == STATUS_MORE_ROUNDS) submitResolveRound(&GpuRenderer::recordResolveLargeRound);
    if (status->flags == 0u) submitResolveRound(&GpuRenderer::recordResolveTail);
  }
  readTimes();
  if (status->flags == 0u) return true;
  prepareRetry(status->flags);
  return false;
}

// One more submission of the frame's resolve (lists in chunks): the status cleared, then what `record`
// records, after a barrier on everything submitted before it.
void GpuRenderer::submitResolveRound(void (GpuRenderer::*record)(VkCommandBuffer)) {
  *static_cast<FrameStatus*>(perFrame_.status.mapped) = {};
  VkCommandBuffer cmd = beginOneTimeCommands(context_);
  computeBarrier(cmd);
  (this->*record)(cmd);
  submitAndWait(context_, cmd);
}

// Makes room for what the last attempt lacked (STATUS_* flags), as the retry policy says
// (retry_policy.h); render selects the pipelines for a new clipper or list chunks. The attempt's
// keys and colours are thrown away, and the next one transforms and relights the vertices (a
// cut-short shade pass may have left some out).
void GpuRenderer::prepareRetry(uint32_t statusFlags) {
  if (retry_.next(statusFlags, context_.info.name, choices_.shadows) == RetryPolicy::Step::GrowLists) {
    createLargeBuffers(uint32_t(std::min<uint64_t>(2ull * largeCapacity_, UINT32_MAX - 1)),
                       uint32_t(std::min<uint64_t>(2ull * largeSetupCapacity_, UINT32_MAX)));
    updateDescriptors();
  }
  keysDirty_ = true;
  control_.shadeColors = 1u;
  control_.shadePositions = 1u;
  writeControl();
}

void GpuRenderer::readTimes() {
  const std::vector<double> t = readTimestamps(context_, timestamps_);
  if (t.size() < TIMESTAMP_SLOTS) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    times_ = {nan, nan, nan, nan};
    return;
  }
  times_ = {t[1] - t[0], t[2] - t[1], t[3] - t[2], t[3] - t[0]};  // raster: triangle + clip
}

}  // namespace phongvk
