// scene.cpp — the scene file's rules (DESIGN.md "Scene file" and "Camera"). The generic checks
// (types, ranges, paths in messages) live in scene_json.cpp; this file says which apply where.
#include "scene.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "animate.h"
#include "camera.h"
#include "scene_json.h"

namespace phongvk {
namespace {

using namespace scenejson;

// "animate" is read by SceneSequence (animate.h), which hands readScene each frame without it.
const Keys kSceneKeys = {"camera",  "background", "ambient", "lights",
                         "materials", "objects",    "render",  "animate"};
const Keys kCameraKeys = {"position",   "direction", "look_at", "up",   "fov", "aspect",
                          "resolution", "width",     "height",  "near", "far"};
const Keys kLightKeys = {"position", "intensity", "color"};
const Keys kMaterialKeys = {"ka", "kd", "ks", "n", "attenuation", "color"};
const Keys kRenderKeys = {"interpolation"};
const Keys kObjectKeys = {"shape", "material", "subdivide", "closed"};  // every shape

struct ShapeInfo {
  Shape shape;
  std::string_view name;
  Keys keys;  // on top of kObjectKeys
};

const std::vector<ShapeInfo> kShapes = {
    {Shape::Sphere, "sphere", {"center", "radius", "segments"}},
    {Shape::Cube, "cube", {"center", "size"}},
    {Shape::Cylinder, "cylinder", {"center", "radius", "height", "segments"}},
    {Shape::Cone, "cone", {"center", "radius", "height", "segments", "rings"}},
    {Shape::Icosphere, "icosphere", {"center", "radius"}},
    {Shape::Polyhedron, "polyhedron", {"points"}},
    {Shape::Mesh, "mesh", {"file", "scale", "translate"}},
};

// Below this |cross(f, up)| the camera's right vector is numerically meaningless.
constexpr double kParallelTolerance = 1e-6;

// A narrower field of view makes the focal length (up to 8192 / tan(fov / 2) pixels per metre)
// large enough that focal times a distance overflows a 32-bit float in the shaders.
constexpr double kMinFov = 1e-6;

// Why `path` cannot be read as a regular file, or nothing if it can. Checks the type before
// opening: opening a FIFO for reading would block.
std::optional<std::string> unreadableReason(const std::string& path) {
  struct stat info;
  if (::stat(path.c_str(), &info) != 0) return std::strerror(errno);
  if (S_ISDIR(info.st_mode)) return std::strerror(EISDIR);
  if (!S_ISREG(info.st_mode)) return std::string("not a regular file");
  int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return std::strerror(errno);
  ::close(fd);
  return std::nullopt;
}

// ---- values shared by several sections ----

float nonNegativeFloat(const Node& node) { return toFloat(node, atLeast(node, 0)); }
// Vector elements are read as doubles; these hold values a float represents exactly.
double floatComponent(const Node& node) { return toFloat(node, number(node)); }
double nonNegativeComponent(const Node& node) { return nonNegativeFloat(node); }
double unitComponent(const Node& node) { return inRange(node, 0, 1); }

glm::vec3 color(const Node& node) { return glm::vec3(vec3(node, nonNegativeComponent)); }
glm::vec3 unitColor(const Node& node) { return glm::vec3(vec3(node, unitComponent)); }

// Positions and sizes stay within MAX_COORDINATE metres, so that every offset, distance and
// squared distance the renderers take in float stays finite (a 1e300 m centre used to become an
// infinite eye offset and NaN vertices).
double coordinate(const Node& node) { return inRange(node, -MAX_COORDINATE, MAX_COORDINATE); }
glm::dvec3 point(const Node& node) { return vec3(node, coordinate); }

double length(const Node& node) {
  double value = positive(node);
  if (value > MAX_COORDINATE) {
    node.fail("must be <= " + formatNumber(MAX_COORDINATE) + ", got " + formatNumber(value));
  }
  return value;
}

// A direction the camera basis can normalize: length neither zero nor overflowing.
glm::dvec3 usableDirection(const Node& node, glm::dvec3 direction) {
  double length = glm::length(direction);
  if (!std::isnormal(length)) {
    node.fail("must have a non-zero finite length, got length " + formatNumber(length));
  }
  return direction;
}

// ---- camera ----

// "direction", or "look_at" (a point) made into one; exactly one of them.
glm::dvec3 readViewDirection(const Node& camera, glm::dvec3 position) {
  auto direction = camera.find("direction");
  auto lookAt = camera.find("look_at");
  if (direction && lookAt) lookAt->fail("cannot be given together with 'direction'");
  if (direction) return usableDirection(*direction, vec3(*direction));
  if (!lookAt) camera.fail("missing required field 'direction' (or 'look_at')");
  glm::dvec3 target = point(*lookAt);
  if (target == position) lookAt->fail("equals camera.position, so there is no view direction");
  return usableDirection(*lookAt, target - position);
}

glm::dvec3 readUp(const Node& camera, glm::dvec3 direction) {
  glm::dvec3 up = {0, 0, 1};
  auto node = camera.find("up");
  if (node) up = usableDirection(*node, vec3(*node));
  glm::dvec3 side = glm::cross(glm::normalize(direction), glm::normalize(up));
  if (glm::length(side) < kParallelTolerance) camera.failAt("up", "parallel to the view direction");
  return up;
}

// DESIGN.md "Camera": H = floor(2·resolution·tan(fov/2)), W = floor(2·resolution·tan(fov/2)·aspect)
// (the same operations as makeView, so a scene that loads also makes a view).
void checkImageSizeFromResolution(const Node& camera, const CameraSpec& spec) {
  double planeHeight = 2 * spec.resolution * std::tan(glm::radians(spec.fov) / 2);
  double height = std::floor(planeHeight);
  double width = std::floor(planeHeight * spec.aspect);
  if (width >= 1 && height >= 1 && width <= MAX_IMAGE_SIDE && height <= MAX_IMAGE_SIDE) return;
  std::string size = formatNumber(width) + "x" + formatNumber(height);
  std::string inputs = "resolution " + formatNumber(spec.resolution) + ", fov " +
                       formatNumber(spec.fov) + ", aspect " + formatNumber(spec.aspect);
  camera.failAt("resolution", "image would be " + size + " pixels (" + inputs +
                                  "); each side must be 1 to " + std::to_string(MAX_IMAGE_SIDE));
}

// Either resolution + aspect, or width + height (which then set the aspect).
void readImageSize(const Node& camera, CameraSpec& spec) {
  auto width = camera.find("width");
  auto height = camera.find("height");
  if (!width && !height) {
    if (auto node = camera.find("aspect")) spec.aspect = positive(*node);
    if (auto node = camera.find("resolution")) spec.resolution = positive(*node);
    checkImageSizeFromResolution(camera, spec);
    return;
  }
  if (!height) width->fail("must be given together with 'height'");
  if (!width) height->fail("must be given together with 'width'");
  for (std::string_view key : {"resolution", "aspect"}) {
    if (camera.find(key)) camera.failAt(key, "cannot be given together with 'width' and 'height'");
  }
  spec.width = integer(*width, 1, MAX_IMAGE_SIDE);
  spec.height = integer(*height, 1, MAX_IMAGE_SIDE);
  spec.aspect = double(spec.width) / spec.height;
}

void readDepthRange(const Node& camera, CameraSpec& spec) {
  if (auto node = camera.find("near")) spec.nearPlane = positive(*node);
  // The renderers clip at near as a float: one that rounds to 0 would let them divide by w = 0.
  if (static_cast<float>(spec.nearPlane) < FLT_MIN) {
    camera.failAt("near", "must be >= " + formatNumber(FLT_MIN) + " (the smallest normal 32-bit float), got " +
                              formatNumber(spec.nearPlane));
  }
  if (auto node = camera.find("far")) spec.farPlane = number(*node);
  if (!(spec.farPlane > spec.nearPlane)) {
    camera.failAt("far", "must be > near (" + formatNumber(spec.nearPlane) + "), got " +
                             formatNumber(spec.farPlane));
  }
}

CameraSpec readCamera(const Node& camera) {
  requireObject(camera);
  checkKeys(camera, kCameraKeys);
  CameraSpec spec;
  spec.position = point(camera.require("position"));
  spec.direction = readViewDirection(camera, spec.position);
  spec.up = readUp(camera, spec.direction);
  if (auto node = camera.find("fov")) spec.fov = inOpenRange(*node, 0, 180);
  if (spec.fov < kMinFov) {
    camera.failAt("fov", "must be >= " + formatNumber(kMinFov) +
                             " degrees (a narrower view overflows 32-bit floats), got " + formatNumber(spec.fov));
  }
  readImageSize(camera, spec);
  readDepthRange(camera, spec);
  return spec;
}

// ---- lights ----

Light readLight(const Node& node) {
  requireObject(node);
  checkKeys(node, kLightKeys);
  Light light;
  light.position = point(node.require("position"));
  if (auto intensity = node.find("intensity")) light.intensity = nonNegativeFloat(*intensity);
  if (auto lightColor = node.find("color")) light.color = color(*lightColor);
  return light;
}

std::vector<Light> readLights(const Node& node) {
  requireArray(node);
  std::vector<Light> lights;
  for (size_t i = 0; i < node.json().size(); ++i) lights.push_back(readLight(node.element(i)));
  return lights;
}

// ---- materials ----

// 1 / (a + b d + c d^2) needs a + b d + c d^2 > 0 for every distance d > 0: a and c may not be
// negative (small and large d), not all zero, and a negative b needs the quadratic to have no
// real root (b^2 < 4ac). Checked on the floats the renderers will use.
glm::vec3 readAttenuation(const Node& node) {
  glm::vec3 abc = glm::vec3(vec3(node, floatComponent));
  double a = abc.x, b = abc.y, c = abc.z;
  bool allZero = a == 0 && b == 0 && c == 0;
  if (a < 0 || c < 0 || allZero || !(b >= 0 || b * b < 4 * a * c)) {
    node.fail("a + b*d + c*d^2 must stay positive for all distances d > 0, got [" +
              formatNumber(abc.x) + ", " + formatNumber(abc.y) + ", " + formatNumber(abc.z) + "]");
  }
  return abc;
}

Material readMaterial(const Node& node) {
  requireObject(node);
  checkKeys(node, kMaterialKeys);
  Material material;
  if (auto ka = node.find("ka")) material.ka = nonNegativeFloat(*ka);
  if (auto kd = node.find("kd")) material.kd = nonNegativeFloat(*kd);
  if (auto ks = node.find("ks")) material.ks = nonNegativeFloat(*ks);
  if (auto n = node.find("n")) material.n = nonNegativeFloat(*n);
  if (auto attenuation = node.find("attenuation")) {
    material.attenuation = readAttenuation(*attenuation);
  }
  if (auto materialColor = node.find("color")) material.color = color(*materialColor);
  return material;
}

// Scene::materials as it is built: the named materials first, in file order, then one entry per
// inline material, and one shared default for objects that name none.
class MaterialTable {
 public:
  void readNamed(const Node& node) {
    requireObject(node);
    for (const auto& [name, value] : node.json().items()) {
      materials_.push_back(readMaterial(node.child(name)));
      names_.push_back(name);
    }
  }

