// renderer_impl.h — what every backend of the public Renderer shares: the scene it built and
// uploaded last, reused while the geometry stays the same (scene_data.h sameGeometry), and the
// statistics. A backend says how it uploads built meshes and renders one frame.
#pragma once

#include "phongvk/phongvk.h"
#include "prepare/scene_data.h"

#include <memory>
#include <mutex>
#include <optional>
#include <string>

namespace phongvk {

// What every backend implements; the backends (backends.cpp) name it RendererImpl.
class Renderer::Impl {
 public:
  virtual ~Impl() = default;

  // One frame of `scene`: builds and uploads its meshes unless the last scene had the same
  // geometry (and as many materials and lights), then renders. A backend may read the image into
  // `storage`'s pixels.
  RenderOutput render(const Scene& scene, bool withKeys, Image storage = {});
  // One frame with the outputs asked for, from its keys (outputs.cpp).
  RenderedFrame renderOutputs(const Scene& scene, const Outputs& outputs);
  // The last frame's device times (NaN where not measured); wallMs is left to the caller.
  virtual FrameTime lastFrameTime() const = 0;
  virtual Backend backend() const = 0;
  virtual std::string deviceName() const = 0;
  RendererStats stats() const;

 protected:
  // New meshes (or new material or light counts): replace whatever was uploaded.
  virtual void upload(const SceneData& data, uint32_t firstFrameClip) = 0;  // FrameInputs::clip
  virtual RenderOutput draw(const SceneData& data, const FrameInputs& in, bool withKeys, Image storage) = 0;
  // Frames whose lighting the backend computed, and frames it rendered again (gpu).
  virtual uint64_t framesShaded() const = 0;
  virtual uint64_t framesRepeated() const { return 0; }
  virtual uint64_t validationMessages() const { return 0; }
  // Start-up (RendererStats::contextMs and the rest); the reference has none.
  virtual void addStartup(RendererStats&) const {}

 private:
  // Makes data_ hold `scene`'s meshes and shading, building and uploading them unless the last
  // scene's can serve, and camera_ its camera (fitted where asked, camera_fit.h).
  void prepare(const Scene& scene);
  // render, with busy_ held by the caller.
  RenderOutput renderHeld(const Scene& scene, bool withKeys, Image storage);
  // Lights at the camera placed, the camera fitted, where the scene asks for it.
  void frame(const SceneSpec& spec);
  // The view the frames are rendered in: the camera's, samples times larger on each side.
  View sampleView() const;

  // Held by render and stats: a renderer used from several threads renders one frame at a time
  // (its device buffers and the scene it built are one frame's).
  mutable std::mutex busy_;
  std::optional<SceneData> data_;
  std::shared_ptr<const SceneSpec> builtFrom_;  // the scene data_'s meshes were built from
  CameraSpec camera_;
  uint64_t sceneBuilds_ = 0;
  uint64_t framesRendered_ = 0;
  double buildMs_ = 0;
  double firstFrameMs_ = 0;  // RendererStats::firstFrameMs
  std::string builtNotice_;  // what the scene's meshes and fitted camera call for, set when it is built
  std::string notice_;       // RendererStats::notice: that, and what this frame's camera calls for
};

struct RendererAccess {
  using Impl = Renderer::Impl;
};
using RendererImpl = RendererAccess::Impl;

// The backends (backends.cpp).
std::unique_ptr<RendererImpl> makeBackend(const RendererOptions& options);

}  // namespace phongvk
