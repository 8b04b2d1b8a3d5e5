// graphics_renderer.cpp — the graphics-pipeline baseline: one indexed draw per run of objects that
// share a cull mode, into an RGBA8 colour and a reversed-Z float depth attachment, copied out.
#include "graphics/graphics_renderer.h"
#include "vulkan/pipeline_cache.h"

#include "graphics/graphics_pipeline.h"
#include "image/packed_pixels.h"
#include "vulkan/pipelines.h"
#include "vulkan/resources.h"
#include "vulkan/submit.h"
#include "vulkan/vk_check.h"

#include <cstdint>  // the generated SPIR-V headers use uint32_t without including it
#include "shaders/gouraud.h"
#include "shaders/graphics_baseline_frag.spv.h"
#include "shaders/graphics_baseline_vert.spv.h"
#include "shaders/shared.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace phongvk {

namespace {

using namespace gpu;

constexpr VkFormat COLOR_FORMAT = VK_FORMAT_R8G8B8A8_UNORM;  // bytes as imageFromPacked reads them
// Reversed-Z in 32-bit float: relative depth precision is the same near and far (docs/DESIGN.md
// "Visibility" asks that a 1 m object 1e5 m away not speckle).
constexpr VkFormat DEPTH_FORMAT = VK_FORMAT_D32_SFLOAT;
constexpr float DEPTH_CLEAR = 0.0f;  // the far plane
// Nearer is larger. Strictly greater: on a tie the fragment drawn first stays, as the lower
// triangle id wins in the reference (see DrawRun).
constexpr VkCompareOp DEPTH_COMPARE = VK_COMPARE_OP_GREATER;

// The vertex shader's buffers (shaders/bindings.glsl); the fragment shader reads none.
constexpr Binding BINDINGS[] = {sharedBinding(BINDING_FRAME), sharedBinding(BINDING_VERTICES),
                                sharedBinding(BINDING_OBJECTS), sharedBinding(BINDING_MATERIALS),
                                sharedBinding(BINDING_LIGHTS)};

enum Timestamp { DRAW_BEGIN, DRAW_END, TIMESTAMP_COUNT };

// Consecutive triangles whose objects share a cull mode: one draw each, in triangle order, so
// the depth test's tie rule (the first drawn stays) picks the lower triangle id as the reference.
struct DrawRun {
  uint32_t firstTriangle;
  uint32_t triangleCount;
  bool cullBack;
};

std::vector<DrawRun> drawRuns(const SceneData& data) {
  std::vector<DrawRun> runs;
  for (uint32_t t = 0; t < data.triangles.size(); ++t) {
    const bool cullBack = (data.objects[data.triangles[t].w].flags & OBJECT_CULL_BACK) != 0;
    if (runs.empty() || runs.back().cullBack != cullBack) runs.push_back({t, 0, cullBack});
    ++runs.back().triangleCount;
  }
  return runs;
}

std::vector<uint32_t> triangleIndices(const SceneData& data) {
  std::vector<uint32_t> indices;
  indices.reserve(data.triangles.size() * 3);
  for (const glm::uvec4& t : data.triangles) indices.insert(indices.end(), {t.x, t.y, t.z});
  return indices;
}

// Throws when the scene exceeds a limit of the draw: texel buffer size (the vertex shader reads the
// vertices as texels; no storage buffer holds them), index values and count.
void checkSceneFits(const VulkanContext& context, const SceneData& data) {
  const VkPhysicalDeviceLimits& limits = context.properties.limits;
  const uint64_t vertexBytes = uint64_t(data.vertices.size()) * sizeof(VertexIn);
  checkDeviceLimit(context, "the vertices", vertexBytes / TEXEL_BYTES, "", "maxTexelBufferElements",
                   limits.maxTexelBufferElements);
  if (!data.vertices.empty()) {
    checkDeviceLimit(context, "the vertex indices", data.vertices.size() - 1, "", "maxDrawIndexedIndexValue",
                     limits.maxDrawIndexedIndexValue);
  }
  checkDeviceLimit(context, "the indices", uint64_t(data.triangles.size()) * 3, "", "a 32-bit index count",
                   std::numeric_limits<uint32_t>::max());
}

// The context's queue was chosen for compute; this renderer also draws on it.
void checkGraphicsQueue(const VulkanContext& context) {
  uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(context.physicalDevice, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(context.physicalDevice, &count, families.data());
  if (!(families.at(context.queueFamily).queueFlags & VK_QUEUE_GRAPHICS_BIT))
    throw DeviceError("the graphics backend needs graphics on " + context.info.name + "'s queue family " +
                             std::to_string(context.queueFamily) + ", which only has compute");
}

void checkImageSize(const VulkanContext& context, uint32_t width, uint32_t height) {
  const VkPhysicalDeviceLimits& limits = context.properties.limits;
  const uint32_t limit = std::min(limits.maxImageDimension2D, std::min(limits.maxFramebufferWidth,
                                                                       limits.maxFramebufferHeight));
  if (width == 0 || height == 0 || width > limit || height > limit)
    throw DeviceError("image size " + std::to_string(width) + "x" + std::to_string(height) +
                             " is not between 1 and " + context.info.name + "'s largest framebuffer (" +
                             std::to_string(limit) + ")");
}

// The background as the attachment's clear value, already rounded as the reference rounds it
// (packColor): k / 255 converts back to exactly k, whatever rounding the device's clear uses.
VkClearColorValue backgroundClear(const FrameData& frame) {
  const uint32_t packed = packColor(frame.background);
  VkClearColorValue value = {};
  for (int c = 0; c < 4; ++c) value.float32[c] = float((packed >> (8 * c)) & 0xFFu) / 255.0f;
  return value;
}

template <typename T>
void createFilled(Buffer& buffer, const VulkanContext& context, const std::vector<T>& data, VkBufferUsageFlags usage,
                  MemoryKind kind) {
  createBuffer(buffer, context, data.size() * sizeof(T), usage, kind);
  if (!data.empty()) uploadToBuffer(context, buffer, data.data(), data.size() * sizeof(T));
}

// Per-frame arrays must keep the scene's sizes: the buffers were made for them.
template <typename T>
void uploadSameSize(const VulkanContext& context, Buffer& buffer, const std::vector<T>& data, size_t expected,
                    const char* what) {
  if (data.size() != expected)
    throw ArgumentError(std::string("a frame may not change the number of ") + what);
  if (!data.empty()) uploadToBuffer(context, buffer, data.data(), data.size() * sizeof(T));
}

}  // namespace

struct GraphicsRenderer::State {
  explicit State(const VulkanContext& context) : context(context) {}

