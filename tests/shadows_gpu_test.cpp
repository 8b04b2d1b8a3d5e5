// shadows_gpu_test.cpp — shadow rays (docs/DESIGN.md "Shadows"): the tree the host builds, the
// watertight test on the edges it exists for, a sphere's shadow on a plane against its closed form
// to the pixel, hostile lights and triangles, moving objects, and both renderers giving the same
// bytes and keys in every case.
#include "prepare/scene_data.h"
#include "prepare/shadow_bvh.h"
#include "scene/scene.h"
#include "test_util.h"

#include <phongvk/phongvk.h>

#include <gtest/gtest.h>

#include <chrono>
#include <cstring>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace phongvk {
namespace {

using gpu::BvhNode;
using gpu::ShadowGeometry;
using gpu::ShadowTriangle;

// Both renderers' image of `scene`, which must be the same bytes and keys; the image.
Image both(const Scene& scene) {
  Renderer cpu(Backend::Cpu), gpu(RendererOptions{Backend::Gpu, -1, true});
  const RenderOutput a = cpu.renderWithKeys(scene), b = gpu.renderWithKeys(scene);
  EXPECT_TRUE(a.image.rgb == b.image.rgb) << "the renderers' images differ";
  EXPECT_TRUE(a.keys == b.keys) << "the renderers' keys differ";
  EXPECT_EQ(gpu.stats().validationMessages, 0u);
  return a.image;
}

ShadowTriangle triangle(glm::vec3 a, glm::vec3 b, glm::vec3 c, uint32_t id) {
  ShadowTriangle t{};
  t.a = a;
  t.b = b;
  t.c = c;
  t.id = id;
  t.v0 = 3 * id;
  t.v1 = 3 * id + 1;
  t.v2 = 3 * id + 2;
  return t;
}

const glm::uvec3 NO_OWNER(gpu::SHADOW_NO_OWNER);

bool blocked(const ShadowGeometry& g, glm::vec3 from, glm::vec3 to, glm::uvec3 owners = NO_OWNER) {
  return gpu::shadowRayBlocked(g, gpu::shadowRay(from, to - from, true, owners));
}

// Depth of the subtree at `node`, checking that each box holds its triangles and children.
int checkedDepth(const ShadowGeometry& g, uint32_t node, std::vector<int>& seen) {
  const BvhNode& n = g.nodes[node];
  const auto inside = [&](glm::vec3 p) { return glm::all(glm::lessThanEqual(n.low, p)) && glm::all(glm::lessThanEqual(p, n.high)); };
  if (n.count != 0) {
    for (uint32_t k = 0; k < n.count; ++k) {
      const ShadowTriangle& t = g.triangles[n.index + k];
      EXPECT_TRUE(inside(t.a) && inside(t.b) && inside(t.c));
      ++seen[n.index + k];
    }
    return 1;
  }
  for (uint32_t child : {node + 1, n.index}) {
    EXPECT_TRUE(inside(g.nodes[child].low) && inside(g.nodes[child].high));
  }
  return 1 + std::max(checkedDepth(g, node + 1, seen), checkedDepth(g, n.index, seen));
}

TEST(ShadowBvh, HoldsEveryTriangleOnceWithinItsBoundsAndTheSameTreeEveryTime) {
  std::vector<ShadowTriangle> triangles;
  uint32_t seed = 12345;
  const auto next = [&] {
    seed = seed * 1664525u + 1013904223u;
    return float(seed >> 8) / float(1 << 24) * 10.0f - 5.0f;
  };
  for (uint32_t i = 0; i < 10000; ++i) {
    const glm::vec3 p(next(), next(), next());
    triangles.push_back(triangle(p, p + glm::vec3(0.1f, 0, 0), p + glm::vec3(0, 0.1f, 0), i));
  }
  for (uint32_t i = 10000; i < 10100; ++i) triangles.push_back(triangle({1, 1, 1}, {1, 1, 1}, {1, 1, 1}, i));  // one point
  const ShadowGeometry g = buildShadowBvh(triangles);
  std::vector<int> seen(g.triangles.size(), 0);
  const int depth = checkedDepth(g, 0, seen);
  EXPECT_LE(depth, 30 + int(std::ceil(std::log2(10100.0 / BVH_LEAF_TRIANGLES))) + 2);
  EXPECT_LE(g.nodes.size(), shadowBvhNodeCapacity(10100));
  EXPECT_LE(depth, int(gpu::SHADOW_STACK));
  for (int count : seen) EXPECT_EQ(count, 1);
  const ShadowGeometry again = buildShadowBvh(triangles);
  ASSERT_EQ(again.nodes.size(), g.nodes.size());
  EXPECT_EQ(std::memcmp(again.nodes.data(), g.nodes.data(), g.nodes.size() * sizeof(BvhNode)), 0);
  EXPECT_EQ(std::memcmp(again.triangles.data(), g.triangles.data(), g.triangles.size() * sizeof(ShadowTriangle)), 0);
}

TEST(ShadowRays, NoRaySlipsThroughASharedEdgeOrCorner) {
  // A unit square of two triangles at z = 0, hit exactly on its diagonal, its corners and its
  // edges' midpoints from above: every such ray is blocked by one of the two.
  const ShadowGeometry g = buildShadowBvh({triangle({0, 0, 0}, {1, 0, 0}, {1, 1, 0}, 0), triangle({0, 0, 0}, {1, 1, 0}, {0, 1, 0}, 1)});
  for (float t : {0.0f, 0.125f, 0.25f, 0.5f, 0.75f, 1.0f}) EXPECT_TRUE(blocked(g, {t, t, 1}, {t, t, -1})) << t;  // the diagonal
  for (float t : {0.125f, 0.25f, 0.5f, 0.75f}) {  // slanted, through (t, t, 0), the diagonal's inner points
    EXPECT_TRUE(blocked(g, {t - 0.25f, t + 0.5f, 1}, {t + 0.25f, t - 0.5f, -1})) << t;
  }
  EXPECT_TRUE(blocked(g, {0.5f, 0.0f, 1}, {0.5f, 0.0f, -1}));   // an outer edge
  EXPECT_FALSE(blocked(g, {1.5f, 0.5f, 1}, {1.5f, 0.5f, -1}));  // beside the square
  EXPECT_FALSE(blocked(g, {0.5f, 0.5f, 1}, {0.5f, 0.5f, 0.5f}));  // stops short of it
  EXPECT_FALSE(blocked(g, {0.5f, 0.5f, 0}, {0.5f, 0.5f, 1}));   // starts on it (t = 0): not blocked
  // A point on the square is not shadowed by the square's triangles it owns.
  EXPECT_FALSE(blocked(g, {0.25f, 0.5f, -1}, {0.25f, 0.5f, 1}, glm::uvec3(3, 4, 5)));
  EXPECT_TRUE(blocked(g, {0.25f, 0.5f, -1}, {0.25f, 0.5f, 1}, glm::uvec3(0, 1, 2)));  // the other half is hit
}

TEST(ShadowRays, DegenerateTrianglesNeverBlockAndSliversAreWatertight) {
  const ShadowGeometry degenerate = buildShadowBvh({triangle({0, 0, 0}, {0, 0, 0}, {0, 0, 0}, 0),    // a point
                                                    triangle({-1, 0, 0}, {1, 0, 0}, {2, 0, 0}, 1)});  // a line
  EXPECT_FALSE(blocked(degenerate, {0, 0, 1}, {0, 0, -1}));
  EXPECT_FALSE(blocked(degenerate, {0.5f, 0, 1}, {0.5f, 0, -1}));
  EXPECT_FALSE(blocked(degenerate, {0, 0, 0}, {0, 0, 0}));  // no direction at all
  // A sliver 1e-30 m high: a ray through its base edge is blocked, one 1e-6 m beside it is not.
  const ShadowGeometry sliver = buildShadowBvh({triangle({-1, 0, 0}, {1, 0, 0}, {0, 1e-30f, 0}, 0)});
  EXPECT_TRUE(blocked(sliver, {0.5f, 0, 1}, {0.5f, 0, -1}));
  EXPECT_FALSE(blocked(sliver, {0.5f, 1e-6f, 1}, {0.5f, 1e-6f, -1}));
}

// A sphere of radius 0.5 at height 1.2 over a floor whose top is z = 0, a point light at (0, 0, 3)
// that casts shadows, seen straight down by an orthographic camera 4 m across in `n` pixels.
std::string sphereOverPlane(int n, const std::string& shading) {
  return R"({"camera": {"position": [0, 0, 10], "look_at": [0, 0, 0], "up": [0, 1, 0], "projection": "orthographic",
               "ortho_height": 4, "width": )" + std::to_string(n) + R"(, "height": )" + std::to_string(n) + R"(},
    "ambient": [0, 0, 0], "render": {"shading": ")" + shading + R"("},
    "lights": [{"position": [0, 0, 3], "shadows": true}],
    "materials": {"m": {"ka": 0, "kd": 1, "ks": 0, "attenuation": [1, 0, 0], "color": [1, 1, 1]}},
    "objects": [{"shape": "cube", "center": [0, 0, -0.02], "size": 4, "scale": [1, 1, 0.01], "material": "m"},
                {"shape": "icosphere", "center": [0, 0, 1.2], "radius": 0.5, "subdivide": 5, "material": "m"}]})";
}

