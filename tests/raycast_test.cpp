// The analytic ground truth of the benchmark's error sweep: pixel values worked out by hand, the
// silhouette's size from the tangent cone, and agreement with a finely tessellated render (which
// would catch a flipped axis or a half-pixel shift the hand-checked centre cannot see).
#include "scene/camera.h"
#include "phongvk/compare.h"
#include "reference/raycast.h"
#include "reference/render_reference.h"

#include <gtest/gtest.h>

#include <cmath>

namespace phongvk {
namespace {

// A unit sphere 5 m in front of the eye, lit from the eye. fov 90 on a 201 x 201 image puts the
// focal length at 100.5 px and pixel (100, 100)'s centre exactly on the axis.
const char* HEAD_ON = R"({
  "camera": {"position": [0, -5, 0], "direction": [0, 1, 0], "fov": 90, "width": 201, "height": 201},
  "background": [0.2, 0.4, 0.6],
  "lights": [{"position": [0, -5, 0]}],
  "objects": [{"shape": "icosphere", "radius": 1,
               "material": {"ka": 0.1, "kd": 0.4, "ks": 0.2, "n": 10, "attenuation": [1, 0.25, 0], "color": [1, 0.5, 0]}}]
})";

SceneSpec sceneFrom(const std::string& json) { return parseSceneSpec(json, "inline.json", "."); }

Image raycast(const std::string& json) {
  const SceneSpec scene = sceneFrom(json);
  return raycastSphere(scene, makeView(scene.camera));
}

void expectPixel(const Image& image, int x, int y, int r, int g, int b) {
  const uint8_t* p = image.pixel(x, y);
  EXPECT_EQ(int(p[0]), r) << "pixel " << x << "," << y;
  EXPECT_EQ(int(p[1]), g) << "pixel " << x << "," << y;
  EXPECT_EQ(int(p[2]), b) << "pixel " << x << "," << y;
}

bool isBackground(const Image& image, int x, int y) {
  const uint8_t* p = image.pixel(x, y);
  return p[0] == 51 && p[1] == 102 && p[2] == 153;
}

TEST(Raycast, CentreOfAHeadOnLitSphere) {
  // P = (0, -1, 0), N = l = V = r = (0, -1, 0), d = 4: S = 1 / (1 + 0.25 * 4) = 0.5, specular 1.
  // 0.1 C + 0.5 C (0.4 + 0.2) = 0.4 C = (0.4, 0.2, 0) -> 102, 51, 0.
  expectPixel(raycast(HEAD_ON), 100, 100, 102, 51, 0);
}

TEST(Raycast, BackgroundAroundTheSphere) {
  const Image image = raycast(HEAD_ON);
  expectPixel(image, 0, 0, 51, 102, 153);  // 0.2, 0.4, 0.6 -> 51, 102, 153
  expectPixel(image, 200, 200, 51, 102, 153);
}

TEST(Raycast, SilhouetteRadiusFollowsTheTangentCone) {
  // The tangent cone's radius on the image plane: focal * R / sqrt(D^2 - R^2) = 100.5 / sqrt(24)
  // = 20.51 px, so pixel centres 0..20 px from the axis are covered and 21 is not: 41 pixels in
  // the middle row and column (the nearest pixel centres are 0.49 px from the silhouette).
  const Image image = raycast(HEAD_ON);
  int row = 0, column = 0;
  for (int i = 0; i < image.width; ++i) {
    row += !isBackground(image, i, 100);
    column += !isBackground(image, 100, i);
  }
  EXPECT_EQ(row, 41);
  EXPECT_EQ(column, 41);
  EXPECT_FALSE(isBackground(image, 80, 100));
  EXPECT_TRUE(isBackground(image, 79, 100));
  EXPECT_FALSE(isBackground(image, 100, 120));
  EXPECT_TRUE(isBackground(image, 100, 121));
}

TEST(Raycast, EyeInsideTheSphereSeesOnlyBackground) {
  // The nearer hit is behind the eye; the far side faces away and closed objects are culled.
  SceneSpec scene = sceneFrom(HEAD_ON);
  scene.camera.position = {0, 0, 0};
  const Image image = raycastSphere(scene, makeView(scene.camera));
  for (int y = 0; y < image.height; y += 20) {
    for (int x = 0; x < image.width; x += 20) EXPECT_TRUE(isBackground(image, x, y)) << x << "," << y;
  }
}

TEST(Raycast, FineMeshConvergesToTheGroundTruth) {
  // Lit from the upper right and seen close up (fov 30: the sphere is 153 px across). Gouraud
  // shading on 20480 triangles is within 42 dB of the truth; the truth flipped upside down (a
  // wrong y axis) is at 28 dB, as highlight and terminator move. The largest difference is no
  // help: at the silhouette the inscribed mesh misses pixels the exact sphere covers.
  SceneSpec scene = sceneFrom(HEAD_ON);
  scene.camera.fov = 30;
  scene.lights[0].position = {3, -4, 3};
  scene.objects[0].subdivide = 5;
  const View view = makeView(scene.camera);
  const SceneData data = buildSceneData(scene);
  const Image mesh = renderReference(data, makeFrame(data, view)).image;
  const DiffStats stats = compareImages(raycastSphere(scene, view), mesh);
  EXPECT_GT(stats.psnr, 38.0) << formatDiff(stats);
  EXPECT_LT(stats.differing, 1000u) << formatDiff(stats);  // of 40401 pixels
}

