// backends.cpp — the public Renderer's three backends: the reference, the Vulkan compute port
// (with the device's float probe, run once per renderer) and the graphics-pipeline baseline.
#include "api/renderer_impl.h"

#include "api/timing.h"

#include "compute/gpu_renderer.h"
#include "graphics/graphics_renderer.h"
#include "reference/render_reference.h"
#include "vulkan/context.h"
#include "vulkan/float_probe.h"
#include "vulkan/resources.h"

#include <cmath>
#include <limits>
#include <optional>

namespace phongvk {
namespace {

constexpr double NOT_MEASURED = std::numeric_limits<double>::quiet_NaN();

// The reference; its "device" is this CPU thread, so a frame's device time is its compute time.
class CpuBackend : public RendererImpl {
 public:
  FrameTime lastFrameTime() const override { return {0, lastMs_, NOT_MEASURED, NOT_MEASURED, NOT_MEASURED}; }
  Backend backend() const override { return Backend::Cpu; }
  std::string deviceName() const override { return "cpu (reference)"; }

 protected:
  void upload(const SceneData&, uint32_t) override {}
  RenderOutput draw(const SceneData& data, const FrameInputs& in, bool withKeys, Image) override {
    ++frames_;
    const auto start = Clock::now();
    RenderOutput out = renderReference(data, in);
    lastMs_ = msSince(start);
    if (!withKeys) out.keys.clear();
    return out;
  }
  uint64_t framesShaded() const override { return frames_; }

 private:
  uint64_t frames_ = 0;
  double lastMs_ = NOT_MEASURED;
};

// A Vulkan context for the backends that need one. Every call into Vulkan holds a ContextLock:
// renderers in other threads have contexts of their own, and volk's function table is the
// process's. The derived backend's renderer is released (under the lock) in its destructor, before
// this one destroys the context.
class VulkanBackend : public RendererImpl {
 public:
  explicit VulkanBackend(const RendererOptions& options) {
    const auto start = Clock::now();
    context_ = createContext({options.device, options.validate, true});
    contextMs_ = msSince(start);
  }
  ~VulkanBackend() override { destroyContext(context_); }
  // The device and its key path: "llvmpipe (LLVM 15.0.6, 256 bits), keys: 64-bit atomics".
  std::string deviceName() const override { return context_.info.name + ", keys: " + keyPathWords(context_.info); }

 protected:
  uint64_t validationMessages() const override { return context_.validation ? context_.validation->count() : 0; }
  void addStartup(RendererStats& s) const override {
    s.contextMs = contextMs_;
    s.deviceBytes = phongvk::deviceBytes(context_);
  }
  VulkanContext context_;
  double contextMs_ = 0;
};

class GpuBackend : public VulkanBackend {
 public:
  // The device's division and square root decide which builds of the passes it runs.
  explicit GpuBackend(const RendererOptions& options) : VulkanBackend(options) {
    const ContextLock lock(context_);
    const auto start = Clock::now();
    exactFloats_ = useExactFloats(context_, &probeCached_);
    probeMs_ = probeCached_ ? 0.0 : msSince(start);
  }
  ~GpuBackend() override {
    const ContextLock lock(context_);
    renderer_.reset();
    pipelines_.reset();
  }

  FrameTime lastFrameTime() const override {
    const PassTimes& t = renderer_->lastPassTimes();
    return {0, t.total, t.shade, t.raster, t.resolve};
  }
  Backend backend() const override { return Backend::Gpu; }

 protected:
  void upload(const SceneData& data, uint32_t firstFrameClip) override {
    const ContextLock lock(context_);
    if (renderer_) {  // a new geometry: new scene buffers; the image's buffers and the pipelines stay
      try {
        renderer_->replaceScene(data, firstFrameClip);
        return;
      } catch (...) {
        renderer_.reset();
        throw;
      }
    }
    GpuRendererOptions options;
    options.exactFloats = exactFloats_;
    options.pipelines = pipelines_;
    options.clip = firstFrameClip;
    renderer_.emplace(context_, data, options);
  }
  RenderOutput draw(const SceneData&, const FrameInputs& in, bool withKeys, Image storage) override {
    const ContextLock lock(context_);
    return renderer_->render(in, withKeys, std::move(storage));
  }
  uint64_t framesShaded() const override { return renderer_ ? renderer_->framesShaded() : 0; }
  uint64_t framesRepeated() const override { return renderer_ ? renderer_->framesRepeated() : 0; }
  void addStartup(RendererStats& s) const override {
    VulkanBackend::addStartup(s);
    s.probeMs = probeMs_;
    s.probeCached = probeCached_;
    s.pipelinesMs = pipelines_->compileMs();
  }

 private:
  bool exactFloats_ = false;
  std::shared_ptr<GpuPipelineSet> pipelines_ = std::make_shared<GpuPipelineSet>(context_);  // outlives renderer_
  std::optional<GpuRenderer> renderer_;  // made for the first scene, given each new geometry after
  double probeMs_ = 0;
  bool probeCached_ = false;
};

class GraphicsBackend : public VulkanBackend {
 public:
  using VulkanBackend::VulkanBackend;
  ~GraphicsBackend() override {
    const ContextLock lock(context_);
    renderer_.reset();
  }

  FrameTime lastFrameTime() const override {
    return {0, renderer_->lastDeviceMs(), NOT_MEASURED, NOT_MEASURED, NOT_MEASURED};
  }
  Backend backend() const override { return Backend::Graphics; }

 protected:
  void upload(const SceneData& data, uint32_t) override {
    if (hasQuads(data)) {
      throw SceneError("the graphics backend (the benchmark's baseline) draws triangles only: use the gpu or cpu "
                       "backend for points and lines");
    }
    const ContextLock lock(context_);
    renderer_.reset();
    renderer_.emplace(context_, data);
  }
  RenderOutput draw(const SceneData&, const FrameInputs& in, bool, Image) override {
    if (in.frame.shading != gpu::SHADING_GOURAUD || in.frame.specular != gpu::SPECULAR_PHONG) {
      throw SceneError("the graphics backend (the benchmark's baseline) renders Gouraud shading with the paper's "
                       "specular model only: use the gpu or cpu backend for render.shading and render.specular");
    }
    const ContextLock lock(context_);
    ++frames_;
    return renderer_->render(in);
  }
  uint64_t framesShaded() const override { return frames_; }

 private:
  std::optional<GraphicsRenderer> renderer_;
  uint64_t frames_ = 0;
};

}  // namespace

std::unique_ptr<RendererImpl> makeBackend(const RendererOptions& options) {
  switch (options.backend) {
    case Backend::Cpu: return std::make_unique<CpuBackend>();
    case Backend::Graphics: return std::make_unique<GraphicsBackend>(options);
    case Backend::Gpu: break;
  }
  return std::make_unique<GpuBackend>(options);
}

}  // namespace phongvk
