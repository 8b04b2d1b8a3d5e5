#include "prepare/scene_data.h"

#include "base/huge_pages.h"
#include "base/number_text.h"
#include "prepare/shadow_bvh.h"
#include "shaders/phong.h"
#include "shaders/screen_quads.h"
#include "scene/object_mesh.h"

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <cmath>
#include <limits>
#include <map>

namespace phongvk {

namespace {

// The material as the renderers read it; its texture's index in `textures` (none if not there).
gpu::MaterialData toGpu(const MaterialSpec& m, const std::map<const TextureImage*, uint32_t>& textures) {
  gpu::MaterialData g{};
  const auto texture = m.textureImage ? textures.find(m.textureImage.get()) : textures.end();
  g.texture = texture != textures.end() ? texture->second : gpu::TEXTURE_NONE;
  g.color = m.color;
  g.ka = m.ka;
  g.attenuation = m.attenuation;
  g.kd = m.kd;
  g.ks = m.ks;
  g.n = m.n;
  return g;
}

// FrameData::projection of a camera that is, or is not, orthographic.
uint32_t projectionOf(bool orthographic) {
  return orthographic ? gpu::PROJECTION_ORTHOGRAPHIC : gpu::PROJECTION_PERSPECTIVE;
}

}  // namespace

ObjectMesh buildSceneObject(const SceneSpec& scene, const Object& object) {
  try {
    return buildObjectMesh(object);
  } catch (const SceneError& error) {  // the object's JSON path and any inner file: the scene file first
    if (scene.path.empty()) throw;
    std::string why = error.what();
    const std::string inner = object.jsonPath + ".file: " + object.file + ": ";
    if (scene.modelAlone && why.rfind(inner, 0) == 0) why.erase(0, inner.size());
    throw SceneError(scene.path + ": " + why);
  }
}

namespace {

// Every object's mesh, and the scene's vertex and triangle counts, so that the flat arrays are
// allocated once at their final size: grown object by object, they were allocated about twice
// over (fresh memory the kernel zero-fills page by page) and copied at each growth
// (docs/PERFORMANCE.md, "Mesh loading"). Throws SceneError past 2^32 vertices.
std::vector<ObjectMesh> buildMeshes(const SceneSpec& scene, size_t& vertices, size_t& records) {
  std::vector<ObjectMesh> meshes;
  meshes.reserve(scene.objects.size());
  vertices = records = 0;
  for (const Object& object : scene.objects) {
    meshes.push_back(buildSceneObject(scene, object));
    const Mesh& mesh = meshes.back().mesh;
    vertices += mesh.positions.size();
    records += mesh.triangles.size() + 2 * (mesh.lines.size() + mesh.points.size());
    if (vertices > std::numeric_limits<uint32_t>::max()) {
      throw SceneError(object.jsonPath + ": the scene has more than 2^32 vertices");
    }
    if (records >= std::numeric_limits<uint32_t>::max()) {  // a key's id is 32 bits, all ones for none
      throw SceneError(object.jsonPath + ": the scene has more than 2^32 triangles and quads of points and lines");
    }
  }
  return meshes;
}

// A point's or a line's quad width in 1/256 pixel (screen_quads.h), from the object's pixels
// (checked to be at least 1/256 and at most QUAD_MAX_WIDTH where the scene was read).
uint32_t quadWidthUnits(double pixels) { return uint32_t(std::lround(pixels * 256.0)); }

// The quads of an object's lines and points (two records each, screen_quads.h), kept apart until
// every object's triangles are in: the triangle array holds triangles, then lines, then points.
struct QuadRecords {
  std::vector<glm::uvec4> lines;
  std::vector<glm::uvec4> points;
};

void appendQuads(QuadRecords& quads, const Mesh& mesh, const SceneSpec& scene, const Object& object, uint32_t base,
                 uint32_t objectIndex) {
  const uint32_t lineWidth = quadWidthUnits(object.lineWidth.value_or(scene.lineWidth));
  const uint32_t pointSize = quadWidthUnits(object.pointSize.value_or(scene.pointSize));
  for (const glm::uvec2& l : mesh.lines) {
    for (bool second : {false, true})
      quads.lines.push_back({base + l.x, base + l.y, gpu::quadCode(lineWidth, false, second), objectIndex});
  }
  for (uint32_t p : mesh.points) {
    for (bool second : {false, true})
      quads.points.push_back({base + p, base + p, gpu::quadCode(pointSize, true, second), objectIndex});
  }
}

// Texture `image`'s index in data.textures, its texels appended to the pool the first time (each
// texture once, however many meshes, objects or materials share it).
uint32_t pooledTexture(SceneData& data, const std::shared_ptr<const TextureImage>& image) {
  const auto [it, added] = data.textureIndex.emplace(image.get(), uint32_t(data.textures.size()));
  if (!added) return it->second;
  if (data.texelCount + image->texels.size() > std::numeric_limits<uint32_t>::max())
    throw SceneError("the scene's textures hold more than 2^32 texels");
  data.textures.push_back({uint32_t(data.texelCount), image->width, image->height, image->wrapU | image->wrapV << 8});
  data.textureImages.push_back(image);
  data.texelCount += image->texels.size();
  return it->second;
}

// The object's texture coordinates and textures (the scene's indices), a record per vertex.
// Throws SceneError when its material has a texture and its mesh no coordinates.
void appendTexturing(SceneData& data, const Mesh& mesh, const MaterialSpec& material, const std::string& object) {
  if (material.textureImage && mesh.uvs.empty())
    throw SceneError(object + ".material.texture: the object's mesh has no texture coordinates to sample it with");
  std::vector<uint32_t> index;
  for (const auto& texture : mesh.textures) index.push_back(pooledTexture(data, texture));
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    const uint32_t own = mesh.textureIds.empty() ? gpu::TEXTURE_NONE : mesh.textureIds[i];
    data.uvs.push_back({mesh.uvs.empty() ? glm::vec2(0.0f) : mesh.uvs[i], own == gpu::TEXTURE_NONE ? own : index[own], 0u});
  }
}

// Object `object` of `scene` for a message: "scene.json: objects[2]".
std::string sceneWhere(const SceneSpec& scene, const Object& object) {
  return (scene.path.empty() ? "" : scene.path + ": ") + object.jsonPath;
}

// Whether a scene of these meshes and materials samples a texture anywhere.
bool anyTexture(const std::vector<ObjectMesh>& meshes, const SceneSpec& scene) {
  return std::any_of(meshes.begin(), meshes.end(), [](const ObjectMesh& m) { return !m.mesh.textures.empty(); }) ||
         std::any_of(scene.objects.begin(), scene.objects.end(),
                     [&](const Object& o) { return scene.materials[size_t(o.material)].textureImage != nullptr; });
}

void appendObject(SceneData& data, const ObjectMesh& built, uint32_t objectIndex) {
  const Mesh& mesh = built.mesh;
  const uint64_t base = data.vertices.size();
  std::array<glm::dvec3, 2> box = {glm::dvec3(HUGE_VAL), glm::dvec3(-HUGE_VAL)};
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    box[0] = glm::min(box[0], glm::dvec3(mesh.positions[i]));
    box[1] = glm::max(box[1], glm::dvec3(mesh.positions[i]));
    const uint32_t color = mesh.colors.empty() ? gpu::VERTEX_WHITE : mesh.colors[i];
    data.vertices.push_back({mesh.positions[i], objectIndex, mesh.normals[i], color});
  }
  for (const glm::uvec3& t : mesh.triangles) {
    data.triangles.push_back(glm::uvec4(glm::uvec3(static_cast<uint32_t>(base)) + t, objectIndex));
  }
  data.objectOrigins.push_back(built.origin);
  data.objectBoxes.push_back(box);
  for (const MeshLight& light : built.lights) data.fileLights.push_back({objectIndex, light});
  gpu::ObjectData o{};
  o.flags = built.closed ? gpu::OBJECT_CULL_BACK : 0u;  // the material: refreshShading
  data.objects.push_back(o);
}

