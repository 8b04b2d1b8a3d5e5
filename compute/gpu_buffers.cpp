// gpu_buffers.cpp — the compute port's buffers: the scene uploaded once, the per-pixel and
// per-bin buffers sized to the image, the large triangles' lists grown when a frame needs more,
// the descriptor set over all of them, and each frame's uploads of only what changed.
#include "compute/gpu_renderer.h"

#include "prepare/shadow_bvh.h"
#include "shaders/large_triangles.h"
#include "vulkan/vk_check.h"

#include <algorithm>
#include <stdexcept>

namespace phongvk {

using namespace gpu;

namespace {

constexpr VkBufferUsageFlags STORAGE = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;

uint32_t binsAcross(uint32_t pixels) { return groupCount(pixels, BIN_SIZE); }

// Whether the passes read the arrays as texels (texel views), or as storage buffers
// (VulkanContext::storageArrays, bindings.glsl TEXELS).
bool texelViews(const VulkanContext& context) { return !context.storageArrays; }

// Throws when one array would exceed the device's largest storage buffer binding.
void checkFits(const VulkanContext& context, VkDeviceSize bytes, const char* what) {
  checkDeviceLimit(context, what, bytes, "bytes", "maxStorageBufferRange",
                   context.properties.limits.maxStorageBufferRange);
}

// Throws when an array the passes read as texels would exceed the device's largest texel buffer,
// or where they are read as storage buffers (VulkanContext::storageArrays) its largest storage buffer.
void checkTexels(const VulkanContext& context, VkDeviceSize texels, const char* what) {
  if (context.storageArrays) return checkFits(context, texels * TEXEL_BYTES, what);
  checkDeviceLimit(context, what, texels, "texels", "maxTexelBufferElements",
                   context.properties.limits.maxTexelBufferElements);
}

// The vertices one shade dispatch writes (gpu_layout.h ShadeChunk): as many shaded positions (16
// bytes) as one storage-buffer binding holds, a multiple of 16 so that every chunk starts at a
// multiple of 256 bytes (the largest minStorageBufferOffsetAlignment Vulkan allows).
uint32_t shadeChunkVertices(const VulkanContext& context) {
  return std::max<uint32_t>(16, context.properties.limits.maxStorageBufferRange / sizeof(glm::vec4) / 16 * 16);
}

// Throws, before anything is allocated, when one of the scene's arrays exceeds a device limit:
// arrays the passes only read are bound as texels alone (maxStorageBufferRange does not apply to
// them); the clip list is written as one storage buffer, the shaded vertices in chunks.
void checkSceneFitsDevice(const VulkanContext& context, const SceneData& data) {
  auto texels = [&](VkDeviceSize bytes, const char* what) { checkTexels(context, bytes / TEXEL_BYTES, what); };
  texels(data.vertices.size() * sizeof(VertexIn), "the vertices");
  texels(data.triangles.size() * sizeof(glm::uvec4), "the triangles");
  texels(data.objects.size() * sizeof(ObjectData), "the objects");
  texels(data.materials.size() * sizeof(MaterialData), "the materials");
  texels(data.lights.size() * sizeof(LightData), "the lights");
  // The shade pass writes them in chunks of one binding each (shadeChunkVertices): only where they
  // are read as storage buffers does one binding hold them all.
  texels(data.vertices.size() * sizeof(glm::vec4), "the shaded vertex positions");  // and colours
  checkFits(context, clipListBytes(uint32_t(data.triangles.size()), context.info.keys32), "the clip list");
  texels(data.uvs.size() * sizeof(VertexUv), "the texture coordinates");
  if (data.shadows) {
    texels(shadowBvhNodeCapacity(data.shadows->triangles.size()) * sizeof(BvhNode), "the shadow rays' tree");
    texels(data.shadows->triangles.size() * sizeof(ShadowTriangle), "the shadow rays' triangles");
  }
  texels(data.texelCount * sizeof(uint32_t) + TEXEL_BYTES - 1, "the textures' texels");
}

// The textures' texels, four to a texel (bindings.glsl poolTexel), the last texel padded. Each
// texture is uploaded from where it was decoded, one at a time: the host never holds a second copy
// of them all.
void createTexelPool(TexelBuffer& pool, const VulkanContext& context, const SceneData& data) {
  const VkDeviceSize bytes = data.texelCount * sizeof(uint32_t);
  createTexelBuffer(pool, context, nullptr, (bytes + TEXEL_BYTES - 1) / TEXEL_BYTES * TEXEL_BYTES, 0, MemoryKind::DeviceLocal,
                    texelViews(context));
  for (size_t t = 0; t < data.textureImages.size(); ++t) {
    const Texels& texels = data.textureImages[t]->texels;
    uploadToBuffer(context, pool.buffer, texels.data(), texels.size() * sizeof(uint32_t),
                   VkDeviceSize(data.textures[t].offset) * sizeof(uint32_t));
  }
}

}  // namespace

void GpuRenderer::checkSceneFits(const SceneData& data) const { checkSceneFitsDevice(context_, data); }

// The buffers whose size does not depend on the scene or the image.
void GpuRenderer::createFrameBuffers() {
  createBuffer(perFrame_.frame, context_, sizeof(FrameData), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, MemoryKind::HostVisible);
  createBuffer(perFrame_.control, context_, sizeof(PassControl), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
               MemoryKind::HostVisible);
  createBuffer(perFrame_.status, context_, sizeof(FrameStatus), STORAGE, MemoryKind::HostVisible);
}

// The scene's buffers, made anew (the caller has checked that it fits: checkSceneFits).
void GpuRenderer::uploadScene(const SceneData& data) {
  vertexCount_ = static_cast<uint32_t>(data.vertices.size());
  triangleCount_ = static_cast<uint32_t>(data.triangles.size());
  pointQuads_ = pointQuadRange(data);
  createTexelBuffer(scene_.vertices, context_, data.vertices, MemoryKind::DeviceLocal, texelViews(context_));
  createTexelBuffer(scene_.triangles, context_, data.triangles, MemoryKind::DeviceLocal, texelViews(context_));
  // Objects (eye offsets), materials and lights may change per frame: small and host visible.
  createTexelBuffer(scene_.objects, context_, data.objects, MemoryKind::HostVisible, texelViews(context_));
  createTexelBuffer(scene_.materials, context_, data.materials, MemoryKind::HostVisible, texelViews(context_));
  createTexelBuffer(scene_.lights, context_, data.lights, MemoryKind::HostVisible, texelViews(context_));
  changes_.restart(data, choices_.unlit);
  // Written by the shade pass as storage buffers, read by the others as texels.
  const VkDeviceSize shadedBytes = VkDeviceSize(vertexCount_) * sizeof(glm::vec4);
  createTexelBuffer(scene_.shadedPositions, context_, nullptr, shadedBytes, STORAGE, MemoryKind::DeviceLocal, texelViews(context_));
  createTexelBuffer(scene_.shadedColors, context_, nullptr, shadedBytes, STORAGE, MemoryKind::DeviceLocal, texelViews(context_));
  createTexelBuffer(scene_.uvs, context_, data.uvs, MemoryKind::DeviceLocal, texelViews(context_));
  const ShadowGeometry none;
  const ShadowGeometry& shadows = data.shadows ? *data.shadows : none;
  // Room for any tree over these triangles: one built again for moved objects may have more nodes.
  const VkDeviceSize nodeBytes = shadowBvhNodeCapacity(shadows.triangles.size()) * sizeof(BvhNode);
  createTexelBuffer(scene_.bvhNodes, context_, nullptr, nodeBytes, 0, MemoryKind::DeviceLocal, texelViews(context_));
  if (!shadows.nodes.empty()) uploadToBuffer(context_, scene_.bvhNodes.buffer, shadows.nodes.data(), shadows.nodes.size() * sizeof(BvhNode));
  createTexelBuffer(scene_.shadowTriangles, context_, shadows.triangles, MemoryKind::DeviceLocal, texelViews(context_));
  createTexelBuffer(scene_.textures, context_, data.textures, MemoryKind::DeviceLocal, texelViews(context_));
  createTexelPool(scene_.texelPool, context_, data);
  createBuffer(scene_.clipList, context_, clipListBytes(triangleCount_, context_.info.keys32), STORAGE | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT, MemoryKind::DeviceLocal);
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
  for (Buffer* b : {&image_.keys, &image_.bins, &image_.colors, &image_.keyReadback}) destroyBuffer(*b, context_);
  createLargeBuffersFor(pixels);
  // With the colours in the key slots the host reads and resets the keys in place (Shared memory).
  createBuffer(image_.keys, context_, pixels * sizeof(uint64_t),
               STORAGE | VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
               choices_.colorsInKeys ? MemoryKind::Shared : MemoryKind::DeviceLocal);
  createBuffer(image_.bins, context_, sizeof(BinList) + 3 * bins * sizeof(uint32_t),
               STORAGE | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT, MemoryKind::DeviceLocal);
  keysDirty_ = true;  // the first frame clears the new keys
  width_ = width;
  height_ = height;
  ensureColorBuffer(!choices_.colorsInKeys);  // updates the descriptors
}

// The colour buffer: the whole image when resolve writes colours there (ColorOutput::ColorBuffer,
// or a frame with keys), else 4 bytes that only keep its descriptor valid. The pack pass (or, in
// frames with keys, resolve) writes the colours straight into host-visible memory, where the host
// reads them in place: no device copy.
void GpuRenderer::ensureColorBuffer(bool wholeImage) {
  // RGB bytes, rounded up to whole words for the background and pack passes.
  const VkDeviceSize bytes = wholeImage ? (3 * VkDeviceSize(width_) * height_ + 3) / 4 * 4 : sizeof(uint32_t);
  if (image_.colors.buffer != VK_NULL_HANDLE && image_.colors.size >= bytes) return;
  destroyBuffer(image_.colors, context_);
  createBuffer(image_.colors, context_, bytes, STORAGE | VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryKind::HostVisible);
  updateDescriptors();
}

// The large triangles' lists for an image of `pixels` and the scene's triangles: they grow with the
// image (gpu_layout.h LARGE_*), and further when a frame needs more (prepareRetry).
void GpuRenderer::createLargeBuffersFor(VkDeviceSize pixels) {
  createLargeBuffers(uint32_t(std::max<VkDeviceSize>(LARGE_ENTRIES_MIN, pixels / LARGE_ENTRY_PIXELS)),
                     std::min<uint32_t>(std::max(triangleCount_, 1u),
                                        uint32_t(std::max<VkDeviceSize>(LARGE_SETUPS_MIN, pixels / LARGE_SETUP_PIXELS))));
}

// Room for `entries` bin entries and `setups` set-up records of large triangles, replacing any
// there was. Both are written as storage buffers and read by resolve as texels (an entry is one
// texel). Throws, naming the limit, when they would pass the device's.
void GpuRenderer::createLargeBuffers(uint32_t entries, uint32_t setups) {
  const VkDeviceSize largeBytes = sizeof(LargeList) + VkDeviceSize(entries) * sizeof(LargeEntry);
  const VkDeviceSize setupBytes = VkDeviceSize(setups) * sizeof(LargeSetup);
  // A wide point or line is two large triangles, its quad's halves: the names say so, as a scene of
  // nothing but points may meet these limits.
  const char* entriesName = "the large triangles' bin entries (a point's or a line's quad is two triangles)";
  const char* setupsName = "the large triangles' set-ups (a point's or a line's quad is two triangles)";
  checkFits(context_, largeBytes, entriesName);
  checkFits(context_, setupBytes, setupsName);
  checkTexels(context_, largeBytes / TEXEL_BYTES, entriesName);
  checkTexels(context_, setupBytes / TEXEL_BYTES, setupsName);
  destroyTexelBuffer(image_.large, context_);
  destroyTexelBuffer(image_.largeSetups, context_);
  createTexelBuffer(image_.large, context_, nullptr, largeBytes, STORAGE, MemoryKind::DeviceLocal, texelViews(context_));
  createTexelBuffer(image_.largeSetups, context_, nullptr, setupBytes, STORAGE, MemoryKind::DeviceLocal, texelViews(context_));
  largeCapacity_ = entries;
  largeSetupCapacity_ = setups;
}

// One descriptor set for every pass, written from the buffers each binding of shared.h's table
// names, and one more for each further chunk of the shade pass (gpu_layout.h ShadeChunk), whose
// shaded bindings start at that chunk. Identically defined set layouts are compatible, so the
// raster pass's serves all.
void GpuRenderer::updateDescriptors() {
  const uint32_t perChunk = shadeChunkVertices(context_);
  const uint32_t chunks = std::max(1u, groupCount(vertexCount_, perChunk));
  if (chunks > arenaSets_) {
    createDescriptorArena(arena_, context_, chunks, std::size(SHARED_BINDINGS));
    arenaSets_ = chunks;
  } else {
    VK_CHECK(vkResetDescriptorPool(context_.device, arena_.pool, 0));
  }
  BufferDescriptor descriptors[] = {
      bufferDescriptor(BINDING_FRAME, perFrame_.frame),
      bufferDescriptor(BINDING_CONTROL, perFrame_.control),
      texelDescriptor(bindings_[BINDING_VERTICES], scene_.vertices),
      texelDescriptor(bindings_[BINDING_TRIANGLES], scene_.triangles),
      texelDescriptor(bindings_[BINDING_OBJECTS], scene_.objects),
      texelDescriptor(bindings_[BINDING_MATERIALS], scene_.materials),
      texelDescriptor(bindings_[BINDING_LIGHTS], scene_.lights),
      texelDescriptor(bindings_[BINDING_SHADED], scene_.shadedPositions),
      texelDescriptor(bindings_[BINDING_SHADED_TEXELS], scene_.shadedPositions),
      texelDescriptor(bindings_[BINDING_SHADED_COLORS], scene_.shadedColors),
      texelDescriptor(bindings_[BINDING_SHADED_COLOR_TEXELS], scene_.shadedColors),
      bufferDescriptor(BINDING_KEYS, image_.keys),
      bufferDescriptor(BINDING_COLOR, image_.colors),
      texelDescriptor(bindings_[BINDING_LARGE], image_.large),
      texelDescriptor(bindings_[BINDING_LARGE_TEXELS], image_.large),
      bufferDescriptor(BINDING_BINS, image_.bins),
      texelDescriptor(bindings_[BINDING_LARGE_SETUPS], image_.largeSetups),
      texelDescriptor(bindings_[BINDING_LARGE_SETUP_TEXELS], image_.largeSetups),
      bufferDescriptor(BINDING_CLIP_LIST, scene_.clipList),
      bufferDescriptor(BINDING_STATUS, perFrame_.status),
      texelDescriptor(bindings_[BINDING_UVS], scene_.uvs),
      texelDescriptor(bindings_[BINDING_TEXTURES], scene_.textures),
      texelDescriptor(bindings_[BINDING_TEXEL_POOL], scene_.texelPool),
      texelDescriptor(bindings_[BINDING_BVH_NODES], scene_.bvhNodes),
      texelDescriptor(bindings_[BINDING_SHADOW_TRIANGLES], scene_.shadowTriangles),
  };
  static_assert(std::size(descriptors) == std::size(SHARED_BINDINGS), "every binding of the table is written");
  shadeDispatches_.clear();
  for (uint32_t k = 0; k < chunks; ++k) {
    const uint32_t first = k * perChunk, end = std::min(vertexCount_, first + perChunk);
    for (BufferDescriptor& d : descriptors) {
      if (d.binding != BINDING_SHADED && d.binding != BINDING_SHADED_COLORS) continue;
      d.offset = VkDeviceSize(first) * sizeof(glm::vec4);
      d.range = k + 1 < chunks ? VkDeviceSize(perChunk) * sizeof(glm::vec4) : VK_WHOLE_SIZE;
    }
    shadeDispatches_.push_back({{first, end}, allocateDescriptorSet(context_, arena_, current_[RASTER].setLayout, descriptors)});
  }
}

// Sends the frame, and the objects, materials and lights where they changed (FrameChanges), with
// the pass control saying what the shade pass redoes (writeControl).
void GpuRenderer::uploadFrame(const FrameInputs& in) {
  const ShadeWork work = changes_.send(context_,
                                      {scene_.objects.buffer, scene_.materials.buffer, scene_.lights.buffer,
                                       scene_.bvhNodes.buffer, scene_.shadowTriangles.buffer},
                                      in);
  frame_ = in.frame;
  uploadToBuffer(context_, perFrame_.frame, &frame_, sizeof(FrameData));
  frameColorsInKeys_ = choices_.colorsInKeys && !withKeys_;
  control_.shadeColors = work.colors ? 1u : 0u;
  control_.shadePositions = work.positions ? 1u : 0u;
  writeControl();
}

// The pass control for the frame being rendered, from the renderer's buffers, image and workgroup
// cap (which the retries grow) and the shade flags uploadFrame or prepareRetry set; uploaded.
void GpuRenderer::writeControl() {
  control_.triangleCount = triangleCount_;
  control_.pointBase = pointQuads_.x;
  control_.pointEnd = pointQuads_.y;
  control_.largeCapacity = largeCapacity_;
  control_.largeSetupCapacity = largeSetupCapacity_;
  control_.binsX = binsAcross(width_);
  control_.binCount = binsAcross(width_) * binsAcross(height_);
  control_.groupCap = retry_.groupCap();
  control_.loopProbe = LOOP_PROBE_ITERATIONS;
  uploadToBuffer(context_, perFrame_.control, &control_, sizeof(PassControl));
}

}  // namespace phongvk
