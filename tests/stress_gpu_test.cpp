// stress_gpu_test.cpp — scenes nobody planned for (scenes/stress/README.md says what each one
// provokes). Every case is rendered by the reference and by the Vulkan port, and must give:
//   - finite vertex data (positions and unclamped colours from the shading pass),
//   - the same winning triangle at every pixel (coverage and visibility equal to the reference),
//   - the same keys and the same image bytes,
//   - not one validation-layer message.
// Each case prints one "stress:" line with its measured diff, for the record.
#include "phongvk/compare.h"
#include "prepare/scene_data.h"
#include "reference/render_reference.h"
#include "scene/camera.h"
#include "scene/scene.h"
#include "shaders/depth.h"
#include "shaders/phong.h"

#include "stress_geometry.h"
#include "test_util.h"
#include "tests/stress_fixture.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace phongvk {
namespace {

using namespace test;

// True when the triangle that won `key` faces the eye (depth.h: dot(h0, n) < 0).
bool winnerFacesEye(const StressResult& r, const std::vector<gpu::ShadedVertex>& shaded, uint64_t key) {
  const glm::uvec4 t = r.data.triangles[uint32_t(key)];
  const gpu::TrianglePlane plane =
      gpu::trianglePlane(glm::vec3(shaded[t.x].hpos), glm::vec3(shaded[t.y].hpos), glm::vec3(shaded[t.z].hpos));
  return plane.h0n < 0.0f;
}

// Pixels of `object` won by a triangle facing away from the eye: on an open but convex object
// seen from outside, each is a back face that beat the front face in depth (speckle).
size_t backFacesWon(const StressResult& r, uint32_t object) {
  const std::vector<gpu::ShadedVertex> shaded = shadeVertices(r.data, r.in);
  size_t count = 0;
  for (uint64_t key : r.reference.keys) {
    if (key != gpu::KEY_CLEAR && objectOf(r.data, key) == object && !winnerFacesEye(r, shaded, key)) ++count;
  }
  return count;
}

// ---- geometry around the eye ----

TEST_F(StressTest, TrianglesCrossingTheNearPlaneAndBehindTheCamera) {
  const StressResult r = renderScene("near_plane.json");
  const std::vector<size_t> pixels = pixelsPerObject(r.data, r.reference.keys);
  EXPECT_GT(pixels[0], 5000u) << "the floor runs behind the camera and must still fill the lower image";
  EXPECT_GT(pixels[1], 1000u) << "the cube straddling the near plane is drawn, cut open";
  EXPECT_GT(pixels[3], 1000u) << "the triangles with vertices behind the eye are drawn (clipped)";
  // behind_camera.obj's third triangle lies wholly behind the eye: it must never win a pixel.
  const uint32_t wholeBehind = uint32_t(r.data.triangles.size()) - 2;
  for (uint64_t key : r.reference.keys) ASSERT_NE(uint32_t(key), wholeBehind) << "a triangle behind the eye was drawn";
}

TEST_F(StressTest, CameraInsideObjects) {
  const StressResult r = renderScene("inside_object.json");
  const std::vector<size_t> pixels = pixelsPerObject(r.data, r.reference.keys);
  EXPECT_EQ(pixels[0], 0u) << "seen from inside, a closed sphere shows only back faces: all culled";
  EXPECT_EQ(coveredPixels(r.reference.keys), r.reference.keys.size()) << "the open cube around the eye fills the view";
  EXPECT_GT(pixels[2], 100u);
}

// ---- scale ----

TEST_F(StressTest, HugeCoordinates) {
  const StressResult r = renderScene("huge_coordinates.json");
  const std::vector<size_t> pixels = pixelsPerObject(r.data, r.reference.keys);
  EXPECT_GT(pixels[0], 500u);
  EXPECT_GT(pixels[1], 100u);
}

// Objects 1e4, 1e5 and 1e6 m away through a 0.02 degree lens. The sphere at 1e5 m is open, so its
// back faces are not culled: with a depth that keeps its precision there, none wins a pixel.
TEST_F(StressTest, FarAwayObjectsThroughANarrowLens) {
  const StressResult r = renderScene("far_away.json");
  const std::vector<size_t> pixels = pixelsPerObject(r.data, r.reference.keys);
  for (size_t object = 0; object < 3; ++object) EXPECT_GT(pixels[object], 50u) << "object " << object;
  EXPECT_EQ(backFacesWon(r, 1), 0u) << "back faces of the open sphere 1e5 m away speckle through";
}

TEST_F(StressTest, TinyObjects) {
  const StressResult r = renderScene("tiny.json");
  const std::vector<size_t> pixels = pixelsPerObject(r.data, r.reference.keys);
  for (size_t object = 0; object < 3; ++object) EXPECT_GT(pixels[object], 50u) << "object " << object;
  EXPECT_EQ(backFacesWon(r, 2), 0u) << "back faces of the open 2e-5 m icosphere speckle through";
}

// ---- triangle shapes ----

TEST_F(StressTest, SliversAndZeroAreaTriangles) {
  const StressResult r = renderScene("slivers.json");
  size_t fan = 0, degenerate = 0;
  for (const glm::uvec4& t : r.data.triangles) (t.w == 0 ? fan : degenerate) += 1;
  EXPECT_EQ(fan, 4000u) << "slivers.obj: the importer keeps all 4000 slivers and drops the 3 zero-area triangles";
  EXPECT_EQ(degenerate, 3u) << "degenerate.obj: 2 real triangles and the nearly collinear one survive import";
  const std::vector<size_t> pixels = pixelsPerObject(r.data, r.reference.keys);
  EXPECT_GT(pixels[0], 500u) << "the fan of slivers covers its wedge";
}

// Triangles the importer would drop, handed to the renderers directly: repeated indices, a
// repeated position, collinear points. The raster's own zero-area test must skip them.
TEST_F(StressTest, ZeroAreaTrianglesGivenDirectlySkippedByTheRaster) {
  const SceneSpec scene = loadSceneSpec(test::sourcePath("scenes/stress/one_pixel.json"));
  SceneData data = buildSceneData(scene);
  const uint32_t base = uint32_t(data.vertices.size());
  const glm::vec3 n(-1, 0, 0);
  for (glm::vec3 p : {glm::vec3(-1, -0.3f, -0.3f), glm::vec3(-1, 0.3f, -0.3f), glm::vec3(-1, 0.3f, -0.3f),
                      glm::vec3(-1, -0.3f, 0.3f), glm::vec3(-1, 0, 0), glm::vec3(-1, 0.3f, 0.3f)}) {
    data.vertices.push_back({p, 0, n, 0});
  }
  data.triangles.clear();  // only the degenerate ones: whatever is covered is a bug
  for (glm::uvec3 t : {glm::uvec3(0, 0, 1), glm::uvec3(0, 1, 2), glm::uvec3(0, 4, 5), glm::uvec3(3, 3, 3)}) {
    data.triangles.push_back(glm::uvec4(t + base, 0));
  }
  const FrameInputs in = makeFrame(data, makeView(withImageSize(scene.camera, 64, 48)));
  const StressResult r = renderBoth(std::move(data), in, "zero-area (direct)");
  EXPECT_EQ(coveredPixels(r.reference.keys), 0u);
}

TEST_F(StressTest, MillionSubpixelTriangles) {
  const StressResult r = renderScene("million_triangles.json");
  EXPECT_GT(r.data.triangles.size(), 1000000u);
  std::set<uint32_t> winners;
  for (uint64_t key : r.reference.keys) {
    if (key != gpu::KEY_CLEAR) winners.insert(uint32_t(key));
  }
  EXPECT_GT(winners.size(), coveredPixels(r.reference.keys) * 9 / 10) << "triangles are sub-pixel: most pixels have their own";
}

TEST_F(StressTest, HugeTriangles) {
  const StressResult r = renderScene("huge_triangles.json");
  // huge_triangle.obj's side vertices project past the guard band, so clipping must cut it.
  const std::vector<gpu::ShadedVertex> shaded = shadeVertices(r.data, r.in);
  const glm::uvec4 huge = r.data.triangles[0];
  const glm::vec4 side = shaded[huge.x].hpos;
  EXPECT_GT(std::abs(side.x / side.z), gpu::GUARD_BAND) << "the triangle is not large enough to test the guard band";
  const std::vector<size_t> pixels = pixelsPerObject(r.data, r.reference.keys);
  EXPECT_GT(pixels[0], r.reference.keys.size() / 2) << "the 2e6-pixel triangle fills the view below the horizon";
  EXPECT_GT(pixels[1], 1000u);
}

// ---- shared edges and coincident surfaces ----

TEST_F(StressTest, SharedEdgesOfAJitteredGrid) { renderScene("shared_edges.json"); }

// `grid` as the only object of `base`: 1.4x the view wide, 3 m in front of the eye, tilted in
// depth (0.5 x + 0.3 y) so edges are shared in perspective, moved by `shift` pixels.
SceneData gridSceneData(SceneData base, const View& view, const test::TiledSquare& grid, glm::dvec2 shift) {
  const double pixel = 3.0 / view.focal.x;  // metres per pixel at the grid's centre
  base.vertices.clear();
  base.triangles.clear();
  base.quadBase = base.quadStart = UINT32_MAX;  // triangles only
  for (glm::vec2 p : grid.positions) {
    const glm::dvec3 local = view.right * (1.4 * 32 * pixel * p.x) + view.up * (1.4 * 24 * pixel * p.y) +
                             view.forward * (0.5 * p.x + 0.3 * p.y);
    base.vertices.push_back({glm::vec3(local), 0, glm::vec3(-view.forward), 0});
  }
  for (glm::uvec3 t : grid.triangles) base.triangles.push_back(glm::uvec4(t, 0));
  base.objects.resize(1);
  base.objects[0].flags = 0;  // both orientations drawn
  base.objectOrigins = {view.eye + view.forward * 3.0 + (view.right * shift.x + view.up * shift.y) * pixel};
  return base;
}

// The jittered grid of stress_geometry.h filling the whole 64x48 view, moved by many subpixel
// amounts: both backends must cover every pixel and pick the same triangle everywhere. (That each
// pixel is covered exactly once is counted in coverage_test.cpp, with the same edges.h code.)
TEST_F(StressTest, SharedEdgesAtManySubpixelOffsets) {
  const SceneSpec scene = loadSceneSpec(test::sourcePath("scenes/stress/one_pixel.json"));
  const View view = makeView(withImageSize(scene.camera, 64, 48));
  const SceneData base = buildSceneData(scene);
  const test::TiledSquare grid = test::jitteredGrid(24, 0.15f, 7);
  for (int k = 0; k < 8; ++k) {
    SceneData data = gridSceneData(base, view, grid, glm::dvec2(k / 8.0, (k * 5 % 8) / 8.0));
    const FrameInputs in = makeFrame(data, view);
    const StressResult r = renderBoth(std::move(data), in, "grid offset " + std::to_string(k) + "/8 px");
    EXPECT_EQ(coveredPixels(r.gpu.keys), r.gpu.keys.size()) << "a crack between shared edges on the GPU";
    EXPECT_EQ(coveredPixels(r.reference.keys), r.reference.keys.size()) << "a crack between shared edges";
  }
}

// Coincident and near-coincident surfaces z-fight on purpose (scenes/stress/README.md). The
// fight's outcome is the key order: deterministic, the same on both backends and run to run.
TEST_F(StressTest, CoincidentSurfacesFightDeterministically) {
  const StressResult r = renderScene("z_fighting.json");
  const std::vector<size_t> pixels = pixelsPerObject(r.data, r.reference.keys);
  EXPECT_GT(pixels[0] * pixels[1] * pixels[2], 0u) << "all three coincident cubes win some pixels: they do fight";
  GpuRenderer renderer(context_, r.data);
  for (int run = 0; run < 3; ++run) {
    EXPECT_EQ(renderer.render(r.in, true).keys, r.gpu.keys) << "the GPU's winners changed from run to run";
  }
}

// ---- lighting corner cases ----

// A light exactly at a cube's corner (d = 0), one inside the sphere, one at the sphere's pole;
// n = 0, n = 1000, ks = 0, kd = 0 and attenuation only on c.
TEST_F(StressTest, DegenerateLights) {
  const StressResult r = renderScene("lights_degenerate.json");
  bool lightAtVertex = false;
  for (const gpu::VertexIn& v : r.data.vertices) {
    const glm::vec3 p = gpu::lightingPosition(v.position, r.data.objects[v.object].lightOffset);
    for (const gpu::LightData& light : r.data.lights) lightAtVertex = lightAtVertex || p == light.position;
  }
  EXPECT_TRUE(lightAtVertex) << "the scene must put a light exactly on a vertex (d = 0)";
  const std::vector<size_t> pixels = pixelsPerObject(r.data, r.reference.keys);
  for (size_t object = 0; object < 4; ++object) EXPECT_GT(pixels[object], 100u) << "object " << object;
}

TEST_F(StressTest, SixtyFourLights) {
  const StressResult r = renderScene("lights_64.json");
  EXPECT_EQ(r.data.lights.size(), 64u);
}

// Colours that overflow float must still give the saturated picture, not NaN. Both gave black
// NaN pixels until phong.h held every lighting factor below COLOR_MAX.
void expectPixel(const StressResult& r, int x, int y, glm::u8vec3 want) {
  for (const Image* image : {&r.reference.image, &r.gpu.image}) {
    const uint8_t* p = image->pixel(x, y);
    EXPECT_EQ(glm::u8vec3(p[0], p[1], p[2]), want)
        << (image == &r.reference.image ? "reference" : "gpu") << " pixel (" << x << ", " << y << ")";
  }
}

// A light 1e-20 m from a vertex, attenuation [0, 0, 1]: d^2 underflows, S = 1/0 = inf, and
// inf * (C o L) with C = [1, 0, 0] was NaN in green and blue, and the NaN vertex colour turned the
// whole triangle black. It is saturated red: vertex 0 is (nearly) infinitely bright.
TEST_F(StressTest, LightNearlyAtAVertexGivesAFinitePicture) {
  const StressResult r = renderScene("light_near_vertex.json");
  expectPixel(r, 32, 24, {255, 0, 0});
}

// ka * C * A = 1e30 * 1 * 1e30 overflows to inf in red and blue (each factor is a valid float).
// Infinite vertex colours made inf - inf = NaN in the Gouraud interpolation: the sphere came out
// black. It is saturated magenta.
TEST_F(StressTest, OverflowingLightingGivesAFinitePicture) {
  const StressResult r = renderScene("lighting_overflow.json");
  expectPixel(r, 32, 24, {255, 0, 255});
}

// ---- image sizes ----

TEST_F(StressTest, OnePixelImage) {
  const StressResult r = renderScene("one_pixel.json");
  EXPECT_EQ(coveredPixels(r.reference.keys), 1u);
}

}  // namespace
}  // namespace phongvk