glm::vec3 inBasis(const View& view, const glm::dvec3& v) {
  return glm::vec3(glm::dot(view.right, v), glm::dot(view.up, v), glm::dot(view.forward, v));
}

// Whether world point p lies outside the clip volume (clip.h insidePlanes) in `view`, or within a
// margin of its planes that covers the float arithmetic of the passes' positions.
bool nearOrOutsideClipVolume(const View& view, const glm::dvec3& p) {
  const glm::dvec3 d = p - view.eye;
  const double z = glm::dot(view.forward, d);
  const double x = std::abs(view.focal.x * glm::dot(view.right, d));
  const double y = std::abs(view.focal.y * glm::dot(view.up, d));
  const double band = double(gpu::GUARD_BAND) * (view.orthographic ? 1.0 : z);
  constexpr double MARGIN = 1e-5;  // relative; float positions are good to a few 1e-7
  return !(z - view.nearPlane > MARGIN * (glm::length(d) + view.nearPlane) && band - x > MARGIN * (band + x) &&
           band - y > MARGIN * (band + y));
}

glm::dvec3 meanOrigin(const std::vector<glm::dvec3>& origins) {
  glm::dvec3 sum(0.0);
  for (const glm::dvec3& o : origins) sum += o;
  return origins.empty() ? sum : sum / double(origins.size());
}

