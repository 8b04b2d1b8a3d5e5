#include "gpu_renderer.h"

#include "host/vk_check.h"

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
#include "shaders/resolve_small.spv.h"
#include "shaders/resolve_small_exact.spv.h"
#include "shaders/shade_vertices.spv.h"
#include "shaders/shade_vertices_exact.spv.h"
#include "shaders/raster.h"
#include "shaders/shared.h"

#include <algorithm>
#include <cstring>
#include <exception>
#include <future>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace phongvk {

namespace {

using namespace gpu;

constexpr VkBufferUsageFlags STORAGE = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;

// Every pass sees the same descriptor set (shaders/bindings.glsl).
constexpr Binding BINDINGS[] = {
    {BINDING_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},         {BINDING_VERTICES, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER},
    {BINDING_TRIANGLES, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER}, {BINDING_OBJECTS, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER},
    {BINDING_MATERIALS, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER}, {BINDING_LIGHTS, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER},
    {BINDING_SHADED, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},    {BINDING_KEYS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
    {BINDING_COLOR, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},     {BINDING_LARGE, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
    {BINDING_BINS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},     {BINDING_LARGE_SETUPS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
    {BINDING_CLIP_LIST, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}, {BINDING_SHADED_TEXELS, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER},
    {BINDING_LARGE_TEXELS, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER},
    {BINDING_LARGE_SETUP_TEXELS, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER},
    {BINDING_SHADED_COLORS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
    {BINDING_SHADED_COLOR_TEXELS, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER},
    {BINDING_STATUS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER},
};

// The most workgroups one pass launches on this device (shared.h: CPU_DISPATCH_GROUPS).
uint32_t groupCapFor(const VulkanContext& context) {
  return context.properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU ? CPU_DISPATCH_GROUPS : MAX_DISPATCH_GROUPS;
}

uint32_t binsAcross(uint32_t pixels) { return groupCount(pixels, BIN_SIZE); }

// The colour buffer's words: the background and pack passes' work items (an invocation each).
uint32_t colorWords(const FrameData& frame) { return groupCount(3 * frame.width * frame.height, 4); }

// Throws when one array would exceed the device's largest storage buffer binding.
void checkFits(const VulkanContext& context, VkDeviceSize bytes, const char* what) {
  checkDeviceLimit(context, what, bytes, "bytes", "maxStorageBufferRange",
                   context.properties.limits.maxStorageBufferRange);
}

// Throws when a texel view would exceed the device's largest texel buffer.
void checkTexels(const VulkanContext& context, VkDeviceSize texels, const char* what) {
  checkDeviceLimit(context, what, texels, "texels", "maxTexelBufferElements",
                   context.properties.limits.maxTexelBufferElements);
}

// Throws, before anything is allocated, when one of the scene's arrays exceeds a device limit:
// arrays the passes only read are bound as texels alone (maxStorageBufferRange does not apply to
// them); the shaded vertices and the clip list are written as storage buffers.
void checkSceneFits(const VulkanContext& context, const SceneData& data) {
  auto texels = [&](VkDeviceSize bytes, const char* what) { checkTexels(context, bytes / TEXEL_BYTES, what); };
  texels(data.vertices.size() * sizeof(VertexIn), "the vertices");
  texels(data.triangles.size() * sizeof(glm::uvec4), "the triangles");
  texels(data.objects.size() * sizeof(ObjectData), "the objects");
  texels(data.materials.size() * sizeof(MaterialData), "the materials");
  texels(data.lights.size() * sizeof(LightData), "the lights");
  checkFits(context, data.vertices.size() * sizeof(glm::vec4), "the shaded vertex positions");  // and colours
  texels(data.vertices.size() * sizeof(glm::vec4), "the shaded vertex positions");
  checkFits(context, sizeof(IdList) + data.triangles.size() * sizeof(uint32_t), "the clip list");
}

}  // namespace

GpuRenderer::GpuRenderer(const VulkanContext& context, const SceneData& data, WorkLayout layout,
                         ColorOutput output, uint32_t firstGroupCap)
    : context_(context) {
  groupCap_ = firstGroupCap != 0 ? std::min(firstGroupCap, MAX_DISPATCH_GROUPS) : groupCapFor(context_);
  const bool cpu = context_.properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
  const bool cpuLayout = layout == WorkLayout::Cpu || (layout == WorkLayout::Auto && cpu);
  resolveTiles_ = cpuLayout ? 1u : 8u;
  binPass_ = !cpuLayout;
  if (output == ColorOutput::InKeySlots && !hasSharedMemory(context_)) {
    throw std::invalid_argument("colours in the key slots need memory that is device local and host cached");
  }
  colorsInKeys_ = output == ColorOutput::InKeySlots || (output == ColorOutput::Auto && hasSharedMemory(context_));
  try {
    // What the scene's frames will use, all at once; the raster pass's set layout serves every
    // pass (updateDescriptors).
    const std::vector<PipelineRequest> requests =
        requestsFor(data.materials, data.lights.size(), data.interpolation, resolveOutput(false));
    compilePipelines(requests);
    current_[RASTER] = pipeline(requests[RASTER]);
    createDescriptorArena(arena_, context_, 1);
    createTimestampPool(timestamps_, context_, TIMESTAMP_SLOTS);
    uploadScene(data);
  } catch (...) {
    release();
    throw;
  }
}

GpuRenderer::~GpuRenderer() { release(); }

void GpuRenderer::release() {
  for (Buffer* b : {&frame_, &clipList_, &keys_, &bins_, &colors_, &keyReadback_, &status_}) {
    destroyBuffer(*b, context_);
  }
  for (TexelBuffer* t : {&vertices_, &triangles_, &objects_, &materials_, &lights_, &shadedPositions_, &shadedColors_,
                         &large_, &largeSetups_}) {
    destroyTexelBuffer(*t, context_);
  }
  destroyTimestampPool(timestamps_, context_);
  destroyDescriptorArena(arena_, context_);
  for (auto& [key, p] : pipelines_) destroyComputePipeline(p, context_);
  pipelines_.clear();
}

namespace {

struct ShaderCode {
  const uint32_t* spirv;
  size_t bytes;
};

#define SHADER(name) {spirv_##name, sizeof(spirv_##name)}

// Per pass (GpuRenderer::Pass order): the build with the device's own division and sqrt, and the
// `_exact` build that corrects them (shaders/exact_float.h), for devices whose own are off.
constexpr ShaderCode SHADERS[][2] = {
    {SHADER(shade_vertices), SHADER(shade_vertices_exact)},
    {SHADER(raster_triangles), SHADER(raster_triangles_exact)},
    {SHADER(clip_triangles), SHADER(clip_triangles_exact)},
    {SHADER(resolve_small), SHADER(resolve_small_exact)},
    {SHADER(resolve_large), SHADER(resolve_large_exact)},
    {SHADER(bin_large), SHADER(bin_large_exact)},
    {SHADER(fill_background), SHADER(fill_background_exact)},
    {SHADER(pack_colors), SHADER(pack_colors_exact)},
};

#undef SHADER

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

namespace {

std::vector<uint32_t> pipelineKey(uint32_t pass, const std::vector<SpecConstant>& specs) {
  std::vector<uint32_t> key = {pass};
  for (const SpecConstant& s : specs) key.insert(key.end(), {s.id, s.value});
  return key;
}

}  // namespace

// Compiles the requested pipelines not compiled before, all at once on threads of their own (a
// CPU device compiles each on the calling thread: ~30-40 ms apiece for the raster, clip and
// large-resolve passes on lavapipe), and keeps them: a sequence that toggles a feature (a ks
// sweep through 0) compiles each variant once. Every thread is joined before any error is rethrown.
void GpuRenderer::compilePipelines(const std::vector<PipelineRequest>& requests) {
  std::vector<std::pair<std::vector<uint32_t>, std::future<ComputePipeline>>> pending;
  for (const PipelineRequest& r : requests) {
    std::vector<uint32_t> key = pipelineKey(r.pass, r.specs);
    if (pipelines_.count(key) != 0) continue;
    const ShaderCode code = SHADERS[r.pass][context_.floats.useExact() ? 1 : 0];
    pending.emplace_back(std::move(key), std::async(std::launch::async, [this, code, specs = r.specs] {
                           return createComputePipeline(context_, code.spirv, code.bytes, BINDINGS, 0, specs);
                         }));
  }
  std::exception_ptr failure;
  for (auto& [key, compiled] : pending) {
    try {
      pipelines_[key] = compiled.get();
    } catch (...) {
      if (!failure) failure = std::current_exception();
    }
  }
  if (failure) std::rethrow_exception(failure);
}

// The pipeline compilePipelines made for `request`.
const ComputePipeline& GpuRenderer::pipeline(const PipelineRequest& request) const {
  return pipelines_.at(pipelineKey(request.pass, request.specs));
}

// Every pass's pipeline for frames with these materials, lights and interpolation mode, whose
// colours go where `output` says (RESOLVE_OUTPUT_*).
std::vector<GpuRenderer::PipelineRequest> GpuRenderer::requestsFor(const std::vector<MaterialData>& materials,
                                                                   size_t lightCount, uint32_t interpolation,
                                                                   uint32_t output) const {
  std::vector<PipelineRequest> requests = {
      {SHADE, shadeSpecs(materials, lightCount)},
      {RASTER, {}},
      {CLIP, {{SPEC_BIN_PASS, binPass_}}},
      {RESOLVE_SMALL, {{SPEC_INTERPOLATION, interpolation}, {SPEC_RESOLVE_OUTPUT, output}}},
      {RESOLVE_LARGE,
       {{SPEC_INTERPOLATION, interpolation}, {SPEC_RESOLVE_TILES, resolveTiles_}, {SPEC_RESOLVE_OUTPUT, output}}},
  };
  if (binPass_) requests.push_back({BIN_LARGE, {}});
  if (output == RESOLVE_OUTPUT_KEEP_KEYS) requests.push_back({FILL, {}});  // the colour buffer's background
  if (packsColors(output == RESOLVE_OUTPUT_KEEP_KEYS)) requests.push_back({PACK, {}});
  return requests;
}

// Where resolve puts a frame's colours (FrameData.keepKeys, as uploadFrame sets it): frames with
// keys compile their own resolve pipelines when first asked for. Without keys the colours go to
// the key slots, where the host reads them (colorsInKeys_) or the pack pass packs them into the
// colour buffer.
uint32_t GpuRenderer::resolveOutput(bool withKeys) const {
  return withKeys ? RESOLVE_OUTPUT_KEEP_KEYS : RESOLVE_OUTPUT_KEY_SLOTS;
}

bool GpuRenderer::packsColors(bool withKeys) const { return !withKeys && !colorsInKeys_; }

void GpuRenderer::selectPipelines(const FrameInputs& in, bool withKeys) {
  const std::vector<PipelineRequest> requests =
      requestsFor(in.materials, in.lights.size(), in.frame.interpolation, resolveOutput(withKeys));
  compilePipelines(requests);
  for (const PipelineRequest& r : requests) current_[r.pass] = pipeline(r);
}

void GpuRenderer::uploadScene(const SceneData& data) {
  checkSceneFits(context_, data);
  vertexCount_ = static_cast<uint32_t>(data.vertices.size());
  triangleCount_ = static_cast<uint32_t>(data.triangles.size());
  createTexelBuffer(vertices_, context_, data.vertices, MemoryKind::DeviceLocal);
  createTexelBuffer(triangles_, context_, data.triangles, MemoryKind::DeviceLocal);
  // Objects (eye offsets), materials and lights may change per frame: small and host visible.
  createTexelBuffer(objects_, context_, data.objects, MemoryKind::HostVisible);
  createTexelBuffer(materials_, context_, data.materials, MemoryKind::HostVisible);
  createTexelBuffer(lights_, context_, data.lights, MemoryKind::HostVisible);
  lastObjects_ = data.objects;
  lastMaterials_ = data.materials;
  lastLights_ = data.lights;
  createBuffer(frame_, context_, sizeof(FrameData), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, MemoryKind::HostVisible);
  createBuffer(status_, context_, sizeof(FrameStatus), STORAGE, MemoryKind::HostVisible);
  // Written by the shade pass as storage buffers, read by the others as texels.
  const VkDeviceSize shadedBytes = VkDeviceSize(vertexCount_) * sizeof(glm::vec4);
  createTexelBuffer(shadedPositions_, context_, nullptr, shadedBytes, STORAGE, MemoryKind::DeviceLocal);
  createTexelBuffer(shadedColors_, context_, nullptr, shadedBytes, STORAGE, MemoryKind::DeviceLocal);
  const VkDeviceSize clipBytes = sizeof(IdList) + VkDeviceSize(triangleCount_) * sizeof(uint32_t);
  createBuffer(clipList_, context_, clipBytes, STORAGE | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT, MemoryKind::DeviceLocal);

}

// New keys are cleared by the first frame (keysDirty_). Where the host reads the colours from the
// key slots it resets them as it goes, so the next frame need not clear the key buffer; elsewhere
// (the pack pass, frames with keys, frames rendered again) the next frame clears it with one fill,
// which on a GPU is cheaper than resetting the slots from the passes.
void GpuRenderer::ensureImageBuffers(uint32_t width, uint32_t height) {
  if (width == width_ && height == height_) return;
  const VkDeviceSize pixels = VkDeviceSize(width) * height;
  const VkDeviceSize bins = VkDeviceSize(binsAcross(width)) * binsAcross(height);
  checkFits(context_, pixels * sizeof(uint64_t), "the per-pixel depth keys");
  for (Buffer* b : {&keys_, &bins_, &colors_, &keyReadback_}) destroyBuffer(*b, context_);
  // The large triangles' lists grow with the image (shared.h LARGE_*), and further when a frame needs more.
  createLargeBuffers(uint32_t(std::max<VkDeviceSize>(LARGE_ENTRIES_MIN, pixels / LARGE_ENTRY_PIXELS)),
                     std::min<uint32_t>(std::max(triangleCount_, 1u),
                                        uint32_t(std::max<VkDeviceSize>(LARGE_SETUPS_MIN, pixels / LARGE_SETUP_PIXELS))));
  // With the colours in the key slots the host reads and resets the keys in place (Shared memory).
  createBuffer(keys_, context_, pixels * sizeof(uint64_t),
               STORAGE | VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
               colorsInKeys_ ? MemoryKind::Shared : MemoryKind::DeviceLocal);
  createBuffer(bins_, context_, sizeof(BinList) + 3 * bins * sizeof(uint32_t),
               STORAGE | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT, MemoryKind::DeviceLocal);
  keysDirty_ = true;  // the first frame clears the new keys
  width_ = width;
  height_ = height;
  ensureColorBuffer(!colorsInKeys_);  // updates the descriptors
}

// The colour buffer: the whole image when resolve writes colours there (ColorOutput::ColorBuffer,
// or a frame with keys), else 4 bytes that only keep its descriptor valid. The pack pass (or, in
// frames with keys, resolve) writes the colours straight into host-visible memory, where the host
// reads them in place: no device copy.
void GpuRenderer::ensureColorBuffer(bool wholeImage) {
  // RGB bytes, rounded up to whole words for the background and pack passes.
  const VkDeviceSize bytes = wholeImage ? (3 * VkDeviceSize(width_) * height_ + 3) / 4 * 4 : sizeof(uint32_t);
  if (colors_.buffer != VK_NULL_HANDLE && colors_.size >= bytes) return;
  destroyBuffer(colors_, context_);
  createBuffer(colors_, context_, bytes, STORAGE | VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryKind::HostVisible);
  updateDescriptors();
}

// Room for `entries` bin entries and `setups` set-up records of large triangles, replacing any
// there was. Both are written as storage buffers and read by resolve as texels (an entry is one
// texel). Throws, naming the limit, when they would pass the device's.
void GpuRenderer::createLargeBuffers(uint32_t entries, uint32_t setups) {
  const VkDeviceSize largeBytes = sizeof(LargeList) + VkDeviceSize(entries) * sizeof(LargeEntry);
  const VkDeviceSize setupBytes = VkDeviceSize(setups) * sizeof(LargeSetup);
  checkFits(context_, largeBytes, "the large triangles' bin entries");
  checkFits(context_, setupBytes, "the large triangles' set-ups");
  checkTexels(context_, largeBytes / TEXEL_BYTES, "the large triangles' bin entries");
  checkTexels(context_, setupBytes / TEXEL_BYTES, "the large triangles' set-ups");
  destroyTexelBuffer(large_, context_);
  destroyTexelBuffer(largeSetups_, context_);
  createTexelBuffer(large_, context_, nullptr, largeBytes, STORAGE, MemoryKind::DeviceLocal);
  createTexelBuffer(largeSetups_, context_, nullptr, setupBytes, STORAGE, MemoryKind::DeviceLocal);
  largeCapacity_ = entries;
  largeSetupCapacity_ = setups;
}

void GpuRenderer::updateDescriptors() {
  if (set_ != VK_NULL_HANDLE) {
    VK_CHECK(vkResetDescriptorPool(context_.device, arena_.pool, 0));
  }
  const VkDescriptorType storage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  const BufferDescriptor descriptors[] = {
      {BINDING_FRAME, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, frame_.buffer},
      texelDescriptor(BINDING_VERTICES, vertices_),
      texelDescriptor(BINDING_TRIANGLES, triangles_),
      texelDescriptor(BINDING_OBJECTS, objects_),
      texelDescriptor(BINDING_MATERIALS, materials_),
      texelDescriptor(BINDING_LIGHTS, lights_),
      {BINDING_SHADED, storage, shadedPositions_.buffer.buffer},
      {BINDING_SHADED_COLORS, storage, shadedColors_.buffer.buffer},
      {BINDING_KEYS, storage, keys_.buffer},
      {BINDING_COLOR, storage, colors_.buffer},
      {BINDING_LARGE, storage, large_.buffer.buffer},
      texelDescriptor(BINDING_LARGE_TEXELS, large_),
      {BINDING_BINS, storage, bins_.buffer},
      {BINDING_LARGE_SETUPS, storage, largeSetups_.buffer.buffer},
      texelDescriptor(BINDING_LARGE_SETUP_TEXELS, largeSetups_),
      {BINDING_CLIP_LIST, storage, clipList_.buffer},
      {BINDING_STATUS, storage, status_.buffer},
      texelDescriptor(BINDING_SHADED_TEXELS, shadedPositions_),
      texelDescriptor(BINDING_SHADED_COLOR_TEXELS, shadedColors_),
  };
  // Identically defined set layouts are compatible: one set serves every pass.
  set_ = allocateDescriptorSet(context_, arena_, current_[RASTER].setLayout, descriptors);
}

namespace {

template <typename T>
bool sameBytes(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

// Uploads `next` into `buffer` unless it equals what was sent last time; true if it changed.
template <typename T>
bool uploadIfChanged(const VulkanContext& context, Buffer& buffer, const std::vector<T>& next, std::vector<T>& last,
                     const char* what) {
  if (sameBytes(next, last)) return false;
  if (next.size() != last.size() && !last.empty()) {
    throw std::invalid_argument(std::string("a frame may not change the number of ") + what);
  }
  if (!next.empty()) uploadToBuffer(context, buffer, next.data(), next.size() * sizeof(T));
  last = next;
  return true;
}

}  // namespace

// The frame fields that follow the renderer's buffers and workgroup cap, which prepareRetry grows.
void GpuRenderer::setRendererLimits(FrameData& frame) const {
  frame.largeCapacity = largeCapacity_;
  frame.largeSetupCapacity = largeSetupCapacity_;
  frame.groupCap = groupCap_;
}

// Sends only what changed since the last frame. Vertex colours are recomputed only when their
// inputs changed: materials, lights, ambient, or the eye when some material is specular.
void GpuRenderer::uploadFrame(const FrameInputs& in, bool withKeys) {
  const bool materialsChanged = uploadIfChanged(context_, materials_.buffer, in.materials, lastMaterials_, "materials");
  const bool lightsChanged = uploadIfChanged(context_, lights_.buffer, in.lights, lastLights_, "lights");
  const bool objectsChanged = uploadIfChanged(context_, objects_.buffer, in.objects, lastObjects_, "objects");
  const FrameData& f = in.frame;
  // Positions follow the camera basis, the focal length and the objects' offsets (toHomogeneous).
  const bool positionsStale = !framesSent_ || objectsChanged || f.right != lastFrame_.right ||
                              f.up != lastFrame_.up || f.forward != lastFrame_.forward || f.focal != lastFrame_.focal;
  const bool eyeMoved = !framesSent_ || f.eye != lastFrame_.eye;
  const bool ambientChanged = !framesSent_ || f.ambient != lastFrame_.ambient;
  const bool colorsStale = !framesSent_ || materialsChanged || lightsChanged || ambientChanged ||
                           (eyeMoved && !lightingIsViewIndependent(in));
  FrameData frame = f;
  setRendererLimits(frame);
  frame.binsX = binsAcross(frame.width);
  frame.loopProbe = LOOP_PROBE_ITERATIONS;
  frame.binCount = binsAcross(frame.width) * binsAcross(frame.height);
  frame.keepKeys = withKeys ? 1u : 0u;
  frame.colorsInKeys = colorsInKeys_ && !withKeys ? 1u : 0u;
  frame.shadeColors = colorsStale ? 1u : 0u;
  frame.shadePositions = positionsStale ? 1u : 0u;
  uploadToBuffer(context_, frame_, &frame, sizeof(FrameData));
  lastFrame_ = frame;
  ++framesSent_;
  framesShaded_ += colorsStale;
  framesTransformed_ += positionsStale;
}

void GpuRenderer::recordFrame(VkCommandBuffer cmd, const FrameData& frame, bool withKeys) {
  resetTimestamps(cmd, timestamps_);
  if (keysDirty_) vkCmdFillBuffer(cmd, keys_.buffer, 0, VK_WHOLE_SIZE, 0xFFFFFFFFu);  // KEY_CLEAR everywhere
  const VkDeviceSize binBytes = VkDeviceSize(frame.binCount) * sizeof(uint32_t);
  vkCmdFillBuffer(cmd, bins_.buffer, sizeof(BinList), binBytes, 0u);                   // no flags
  vkCmdFillBuffer(cmd, bins_.buffer, sizeof(BinList) + binBytes, binBytes, LIST_END);  // empty lists
  const BinList noBins = {0, 0, 1, 1};
  vkCmdUpdateBuffer(cmd, bins_.buffer, 0, sizeof noBins, &noBins);
  const LargeList emptyList = {0, 0, 0, 0};
  vkCmdUpdateBuffer(cmd, large_.buffer.buffer, 0, sizeof emptyList, &emptyList);
  const IdList noClipping = {0, 0, 1, 1, 0, 1, 1, 0};
  vkCmdUpdateBuffer(cmd, clipList_.buffer, 0, sizeof noClipping, &noClipping);
  transferToComputeBarrier(cmd);

  auto bind = [&](Pass pass) {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, current_[pass].pipeline);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, current_[pass].layout, 0, 1, &set_, 0, nullptr);
  };
  writeTimestamp(cmd, timestamps_, 0);
  const uint32_t cap = frame.groupCap;
  if (withKeys) {  // untouched bins are not resolved: their pixels keep this fill
    bind(FILL);
    vkCmdDispatch(cmd, std::min(groupCount(colorWords(frame), FILL_GROUP_SIZE), cap), 1, 1);
  }
  if (frame.shadeColors != 0u || frame.shadePositions != 0u) {  // else last frame's still hold
    bind(SHADE);
    vkCmdDispatch(cmd, std::min(groupCount(vertexCount_, SHADE_GROUP_SIZE), cap), 1, 1);
    computeBarrier(cmd);
  }
  writeTimestamp(cmd, timestamps_, 1);
  bind(RASTER);
  vkCmdDispatch(cmd, std::min(groupCount(triangleCount_, SETUP_GROUP_SIZE), cap), 1, 1);
  computeBarrier(cmd);
  bind(CLIP);
  vkCmdDispatchIndirect(cmd, clipList_.buffer, offsetof(IdList, groupsX));
  computeBarrier(cmd);
  if (binPass_) {
    bind(BIN_LARGE);
    vkCmdDispatchIndirect(cmd, clipList_.buffer, offsetof(IdList, binGroupsX));
    computeBarrier(cmd);
  }
  writeTimestamp(cmd, timestamps_, 2);
  // Small reads the keys large left. The barrier after the last one also keeps lavapipe from
  // writing the next timestamp before the dispatch ends.
  for (Pass pass : {RESOLVE_LARGE, RESOLVE_SMALL}) {
    bind(pass);
    vkCmdDispatchIndirect(cmd, bins_.buffer, offsetof(BinList, groupsX));
    computeBarrier(cmd);
  }
  if (packsColors(withKeys)) {  // the colours from the key slots into the colour buffer
    bind(PACK);
    vkCmdDispatch(cmd, std::min(groupCount(colorWords(frame), PACK_GROUP_SIZE), cap), 1, 1);
    computeBarrier(cmd);
  }
  writeTimestamp(cmd, timestamps_, 3);
  if (withKeys) {  // resolve left the final keys (frame.keepKeys): copy them; the next frame clears them
    memoryBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                  VK_ACCESS_TRANSFER_READ_BIT);
    VkBufferCopy keyCopy = {0, 0, VkDeviceSize(frame.width) * frame.height * sizeof(uint64_t)};
    vkCmdCopyBuffer(cmd, keys_.buffer, keyReadback_.buffer, 1, &keyCopy);
  }
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

RenderOutput GpuRenderer::render(const FrameInputs& in, bool withKeys) {
  ensureImageBuffers(in.frame.width, in.frame.height);
  const VkDeviceSize pixels = VkDeviceSize(width_) * height_;
  if (withKeys && keyReadback_.buffer == VK_NULL_HANDLE) {
    createBuffer(keyReadback_, context_, pixels * sizeof(uint64_t), VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                 MemoryKind::HostVisible);
  }
  uploadFrame(in, withKeys);
  selectPipelines(in, withKeys);
  if (lastFrame_.colorsInKeys == 0u) ensureColorBuffer(true);
  while (!renderAttempt(withKeys)) {
  }

  RenderOutput out;
  out.image = readImage(lastFrame_);
  if (withKeys) {
    out.keys.resize(pixels);
    readFromBuffer(context_, keyReadback_, out.keys.data(), pixels * sizeof(uint64_t));
  }
  return out;
}

// Renders the uploaded frame once; false when it must be rendered again (prepareRetry has grown
// what it lacked).
bool GpuRenderer::renderAttempt(bool withKeys) {
  auto* status = static_cast<FrameStatus*>(status_.mapped);
  *status = {};  // coherent memory: the device sees it at submission
  VkCommandBuffer cmd = beginOneTimeCommands(context_);
  recordFrame(cmd, lastFrame_, withKeys);  // as uploaded (bin counts included); clears keysDirty_ keys first
  // What this frame leaves in the key slots for the next to clear: its final keys (withKeys), or
  // its colours, unless the host resets those as it reads them (readImage; the pack pass does not).
  keysDirty_ = true;
  submitAndWait(context_, cmd);
  readTimes();
  if (status->flags == 0u) return true;
  prepareRetry(status->flags);
  return false;
}

// Makes room for what the last attempt lacked (STATUS_* flags): twice the large triangles' lists,
// or 16 times the workgroups per pass. The attempt's keys and colours are thrown away, and the
// next one transforms and relights the vertices (a cut-short shade pass may have left some out).
void GpuRenderer::prepareRetry(uint32_t statusFlags) {
  if (statusFlags & STATUS_LARGE_OVERFLOW) {
    createLargeBuffers(uint32_t(std::min<uint64_t>(2ull * largeCapacity_, UINT32_MAX - 1)),
                       uint32_t(std::min<uint64_t>(2ull * largeSetupCapacity_, UINT32_MAX)));
    updateDescriptors();
  } else if (groupCap_ < MAX_DISPATCH_GROUPS) {
    groupCap_ = std::min(groupCap_ * 16u, MAX_DISPATCH_GROUPS);
  } else {
    throw std::runtime_error("scene too large for " + context_.report.name +
                             ": a pass needs more loop iterations per invocation than the device allows, even with " +
                             std::to_string(groupCap_) + " workgroups");
  }
  keysDirty_ = true;
  ++framesRepeated_;
  setRendererLimits(lastFrame_);
  lastFrame_.shadeColors = 1u;
  lastFrame_.shadePositions = 1u;
  uploadToBuffer(context_, frame_, &lastFrame_, sizeof(FrameData));
}

namespace {

// The image in the key slots resolve left (FrameData.colorsInKeys): a slot's colour, or the
// background where resolve left KEY_CLEAR; every slot is reset to KEY_CLEAR for the next frame.
Image imageFromKeySlots(std::span<uint64_t> slots, uint32_t background, int width, int height) {
  Image image(width, height);
  auto take = [&](size_t i) {
    const uint64_t slot = slots[i];
    if (slot == KEY_CLEAR) return background;
    slots[i] = KEY_CLEAR;
    return uint32_t(slot);
  };
  size_t i = 0;
  for (; i + 4 <= slots.size(); i += 4) image.setPackedFour(i, take(i), take(i + 1), take(i + 2), take(i + 3));
  for (; i < slots.size(); ++i) image.setPacked(i, take(i));
  return image;
}

}  // namespace

// The frame's image, read where resolve wrote it (host-visible, coherent; submitAndWait's closing
// barrier made the writes visible to the host): no copy first.
Image GpuRenderer::readImage(const FrameData& frame) {
  const size_t pixels = size_t(width_) * height_;
  if (frame.colorsInKeys == 0u) {
    // Resolve wrote the image's own layout: one copy, into storage not zero-filled first (that pass
    // cost a third of the copy: 1385x923 0.099 -> 0.067 ms, 4K 1.69 -> 1.10 ms, median of 21).
    Image image;
    image.width = int(width_);
    image.height = int(height_);
    const auto* bytes = static_cast<const uint8_t*>(colors_.mapped);
    image.rgb.assign(bytes, bytes + 3 * pixels);
    return image;
  }
  Image image = imageFromKeySlots({static_cast<uint64_t*>(keys_.mapped), pixels}, packColor(frame.background),
                                  int(width_), int(height_));
  keysDirty_ = false;
  return image;
}

}  // namespace phongvk
