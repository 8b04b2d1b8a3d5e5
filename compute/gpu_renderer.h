// gpu_renderer.h — the Vulkan compute port: per-vertex Phong, 64-bit atomic-depth raster and
// Gouraud resolve (docs/DESIGN.md "GPU pipeline shape"). The scene is uploaded once; each frame sends
// only the camera-dependent data (FrameInputs).
#pragma once

#include "compute/frame_changes.h"
#include "compute/passes.h"
#include "compute/retry_policy.h"
#include "phongvk/image.h"
#include "prepare/scene_data.h"
#include "shaders/gpu_layout.h"
#include "vulkan/context.h"
#include "vulkan/pipelines.h"
#include "vulkan/resources.h"
#include "vulkan/submit.h"

#include <map>
#include <memory>
#include <optional>
#include <vector>

namespace phongvk {

// Device time per pass of the last frame, in milliseconds (NaN when the device has no timestamps).
struct PassTimes {
  double shade = 0;    // vertex shading, and in frames with keys the colour buffer's background fill
  double raster = 0;   // triangle, clip and bin passes: setup, culling, clipping, small triangles
  double resolve = 0;  // large triangles (binned), then colours (and a GPU's pack pass)
  double total = 0;
};

// How the passes lay their work out for the device. Cpu: a resolve workgroup takes one 8x8 tile
// (8 lanes per tile), so a CPU device's 8-wide SIMD batch is a whole workgroup and per-tile work
// runs once per tile; the clip pass links each large triangle into its bins' lists itself (a loop
// per invocation runs at CPU speed). Gpu: eight tiles per resolve workgroup, so a GPU's warps are
// full, and the bin pass (bin_large.comp) links each (large triangle, bin) pair on an invocation
// of its own: one GPU thread walking a screen-filling triangle's bins took most of an H100 frame
// (docs/DECISIONS.md, "Binning"). Auto picks by device type; tests force either on any device.
// Both give the same image and keys.
enum class WorkLayout { Auto, Cpu, Gpu };

// Where resolve leaves the colours. InKeySlots: each in its pixel's 64-bit key slot, which the host
// reads in place and resets (8 bytes per pixel in all; needs MemoryKind::Shared memory, as a CPU
// or integrated device has). ColorBuffer: in the key slots too, then packed by the pack pass into a
// host-visible colour buffer of RGB bytes, the image's own layout (11 bytes per pixel). Auto picks InKeySlots where
// the device has shared memory. Frames rendered with keys (for diffs) always use the colour buffer.
// Tests force either.
enum class ColorOutput { Auto, InKeySlots, ColorBuffer };

// The compute port's pipelines, by pass, specialization and build (`_exact` or not): compiled once
// and kept for as long as whoever holds them. A renderer keeps its own unless given a set; the
// public Renderer gives every GpuRenderer it makes one set, so a new geometry (a new GpuRenderer:
// its buffers and descriptors) compiles no pipeline again.
class GpuPipelineSet {
 public:
  explicit GpuPipelineSet(const VulkanContext& context) : context_(context) {}
  ~GpuPipelineSet();
  GpuPipelineSet(const GpuPipelineSet&) = delete;
  GpuPipelineSet& operator=(const GpuPipelineSet&) = delete;

  const VulkanContext& context() const { return context_; }
  // Time spent compiling the set's pipelines so far.
  double compileMs() const { return compileMs_; }