TEST(Raycast, SpotLightConeMatchesItsClosedFormPerPixel) {
  // A spot light at (0, -4, 0) aimed at the sphere's centre, full within 8 degrees, dark beyond 11:
  // the sphere is 14.5 degrees across from there, so the cone's edge crosses its face. Lit per
  // pixel, the tessellated sphere is within 38 dB of the exact one with the cone in closed form;
  // a point light in its place is far off (the whole face lit).
  SceneSpec scene = sceneFrom(HEAD_ON);
  scene.camera.fov = 30;
  scene.shading = Shading::Phong;
  scene.objects[0].subdivide = 5;
  scene.lights[0].position = {0, -4, 0};
  scene.lights[0].spot = true;
  scene.lights[0].direction = {0, 1, 0};
  scene.lights[0].innerCone = 8;
  scene.lights[0].outerCone = 11;
  const View view = makeView(scene.camera);
  const Image truth = raycastSphere(scene, view);
  const SceneData data = buildSceneData(scene);
  const DiffStats stats = compareImages(truth, renderReference(data, makeFrame(data, view)).image);
  EXPECT_GT(stats.psnr, 38.0) << formatDiff(stats);
  SceneSpec point = scene;
  point.lights[0].spot = false;
  EXPECT_LT(compareImages(truth, raycastSphere(point, view)).psnr, 30.0);
}

// HEAD_ON seen by an orthographic camera 4 m tall: 50.25 px per metre, the axis on pixel 100.
std::string orthographic(double distance) {
  std::string json = HEAD_ON;
  const std::string perspective = R"("fov": 90)";
  json.replace(json.find(perspective), perspective.size(), R"("projection": "orthographic", "ortho_height": 4)");
  const std::string position = "[0, -5, 0], \"direction\"";
  json.replace(json.find(position), position.size(), "[0, " + std::to_string(-distance) + ", 0], \"direction\"");
  return json;
}

TEST(Raycast, OrthographicSilhouetteIsTheSphereAtAnyDistance) {
  // Every pixel looks along the axis, so the silhouette is the sphere's own radius, 50.25 px,
  // however far the eye is: pixels 50..150 of the middle row (the 50th is 50 px off the axis).
  for (double distance : {5.0, 50.0}) {
    const Image image = raycast(orthographic(distance));
    int row = 0;
    for (int i = 0; i < image.width; ++i) row += !isBackground(image, i, 100);
    EXPECT_EQ(row, 101) << distance;
    EXPECT_FALSE(isBackground(image, 50, 100));
    EXPECT_TRUE(isBackground(image, 49, 100));
  }
  // V = -forward everywhere; at the centre it is the perspective camera's V, so the same colour.
  expectPixel(raycast(orthographic(5)), 100, 100, 102, 51, 0);
}

TEST(Raycast, OrthographicFineMeshConvergesToTheGroundTruth) {
  // As FineMeshConvergesToTheGroundTruth, through an orthographic camera, in both per-vertex and
  // per-pixel lighting: the tessellated renders are within 38 dB of the exact sphere, and the
  // truth of a perspective camera is not (the sphere's silhouette and shading differ).
  SceneSpec scene = sceneFrom(orthographic(5));
  scene.lights[0].position = {3, -4, 3};
  scene.objects[0].subdivide = 5;
  const View view = makeView(scene.camera);
  const Image truth = raycastSphere(scene, view);
  for (Shading shading : {Shading::Gouraud, Shading::Phong}) {
    scene.shading = shading;
    const SceneData data = buildSceneData(scene);
    const Image mesh = renderReference(data, makeFrame(data, view)).image;
    const DiffStats stats = compareImages(truth, mesh);
    EXPECT_GT(stats.psnr, 38.0) << formatDiff(stats);
    EXPECT_LT(stats.differing, 1000u) << formatDiff(stats);
  }
  SceneSpec perspective = sceneFrom(HEAD_ON);
  perspective.lights = scene.lights;
  EXPECT_LT(compareImages(truth, raycastSphere(perspective, makeView(perspective.camera))).psnr, 30.0);
}

TEST(Raycast, RejectsScenesThatAreNotOneSphere) {
  SceneSpec scene = sceneFrom(HEAD_ON);
  scene.objects.push_back(scene.objects[0]);
  try {
    raycastSphere(scene, makeView(scene.camera));
    FAIL() << "expected ArgumentError";
  } catch (const ArgumentError& e) {
    EXPECT_STREQ(e.what(), "inline.json: the analytic ground truth needs a scene of exactly one sphere or icosphere");
  }
}

}  // namespace
}  // namespace phongvk
