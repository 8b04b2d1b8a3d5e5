// scene_data.h — the scene flattened into the arrays both renderers consume (shaders/shared.h
// layouts), and the per-frame data derived from a camera view.
#pragma once

#include "prepare/file_lights.h"
#include "scene/camera.h"
#include "scene/object_mesh.h"
#include "scene/scene.h"
#include "shaders/gpu_layout.h"
#include "shaders/shadow_rays.h"
#include "shaders/shared.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <map>
#include <memory>
#include <vector>

namespace phongvk {

// Built once per scene: meshes with normals, materials, lights. Geometry is uploaded once by the
// GPU path; materials and lights may be refreshed per frame (refreshShading).
struct SceneData {
  std::vector<gpu::VertexIn> vertices;      // local to their object's origin
  // xyz: vertex indices; w: object index. Every object's triangles, then every object's lines,
  // then its points, each of those two records: its quad's halves (shaders/screen_quads.h).
  std::vector<glm::uvec4> triangles;
  // The first quad half: in `triangles` (a share's own), and in the whole scene's records (none in
  // arrays made by hand, as tests make them).
  uint32_t quadBase = UINT32_MAX;
  uint32_t quadStart = UINT32_MAX;
  size_t lineCount = 0, pointCount = 0;  // the whole scene's
  std::vector<glm::dvec3> objectOrigins;    // world, double: offsets are taken in double
  // Each object's box about its origin, in its own axes (a posed object's before its pose).
  std::vector<std::array<glm::dvec3, 2>> objectBoxes;
  // Lighting is evaluated relative to this point (the mean object origin): fixed while no posed
  // object moves, so a moving camera leaves view-independent lighting bitwise unchanged.
  glm::dvec3 lightingOrigin{0.0};
  std::vector<gpu::ObjectData> objects;     // material, flags, lightOffset; viewOffset per frame
  std::vector<gpu::MaterialData> materials;
  std::vector<gpu::LightData> lights;       // positions relative to lightingOrigin
  // The lights the objects' model files place (after the scene's own in `lights`): in their
  // object's frame, placed where it stands by refreshShading.
  std::vector<ObjectLight> fileLights;
  // With a light that casts shadows (docs/DESIGN.md "Shadows"): the triangles of the objects that
  // cast them (w: the object, as in `triangles`; all of the scene's, with a share of it), and the
  // tree the shadow rays walk, built for the objects' places as they were (shadowPlacement) and
  // built again when they move (placeObjects), each build a new shadowVersion.
  bool shadowed = false;  // some light casts shadows: the tree is built
  std::vector<glm::uvec4> shadowCasters;
  std::vector<uint32_t> shadowCasterIds;  // each caster's index in the whole scene's triangles
  std::shared_ptr<const gpu::ShadowGeometry> shadows;
  std::vector<gpu::ObjectData> shadowPlacement;
  uint64_t shadowVersion = 0;
  // Textures (docs/DESIGN.md "Textures"): for a scene with any, each vertex's texture coordinate and
  // texture, and every texture once: its texels (RGBA8) held where they were decoded, not copied,
  // TextureData::offset counting the texels of the textures before it; empty otherwise.
  std::vector<gpu::VertexUv> uvs;
  std::vector<gpu::TextureData> textures;
  std::vector<std::shared_ptr<const TextureImage>> textureImages;  // one per entry of `textures`
  uint64_t texelCount = 0;  // of every texture
  uint32_t textureFilter = gpu::TEXTURE_FILTER_BILINEAR;
  std::map<const TextureImage*, uint32_t> textureIndex;  // each texture's index in `textures`
  std::vector<std::string> notices;  // the meshes' (Mesh::notice), each once
  glm::dvec3 boundsMin{0.0}, boundsMax{0.0};  // world box around every vertex (camera_fit.h)
  glm::vec3 background{0.0f};
  glm::vec3 ambient{1.0f};
  uint32_t interpolation = gpu::INTERP_PERSPECTIVE;
  uint32_t shading = gpu::SHADING_GOURAUD;
  uint32_t specular = gpu::SPECULAR_PHONG;
  // The scene camera's projection (gpu::PROJECTION_*): frames take their camera's, this only says
  // which pipelines the GPU renderer compiles when the scene is uploaded.
  uint32_t projection = gpu::PROJECTION_PERSPECTIVE;
  int samples = 1;  // per pixel, on a regular grid (1, 4, 9 or 16): the frame is rendered this many times larger
  // With a share of the scene (SceneSpec::sharePart): the whole scene's index of triangles[0]. The
  // renderers' keys name triangles by their index here; add this to name them in the whole scene.
  uint32_t triangleBase = 0;
};

// One frame's inputs to either renderer: the frame constants, the per-object offsets from the eye,
// and the shading data (materials, lights) in force for this frame.
struct FrameInputs {
  gpu::FrameData frame{};
  std::vector<gpu::ObjectData> objects;
  std::vector<gpu::LightData> lights;
  std::vector<gpu::MaterialData> materials;
  // Whether the compute port's clip pass needs the clipper (gpu_layout.h CLIP_*, boxClip): not when
  // no triangle can cross the near plane or the guard band (the box holds every vertex, the clip
  // volume is convex).
  uint32_t clip = gpu::CLIP_ALL;
  // The shadow rays' tree (SceneData::shadows) and its build; none without shadowed lights.
  std::shared_ptr<const gpu::ShadowGeometry> shadows;
  uint64_t shadowVersion = 0;
};

// One object's mesh (object_mesh.h buildObjectMesh), its SceneError led by the scene's file; a
// model file alone's names that file and its line only ("m.ply: line 7: ...").
ObjectMesh buildSceneObject(const SceneSpec& scene, const Object& object);

// Texel `index` of the textures' pool (TextureData::offset + the texel's index in texture `texture`).
inline uint32_t pooledTexel(const SceneData& data, uint32_t texture, uint32_t index) {
  return data.textureImages[texture]->texels[index - data.textures[texture].offset];
}

// The bytes a built scene's textures take: texels, texture coordinates and the texture table.
uint64_t textureBytes(const SceneData& data);

// Builds every object's mesh and flattens the scene. Throws SceneError, also for a scene without
// objects.
SceneData buildSceneData(const SceneSpec& scene);

// Whether record `id` of data.triangles is a point's or a line's quad half.
inline bool isQuadRecord(const SceneData& data, uint32_t id) { return id >= data.quadBase; }

// Whether the scene (a share: its part) draws points or lines.
inline bool hasQuads(const SceneData& data) { return data.quadBase < data.triangles.size(); }

// The records of data.triangles (a share's own) that hold whole point quads, both halves of each, as
// [x, y): the GPU's point pass draws them (shaders/raster_triangles.comp). A share may begin on a
// quad's second half or end on a first half: those halves stay the triangle pass's. x = y: none.
inline glm::uvec2 pointQuadRange(const SceneData& data) {
  const uint64_t count = data.triangles.size();
  if (data.pointCount == 0) return glm::uvec2(uint32_t(count));
  const uint64_t start = uint64_t(data.quadStart) + 2 * data.lineCount, first = data.triangleBase;  // the whole scene's
  const uint64_t base = std::min(start >= first ? start - first : (first - start) % 2, count);
  return glm::uvec2(uint32_t(base), uint32_t(base + (count - base) / 2 * 2));
}

// A record of the whole scene (a key's id) as the primitive it draws: a triangle keeps its index, a
// line or a point, whose quad is two records, is numbered after the triangles (lines first, then
// points, objects in order): the ids the outputs show (docs/DESIGN.md "Points and lines").
inline uint32_t primitiveOf(const SceneData& data, uint32_t record) {
  return record < data.quadStart ? record : data.quadStart + (record - data.quadStart) / 2;
}

// True when a and b make the same meshes: the same objects, in order, with the same shapes,
// geometry values, mesh files (unchanged on disk) or mesh arrays (the same added mesh), and culling. Materials, lights, the camera and
// the render options may differ: refreshShading and makeFrame take those from b. Objects placed
// by a pose (Object::poseLinear) may stand elsewhere: placeObjects takes their places from b.
bool sameGeometry(const SceneSpec& a, const SceneSpec& b);

// Places every object of `data` as `scene` says: the posed objects' origins and linear parts
// (ObjectData rows and OBJECT_POSED, set only for a linear part other than the identity, so an
// object posed by a translation alone renders as one without a pose), the scene's box, and the
// lighting origin with each object's offset from it. buildSceneData calls it, and a renderer again
// for a frame of the same geometry (sameGeometry), so a moved object renders the bytes of one
// built where it now stands. Call refreshShading after it (the lights follow the lighting origin).
// With shadowed lights it builds the shadow rays' tree again where an object's place for lighting
// changed (SceneData::shadows).
void placeObjects(SceneData& data, const SceneSpec& scene);

// Whether some light of the scene casts shadows (LightSpec::shadows), or may: a mesh file's lights
// with the object's "file_light_shadows", before the file is read (the memory estimate counts the
// tree for it; the build makes one only where the file places lights).
bool hasShadowedLights(const SceneSpec& scene);

// Replaces what a frame of a sequence may change without touching geometry: materials, lights,
// ambient, background and the render options. The scene must have the same objects as `data`'s.
void refreshShading(SceneData& data, const SceneSpec& scene);

// True when the vertex colours do not depend on where the eye is: no light, or no material with
// a specular term.
bool lightingIsViewIndependent(const FrameInputs& in);

// Whether every vertex is drawn unlit: points and lines given no normal (docs/DESIGN.md "Points and
// lines"), and no triangle, whose vertices always have one. Such a scene's vertex colours are its
// materials' and vertices' colours whatever the lights, the ambient and the eye.
bool everyVertexUnlit(const SceneData& data);

// Whether every object of `a` has the place for lighting it has in `b`: what ObjectData holds from
// lightOffset on (offset, flags, pose). Its viewOffset follows the camera, and the positions alone.
bool sameLightingPlaces(const std::vector<gpu::ObjectData>& a, const std::vector<gpu::ObjectData>& b);

// The frame for `view`: camera basis, image size, and offsets from the eye computed in double.
FrameInputs makeFrame(const SceneData& data, const View& view);

// Corner `corner` (0..7: bit 0 picks x, bit 1 y, bit 2 z from `high` over `low`) of a box.
inline glm::dvec3 boxCorner(const glm::dvec3& low, const glm::dvec3& high, int corner) {
  return {corner & 1 ? high.x : low.x, corner & 2 ? high.y : low.y, corner & 4 ? high.z : low.z};
}

// FrameInputs::clip of a frame of `data` seen in `view`: CLIP_NONE when no corner of the scene's
// box is behind the near plane or past the guard band, or within a margin of them; else CLIP_ALL.
uint32_t boxClip(const SceneData& data, const View& view);

}  // namespace phongvk