// The triangles that cast shadows (SceneData::shadowCasters), before a share keeps its own.
void keepShadowCasters(SceneData& data, const SceneSpec& scene) {
  data.shadowed = true;
  for (size_t i = 0; i < data.quadStart; ++i) {  // points and lines cast none
    if (!scene.objects[data.triangles[i].w].castShadows) continue;
    data.shadowCasters.push_back(data.triangles[i]);
    data.shadowCasterIds.push_back(uint32_t(i));
  }
}

bool sceneLightsCastShadows(const SceneSpec& scene) {
  return std::any_of(scene.lights.begin(), scene.lights.end(), [](const LightSpec& l) { return l.shadows; });
}

// Whether the built scene traces shadow rays: a scene light casts shadows, or a light a mesh file
// placed whose object says "file_light_shadows" (known once the files are read).
bool tracesShadows(const SceneData& data, const SceneSpec& scene) {
  return sceneLightsCastShadows(scene) || std::any_of(data.fileLights.begin(), data.fileLights.end(), [&](const ObjectLight& f) {
           return scene.objects[f.object].fileLightShadows;
         });
}

// The shadow rays' tree for the objects where they now stand, unless it was built for these places.
// Each caster's vertices as the shade pass lights them: posed, in the lighting frame.
void placeShadowCasters(SceneData& data) {
  if (!data.shadowed || (data.shadows && sameLightingPlaces(data.shadowPlacement, data.objects))) return;
  std::vector<gpu::ShadowTriangle> triangles(data.shadowCasters.size());
  const auto lit = [&](uint32_t index) {
    const gpu::ObjectData& object = data.objects[data.vertices[index].object];
    return gpu::lightingPosition(gpu::posedVertex(data.vertices[index], object).position, object.lightOffset);
  };
  for (size_t i = 0; i < triangles.size(); ++i) {
    const glm::uvec4& t = data.shadowCasters[i];
    triangles[i] = {lit(t.x), data.shadowCasterIds[i], lit(t.y), t.x, lit(t.z), t.y, t.z, 0, 0, 0};
  }
  data.shadows = std::make_shared<const gpu::ShadowGeometry>(buildShadowBvh(std::move(triangles)));
  data.shadowPlacement = data.objects;
  ++data.shadowVersion;
}

// The scene's lights and those its model files place: at most MAX_LIGHTS.
void checkFileLightCount(const SceneData& data, const SceneSpec& scene) {
  if (data.fileLights.empty() || scene.lights.size() + data.fileLights.size() <= MAX_LIGHTS) return;
  const Object& first = scene.objects[data.fileLights.front().object];
  throw SceneError((scene.path.empty() ? "" : scene.path + ": ") + first.jsonPath + ".file: " + first.file + ": the scene's " +
                   std::to_string(scene.lights.size()) + " lights and the " + std::to_string(data.fileLights.size()) +
                   " its model files place are more than the " + std::to_string(MAX_LIGHTS) +
                   " a scene may have (\"file_lights\": false leaves a file's out)");
}