  void createFixedObjects();
  void uploadScene(const SceneData& data);
  void ensureTargets(uint32_t width, uint32_t height);
  void releaseTargets();
  void uploadFrame(const FrameInputs& in);
  VkPipeline pipelineFor(uint32_t interpolation, uint32_t projection, bool cullBack);
  void recordFrame(VkCommandBuffer cmd, const FrameData& frame);
  void readTime();

  const VulkanContext& context;
  GraphicsLayout layout;
  RenderPass renderPass;
  // [projection][interpolation][cullBack], made when a frame first needs one
  GraphicsPipeline pipelines[2][2][2];
  DescriptorArena arena;
  VkDescriptorSet set = VK_NULL_HANDLE;
  TimestampPool timestamps;
  double deviceMs = std::numeric_limits<double>::quiet_NaN();

  Buffer frame, indices;
  TexelBuffer vertices, objects, materials, lights;
  size_t objectCount = 0, materialCount = 0, lightCount = 0;
  std::vector<DrawRun> runs;

  RenderTarget color, depth;
  Framebuffer framebuffer;
  Buffer readback;
  uint32_t width = 0, height = 0;
};

void GraphicsRenderer::State::createFixedObjects() {
  checkGraphicsQueue(context);
  layout = createGraphicsLayout(context, BINDINGS);
  renderPass = createColorDepthRenderPass(context, COLOR_FORMAT, DEPTH_FORMAT);
  createDescriptorArena(arena, context, 1);
  createTimestampPool(timestamps, context, TIMESTAMP_COUNT);
}

void GraphicsRenderer::State::uploadScene(const SceneData& data) {
  checkSceneFits(context, data);
  // The shaders read the scene's arrays as texels (bindings.glsl), as the compute port does.
  createTexelBuffer(vertices, context, data.vertices, MemoryKind::DeviceLocal);
  createFilled(indices, context, triangleIndices(data), VK_BUFFER_USAGE_INDEX_BUFFER_BIT, MemoryKind::DeviceLocal);
  // Objects (eye offsets), materials and lights may change per frame: small and host visible.
  createTexelBuffer(objects, context, data.objects, MemoryKind::HostVisible);
  createTexelBuffer(materials, context, data.materials, MemoryKind::HostVisible);
  createTexelBuffer(lights, context, data.lights, MemoryKind::HostVisible);
  createBuffer(frame, context, sizeof(FrameData), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, MemoryKind::HostVisible);
  objectCount = data.objects.size();
  materialCount = data.materials.size();
  lightCount = data.lights.size();
  runs = drawRuns(data);

  const BufferDescriptor descriptors[] = {
      bufferDescriptor(BINDING_FRAME, frame), texelDescriptor(sharedBinding(BINDING_VERTICES), vertices),
      texelDescriptor(sharedBinding(BINDING_OBJECTS), objects), texelDescriptor(sharedBinding(BINDING_MATERIALS), materials),
      texelDescriptor(sharedBinding(BINDING_LIGHTS), lights),
  };
  set = allocateDescriptorSet(context, arena, layout.setLayout, descriptors);
}

void GraphicsRenderer::State::releaseTargets() {
  framebuffer.reset();
  color.reset();
  depth.reset();
  destroyBuffer(readback, context);
  width = height = 0;
}

void GraphicsRenderer::State::ensureTargets(uint32_t w, uint32_t h) {
  if (w == width && h == height) return;
  checkImageSize(context, w, h);
  releaseTargets();
  createRenderTarget(color, context, COLOR_FORMAT, w, h,
                     VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, VK_IMAGE_ASPECT_COLOR_BIT);
  // Never stored: the driver may keep depth in fast memory (tile memory on mobile GPUs).
  createRenderTarget(depth, context, DEPTH_FORMAT, w, h,
                     VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT,
                     VK_IMAGE_ASPECT_DEPTH_BIT);
  const VkImageView views[] = {color.view, depth.view};
  VkFramebufferCreateInfo info = { VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO };
  info.renderPass = renderPass.pass;
  info.attachmentCount = static_cast<uint32_t>(std::size(views));
  info.pAttachments = views;
  info.width = w;
  info.height = h;
  info.layers = 1;
  framebuffer = Framebuffer({}, context);
  VK_CHECK(vkCreateFramebuffer(context.device, &info, nullptr, &framebuffer.framebuffer));
  createBuffer(readback, context, VkDeviceSize(w) * h * sizeof(uint32_t), VK_BUFFER_USAGE_TRANSFER_DST_BIT,
               MemoryKind::HostVisible);
  width = w;
  height = h;
}

// Everything per frame is small and host visible: the vertex shader recomputes every colour
// anyway (there is no shaded-vertex buffer to keep), so nothing is gained by skipping uploads.
void GraphicsRenderer::State::uploadFrame(const FrameInputs& in) {
  uploadSameSize(context, objects.buffer, in.objects, objectCount, "objects");
  uploadSameSize(context, materials.buffer, in.materials, materialCount, "materials");
  uploadSameSize(context, lights.buffer, in.lights, lightCount, "lights");
  uploadToBuffer(context, frame, &in.frame, sizeof(FrameData));
}

VkPipeline GraphicsRenderer::State::pipelineFor(uint32_t interpolation, uint32_t projection, bool cullBack) {
  if (interpolation != INTERP_PERSPECTIVE && interpolation != INTERP_SCREEN)
    throw ArgumentError("unknown interpolation mode " + std::to_string(interpolation));
  if (projection != PROJECTION_PERSPECTIVE && projection != PROJECTION_ORTHOGRAPHIC)
    throw ArgumentError("unknown projection " + std::to_string(projection));
  GraphicsPipeline& pipeline = pipelines[projection][interpolation][cullBack];
  if (pipeline.pipeline) return pipeline.pipeline;
  GraphicsPipelineInfo info;
  info.vertexSpirv = spirv_graphics_baseline_vert;
  info.fragmentSpirv = spirv_graphics_baseline_frag;
  info.specs = {{SPEC_INTERPOLATION, interpolation}, {SPEC_LIGHT_COUNT, uint32_t(lightCount)}};
  // Only where it differs from the default: perspective pipelines keep their cache entries.
  if (projection != PROJECTION_PERSPECTIVE) info.specs.push_back({SPEC_PROJECTION, projection});
  info.layout = layout.layout;
  info.renderPass = renderPass.pass;
  info.cullMode = cullBack ? VK_CULL_MODE_BACK_BIT : VK_CULL_MODE_NONE;
  // Our front faces are counter-clockwise seen from outside, which stays counter-clockwise on
  // the y-down screen (edges.h setupEdges); Vulkan's framebuffer is y-down too.
  info.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  info.depthCompare = DEPTH_COMPARE;
  pipeline = createGraphicsPipeline(context, info);
  savePipelineCache(context);
  return pipeline.pipeline;
}

void GraphicsRenderer::State::recordFrame(VkCommandBuffer cmd, const FrameData& f) {
  VkClearValue clears[2] = {};
  clears[0].color = backgroundClear(f);
  clears[1].depthStencil = {DEPTH_CLEAR, 0};
  VkRenderPassBeginInfo begin = { VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO };
  begin.renderPass = renderPass.pass;
  begin.framebuffer = framebuffer.framebuffer;
  begin.renderArea = {{0, 0}, {width, height}};
  begin.clearValueCount = 2;
  begin.pClearValues = clears;
  const VkViewport viewport = {0.0f, 0.0f, float(width), float(height), 0.0f, 1.0f};
  const VkRect2D scissor = {{0, 0}, {width, height}};

  resetTimestamps(cmd, timestamps);
  writeTimestamp(cmd, timestamps, DRAW_BEGIN);
  vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
  vkCmdSetViewport(cmd, 0, 1, &viewport);
  vkCmdSetScissor(cmd, 0, 1, &scissor);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout.layout, 0, 1, &set, 0, nullptr);
  vkCmdBindIndexBuffer(cmd, indices.buffer, 0, VK_INDEX_TYPE_UINT32);
  for (const DrawRun& run : runs) {
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelineFor(f.interpolation, f.projection, run.cullBack));
    vkCmdDrawIndexed(cmd, run.triangleCount * 3, 1, run.firstTriangle * 3, 0, 0);
  }
  vkCmdEndRenderPass(cmd);
  writeTimestamp(cmd, timestamps, DRAW_END);

  VkBufferImageCopy copy = {};
  copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  copy.imageExtent = {width, height, 1};
  vkCmdCopyImageToBuffer(cmd, color.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback.buffer, 1, &copy);
}