 private:
  friend class GpuRenderer;  // compiles into it (gpu_pipelines.cpp)
  const VulkanContext& context_;
  std::map<std::vector<uint32_t>, ComputePipeline> byKey_;
  double compileMs_ = 0;
};

struct GpuRendererOptions {
  WorkLayout layout = WorkLayout::Auto;
  ColorOutput output = ColorOutput::Auto;
  // The most workgroups a pass launches until a frame runs out of loop iterations (0: the
  // device's); tests start low to exercise the retry with more (render).
  uint32_t firstGroupCap = 0;
  // Entries of each bin's large-triangle list resolve takes per round from the first frame on (0:
  // whole lists until a frame runs out of loop iterations); tests force rounds on any scene.
  uint32_t firstListChunk = 0;
  // The passes' `_exact` builds, which correct the device's division and square root: what
  // probeFloatOps(context).useExact() says for the device (vulkan/float_probe.h). Unset, the
  // renderer runs the probe itself; a caller that builds several renderers probes once and says.
  std::optional<bool> exactFloats;
  // Pipelines to compile into and take from (made on the same context); none: the renderer's own.
  std::shared_ptr<GpuPipelineSet> pipelines;
  // The first frame's clipper (its FrameInputs::clip), so that the scene's pipelines are compiled
  // with the clip pass that frame takes.
  uint32_t clip = gpu::CLIP_NONE;
};

class GpuRenderer {
 public:
  // Uploads the scene's vertices, triangles and materials. Throws DeviceError when the
  // scene does not fit the device's buffer limits (naming the limit), VulkanError otherwise.
  GpuRenderer(const VulkanContext& context, const SceneData& data, const GpuRendererOptions& options = {});
  ~GpuRenderer();
  GpuRenderer(const GpuRenderer&) = delete;
  GpuRenderer& operator=(const GpuRenderer&) = delete;

  // Renders one frame. withKeys also reads back the per-pixel visibility keys (for diffs). A frame
  // whose large triangles found no room in their lists, or whose passes ran out of the device's
  // loop iterations (lavapipe), is rendered again with larger lists or more workgroups; throws
  // std::runtime_error, naming the limit, when neither can grow further. The image is read into
  // `storage`'s pixels (reused when large enough, so a loop of frames allocates none).
  RenderOutput render(const FrameInputs& in, bool withKeys = false, Image storage = {});

  // Another scene (a new geometry, or other material or light counts) in place of the uploaded
  // one: its buffers are made anew and the pipelines it needs compiled (none that the pipeline set
  // has), while the image's buffers, the descriptor arena, the timestamps and the pipelines stay.
  // The next frame renders as a fresh renderer's first would: everything sent and shaded, the
  // workgroup cap and list chunks as the options set them. Throws as the constructor; after a
  // throw the renderer must not render again.
  void replaceScene(const SceneData& data, uint32_t clip = gpu::CLIP_NONE);  // clip: as the options'

  // Frames rendered again so far (render), for tests and the benchmark.
  uint64_t framesRepeated() const { return retry_.framesRepeated(); }
  // 0, or how many entries of each bin's large-triangle list resolve takes per round since a frame
  // had lists too long for the device's loop budget (gpu_layout.h LIST_CHUNK_FIRST).
  uint32_t listChunk() const { return retry_.listChunk(); }
  // CLIP_ALL once a frame met a triangle to clip in a clip pass built without the clipper: later
  // frames keep the clipper.
  uint32_t clipFloor() const { return retry_.clipFloor(); }
  // Time spent compiling its pipeline set's pipelines so far, construction included (a shared set:
  // by every renderer that compiled into it).
  double compileMs() const { return pipelines_->compileMs(); }

  const PassTimes& lastPassTimes() const { return times_; }

  // Frames so far whose per-vertex lighting was recomputed (the others only transformed).
  uint64_t framesShaded() const { return changes_.framesShaded(); }

  // Frames so far whose vertex positions were transformed (the others kept the previous frame's:
  // same view and objects).
  uint64_t framesTransformed() const { return changes_.framesTransformed(); }

 private:
  // Before shade, after shade, after the triangle + clip passes, after resolve: PassTimes.
  static constexpr uint32_t TIMESTAMP_SLOTS = 4;

  // The frame loop (gpu_renderer.cpp).
  void release();  // destroys whatever exists; safe to call twice
  bool renderAttempt();
  void submitResolveRound(void (GpuRenderer::*record)(VkCommandBuffer));
  void prepareRetry(uint32_t statusFlags);
  void readTimes();

  // Pipelines (gpu_pipelines.cpp), for the passes passRequests names (passes.h).
  void compilePipelines(const std::vector<PipelineRequest>& requests);
  const ComputePipeline& pipeline(const PipelineRequest& request) const;
  void selectPipelines(const FrameInputs& in);