// A share of the scene (SceneSpec::sharePart): the triangles of the part-th of shareParts near-equal
// contiguous ranges, every vertex, object and bound of the whole scene kept (lighting and a fitted
// camera stay the whole scene's).
void keepShare(SceneData& data, const SceneSpec& scene) {
  if (scene.shareParts <= 1) return;
  const uint64_t count = data.triangles.size(), parts = uint64_t(scene.shareParts), part = uint64_t(scene.sharePart);
  if (count < parts) {
    throw SceneError((scene.path.empty() ? "" : scene.path + ": ") + "the scene's " + std::to_string(count) +
                     " triangles cannot be shared among " + std::to_string(parts) + " processes");
  }
  const uint64_t first = count * part / parts, end = count * (part + 1) / parts;
  data.triangles = std::vector<glm::uvec4>(data.triangles.begin() + first, data.triangles.begin() + end);
  data.triangleBase = uint32_t(first);
  data.quadBase = uint32_t(std::clamp<uint64_t>(data.quadStart, first, end) - first);
}

}  // namespace

SceneData buildSceneData(const SceneSpec& scene) {
  if (scene.objects.empty()) {
    throw SceneError((scene.path.empty() ? "" : scene.path + ": ") + "objects: scene has no objects");
  }
  SceneData data;
  size_t vertices, records;
  std::vector<ObjectMesh> meshes = buildMeshes(scene, vertices, records);
  reserveLarge(data.vertices, vertices);
  reserveLarge(data.triangles, records);
  const bool textured = anyTexture(meshes, scene);
  if (textured) reserveLarge(data.uvs, vertices);
  QuadRecords quads;
  for (size_t i = 0; i < meshes.size(); ++i) {
    const Object& object = scene.objects[i];
    appendQuads(quads, meshes[i].mesh, scene, object, uint32_t(data.vertices.size()), uint32_t(i));
    appendObject(data, meshes[i], static_cast<uint32_t>(i));
    if (textured) appendTexturing(data, meshes[i].mesh, scene.materials[size_t(object.material)], sceneWhere(scene, object));
    const std::string& notice = meshes[i].mesh.notice;
    if (!notice.empty() && std::find(data.notices.begin(), data.notices.end(), notice) == data.notices.end())
      data.notices.push_back(notice);
    meshes[i] = {};  // freed as soon as copied
  }
  data.quadBase = data.quadStart = uint32_t(data.triangles.size());
  data.lineCount = quads.lines.size() / 2;
  data.pointCount = quads.points.size() / 2;
  data.triangles.insert(data.triangles.end(), quads.lines.begin(), quads.lines.end());
  data.triangles.insert(data.triangles.end(), quads.points.begin(), quads.points.end());
  for (const Object& object : scene.objects) {
    if (const auto& texture = scene.materials[size_t(object.material)].textureImage) pooledTexture(data, texture);
  }
  checkFileLightCount(data, scene);
  if (tracesShadows(data, scene)) keepShadowCasters(data, scene);
  keepShare(data, scene);
  placeObjects(data, scene);
  refreshShading(data, scene);
  return data;
}