TEST(Shadows, ASphereCastsTheDiscItsTangentConeCutsFromThePlaneToThePixel) {
  // From the light, 1.8 m above the centre, the sphere spans asin(0.5 / 1.8) of the axis: on the
  // floor, 3 m below the light, a disc of radius 3 tan(asin(0.5 / 1.8)) = 0.8677 m. Seen from
  // above, the sphere itself covers 0.5 m. Every floor pixel whose centre is more than a pixel
  // inside the disc's edge is black (no ambient), every one more than a pixel outside is lit; the
  // inscribed icosphere's silhouette is within 1e-4 m of the sphere's.
  const int n = 256;
  const double pixel = 4.0 / n, disc = 3 * std::tan(std::asin(0.5 / 1.8));
  {
    const char* shading = "phong";  // per pixel: flat shades a triangle's centroid, Gouraud its vertices
    const Image image = both(parseScene(sphereOverPlane(n, shading)));
    int dark = 0, lit = 0;
    for (int y = 0; y < n; ++y) {
      for (int x = 0; x < n; ++x) {
        const double r = std::hypot((x + 0.5) * pixel - 2, (y + 0.5) * pixel - 2);
        const size_t i = (size_t(y) * n + x) * 3;
        const int value = image.rgb[i] + image.rgb[i + 1] + image.rgb[i + 2];
        if (r > 0.5 + pixel && r < disc - pixel) {
          EXPECT_EQ(value, 0) << shading << " at " << x << ", " << y << " (" << r << " m from the axis)";
          ++dark;
        } else if (r > disc + pixel && r < 1.9) {
          EXPECT_GT(value, 0) << shading << " at " << x << ", " << y << " (" << r << " m from the axis)";
          ++lit;
        }
      }
    }
    EXPECT_GT(dark, 2000) << shading;
    EXPECT_GT(lit, 5000) << shading;
  }
}