  // The index for an object's "material": absent, a name, or an inline material object.
  int forObject(const std::optional<Node>& node) {
    if (!node) return defaultIndex();
    if (node->json().is_string()) return named(*node);
    if (!node->json().is_object()) {
      node->fail(std::string("must be a material name or a material object, got ") +
                 node->json().type_name());
    }
    return add(readMaterial(*node));
  }

  std::vector<Material> take() { return std::move(materials_); }

 private:
  int add(const Material& material) {
    materials_.push_back(material);
    return int(materials_.size()) - 1;
  }

  int defaultIndex() {
    if (!defaultIndex_) defaultIndex_ = add(Material{});
    return *defaultIndex_;
  }

  int named(const Node& node) const {
    std::string name = string(node);
    for (size_t i = 0; i < names_.size(); ++i) {
      if (names_[i] == name) return int(i);
    }
    node.fail("unknown material '" + name + "' (" + describeNames() + ")");
  }

  std::string describeNames() const {
    if (names_.empty()) return "no named materials are defined";
    std::string text = "known: ";
    for (size_t i = 0; i < names_.size(); ++i) text += (i ? ", " : "") + names_[i];
    return text;
  }

  std::vector<Material> materials_;
  std::vector<std::string> names_;  // names_[i] names materials_[i]
  std::optional<int> defaultIndex_;
};

// ---- objects ----

const ShapeInfo& readShape(const Node& node) {
  std::string name = string(node);
  for (const ShapeInfo& info : kShapes) {
    if (info.name == name) return info;
  }
  std::string allowed;
  for (const ShapeInfo& info : kShapes) {
    allowed += (allowed.empty() ? "" : ", ") + std::string(info.name);
  }
  node.fail("unknown shape '" + name + "' (allowed: " + allowed + ")");
}

void checkObjectKeys(const Node& node, const ShapeInfo& info) {
  Keys allowed = kObjectKeys;
  allowed.insert(allowed.end(), info.keys.begin(), info.keys.end());
  Keys anyShape;
  for (const ShapeInfo& other : kShapes) {
    anyShape.insert(anyShape.end(), other.keys.begin(), other.keys.end());
  }
  checkKeys(node, allowed, anyShape, "not used by shape '" + std::string(info.name) + "'");
}

std::vector<glm::dvec3> readPoints(const Node& node) {
  requireArray(node);
  size_t count = node.json().size();
  if (count < 4) node.fail("needs at least 4 points, got " + std::to_string(count));
  std::vector<glm::dvec3> points;
  for (size_t i = 0; i < count; ++i) points.push_back(point(node.element(i)));
  return points;
}

// Only checks that the file can be read: the OBJ itself is parsed by the mesh builder.
std::string resolveMeshFile(const Node& node, const std::string& baseDir) {
  std::string file = string(node);
  if (file.empty()) node.fail("must name a file, got an empty string");
  // An absolute `file` replaces baseDir here.
  std::string resolved = (std::filesystem::path(baseDir) / file).string();
  if (auto reason = unreadableReason(resolved)) node.fail("cannot read '" + file + "': " + *reason);
  return resolved;
}

// Each geometry key means the same for every shape that takes it, and checkObjectKeys has
// already rejected the keys this shape does not take, so one reader serves all shapes.
void readGeometry(const Node& node, Object& object, const std::string& baseDir) {
  if (auto center = node.find("center")) object.center = point(*center);
  if (auto radius = node.find("radius")) object.radius = length(*radius);
  if (auto size = node.find("size")) object.size = length(*size);
  if (auto height = node.find("height")) object.height = length(*height);
  if (auto segments = node.find("segments")) object.segments = integer(*segments, 3, 4096);
  if (auto rings = node.find("rings")) object.rings = integer(*rings, 1, 4096);
  if (auto scale = node.find("scale")) object.scale = positive(*scale);
  if (auto translate = node.find("translate")) object.translate = point(*translate);
  if (object.shape == Shape::Polyhedron) object.points = readPoints(node.require("points"));
  if (object.shape == Shape::Mesh) object.file = resolveMeshFile(node.require("file"), baseDir);
}

Object readObject(const Node& node, const std::string& baseDir, MaterialTable& materials) {
  requireObject(node);
  const ShapeInfo& info = readShape(node.require("shape"));
  checkObjectKeys(node, info);
  Object object;
  object.shape = info.shape;
  object.jsonPath = node.path();
  object.closed = info.shape != Shape::Mesh;  // imported meshes are often open or mis-wound
  readGeometry(node, object, baseDir);
  if (auto subdivide = node.find("subdivide")) object.subdivide = integer(*subdivide, 0, 10);
  if (auto closed = node.find("closed")) object.closed = boolean(*closed);
  object.material = materials.forObject(node.find("material"));
  return object;
}

std::vector<Object> readObjects(const Node& node, const std::string& baseDir,
                                MaterialTable& materials) {
  requireArray(node);
  if (node.json().empty()) node.fail("scene has no objects");
  std::vector<Object> objects;
  for (size_t i = 0; i < node.json().size(); ++i) {
    objects.push_back(readObject(node.element(i), baseDir, materials));
  }
  return objects;
}

// ---- render options and the whole scene ----

Interpolation readRender(const Node& node) {
  requireObject(node);
  checkKeys(node, kRenderKeys);
  auto interpolation = node.find("interpolation");
  if (!interpolation) return Interpolation::Perspective;
  std::string mode = string(*interpolation);
  if (mode == "perspective") return Interpolation::Perspective;
  if (mode == "screen") return Interpolation::Screen;
  interpolation->fail("must be one of perspective, screen, got '" + mode + "'");
}

Scene readScene(const Node& root, const std::string& path, const std::string& baseDir) {
  requireObject(root);
  checkKeys(root, kSceneKeys);
  Scene scene;
  scene.path = path;
  scene.camera = readCamera(root.require("camera"));
  if (auto background = root.find("background")) scene.background = unitColor(*background);
  if (auto ambient = root.find("ambient")) scene.ambient = color(*ambient);
  if (auto lights = root.find("lights")) scene.lights = readLights(*lights);
  MaterialTable materials;
  if (auto named = root.find("materials")) materials.readNamed(*named);
  scene.objects = readObjects(root.require("objects"), baseDir, materials);
  scene.materials = materials.take();
  if (auto render = root.find("render")) scene.interpolation = readRender(*render);
  return scene;
}

}  // namespace

std::string readSceneText(const std::string& path) {
  if (auto reason = unreadableReason(path)) {
    throw SceneError(path + ": cannot read file: " + *reason);
  }
  std::ifstream in(path, std::ios::binary);
  std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (!in.is_open()) throw SceneError(path + ": cannot read file: " + std::strerror(errno));
  return text;
}

Scene loadScene(const std::string& path) {
  return parseScene(readSceneText(path), path, std::filesystem::path(path).parent_path().string());
}

Scene parseScene(const std::string& text, const std::string& path, const std::string& baseDir) {
  Json json = parseJson(text, path);
  // The sequence validates the block and parses frame 0's JSON (which has no "animate") here.
  if (json.is_object() && json.contains("animate")) return SceneSequence(std::move(json), path, baseDir).frame(0);
  return readScene(Node(json, "", path), path, baseDir);
}

}  // namespace phongvk
