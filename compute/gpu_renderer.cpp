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
      pipelines_(options.pipelines ? options.pipelines : std::make_shared<GpuPipelineSet>(context)),
      bindings_(sharedBindings(context)) {
  startRetries();
  const bool cpu = context_.properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
  const bool cpuLayout = options.layout == WorkLayout::Cpu || (options.layout == WorkLayout::Auto && cpu);
  resolveTiles_ = cpuLayout ? 1u : 8u;
  binPass_ = !cpuLayout || context_.info.keys32;  // the 32-bit key path's clip pass never links (raster_loops.glsl)
  if (options.output == ColorOutput::InKeySlots && !hasSharedMemory(context_)) {
    throw ArgumentError("colours in the key slots need memory that is device local and host cached");
  }
  colorsInKeys_ = options.output == ColorOutput::InKeySlots ||
                  (options.output == ColorOutput::Auto && hasSharedMemory(context_));
  frameClip_ = options.clip;
  try {
    checkSceneFits(data);
    compileSceneModes(data);
    createDescriptorArena(arena_, context_, 1, std::size(SHARED_BINDINGS));
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
  const std::vector<PipelineRequest> requests = requestsFor(data.materials, data.lights.size(), modes, false);
  compilePipelines(requests);
  current_[RASTER] = pipeline(requests[RASTER]);
}

// The workgroup cap and list chunks a first frame starts from (prepareRetry grows them).
void GpuRenderer::startRetries() {
  groupCap_ = options_.firstGroupCap != 0 ? std::min(options_.firstGroupCap, MAX_DISPATCH_GROUPS) : groupCapFor(context_);
  listChunk_ = options_.firstListChunk;
}

void GpuRenderer::replaceScene(const SceneData& data, uint32_t clip) {
  checkSceneFits(data);  // before anything is released
  scene_ = {};  // the old meshes go before the new ones are allocated
  frameClip_ = std::max(clipFloor_, clip);
  compileSceneModes(data);
  uploadScene(data);
  startRetries();
  if (width_ != 0) createLargeBuffersFor(VkDeviceSize(width_) * height_);  // sized for this scene's triangles
  keysDirty_ = true;
  framesSent_ = 0;  // the next frame sends and shades everything
  updateDescriptors();
}

void GpuRenderer::release() {
  scene_ = {};
  image_ = {};
  perFrame_ = {};
  timestamps_.reset();
  arena_.reset();
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
// what it lacked). With the bins' lists taken in chunks (listChunk_), the first submission ends
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
  if (listChunk_ != 0u) {
    while (status->flags == STATUS_MORE_ROUNDS) submitResolveRound(&GpuRenderer::recordResolveLargeRound);
    if (status->flags == 0u) submitResolveRound(&GpuRenderer::recordResolveTail);
  }
  readTimes();
  if (status->flags == 0u) return true;
  prepareRetry(status->flags);
  return false;
}

// One more submission of the frame's resolve (listChunk_): the status cleared, then what `record`
// records, after a barrier on everything submitted before it.
void GpuRenderer::submitResolveRound(void (GpuRenderer::*record)(VkCommandBuffer)) {
  *static_cast<FrameStatus*>(perFrame_.status.mapped) = {};
  VkCommandBuffer cmd = beginOneTimeCommands(context_);
  computeBarrier(cmd);
  (this->*record)(cmd);
  submitAndWait(context_, cmd);
}

// Makes room for what the last attempt lacked (STATUS_* flags): the clipper (kept for
// the renderer's later frames), or twice the large triangles' lists,
// or 16 times the workgroups per pass, or, with the most workgroups, the bins' lists taken in
// chunks of LIST_CHUNK_FIRST entries and then a quarter as many each time (gpu_layout.h). The
// attempt's keys and colours are thrown away, and the next one transforms and relights the
// vertices (a cut-short shade pass may have left some out). The new sizes are kept for later frames.
void GpuRenderer::prepareRetry(uint32_t statusFlags) {
  if (statusFlags & STATUS_NEEDS_CLIPPING) {
    clipFloor_ = CLIP_ALL;  // render selects the clip pass with the clipper
  } else if (statusFlags & STATUS_LARGE_OVERFLOW) {
    createLargeBuffers(uint32_t(std::min<uint64_t>(2ull * largeCapacity_, UINT32_MAX - 1)),
                       uint32_t(std::min<uint64_t>(2ull * largeSetupCapacity_, UINT32_MAX)));
    updateDescriptors();
  } else if (groupCap_ < MAX_DISPATCH_GROUPS) {
    groupCap_ = std::min(groupCap_ * 16u, MAX_DISPATCH_GROUPS);
  } else if (listChunk_ == 0u || listChunk_ > LIST_CHUNK_MIN) {
    listChunk_ = listChunk_ == 0u ? LIST_CHUNK_FIRST : listChunk_ / 4u;  // render selects its pipelines
  } else {
    throw DeviceError("scene too large for " + context_.info.name +
                             ": a pass needs more loop iterations per invocation than the device allows, even with " +
                             std::to_string(groupCap_) + " workgroups and the large triangles' lists taken " +
                             std::to_string(listChunk_) + " entries at a time");
  }
  keysDirty_ = true;
  ++framesRepeated_;
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