TEST(Shadows, TheLightsOutputCountsTheLightsThatReachEachPixelAlikeOnBoth) {
  // The sphere's disc: 0 lights reach the floor there, 1 beyond it, -1 where nothing is.
  const int n = 64;
  const Scene scene = parseScene(sphereOverPlane(n, "phong"));
  const Outputs outputs{.lights = true};
  const RenderedFrame cpu = Renderer(Backend::Cpu).renderOutputs(scene, outputs);
  const RenderedFrame gpu = Renderer(RendererOptions{Backend::Gpu, -1, true}).renderOutputs(scene, outputs);
  ASSERT_EQ(cpu.lights.size(), size_t(n) * n);
  EXPECT_EQ(cpu.lights, gpu.lights);
  const double pixel = 4.0 / n, disc = 3 * std::tan(std::asin(0.5 / 1.8));
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      const double r = std::hypot((x + 0.5) * pixel - 2, (y + 0.5) * pixel - 2);
      const int32_t count = cpu.lights[size_t(y) * n + x];
      if (r > 0.5 + pixel && r < disc - pixel) EXPECT_EQ(count, 0) << x << ", " << y;
      if (r > disc + pixel && r < 1.9) EXPECT_EQ(count, 1) << x << ", " << y;
    }
  }
  // A light without shadows reaches every surface (the floor fills the view).
  Scene unshadowed = scene;
  std::vector<Light> lights = unshadowed.lights();
  lights[0].shadows = false;
  unshadowed.setLights(lights);
  for (int32_t count : Renderer(Backend::Cpu).renderOutputs(unshadowed, outputs).lights) EXPECT_EQ(count, 1);
}