namespace {

// The rows of `m` (glm: m[column][row]) as ObjectData holds them.
void setRows(const glm::dmat3& m, glm::vec4& r0, glm::vec4& r1, glm::vec4& r2) {
  glm::vec4* rows[3] = {&r0, &r1, &r2};
  for (int r = 0; r < 3; ++r) *rows[r] = glm::vec4(float(m[0][r]), float(m[1][r]), float(m[2][r]), 0.0f);
}

// Object i's place: its origin and pose from the scene where it has one.
void placeOne(SceneData& data, const Object& object, size_t i) {
  gpu::ObjectData& o = data.objects[i];
  o.flags &= ~gpu::OBJECT_POSED;
  if (!object.poseLinear) return;
  data.objectOrigins[i] = object.translate;  // a mesh's origin (object_mesh.cpp makeShape)
  const glm::dmat3& linear = *object.poseLinear;
  if (linear == glm::dmat3(1.0)) return;
  o.flags |= gpu::OBJECT_POSED;
  setRows(linear, o.linear0, o.linear1, o.linear2);
  // The normals are made unit after this map, so it is scaled to a largest entry of 1: the turned
  // normal stays far from float overflow and underflow whatever the pose's scale.
  const glm::dmat3 normals = glm::transpose(glm::inverse(linear));
  double largest = 0;
  for (int c = 0; c < 3; ++c) largest = std::max({largest, std::abs(normals[c].x), std::abs(normals[c].y), std::abs(normals[c].z)});
  setRows(normals / largest, o.normal0, o.normal1, o.normal2);
}

// Object i's world box: its own box about its origin, where posed the box around its eight
// corners turned by the pose (a box that holds the turned vertices, a little larger than theirs).
std::array<glm::dvec3, 2> worldBox(const SceneData& data, const std::optional<glm::dmat3>& pose, size_t i) {
  const auto& [low, high] = data.objectBoxes[i];
  const glm::dvec3 origin = data.objectOrigins[i];
  if (!pose || *pose == glm::dmat3(1.0)) return {origin + low, origin + high};
  std::array<glm::dvec3, 2> box = {glm::dvec3(HUGE_VAL), glm::dvec3(-HUGE_VAL)};
  for (int corner = 0; corner < 8; ++corner) {
    const glm::dvec3 p = origin + *pose * boxCorner(low, high, corner);
    box[0] = glm::min(box[0], p);
    box[1] = glm::max(box[1], p);
  }
  return box;
}

}  // namespace

void placeObjects(SceneData& data, const SceneSpec& scene) {
  data.boundsMin = glm::dvec3(HUGE_VAL);
  data.boundsMax = glm::dvec3(-HUGE_VAL);
  for (size_t i = 0; i < data.objects.size(); ++i) {
    placeOne(data, scene.objects[i], i);
    const auto [low, high] = worldBox(data, scene.objects[i].poseLinear, i);
    if (scene.objects[i].poseLinear && !(glm::all(glm::lessThanEqual(glm::abs(low), glm::dvec3(MAX_COORDINATE))) &&
                                         glm::all(glm::lessThanEqual(glm::abs(high), glm::dvec3(MAX_COORDINATE))))) {
      throw SceneError((scene.path.empty() ? "" : scene.path + ": ") + scene.objects[i].jsonPath +
                       ".pose: places the mesh beyond the " + formatNumber(MAX_COORDINATE) + " m a scene may use");
    }
    data.boundsMin = glm::min(data.boundsMin, low);
    data.boundsMax = glm::max(data.boundsMax, high);
  }
  data.lightingOrigin = meanOrigin(data.objectOrigins);
  for (size_t i = 0; i < data.objects.size(); ++i) {
    data.objects[i].lightOffset = glm::vec3(data.objectOrigins[i] - data.lightingOrigin);
  }
  placeShadowCasters(data);
}

bool sameLightingPlaces(const std::vector<gpu::ObjectData>& a, const std::vector<gpu::ObjectData>& b) {
  if (a.size() != b.size()) return false;
  constexpr size_t FROM = offsetof(gpu::ObjectData, lightOffset);
  for (size_t i = 0; i < a.size(); ++i) {
    if (std::memcmp(reinterpret_cast<const char*>(&a[i]) + FROM, reinterpret_cast<const char*>(&b[i]) + FROM,
                    sizeof(gpu::ObjectData) - FROM) != 0)
      return false;
  }
  return true;
}

bool hasShadowedLights(const SceneSpec& scene) {
  return sceneLightsCastShadows(scene) || std::any_of(scene.objects.begin(), scene.objects.end(), [](const Object& o) {
           return o.shape == Shape::Mesh && !o.arrays && o.fileLights && o.fileLightShadows;
         });
}