void GraphicsRenderer::State::readTime() {
  const std::vector<double> t = readTimestamps(context, timestamps);
  deviceMs = t.size() == TIMESTAMP_COUNT ? t[DRAW_END] - t[DRAW_BEGIN] : std::numeric_limits<double>::quiet_NaN();
}

GraphicsRenderer::GraphicsRenderer(const VulkanContext& context, const SceneData& data)
    : state_(std::make_unique<State>(context)) {
  // On a throw, ~State releases whatever was made.
  state_->createFixedObjects();
  state_->uploadScene(data);
  // Compile the pipelines the scene draws with now, not inside the first (timed) frame.
  for (const DrawRun& run : drawRuns(data)) state_->pipelineFor(data.interpolation, data.projection, run.cullBack);
}

GraphicsRenderer::~GraphicsRenderer() = default;

RenderOutput GraphicsRenderer::render(const FrameInputs& in) {
  State& s = *state_;
  s.ensureTargets(in.frame.width, in.frame.height);
  s.uploadFrame(in);
  VkCommandBuffer cmd = beginOneTimeCommands(s.context);
  s.recordFrame(cmd, in.frame);
  submitAndWait(s.context, cmd);
  s.readTime();

  // Read in place (host-visible, coherent), as the compute port reads its colours.
  RenderOutput out;
  out.image = imageFromPacked({static_cast<const uint32_t*>(s.readback.mapped), size_t(s.width) * s.height},
                              int(s.width), int(s.height));
  return out;
}

double GraphicsRenderer::lastDeviceMs() const { return state_->deviceMs; }

}  // namespace phongvk