TEST(Shadows, ALightInsideAClosedMeshLightsNothingOutside) {
  const std::string json = R"({"camera": {"position": [4, -4, 3], "look_at": [0, 0, 0]}, "ambient": [0.1, 0.1, 0.1],
    "lights": [{"position": [0, 0, 1], "shadows": true}],
    "objects": [{"shape": "cube", "center": [0, 0, -0.05], "size": 4, "scale": [1, 1, 0.025]},
                {"shape": "icosphere", "center": [0, 0, 1], "radius": 0.4, "subdivide": 2}]})";
  const Scene shut = parseScene(json);
  std::string unlit = json;
  unlit.replace(unlit.find(R"("lights": [{"position": [0, 0, 1], "shadows": true}],)"),
                std::string(R"("lights": [{"position": [0, 0, 1], "shadows": true}],)").size(), R"("lights": [],)");
  for (Shading shading : {Shading::Gouraud, Shading::Phong}) {
    Scene a = shut, b = parseScene(unlit);
    RenderSettings settings = a.renderSettings();
    settings.shading = shading;
    a.setRenderSettings(settings);
    b.setRenderSettings(settings);
    EXPECT_TRUE(both(a).rgb == both(b).rgb) << int(shading) << ": the shut-in light reached something";
  }
}

TEST(Shadows, ALightOnASurfaceAndOneAtAVertexGiveTheSameBytesOnBothAndNoNaN) {
  // The light in the floor's top face, then at one of the cube's corners.
  for (const char* at : {"[0.3, 0.2, 0]", "[2, 2, 0]", "[0.5, 0.5, 1]"}) {
    const Scene scene = parseScene(std::string(R"({"camera": {"position": [4, -4, 3], "look_at": [0, 0, 0]},
      "render": {"shading": "phong"}, "lights": [{"position": )") + at + R"(, "shadows": true}],
      "objects": [{"shape": "cube", "center": [0, 0, -0.05], "size": 4, "scale": [1, 1, 0.025]},
                  {"shape": "cube", "center": [0, 0, 0.5], "size": 1}]})");
    both(scene);
  }
}

TEST(Shadows, SliversAndDegenerateTrianglesRenderTheSameBytesOnBoth) {
  for (const char* file : {"scenes/stress/slivers.json", "scenes/stress/lights_degenerate.json", "scenes/stress/shared_edges.json"}) {
    Scene scene = loadScene(test::sourcePath(file));
    std::vector<Light> lights = scene.lights();
    if (lights.empty()) lights.push_back(Light{.position = {2, -3, 4}});
    for (Light& light : lights) light.shadows = true;
    scene.setLights(lights);
    for (Shading shading : {Shading::Gouraud, Shading::Flat, Shading::Phong}) {
      RenderSettings settings = scene.renderSettings();
      settings.shading = shading;
      scene.setRenderSettings(settings);
      both(scene);
    }
  }
}

// An octahedron 1 m across, as MeshArrays.
MeshArrays octahedron() {
  MeshArrays mesh;
  mesh.positions = {0.5f, 0, 0, -0.5f, 0, 0, 0, 0.5f, 0, 0, -0.5f, 0, 0, 0, 0.5f, 0, 0, -0.5f};
  mesh.triangles = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};
  return mesh;
}

Matrix4 at(double x) { return {1, 0, 0, x, 0, 1, 0, 0, 0, 0, 1, 1.2, 0, 0, 0, 1}; }

// The floor and light of sphereOverPlane with an octahedron added by a pose at (x, 0, 1.2).
Scene floorWithOctahedron(double x, ObjectId* id = nullptr) {
  std::string json = sphereOverPlane(96, "phong");
  const std::string ball = R"(,
                {"shape": "icosphere", "center": [0, 0, 1.2], "radius": 0.5, "subdivide": 5, "material": "m"})";
  json.erase(json.find(ball), ball.size());
  Scene scene = parseScene(json);
  const ObjectId added = scene.add(octahedron(), at(x), "m");
  if (id) *id = added;
  return scene;
}

TEST(Shadows, AMovedObjectCarriesItsShadowAndRendersAsOneBuiltWhereItStandsWithoutABuild) {
  ObjectId id;
  Scene scene = floorWithOctahedron(0, &id);
  Renderer cpu(Backend::Cpu), gpu(RendererOptions{Backend::Gpu, -1, true});
  const Image first = gpu.render(scene);
  for (double x : {0.6, -0.3}) {
    scene.setPose(id, at(x));
    const Image fresh = both(floorWithOctahedron(x));
    EXPECT_FALSE(fresh.rgb == first.rgb) << "the shadow did not move";
    EXPECT_TRUE(gpu.render(scene).rgb == fresh.rgb) << x;
    EXPECT_TRUE(cpu.render(scene).rgb == fresh.rgb) << x;
  }
  EXPECT_EQ(gpu.stats().sceneBuilds, 1u);
  EXPECT_EQ(cpu.stats().sceneBuilds, 1u);
}

