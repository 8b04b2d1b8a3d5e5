// scene_fuzzer.cpp — libFuzzer target for the scene loader (scripts/fuzz.sh runs it).
//
// Any bytes must either load or throw SceneError: no crash, no sanitizer report, no hang, no other
// exception. What loads must keep the loader's promises: the camera makes a view, and the meshes
// of a scene small enough to build quickly have finite positions, unit normals and indices in range.
// Mesh files resolve against scenes/, so the seed scenes' meshes/*.obj are found.
#include "prepare/scene_data.h"
#include "shaders/screen_quads.h"
#include "scene/camera.h"
#include "scene/scene.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

using namespace phongvk;

// Objects whose meshes build in well under a millisecond: a fuzzer spending seconds subdividing
// finds nothing else.
bool cheapToBuild(const SceneSpec& scene) {
  for (const Object& o : scene.objects) {
    if (o.segments > 64 || o.rings > 16 || o.subdivide > 2 || o.points.size() > 64) return false;
  }
  return scene.objects.size() <= 16;
}

[[noreturn]] void broken(const std::string& what) {
  std::fprintf(stderr, "scene_fuzzer: %s\n", what.c_str());
  std::abort();
}

// Finite vertices with unit normals (zero for a point's or a line's vertex given none), triangles'
// indices in range, and the quads of points and lines (shaders/screen_quads.h) on vertices in range
// with a width in (0, QUAD_MAX_WIDTH] pixels.
void checkMeshes(const SceneData& data) {
  for (const gpu::VertexIn& v : data.vertices) {
    for (int i = 0; i < 3; ++i) {
      if (!std::isfinite(v.position[i]) || !std::isfinite(v.normal[i])) broken("a vertex is not finite");
    }
    const float length = std::sqrt(v.normal.x * v.normal.x + v.normal.y * v.normal.y + v.normal.z * v.normal.z);
    if (std::abs(length - 1.0f) > 1e-3f && length != 0.0f) broken("a normal is neither unit nor zero: " + std::to_string(length));
  }
  const size_t vertices = data.vertices.size();
  for (uint32_t id = 0; id < data.triangles.size(); ++id) {
    const glm::uvec4& t = data.triangles[id];
    const bool quad = isQuadRecord(data, id);
    if (t.x >= vertices || t.y >= vertices || (!quad && t.z >= vertices)) broken("a triangle index is out of range");
    const uint32_t width = gpu::quadWidth256(t.z);
    if (quad && (width == 0 || width > uint32_t(gpu::QUAD_MAX_WIDTH * 256))) broken("a quad's width is out of range");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* bytes, size_t size) {
  const std::string text(reinterpret_cast<const char*>(bytes), size);
  SceneSpec scene;
  try {
    scene = parseSceneSpec(text, "fuzz.json", PHONGVK_SCENES_DIR);
  } catch (const SceneError&) {
    return 0;  // rejected with a message: the expected outcome for most inputs
  }
  makeView(scene.camera);  // a scene that loads makes a view: a SceneError here is a loader bug
  if (!cheapToBuild(scene)) return 0;
  try {
    checkMeshes(buildSceneData(scene));
  } catch (const SceneError&) {
    // Some inputs only fail while building (a flat hull, a broken OBJ file): still a clear error.
  }
  return 0;
}
