// renderer.cpp — the public Renderer: one backend behind it, the built scene kept across calls.
#include "api/renderer_impl.h"

#include "api/outputs.h"
#include "api/timing.h"
#include "api/scene_access.h"
#include "prepare/camera_fit.h"
#include "prepare/facing.h"
#include "prepare/memory_estimate.h"
#include "scene/camera.h"

#include <cmath>
#include <limits>
#include <mutex>
#include <stdexcept>

namespace phongvk {

void Renderer::Impl::frame(const SceneSpec& spec) {
  if (!needsFraming(spec)) {
    camera_ = spec.camera;
    return;
  }
  const SceneSpec framed = framedScene(spec, *data_);
  refreshShading(*data_, framed);
  camera_ = framed.camera;
}

namespace {

// What the scene's meshes hold that is not rendered (SceneData::notices), in a line.
std::string meshNotices(const SceneData& data) {
  std::string line;
  for (const std::string& notice : data.notices) line += (line.empty() ? "" : "; ") + notice;
  return line;
}

// What messages call the scene: its model file, its scene file, or "the scene".
std::string sceneName(const SceneSpec& spec) {
  return spec.modelAlone && !spec.objects.empty() ? spec.objects[0].file
         : spec.path.empty()                      ? std::string("the scene")
                                                  : spec.path;
}

// RendererStats::notice for a scene just built and framed.
std::string noticeFor(const SceneSpec& spec, const SceneData& data, const CameraSpec& camera) {
  const std::string meshes = meshNotices(data);
  if (!camera.fit || !seenOnlyFromBehind(data, camera.position)) return meshes;
  return sceneName(spec) + ": the fitted camera sees only the back of every triangle (their normals face away from it), so "
                "the model is drawn dark, lit from behind; give the camera another direction or turn the faces" +
         (meshes.empty() ? "" : "; " + meshes);
}

// The frame's notice: the scene's (noticeFor, made when it was built), and, where the camera looks
// away from every object (the box around them all lies behind its near plane, as a pose given in
// the other convention does), that the image is empty and why.
std::string frameNotice(const std::string& built, const SceneSpec& spec, const SceneData& data, const View& view) {
  for (int corner = 0; corner < 8; ++corner) {
    if (glm::dot(boxCorner(data.boundsMin, data.boundsMax, corner) - view.eye, view.forward) > view.nearPlane) return built;
  }
  return sceneName(spec) + ": the camera looks away from every object (all of them lie behind it), so the image " +
         "is empty; a camera pose given in the other convention (\"opengl\" looks down the pose's -z, \"opencv\" " +
         "down its +z) looks the other way" + (built.empty() ? "" : "; " + built);
}

// The samples a frame of `spec` renders: its pixels times the samples per pixel (memory_estimate.h).
uint64_t pixelSamples(const SceneSpec& spec) {
  const View view = makeView(spec.camera);
  return uint64_t(view.width) * uint64_t(view.height) * uint64_t(spec.samples);
}

}  // namespace

void Renderer::Impl::prepare(const Scene& scene) {
  const SceneSpec& spec = SceneAccess::spec(scene);
  const uint64_t samples = pixelSamples(spec);
  if (data_ && builtFrom_ && sameGeometry(*builtFrom_, spec)) {
    checkBuiltSceneMemory(spec, data_->triangles.size(), samples, textureBytes(*data_));  // this frame's size and samples
    const size_t materials = data_->materials.size(), lights = data_->lights.size();
    placeObjects(*data_, spec);  // posed objects may have moved
    refreshShading(*data_, spec);
    frame(spec);
    notice_ = frameNotice(builtNotice_, spec, *data_, makeView(camera_));
    // A backend's buffers are sized for the counts it was built with.
    if (data_->materials.size() == materials && data_->lights.size() == lights) return;
  }
  checkSceneMemory(spec, samples);
  const auto start = Clock::now();
  data_.reset();  // the old meshes go before the new ones are built
  builtFrom_.reset();  // until the new ones are uploaded: a failed upload builds again next time
  data_ = buildSceneData(spec);
  checkBuiltSceneMemory(spec, data_->triangles.size(), samples, textureBytes(*data_));
  frame(spec);
  builtNotice_ = noticeFor(spec, *data_, camera_);
  notice_ = frameNotice(builtNotice_, spec, *data_, makeView(camera_));
  buildMs_ += msSince(start);
  upload(*data_, boxClip(*data_, sampleView()));
  builtFrom_ = std::make_shared<const SceneSpec>(spec);
  ++sceneBuilds_;
}

// With samples per pixel (render.samples), the frame is rendered `side` times wider and higher,
// each pixel's samples on a regular grid of pixel centres, and box-filtered down in 8 bits
// (downscale: the rounded mean of each side x side block): both backends, the same bytes. The
// keys stay per sample.
RenderOutput Renderer::Impl::render(const Scene& scene, bool withKeys, Image storage) {
  const std::lock_guard<std::mutex> one(busy_);
  return renderHeld(scene, withKeys, std::move(storage));
}

RenderedFrame Renderer::Impl::renderOutputs(const Scene& scene, const Outputs& outputs) {
  const std::lock_guard<std::mutex> one(busy_);
  const bool keys = needsKeys(outputs);
  RenderOutput out = renderHeld(scene, keys, {});
  if (!keys) return {std::move(out.image)};
  return outputsFromKeys(std::move(out), sampleGridSide(data_->samples), *data_, makeFrame(*data_, sampleView()), outputs,
                         objectIdsOf(SceneAccess::spec(scene)));
}

View Renderer::Impl::sampleView() const {
  return supersampled(makeView(camera_), sampleGridSide(data_->samples));
}

RenderOutput Renderer::Impl::renderHeld(const Scene& scene, bool withKeys, Image storage) {
  prepare(scene);
  const View view = makeView(camera_);
  const int side = sampleGridSide(data_->samples);
  RenderOutput out = draw(*data_, makeFrame(*data_, sampleView()), withKeys, side == 1 ? std::move(storage) : Image());
  if (side > 1) out.image = downscale(out.image, view.width, view.height);
  // A share's keys name its triangles as the whole scene does (Scene::share); ids stay below 2^32.
  // Only then: a whole scene's keys are not walked again.
  if (const uint32_t base = data_->triangleBase) {
    for (uint64_t& key : out.keys) key += key != ~uint64_t(0) ? base : 0;
  }
  if (framesRendered_++ == 0) firstFrameMs_ = lastFrameTime().deviceMs;
  return out;
}

RendererStats Renderer::Impl::stats() const {
  const std::lock_guard<std::mutex> one(busy_);
  RendererStats s;
  s.sceneBuilds = sceneBuilds_;
  s.framesRendered = framesRendered_;
  s.framesShaded = framesShaded();
  s.framesRepeated = framesRepeated();
  s.triangles = data_ ? std::min<size_t>(data_->triangles.size(), data_->quadBase) : 0;
  s.lines = data_ ? data_->lineCount : 0;
  s.points = data_ ? data_->pointCount : 0;
  s.lights = data_ ? data_->lights.size() : 0;
  s.buildMs = buildMs_;
  s.textureBytes = data_ ? textureBytes(*data_) : 0;
  s.firstFrameMs = firstFrameMs_;
  s.notice = notice_;
  s.validationMessages = validationMessages();
  addStartup(s);
  return s;
}

Renderer::Renderer(Backend backend, int device) : Renderer(RendererOptions{backend, device, false}) {}
Renderer::Renderer(const RendererOptions& options) : impl_(makeBackend(options)) {}
Renderer::~Renderer() = default;

void Renderer::close() { impl_.reset(); }

Renderer::Impl& Renderer::live() const {
  if (!impl_) throw ArgumentError("the renderer is closed: make a new one to render again");
  return *impl_;
}
Renderer::Renderer(Renderer&&) noexcept = default;
Renderer& Renderer::operator=(Renderer&&) noexcept = default;

Image Renderer::render(const Scene& scene) { return live().render(scene, false).image; }

void Renderer::render(const Scene& scene, Image& image) { image = live().render(scene, false, std::move(image)).image; }

RenderOutput Renderer::renderWithKeys(const Scene& scene) {
  if (live().backend() == Backend::Graphics) {
    throw ArgumentError("the graphics backend has no visibility keys; use the gpu or cpu backend");
  }
  return live().render(scene, true);
}

RenderedFrame Renderer::renderOutputs(const Scene& scene, const Outputs& outputs) {
  if (live().backend() == Backend::Graphics && needsKeys(outputs)) {
    throw ArgumentError("the graphics backend has no visibility keys, so no alpha, depth, ids or normals; use the gpu or cpu backend");
  }
  return live().renderOutputs(scene, outputs);
}

std::vector<FrameTime> Renderer::timeFrames(const Scene& scene, int repeat) {
  std::vector<FrameTime> frames;
  Image storage;  // reused, as a sequence reuses its frames' images
  const FrameTimes times = phongvk::timeFrames(repeat, [&] {
    storage = live().render(scene, false, std::move(storage)).image;
    frames.push_back(live().lastFrameTime());
    return frames.back().deviceMs;
  });
  frames.erase(frames.begin());  // the warm-up
  for (size_t i = 0; i < frames.size(); ++i) frames[i].wallMs = times.wallMs[i];
  return frames;
}

Backend Renderer::backend() const { return live().backend(); }
std::string Renderer::deviceName() const { return live().deviceName(); }
RendererStats Renderer::stats() const { return live().stats(); }

const char* backendName(Backend backend) {
  switch (backend) {
    case Backend::Gpu: return "gpu";
    case Backend::Cpu: return "cpu";
    case Backend::Graphics: return "graphics";
  }
  return "gpu";
}

Backend parseBackend(const std::string& name) {
  if (name == "gpu") return Backend::Gpu;
  if (name == "cpu") return Backend::Cpu;
  if (name == "graphics" || name == "raster") return Backend::Graphics;
  throw ArgumentError("unknown backend '" + name + "' (gpu, cpu or graphics)");
}

DiffResult diff(const Scene& scene, const RendererOptions& gpuOptions) {
  RendererOptions options = gpuOptions;
  options.backend = Backend::Gpu;
  Renderer gpu(options);
  return diff(scene, gpu);
}

DiffResult diff(const Scene& scene, Renderer& renderer) {
  DiffResult result;
  result.reference = Renderer(Backend::Cpu).renderWithKeys(scene);
  result.gpu = renderer.renderWithKeys(scene);
  result.deviceName = renderer.deviceName();
  result.stats = compareImages(result.reference.image, result.gpu.image, result.reference.keys, result.gpu.keys);
  return result;
}

void checkSceneMemory(const Scene& scene) { checkSceneMemory(SceneAccess::spec(scene), pixelSamples(SceneAccess::spec(scene))); }

}  // namespace phongvk