TEST(Shadows, TheTreeIsBuiltOncePerPlacementAndOnlyForShadowedLights) {
  SceneSpec spec = parseSceneSpec(sphereOverPlane(32, "phong"), "a.json", ".");
  SceneData data = buildSceneData(spec);
  ASSERT_TRUE(data.shadows);
  EXPECT_EQ(data.shadowVersion, 1u);
  placeObjects(data, spec);  // a frame of the same places (a moving camera or light): no build
  EXPECT_EQ(data.shadowVersion, 1u);
  spec.lights[0].shadows = false;
  EXPECT_FALSE(buildSceneData(spec).shadows) << "no tree without a shadowed light";
  spec.lights[0].shadows = true;
  spec.objects[1].castShadows = false;  // the sphere casts none: only the floor's 12 triangles
  EXPECT_EQ(buildSceneData(spec).shadows->triangles.size(), 12u);
  // A mesh file's own lights with "file_light_shadows": a tree where the file places lights, none
  // where it places none (an OBJ).
  const auto fileScene = [](const std::string& file) {
    return parseSceneSpec(R"({"camera": {"position": [0, -4, 2], "look_at": [0, 0, 0]}, "objects": [
                               {"shape": "mesh", "file": ")" + file + R"(", "file_light_shadows": true}]})",
                          "a.json", PHONGVK_SOURCE_DIR "/scenes");
  };
  EXPECT_TRUE(buildSceneData(fileScene("meshes/lamp.gltf")).shadows);
  EXPECT_FALSE(buildSceneData(fileScene("meshes/torus.obj")).shadows) << "no tree for a file without lights";
}

TEST(Shadows, AThousandShadowedLightsOnASmallSceneRenderInBoundedTimeOrSayWhyNot) {
  std::string lights;
  for (int i = 0; i < 1024; ++i) {
    const double a = i * 0.37;
    lights += std::string(i ? ", " : "") + R"({"position": [)" + std::to_string(2 * std::cos(a)) + ", " +
              std::to_string(2 * std::sin(a)) + R"(, 2], "intensity": 0.002, "shadows": true})";
  }
  const Scene scene = parseScene(R"({"camera": {"position": [4, -4, 3], "look_at": [0, 0, 0], "width": 96, "height": 64},
    "lights": [)" + lights + R"(], "render": {"shading": "phong"},
    "objects": [{"shape": "cube", "center": [0, 0, -0.05], "size": 4, "scale": [1, 1, 0.025]},
                {"shape": "icosphere", "center": [0, 0, 0.5], "radius": 0.4, "subdivide": 2}]})");
  // The reference renders them; the compute port does where the device lets an invocation loop
  // that long, and says why not where it does not (lavapipe allows 65,535 iterations: on this
  // scene 128 to 256 shadowed lights a vertex, 16 to 32 a pixel: docs/DESIGN.md "Shadows").
  const auto start = std::chrono::steady_clock::now();
  for (Shading shading : {Shading::Gouraud, Shading::Phong}) {
    Scene lit = scene;
    lit.setRenderSettings({.shading = shading});
    const Image reference = Renderer(Backend::Cpu).render(lit);
    try {
      EXPECT_TRUE(Renderer(Backend::Gpu).render(lit).rgb == reference.rgb);
    } catch (const DeviceError& e) {
      EXPECT_NE(std::string(e.what()).find("the shadowed lights' rays are part of that work"), std::string::npos) << e.what();
    }
  }
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 120.0);
  // 16 shadowed lights per pixel and 128 per vertex fit on every device.
  std::string few;
  for (int i = 0; i < 128; ++i) {
    few += std::string(i ? ", " : "") + R"({"position": [)" + std::to_string(2 * std::cos(i * 0.37)) + ", " +
           std::to_string(2 * std::sin(i * 0.37)) + R"(, 2], "intensity": 0.01, "shadows": true})";
  }
  Scene gouraud = parseScene(R"({"camera": {"position": [4, -4, 3], "look_at": [0, 0, 0], "width": 96, "height": 64},
    "lights": [)" + few + R"(], "objects": [{"shape": "cube", "center": [0, 0, -0.05], "size": 4, "scale": [1, 1, 0.025]},
                {"shape": "icosphere", "center": [0, 0, 0.5], "radius": 0.4, "subdivide": 2}]})");
  both(gouraud);
  std::vector<Light> sixteen = gouraud.lights();
  sixteen.resize(16);
  gouraud.setLights(sixteen);
  gouraud.setRenderSettings({.shading = Shading::Phong});
  both(gouraud);
}

}  // namespace
}  // namespace phongvk
