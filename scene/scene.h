// scene.h — the validated scene model and its JSON loader (docs/DESIGN.md "Scene file").
// Everything downstream reads this model; nothing downstream re-reads the JSON.
#pragma once

#include "geometry/mesh.h"
#include "phongvk/errors.h"
#include "phongvk/scene_parts.h"  // Shading, Specular, Interpolation: the public enums are the model's

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace phongvk {

// Defaults are the values the paper's own code used (the public Material, scene_parts.h, has the same).
struct MaterialSpec {
  float ka = 0.15f;
  float kd = 1.0f;
  float ks = 0.8f;
  float n = 10.0f;                                  // shininess
  glm::vec3 attenuation = {1.0f, 0.2f, 0.2f};       // a, b, c of 1 / (a + b d + c d^2)
  glm::vec3 color = {0.8f, 0.8f, 0.8f};
  // "texture": a PNG or JPEG that multiplies C (docs/DESIGN.md "Textures"), as an absolute path or
  // a data URI (textureSourceOf), and the decoded image; none when empty.
  std::string texture;
  std::shared_ptr<const TextureImage> textureImage;
};

// The material of a model file rendered alone (model_scene.cpp) and the default one of a scene
// built in code (Scene(width, height)): the file's default without fall-off, so that the light at
// the camera leaves a mesh well exposed at any distance.
inline MaterialSpec noFallOffMaterial() {
  MaterialSpec m;
  m.attenuation = {1.0f, 0.0f, 0.0f};
  return m;
}

struct LightSpec {
  glm::dvec3 position = {0, 0, 0};
  float intensity = 1.0f;
  glm::vec3 color = {1, 1, 1};
  bool atCamera = false;             // "position": "camera": at the eye, wherever the camera is
  // "direction" instead of "position": a directional light (the sun), whose light travels along
  // `direction` (non-zero, any length) and reaches every point alike, without fall-off.
  bool directional = false;
  glm::dvec3 direction = {0, 0, -1};
  // "position" and "direction": a spot light at `position` pointing along `direction`, full within
  // `innerCone` of its axis and dark beyond `outerCone` (half-angles in degrees, 0 <= inner <
  // outer <= 90; glTF KHR_lights_punctual's defaults and fall-off).
  bool spot = false;
  double innerCone = 0;
  double outerCone = 45;
  // "falloff": "inverse_square": a point or spot light falls off as 1/d^2 (windowed to 0 at
  // `range` metres when range > 0, glTF's window) instead of as the material's attenuation says.
  bool inverseSquare = false;
  double range = 0;
  // "shadows": true: lights only the points its shadow ray reaches (docs/DESIGN.md "Shadows").
  bool shadows = false;
};

struct CameraSpec {
  glm::dvec3 position = {0, 0, 0};
  glm::dvec3 direction = {1, 0, 0};  // from "direction", or look_at - position
  glm::dvec3 up = {0, 0, 1};
  double fov = 60;                   // vertical, degrees
  double aspect = 1.5;               // width / height
  double resolution = 800;           // pixels per metre of an image plane 1 m in front of the eye
  int width = 0;                     // when > 0 (with height), sets the image size directly
  int height = 0;
  double nearPlane = 0.05;
  double farPlane = 1000;
  // Pinhole intrinsics ("fx", "fy", "cx", "cy", with width and height; then fov, aspect and
  // resolution are not used): focal lengths and principal point in pixels, OpenCV's convention
  // (pixel centres at integer coordinates).
  bool intrinsics = false;
  double fx = 0, fy = 0, cx = 0, cy = 0;
  // "projection": "orthographic" (with width and height; then fov, aspect and resolution are not
  // used): every pixel looks along the view direction, and the image spans "ortho_height" metres
  // from top to bottom (and ortho_height * width / height across).
  bool orthographic = false;
  double orthoHeight = 1;
  // "fit": position, near and far come from the objects' bounds when the meshes are built
  // (camera_fit.h); `direction` is the view direction.
  bool fit = false;
};

// The most lights a scene may have. The compute port lights a vertex (Gouraud) or a pixel (flat
// and Phong shading, each of a bin's 16 tiles in turn) in a loop over the lights, and lavapipe
// allows one shader invocation 65,535 loop iterations in all: a screen-filling dense mesh with
// 2,048 lights already ran out with Phong shading, where the reference renders it. 1,024 renders
// in every mode on both renderers, and is far beyond what a Phong scene lights itself with.
inline constexpr size_t MAX_LIGHTS = 1024;

// A file's size and modification time: a renderer rebuilds a mesh whose file changed since it
// built it (sameGeometry, scene_data.h).
struct FileVersion {
  uint64_t bytes = 0;
  int64_t modified = 0;  // nanoseconds since the file clock's epoch
  bool operator==(const FileVersion&) const = default;
};

// The file at `path` as it is now (zeros where it cannot be read): a mesh file's or a texture's,
// to tell a changed file from the one read before.
FileVersion fileVersion(const std::string& path);

enum class Shape { Sphere, Cube, Cylinder, Cone, Icosphere, Polyhedron, Mesh };
// The scene file's name of a shape ("sphere", ..., "mesh"; scene_objects.cpp's table of shapes).
std::string_view shapeName(Shape shape);
// The scene file's names of the render choices, in the order of their enums (scene_parts.h).
inline constexpr std::array<const char*, 2> INTERPOLATION_NAMES = {"perspective", "screen"};
inline constexpr std::array<const char*, 2> TEXTURE_FILTER_NAMES = {"nearest", "bilinear"};
inline constexpr std::array<const char*, 3> SHADING_NAMES = {"gouraud", "flat", "phong"};
inline constexpr std::array<const char*, 2> SPECULAR_NAMES = {"phong", "blinn"};
// An inline mesh's texture wrap modes, indexed by gpu::TEXTURE_WRAP_* (glTF's names, lower case).
inline constexpr std::array<const char*, 3> TEXTURE_WRAP_NAMES = {"repeat", "clamp_to_edge", "mirrored_repeat"};
enum class UpAxis { Z, Y };

struct Object {
  Shape shape = Shape::Sphere;
  glm::dvec3 center = {0, 0, 0};
  double radius = 0.5;
  double size = 1;                   // cube edge length
  double height = 1;                 // cylinder / cone, along +z, centred on `center`
  int segments = 32;                 // sphere / cylinder / cone around the axis
  int rings = 1;                     // cone: rings along the side
  int subdivide = 0;                 // 1 -> 4 splits, this many times
  std::vector<glm::dvec3> points;    // polyhedron: convex hull of these
  std::string file;                  // mesh: OBJ, PLY, STL, glTF or GLB path, resolved against the scene folder
  FileVersion fileVersion;           // mesh: the file as it was when the scene was loaded
  uint64_t fileTriangles = 0;        // mesh: what the file will build, estimated then (memory_estimate.h)
  std::shared_ptr<const Mesh> arrays;  // mesh: given as arrays (mesh_arrays.h) instead of a file
  bool baseColors = false;           // mesh: a glTF file's base colours apply (it names no material)
  bool fileLights = true;            // mesh: a glTF file's own lights (KHR_lights_punctual) light the scene
  bool fileLightShadows = false;     // mesh: "file_light_shadows": those lights cast shadows
  bool castShadows = true;           // "cast_shadows": its triangles block shadow rays
  std::optional<double> pointSize;   // "point_size": its points' side in pixels, over the scene's render.point_size
  std::optional<double> lineWidth;   // "line_width": its lines' width in pixels, likewise
  glm::dvec3 translate = {0, 0, 0};  // mesh: the origin of its local frame
  // The local frame's linear map (object_mesh.h objectTransform): `up` first (meshes), then `scale` per axis
  // (non-zero; negative mirrors), then `rotation`.
  UpAxis up = UpAxis::Z;
  glm::dvec3 scale = {1, 1, 1};
  glm::dmat3 rotation{1.0};
  int material = 0;                  // index into SceneSpec::materials
  bool closed = true;                // back faces culled; primitives true, meshes default false
  // Placed by a pose (object_pose.h: Scene::add, the file's "pose"): the pose's linear part, which
  // both renderers apply per vertex to a mesh built in its own coordinates (rotation and scale
  // then none, translate the pose's translation). Moving such an object builds nothing again.
  std::optional<glm::dmat3> poseLinear;
  // What the object_id output says for it ("object_id" in the file): its index in the scene's
  // objects where unset. Scene::add gives each added object one for the scene's life.
  std::optional<int32_t> label;
  std::string jsonPath;              // "objects[3]", for error messages downstream
};

struct SceneSpec {
  std::string path;                  // the file it came from (for messages)
  CameraSpec camera;
  glm::vec3 background = {0, 0, 0};
  glm::vec3 ambient = {1, 1, 1};
  std::vector<LightSpec> lights;
  std::vector<MaterialSpec> materials;   // named ones first (in file order), then inline ones
  std::vector<std::string> materialNames;  // materialNames[i] names materials[i], the named ones
  std::optional<int> defaultMaterial;      // the default material's index, once an object took it
  std::vector<Object> objects;
  Interpolation interpolation = Interpolation::Perspective;
  Shading shading = Shading::Gouraud;
  Specular specular = Specular::Phong;
  int samples = 1;  // per pixel: 1, 4, 9 or 16
  TextureFilter textureFilter = TextureFilter::Bilinear;  // render.texture_filter
  double pointSize = 1;  // render.point_size: pixels (an object's own "point_size" wins)
  double lineWidth = 1;  // render.line_width, likewise
  // Which contiguous share of the built triangles to keep (sharePart of shareParts, near-equal
  // ranges in file order), for one process of a scene split across several (phongvk render --mpi).
  // A mesh file given alone (model_scene.h): its messages name that file only, not the scene
  // phongvk made around it ("m.gltf: index 7 is ...", not "m.gltf: objects[0].file: /abs/m.gltf: ...").
  bool modelAlone = false;
  int sharePart = 0;
  int shareParts = 1;
};

// Reads and validates a scene file. Throws SceneError naming the file and the JSON path.
// A file with an "animate" block gives its frame 0 (animate.h has the other frames).
SceneSpec loadSceneSpec(const std::string& path);

// Parses scene JSON text. `path` names the source in messages (none when empty); relative files
// resolve against `baseDir`. With `objectsLater` the scene may have no objects yet (they come as
// arrays, mesh_arrays.h); rendering a scene without objects is an error either way
// (buildSceneData). Throws SceneError. Like loadSceneSpec, an animated scene gives its frame 0.
SceneSpec parseSceneSpec(const std::string& text, const std::string& path, const std::string& baseDir,
                         bool objectsLater = false);

// A scene file's text. Throws SceneError "<path>: cannot read file: <why>".
std::string readSceneText(const std::string& path);

}  // namespace phongvk
