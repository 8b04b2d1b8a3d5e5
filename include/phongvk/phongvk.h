// phongvk.h — the public C++ API: load a scene, render it with the Vulkan compute port or the CPU
// reference, get an RGB image, diff the two. The phongvk command and outside projects
// (find_package(phongvk), the phongvk::phongvk target) call this and nothing else of the library.
//
//   phongvk::Scene scene = phongvk::loadScene("scenes/basic.json");
//   phongvk::Renderer gpu(phongvk::Backend::Gpu);
//   phongvk::Image image = gpu.render(scene);          // 1385x923, row 0 at the top
//   phongvk::writePng("basic.png", image);
//
// Both renderers implement one contract (docs/DESIGN.md) and give the same bytes on every device.
#pragma once

#include "phongvk/compare.h"
#include "phongvk/devices.h"
#include "phongvk/errors.h"
#include "phongvk/export.h"
#include "phongvk/image.h"
#include "phongvk/mesh.h"
#include "phongvk/scene_parts.h"

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace phongvk {

// The library's version ("1.0.0") and the git revision it was built from ("609e5db", with
// "-dirty" for uncommitted changes; "unknown" outside a checkout).
PHONGVK_API const char* version();
PHONGVK_API const char* revision();

// Scene::triangles: the scene's built geometry in world coordinates. The triangle_ids output
// numbers its primitives in this order: the triangles, then the lines, then the points.
struct SceneTriangles {
  MeshArrays mesh;               // positions, normals (0 where none), triangles, lines and points (vertex indices)
  std::vector<int32_t> objects;  // per triangle: its object's index in the scene
  std::vector<int32_t> lineObjects;   // per line, likewise
  std::vector<int32_t> pointObjects;  // per point, likewise
};

// A validated scene: camera, lights, materials, objects (docs/DESIGN.md "Scene file"). Cheap to
// copy (copies share the validated model). Meshes are built by the renderer that first renders it.
class PHONGVK_API Scene {
 public:
  // An empty scene to build in code, rendered at width x height pixels (1..16384 each): the
  // default Camera (scene_parts.h), one white light at the camera, the scene file's defaults
  // for the rest, and no objects yet (add some with add or addMesh; rendering a scene without
  // objects throws SceneError). A mesh added without a material gets Material{}, which has no
  // fall-off, as a model file rendered alone (scene_parts.h): lit by the light at the camera, it
  // is well exposed at any distance. SceneError for a size out of range.
  Scene(int width, int height);

  // The file it came from, as given ("" for a scene made from text without a name).
  const std::string& path() const;
  // The image the scene's camera renders (or the size set by withImageSize).
  int width() const;
  int height() const;
  size_t objectCount() const;
  size_t lightCount() const;
  // The same scene rendered at width x height pixels (1..16384 each): the vertical field of view
  // is kept and the aspect follows the new size. Throws SceneError for a size out of range.
  Scene withImageSize(int width, int height) const;

  // The same scene rendered with `settings` (checked like a scene file's "render" and
  // "background": SceneError naming render.KEY or background[i]; ArgumentError for a colour that is
  // not finite).
  Scene withRender(const RenderSettings& settings) const;
  // The scene's render settings, and new ones (checked as withRender checks them).
  RenderSettings renderSettings() const;
  void setRenderSettings(const RenderSettings& settings);

  // One share of the scene for a process of `parts` that render it together (phongvk render --mpi):
  // the part-th of `parts` near-equal contiguous ranges of its triangles, in file order, with every
  // vertex, light and the camera of the whole scene. Its keys name triangles by their index in the
  // whole scene, so the shares' keys combine by their minimum, pixel by pixel, into the whole
  // scene's, and each pixel's colour is that of the share that holds its winner. Throws SceneError
  // for a part out of 0..parts-1, or (when rendered) a scene of fewer triangles than parts.
  Scene share(int part, int parts) const;

  // Adds `mesh` as an object of this scene (not of copies made before), with `material` (checked
  // like a scene file's: SceneError naming objects[N].material.KEY, ArgumentError for a value that
  // is not finite; none: the scene's default material, the file's own for a scene from a file,
  // Material{} for Scene(width, height)), or the scene's material named `materialName` (a scene
  // file's "materials"; SceneError for a name it does not have). Throws ArgumentError naming the array ("vertices",
  // "faces", "normals") and its first bad row; the scene is unchanged then.
  void addMesh(const MeshArrays& mesh, const std::optional<Material>& material = std::nullopt, bool closed = false);
  void addMesh(const MeshArrays& mesh, const std::string& materialName, bool closed = false);

  // The same, placed by `pose` (local to world, scene_parts.h Matrix4: the mesh's vertices are in
  // its own coordinates), and a handle to move it (setPose) or take it out (remove). Throws as
  // addMesh, and ArgumentError naming "pose" for a matrix that is not an affine map.
  ObjectId add(const MeshArrays& mesh, const Matrix4& pose = IDENTITY_POSE,
               const std::optional<Material>& material = std::nullopt, bool closed = false);
  ObjectId add(const MeshArrays& mesh, const Matrix4& pose, const std::string& materialName, bool closed = false);
  // The same with a mesh built once (TriangleMesh, mesh.h): the object shares it, so placing one
  // mesh many times builds and holds it once.
  ObjectId add(const TriangleMesh& mesh, const Matrix4& pose = IDENTITY_POSE,
               const std::optional<Material>& material = std::nullopt, bool closed = false);
  ObjectId add(const TriangleMesh& mesh, const Matrix4& pose, const std::string& materialName, bool closed = false);
  // Moves an object added with add, or takes it out. A handle names one object of the scene that
  // gave it for that scene's life (a copy that changes is another scene, whose new handles are its
  // own); RangeError for one this scene does not hold, saying whether it was removed or belongs to
  // another scene.
  void setPose(ObjectId object, const Matrix4& pose);
  void remove(ObjectId object);
  // The object's id in the object_id output (Outputs::objectIds): given by add for the scene's
  // life, whatever is removed or added after it (a scene's own objects first, by index, then one
  // number per add), or the one setObjectId gave it (a label of the caller's: any number in
  // 0..2^31-1, several objects may share one, as classes in a segmentation do; ArgumentError
  // outside that range).
  int32_t objectId(ObjectId object) const;
  void setObjectId(ObjectId object, int32_t id);
  // Whether an added object's triangles block lights that cast shadows (a scene file's
  // "cast_shadows"; true when added): false for a ground plane or a helper that should not.
  bool castsShadows(ObjectId object) const;
  void setCastShadows(ObjectId object, bool casts);
  // The object's geometry replaced by `mesh` in place: its handle, id, pose, material and
  // closedness stay.
  void setMesh(ObjectId object, const TriangleMesh& mesh);

  // Lights added with a handle, as objects are: appended after the scene's lights (those of its
  // file, or set with setLights), checked as a scene file's "lights[N]" (SceneError, the scene
  // unchanged then), changed or taken out by handle (RangeError as for objects). setLights
  // replaces every light and retires every light handle.
  LightId addLight(const Light& light);
  Light light(LightId light) const;
  void setLight(LightId light, const Light& value);
  void removeLight(LightId light);
  // The light at `index` in lights() replaced, its handle (if any) kept; RangeError outside
  // 0..lightCount()-1.
  void setLightAt(size_t index, const Light& value);

  // The world box around every object's vertices, as built: {min, max}. Builds the meshes to know
  // (a renderer builds its own again), so a program placing cameras about a model asks once.
  // Throws SceneError, before building, for a scene whose meshes need more than the memory limit
  // (checkSceneMemory's check, for a frame of no pixels).
  std::array<Vec3, 2> bounds() const;

  // Every triangle as both renderers draw it (shapes tessellated, meshes subdivided, transforms and
  // poses applied), in world coordinates: positions, unit vertex normals and vertex indices in
  // `mesh` (no uvs), and each triangle's object (its index in the scene's objects) in `objects`.
  // For drawing the same geometry with another renderer, or exporting it. Builds the meshes, as
  // bounds() does, and checks the memory limit as it does, then again with what it returns (24
  // bytes a vertex, 28 a triangle) before it makes it.
  SceneTriangles triangles() const;

  // The camera as a value, and a new one (checked like a scene file's "camera": SceneError
  // naming camera.KEY; ArgumentError for a value that is not finite). A camera of size 0 x 0
  // keeps the scene's image size.
  Camera camera() const;
  void setCamera(const Camera& camera);
  // The point lights, and new ones (checked like a scene file's "lights").
  std::vector<Light> lights() const;
  void setLights(const std::vector<Light>& lights);
  // The ambient light (RGB >= 0, default white), and a new one (checked like a scene file's
  // "ambient"; given back in 32-bit floats, as the renderers hold it).
  Vec3 ambient() const;
  void setAmbient(const Vec3& ambient);

  // The scene as scene file JSON text (docs/DESIGN.md "Scene file"): parseScene (or loadScene of
  // the text saved) reads it back into a scene that renders the same bytes, and whose toJson is
  // this text again. Every value is written explicitly: the camera (its image as width and height,
  // or as the resolution and aspect that set it), lights, named materials by name and every other
  // material inline (the default one with its values), each object with its shape's parameters,
  // scale, rotation as {"matrix": rows}, mesh files by absolute path and meshes added as arrays
  // inline ("vertices", "faces", "normals"; at their poses), and the "render" section. An animated
  // scene writes this frame (no "animate" block); a model file loaded alone writes as the scene
  // made around it. Objects added in code become the text's own objects: the scene read back has
  // no handles for setPose or remove, and a mesh added to it later without a material gets the
  // scene file's default material.
  std::string toJson() const;

  // The frames of the file's "animate" block (1 without one; this scene is frame 0), each
  // validated like a scene file, with the meshes added with addMesh or add (built once, at their
  // poses); the camera and lights are the file's frame's. frame throws
  // RangeError outside 0..frameCount()-1, SceneError for a bad frame.
  int frameCount() const;
  Scene frame(int index) const;


 private:
  struct State;  // the validated model and the sequence frame() comes from (api/scene.cpp)
  explicit Scene(std::shared_ptr<State> state);
  std::shared_ptr<State> state_;  // shared by copies; a change copies it unless this scene holds it alone
  friend struct SceneAccess;  // the library's own way in (api/scene_access.h)
};

struct LoadOptions {
  ModelUp up = ModelUp::Usual;  // only for a model file alone: a scene file names each object's "up"
  // Only for a model file alone: true, a fitted orthographic camera (its view spanning the model
  // with a margin); false, the perspective one (as when not given). A scene file's camera says its
  // own "projection", and either given with one is an error.
  std::optional<bool> orthographic;
  // Only for a model file alone: false leaves out the lights a glTF file places
  // (KHR_lights_punctual), lighting it from the camera as other files are. A scene file says it
  // per object ("file_lights"), and false given with one is an error.
  bool fileLights = true;
  // Only for a model file alone: true, the lights a glTF file places cast shadows (as a light's
  // "shadows"). A scene file says it per object ("file_light_shadows"), and true given with one is
  // an error, as it is with fileLights false.
  bool fileLightShadows = false;
};

// Reads and validates a scene file, or a model file (.obj .ply .stl .gltf .glb) as a scene of its
// own: the model in full view, lit from the camera (or by its own lights, a glTF file that places
// some). Throws SceneError naming the file and the JSON
// path (and for a mesh the inner file and line), ArgumentError for an up axis or a projection
// given with a scene file. A file with an "animate" block gives its frame 0.
PHONGVK_API Scene loadScene(const std::string& path, const LoadOptions& options = {});

// The same from JSON text: `name` stands for the file in messages (none when empty) and relative
// mesh paths resolve against `baseDir`. With `objectsLater` the text may have no objects yet
// ("objects": [], as Python's scene_from_dict allows) and get them from add or addMesh; rendering
// a scene without objects throws SceneError. A scene built in code starts from Scene(width, height).
PHONGVK_API Scene parseScene(const std::string& json, const std::string& name = "scene.json",
                             const std::string& baseDir = ".", bool objectsLater = false);

enum class Backend {
  Gpu,       // the Vulkan compute port (the default)
  Cpu,       // the reference: plain single-threaded C++, the specification in code
  Graphics,  // the Vulkan graphics pipeline, the benchmark's speed baseline (not bit-identical)
};

// "gpu", "cpu", "graphics"; parseBackend also takes "raster", the graphics backend's older name.
// parseBackend throws ArgumentError for any other name.
PHONGVK_API const char* backendName(Backend backend);
PHONGVK_API Backend parseBackend(const std::string& name);

struct RendererOptions {
  Backend backend = Backend::Gpu;
  int device = -1;        // Vulkan device index (listDevices); -1: the best usable one
  bool validate = false;  // Vulkan validation layers (also with the environment PHONGVK_VALIDATE=1)
};

// One timed frame: wall clock around the render call, and the device's own time in all and per
// pass (NaN where the backend or device does not measure it: the graphics baseline has no passes;
// the reference's device is the CPU thread, its device time the frame's compute time).
struct FrameTime {
  double wallMs = 0;
  double deviceMs = 0;
  double shadeMs = 0;    // vertex transform and lighting
  double rasterMs = 0;   // triangle set-up, culling, clipping, small triangles, binning
  double resolveMs = 0;  // large triangles, colours
};

// What a renderer has done so far.
struct RendererStats {
  uint64_t sceneBuilds = 0;      // times meshes were built (a scene with new geometry)
  uint64_t framesRendered = 0;
  uint64_t framesShaded = 0;     // frames whose per-vertex lighting was computed (gpu; others reuse it)
  uint64_t framesRepeated = 0;   // frames rendered again with larger lists or more workgroups (gpu)
  size_t triangles = 0;          // of the last scene rendered (a share: its own)
  size_t lines = 0, points = 0;  // of the last scene rendered (docs/DESIGN.md "Points and lines")
  size_t lights = 0;             // that lit it: its own and those its model files place
  double buildMs = 0;            // time spent building meshes, in all (uploads not included)
  uint64_t textureBytes = 0;     // the last scene's textures: texels, coordinates, table (docs/DESIGN.md "Textures")
  uint64_t deviceBytes = 0;      // device memory the renderer's buffers hold now (Vulkan backends; 0 for the reference)
  uint64_t validationMessages = 0;  // Vulkan validation warnings and errors (RendererOptions::validate)
  // Start-up of the Vulkan backends (0 for the reference): the instance and device, the float
  // probe (0 when its answer came from the disk cache), and compiling pipelines so far (first
  // frames and new variants; the pipeline cache on disk serves drivers that keep one).
  double contextMs = 0;
  double probeMs = 0;
  bool probeCached = false;
  double pipelinesMs = 0;
  // The renderer's first frame on the device (ms; 0 before it). lavapipe generates each pass's
  // machine code when the pass first runs, so on a new machine (no Mesa shader cache yet) this is
  // most of a first render; later processes take the code from the cache.
  double firstFrameMs = 0;
  // What a user may not expect of the last scene's picture, in a sentence naming the file; empty
  // when nothing. A fitted camera that sees only the back of every triangle (a one-sided polygon
  // or an open mesh whose normals face away) says so: the model is drawn dark, lit from behind.
  std::string notice;
};

// What a frame can give besides its colours (Renderer::renderOutputs).
struct Outputs {
  bool alpha = false;        // coverage: 255 where triangles cover every sample of the pixel, 0 where none
  bool depth = false;        // metres along the camera's axis to the nearest surface; +inf where empty
  bool objectIds = false;    // the nearest surface's object (index in the scene's objects); -1 where empty
  bool triangleIds = false;  // its triangle (index in the scene: objects in order); -1 where empty
  // The nearest surface's unit shading normal in camera space, x right, y up, z forward (the axis
  // depth runs along: a surface facing the camera has z < 0); 0, 0, 0 where empty. The normal the
  // frame's shading uses there: flat, the triangle's face normal; Gouraud and Phong, the vertex
  // normals interpolated at the pixel (perspective-correct or not, as render.interpolation says)
  // and normalized. On a back face (an open object's) it is the stored normal, facing away from
  // the camera, not flipped.
  bool normals = false;
  // How many of the frame's lights reach the nearest surface (docs/DESIGN.md "Shadows"): each light
  // without shadows, and each shadowed one whose ray from the surface point is not blocked; -1 where
  // empty. Where the frame's shading lights a pixel (flat: the triangle's centroid; Gouraud and
  // Phong: the point under the pixel's nearest sample).
  bool lights = false;
};

// A frame and the outputs asked for, each width x height values, row-major, row 0 at the top
// (an output not asked for is empty); the normals three floats a pixel. With samples per pixel
// (render.samples) the colour and alpha are the samples' box-filtered mean, and the depth, ids and
// normal are the pixel's nearest sample's (the normal taken at that sample's position).
// Every output comes from the visibility keys, which both renderers give bit for bit alike, so
// every output is the same bytes on the gpu and cpu backends.
struct RenderedFrame {
  Image image;  // RGB
  std::vector<uint8_t> alpha;
  std::vector<float> depth;
  std::vector<int32_t> objectIds;
  std::vector<int32_t> triangleIds;
  std::vector<float> normals;  // x, y, z per pixel
  std::vector<int32_t> lights;
};

// Renders scenes on one backend. It keeps what it built and uploaded: rendering a scene with the
// same geometry as the last one (another frame of a sequence, another camera, other materials or
// lights) builds no meshes and sends only what changed. One Vulkan device each. Calls from several
// threads are serialized: the renderer renders one frame at a time (use one renderer a thread to
// render in parallel).
class PHONGVK_API Renderer {
 public:
  // Throws NoDeviceError when the GPU backends find no usable Vulkan device.
  explicit Renderer(Backend backend = Backend::Gpu, int device = -1);
  explicit Renderer(const RendererOptions& options);
  ~Renderer();
  Renderer(Renderer&&) noexcept;
  Renderer& operator=(Renderer&&) noexcept;

  // One frame of `scene`. Throws SceneError for a scene whose meshes cannot be built, and
  // DeviceError naming the device limit a scene exceeds.
  Image render(const Scene& scene);
  // The same into `image`, whose pixel storage the gpu backend reuses when it is large enough: a
  // loop of frames through one Image allocates nothing per frame.
  void render(const Scene& scene, Image& image);
  // The same with the per-pixel visibility keys (for diffs; the gpu backend's keys equal the
  // reference's). The graphics backend has no keys.
  RenderOutput renderWithKeys(const Scene& scene);
  // One frame with the outputs asked for. Throws ArgumentError on the graphics backend (it has no
  // keys), and as render otherwise.
  RenderedFrame renderOutputs(const Scene& scene, const Outputs& outputs);
  // One untimed warm-up frame, then `repeat` timed frames of `scene`.
  std::vector<FrameTime> timeFrames(const Scene& scene, int repeat);

  Backend backend() const;
  // "cpu (reference)" or the Vulkan device's name and key path (devices.h keyPathWords):
  // "llvmpipe (LLVM 15.0.6, 256 bits), keys: 64-bit atomics".
  std::string deviceName() const;
  RendererStats stats() const;

  // Frees what the renderer holds (its Vulkan device, buffers and pipelines) now, before it is
  // destroyed; every call after it throws ArgumentError. Not while another thread renders with it.
  void close();

 private:
  class Impl;  // api/renderer_impl.h
  Impl& live() const;  // ArgumentError once closed
  std::unique_ptr<Impl> impl_;
  friend struct RendererAccess;  // the backends' way to the Impl they implement (api/renderer_impl.h)
};

// The scene rendered by the reference and by the compute port, both with keys, and compared.
struct DiffResult {
  RenderOutput reference;
  RenderOutput gpu;
  DiffStats stats;
  std::string deviceName;
};

// What `phongvk diff` does: the reference against a compute-port renderer made with gpuOptions.
// Throws as Renderer does.
PHONGVK_API DiffResult diff(const Scene& scene, const RendererOptions& gpuOptions = {});

// The same against `renderer` (any backend with keys: the gpu one, or the reference against itself),
// which keeps what it uploads as for any frame.
PHONGVK_API DiffResult diff(const Scene& scene, Renderer& renderer);

// The memory a scene may take, estimated before anything is built (docs/DESIGN.md "Memory") and
// checked again on every frame; a scene beyond it fails with SceneError
// naming the objects that take most. Default: the machine's physical memory, or the environment's
// PHONGVK_MAX_MEMORY_GB (a SceneError when it is not a number of GiB). 0 restores the default.
PHONGVK_API void setMemoryLimit(uint64_t bytes);
// The limit in force, in bytes: what setMemoryLimit set, else PHONGVK_MAX_MEMORY_GB, else the
// machine's physical memory. Throws SceneError for a PHONGVK_MAX_MEMORY_GB that is not a number of
// GiB.
PHONGVK_API uint64_t memoryLimit();
// Throws SceneError when `scene`, as it stands (its size and samples, its meshes estimated before
// they are built), needs more than the memory limit: the check every renderer makes before it
// builds, for a caller that wants it before rendering anything (every frame of a sequence first).
PHONGVK_API void checkSceneMemory(const Scene& scene);
// The most texels a texture may have across or down (docs/DESIGN.md "Textures").
inline constexpr int64_t MAX_TEXTURE_SIDE = 16384;
// Throws for a texture of width x height texels that no scene can hold, for a caller to ask before
// it copies or encodes one: ArgumentError "<what>: ..." for a side outside 1..MAX_TEXTURE_SIDE,
// SceneError naming <what> when its texels (4 bytes each) need more than the memory limit.
PHONGVK_API void checkTextureSize(int64_t width, int64_t height, const std::string& what);
}  // namespace phongvk