uint64_t textureBytes(const SceneData& data) {
  return data.texelCount * sizeof(uint32_t) + data.uvs.size() * sizeof(gpu::VertexUv) +
         data.textures.size() * sizeof(gpu::TextureData);
}

namespace {

// A spot light's axis and cone constants (phong.h spotCone), computed in double and rounded once,
// as glTF defines them: scale = 1 / max(cos inner - cos outer, 0.001), offset = -cos outer * scale.
void setSpotCone(gpu::LightData& g, const LightSpec& l) {
  const double cosInner = std::cos(glm::radians(l.innerCone));
  const double cosOuter = std::cos(glm::radians(l.outerCone));
  const double scale = 1.0 / std::max(cosInner - cosOuter, 0.001);
  g.flags |= gpu::LIGHT_SPOT;
  g.spotAxis = glm::vec3(glm::normalize(l.direction));
  g.spotScale = float(scale);
  g.spotOffset = float(-cosOuter * scale);
}

// The light as the renderers read it. A directional light's l, the unit vector toward it,
// normalised in double: the same floats for both renderers.
gpu::LightData gpuLight(const LightSpec& l, const glm::dvec3& lightingOrigin) {
  gpu::LightData g{};
  g.position = l.directional ? glm::vec3(-glm::normalize(l.direction)) : glm::vec3(l.position - lightingOrigin);
  g.directional = l.directional ? 1.0f : 0.0f;
  if (l.spot) setSpotCone(g, l);
  g.falloff = l.inverseSquare ? 1.0f : 0.0f;
  if (l.shadows) g.flags |= gpu::LIGHT_SHADOWS;
  g.range = float(l.range);
  g.intensity = l.intensity;
  g.color = l.color;
  return g;
}

}  // namespace

void refreshShading(SceneData& data, const SceneSpec& scene) {
  data.materials.clear();
  for (const MaterialSpec& m : scene.materials) data.materials.push_back(toGpu(m, data.textureIndex));
  if (data.materials.empty()) data.materials.push_back(toGpu(MaterialSpec{}, data.textureIndex));
  data.lights.clear();
  // A model alone is lit from the camera unless its file places lights of its own.
  if (!(scene.modelAlone && !data.fileLights.empty())) {
    for (const LightSpec& l : scene.lights) data.lights.push_back(gpuLight(l, data.lightingOrigin));
  }
  for (const ObjectLight& f : data.fileLights) {
    const Object& object = scene.objects[f.object];
    const std::optional<glm::dmat3> pose = object.poseLinear;
    data.lights.push_back(
        gpuLight(fileLightSpec(f.light, data.objectOrigins[f.object], pose, object.fileLightShadows), data.lightingOrigin));
  }
  for (size_t i = 0; i < data.objects.size() && i < scene.objects.size(); ++i) {
    data.objects[i].material = static_cast<uint32_t>(scene.objects[i].material);
  }
  data.background = scene.background;
  data.ambient = scene.ambient;
  data.interpolation = scene.interpolation == Interpolation::Screen ? gpu::INTERP_SCREEN : gpu::INTERP_PERSPECTIVE;
  data.shading = scene.shading == Shading::Flat ? gpu::SHADING_FLAT
                 : scene.shading == Shading::Phong ? gpu::SHADING_PHONG
                                                  : gpu::SHADING_GOURAUD;
  data.specular = scene.specular == Specular::Blinn ? gpu::SPECULAR_BLINN : gpu::SPECULAR_PHONG;
  data.projection = projectionOf(scene.camera.orthographic);
  data.samples = scene.samples;
  data.textureFilter = scene.textureFilter == TextureFilter::Nearest ? gpu::TEXTURE_FILTER_NEAREST : gpu::TEXTURE_FILTER_BILINEAR;
}