  // Buffers, uploads and what changed since the last frame (gpu_buffers.cpp).
  void checkSceneFits(const SceneData& data) const;  // throws, naming the device limit, before anything is made
  void compileSceneModes(const SceneData& data);
  void createFrameBuffers();
  void uploadScene(const SceneData& data);
  void startRetries();
  void ensureImageBuffers(uint32_t width, uint32_t height);
  void createLargeBuffersFor(VkDeviceSize pixels);
  void ensureColorBuffer(bool wholeImage);
  void createLargeBuffers(uint32_t entries, uint32_t setups);
  void updateDescriptors();
  void uploadFrame(const FrameInputs& in);
  void writeControl();

  // Recording a frame's passes (gpu_recording.cpp) and reading its image (gpu_readback.cpp).
  void recordFrame(VkCommandBuffer cmd);
  void recordResolveLargeRound(VkCommandBuffer cmd);
  void recordResolveTail(VkCommandBuffer cmd);
  void bindPass(VkCommandBuffer cmd, Pass pass) const;
  Image readImage(Image storage);

  const VulkanContext& context_;
  GpuRendererOptions options_;  // as made: replaceScene starts from them again
  bool exactFloats_ = false;    // the passes' _exact builds
  // The passes' shape: the work layout, key path and colour output chosen for the device, the
  // scene's textures, and this frame's clipper (the larger of the retries' floor and
  // FrameInputs::clip) and list chunks (the retries').
  PassChoices choices_;
  RetryPolicy retry_;          // the workgroup cap, list chunks and clipper that repeated frames grew
  FrameChanges changes_;       // what the device holds from earlier frames
  bool keysDirty_ = false;     // the key slots may hold colours or keys no one reset: clear them first
  std::shared_ptr<GpuPipelineSet> pipelines_;  // compiled ones, kept across renderers (GpuRendererOptions)
  ComputePipelineHandles current_[PASS_COUNT];  // this frame's (owned by pipelines_)
  std::vector<Binding> bindings_;  // the shared set as this context's shaders declare it (sharedBindings)
  DescriptorArena arena_;
  uint32_t arenaSets_ = 0;  // the sets arena_ has room for
  // The shade pass's dispatches (gpu_layout.h ShadeChunk), each with a set whose shaded bindings
  // start at its chunk; the first's set is the one every other pass binds (updateDescriptors).
  struct ShadeDispatch {
    gpu::ShadeChunk chunk;
    VkDescriptorSet set;
  };
  std::vector<ShadeDispatch> shadeDispatches_;
  TimestampPool timestamps_;
  PassTimes times_;

  // The buffers, grouped by how long they live; each frees itself (vulkan/resources.h).
  // The scene's: made by uploadScene, replaced with a new geometry (replaceScene).
  struct SceneBuffers {
    TexelBuffer vertices, triangles, objects, materials, lights;  // read as texels (bindings.glsl)
    TexelBuffer shadedPositions, shadedColors;  // written by the shade pass, read as texels
    Buffer clipList;
    TexelBuffer uvs, textures, texelPool;  // the textures' (a texel each where the scene has none)
    TexelBuffer bvhNodes, shadowTriangles;  // the shadow rays' tree (a texel each where no light casts shadows)
  };
  // The image's: sized to the image (ensureImageBuffers) and, for the large-triangle lists, to
  // the scene's triangles as well (createLargeBuffersFor).
  struct ImageBuffers {
    Buffer keys, bins, colors, keyReadback;
    TexelBuffer large, largeSetups;  // written as storage, read by resolve as texels
  };
  // The renderer's own: what each frame uploads and what its passes report.
  struct FrameBuffers {
    Buffer frame, control, status;
  };
  SceneBuffers scene_;
  ImageBuffers image_;
  FrameBuffers perFrame_;
  uint32_t vertexCount_ = 0;
  uint32_t triangleCount_ = 0;
  glm::uvec2 pointQuads_{0};  // the records the point pass draws (prepare/scene_data.h pointQuadRange)
  uint32_t largeCapacity_ = 0;
  uint32_t largeSetupCapacity_ = 0;
  uint32_t width_ = 0;
  uint32_t height_ = 0;

  // The frame being rendered, as uploaded: the scene's frame and the pass control this renderer
  // wrote for it (writeControl), whether it keeps its keys, and where its colours end up.
  gpu::FrameData frame_{};
  gpu::PassControl control_{};
  bool withKeys_ = false;
  bool frameColorsInKeys_ = false;
};

}  // namespace phongvk