namespace {

bool sameObjectGeometry(const Object& a, const Object& b) {
  return a.shape == b.shape && a.fileLights == b.fileLights && a.fileLightShadows == b.fileLightShadows && a.castShadows == b.castShadows && a.pointSize == b.pointSize && a.lineWidth == b.lineWidth && a.center == b.center && a.radius == b.radius && a.size == b.size &&
         a.height == b.height && a.segments == b.segments && a.rings == b.rings && a.subdivide == b.subdivide &&
         a.points == b.points && a.file == b.file && a.fileVersion == b.fileVersion && a.arrays == b.arrays &&
         a.scale == b.scale && a.rotation == b.rotation && a.up == b.up && a.baseColors == b.baseColors &&
         a.closed == b.closed && a.poseLinear.has_value() == b.poseLinear.has_value() &&
         (a.poseLinear.has_value() || a.translate == b.translate);  // a posed object's place is not its geometry
}

// Whether the materials of a and b sample the same textures (the texel pool is built with the meshes).
bool sameTextures(const SceneSpec& a, const SceneSpec& b) {
  return std::equal(a.materials.begin(), a.materials.end(), b.materials.begin(), b.materials.end(),
                    [](const MaterialSpec& x, const MaterialSpec& y) { return x.textureImage == y.textureImage; });
}

}  // namespace

bool sameGeometry(const SceneSpec& a, const SceneSpec& b) {
  return sameTextures(a, b) && hasShadowedLights(a) == hasShadowedLights(b) && a.pointSize == b.pointSize &&
         a.lineWidth == b.lineWidth && a.sharePart == b.sharePart && a.shareParts == b.shareParts && std::equal(a.objects.begin(), a.objects.end(), b.objects.begin(), b.objects.end(), sameObjectGeometry);
}

bool lightingIsViewIndependent(const FrameInputs& in) {
  if (in.lights.empty()) return true;
  for (const gpu::MaterialData& m : in.materials) {
    if (m.ks != 0.0f) return false;
  }
  return true;
}

bool everyVertexUnlit(const SceneData& data) {
  for (const gpu::VertexIn& v : data.vertices) {
    if (!gpu::isUnlit(v.normal)) return false;
  }
  return true;
}

uint32_t boxClip(const SceneData& data, const View& view) {
  for (int corner = 0; corner < 8; ++corner) {
    if (nearOrOutsideClipVolume(view, boxCorner(data.boundsMin, data.boundsMax, corner))) return gpu::CLIP_ALL;
  }
  return gpu::CLIP_NONE;
}

FrameInputs makeFrame(const SceneData& data, const View& view) {
  FrameInputs in;
  gpu::FrameData& f = in.frame;
  f.right = glm::vec4(glm::vec3(view.right), 0.0f);
  f.up = glm::vec4(glm::vec3(view.up), 0.0f);
  f.forward = glm::vec4(glm::vec3(view.forward), 0.0f);
  f.ambient = data.ambient;
  f.focalX = static_cast<float>(view.focal.x);
  f.focalY = static_cast<float>(view.focal.y);
  f.background = data.background;
  f.nearPlane = static_cast<float>(view.nearPlane);
  f.principal = glm::vec2(view.principal);
  f.farPlane = static_cast<float>(view.farPlane);
  f.width = static_cast<uint32_t>(view.width);
  f.height = static_cast<uint32_t>(view.height);
  f.interpolation = data.interpolation;
  f.shading = data.shading;
  f.specular = data.specular;
  f.eye = glm::vec3(view.eye - data.lightingOrigin);
  f.projection = projectionOf(view.orthographic);
  f.textureFilter = data.textureFilter;
  f.quadBase = data.quadBase;
  f.pixelScale = float(view.pixelScale);

  in.objects = data.objects;
  for (size_t i = 0; i < in.objects.size(); ++i) {
    in.objects[i].viewOffset = inBasis(view, data.objectOrigins[i] - view.eye);
  }
  in.lights = data.lights;
  in.materials = data.materials;
  in.clip = boxClip(data, view);
  in.shadows = data.shadows;
  in.shadowVersion = data.shadowVersion;
  return in;
}

}  // namespace phongvk
