// Camera (docs/DESIGN.md "Camera"): image size from resolution, the basis, and where points land.
#include "prepare/camera_fit.h"
#include "prepare/scene_data.h"
#include "scene/camera.h"
#include "shaders/edges.h"
#include "shaders/phong.h"

#include <gtest/gtest.h>

namespace phongvk {
namespace {

CameraSpec lookingAlongY() {
  CameraSpec c;
  c.position = {1, 2, 3};
  c.direction = {0, 1, 0};
  return c;
}

// Where a world point lands on the image (pixel coordinates, y down), via the shared maths.
glm::vec2 project(const CameraSpec& camera, glm::dvec3 world) {
  const View view = makeView(camera);
  SceneData data;
  data.objects.resize(1);
  data.objectOrigins = {world};
  const FrameInputs in = makeFrame(data, view);
  const glm::vec3 h = gpu::toHomogeneous(glm::vec3(0.0f), in.objects[0].viewOffset, in.frame);
  const float w = gpu::homogeneousW(h, in.frame.projection);
  return glm::vec2(h.x / w, h.y / w) + in.frame.principal;
}

TEST(Camera, DefaultImageIs1385x923) {
  const View view = makeView(lookingAlongY());
  EXPECT_EQ(view.width, 1385);
  EXPECT_EQ(view.height, 923);
  EXPECT_DOUBLE_EQ(view.focal.x, 800.0);
}

TEST(Camera, WidthAndHeightSetTheSizeAndKeepTheVerticalFov) {
  CameraSpec c = withImageSize(lookingAlongY(), 640, 480);
  const View view = makeView(c);
  EXPECT_EQ(view.width, 640);
  EXPECT_EQ(view.height, 480);
  EXPECT_NEAR(view.focal.y, 240.0 / std::tan(glm::radians(30.0)), 1e-9);
}

TEST(Camera, PointOnTheViewAxisLandsAtTheImageCentre) {
  const glm::vec2 p = project(lookingAlongY(), {1, 7, 3});
  EXPECT_FLOAT_EQ(p.x, 692.5f);
  EXPECT_FLOAT_EQ(p.y, 461.5f);
}

TEST(Camera, RightIsRightAndUpIsUp) {
  // Looking along +y with z up, +x is to the camera's right.
  const glm::vec2 right = project(lookingAlongY(), {1.5, 7, 3});
  EXPECT_FLOAT_EQ(right.x, 692.5f + 800.0f * 0.5f / 5.0f);
  EXPECT_FLOAT_EQ(right.y, 461.5f);
  const glm::vec2 up = project(lookingAlongY(), {1, 7, 3.5});
  EXPECT_FLOAT_EQ(up.x, 692.5f);
  EXPECT_FLOAT_EQ(up.y, 461.5f - 800.0f * 0.5f / 5.0f);
}

TEST(Camera, BasisIsOrthonormalAndRightHanded) {
  CameraSpec c = lookingAlongY();
  c.direction = {-1, 2, -0.5};
  c.up = {0.1, 0, 1};
  const View v = makeView(c);
  EXPECT_NEAR(glm::length(v.right), 1.0, 1e-12);
  EXPECT_NEAR(glm::length(v.up), 1.0, 1e-12);
  EXPECT_NEAR(glm::dot(v.right, v.forward), 0.0, 1e-12);
  EXPECT_NEAR(glm::dot(v.up, v.forward), 0.0, 1e-12);
  EXPECT_GT(glm::dot(v.up, c.up), 0.0);  // world up stays up
  EXPECT_NEAR(glm::dot(glm::cross(v.right, v.up), v.forward), -1.0, 1e-12);  // r x u = -f
}

TEST(Camera, UpParallelToDirectionIsAnError) {
  CameraSpec c = lookingAlongY();
  c.up = {0, -2, 0};
  EXPECT_THROW(
      {
        try {
          makeView(c);
        } catch (const SceneError& e) {
          EXPECT_STREQ(e.what(), "camera.up: parallel to the view direction");
          throw;
        }
      },
      SceneError);
}

TEST(Camera, FarObjectKeepsPrecisionThroughDoubleOffsets) {
  // A point 1e6 m down the axis and 1 mm to the right, seen with a 0.001 degree fov on a
  // 100x100 image (focal = 50 / tan(0.0005 deg) = 5.73e6 px): it lands 5.73 px right of centre.
  // The offset from the eye is taken in double; float world coordinates (ulp 0.0625 m at 1e6)
  // would have rounded the millimetre away.
  CameraSpec c = withImageSize(lookingAlongY(), 100, 100);
  c.fov = 0.001;
  const glm::vec2 centre = project(c, {1, 2 + 1e6, 3});
  const glm::vec2 shifted = project(c, {1.001, 2 + 1e6, 3});
  const double focal = 50.0 / std::tan(glm::radians(0.0005));
  EXPECT_FLOAT_EQ(centre.x, 50.0f);
  EXPECT_NEAR(shifted.x - centre.x, focal * 0.001 / 1e6, 1e-3);
}

// A camera with intrinsics: fx 300, fy 200, principal point (40.25, 70) in OpenCV's pixel
// coordinates (centres at integers), on a 160 x 100 image.
CameraSpec withIntrinsics() {
  CameraSpec c = withImageSize(lookingAlongY(), 160, 100);
  c.intrinsics = true;
  c.fx = 300;
  c.fy = 200;
  c.cx = 40.25;
  c.cy = 70;
  return c;
}

TEST(Camera, IntrinsicsProjectAsOpenCVDoes) {
  // u = fx X / Z + cx, v = fy Y / Z + cy (Y down) in OpenCV's coordinates, + 0.5 in phongvk's,
  // whose pixel centres sit at x + 0.5.
  const CameraSpec c = withIntrinsics();
  const glm::vec2 p = project(c, {1 + 0.5, 2 + 5, 3 - 0.25});  // X 0.5, Y 0.25, Z 5
  EXPECT_FLOAT_EQ(p.x, float(300 * 0.5 / 5 + 40.25 + 0.5));
  EXPECT_FLOAT_EQ(p.y, float(200 * 0.25 / 5 + 70 + 0.5));
}

TEST(Camera, SupersamplingScalesTheIntrinsics) {
  const View view = supersampled(makeView(withIntrinsics()), 3);
  EXPECT_EQ(view.focal, glm::dvec2(900, 600));
  EXPECT_EQ(view.principal, glm::dvec2(3 * 40.75, 3 * 70.5));
}

TEST(Camera, ResizingKeepsTheVerticalFieldAndThePrincipalPointsPlace) {
  const View view = makeView(withImageSize(withIntrinsics(), 320, 50));
  EXPECT_EQ(view.focal, glm::dvec2(150, 100));            // scaled with the height: fx / fy kept
  EXPECT_EQ(view.principal, glm::dvec2(81.5, 35.25));     // at the same share of each side
}

TEST(Camera, AFittedCameraNeedsThePrincipalPointInsideTheImage) {
  SceneSpec scene;
  scene.camera = withIntrinsics();
  scene.camera.fit = true;
  SceneData data;
  data.boundsMin = {-1, -1, -1};
  data.boundsMax = {1, 1, 1};
  // The narrowest angle is to the left side, 40.75 px from the axis at fx 300 (the bottom is 29.5 px
  // away at fy 200): the bounding sphere fills it with the 5% margin.
  const SceneSpec framed = framedScene(scene, data);
  const double distance = 1.05 * std::sqrt(3.0) / std::sin(std::atan(40.75 / 300));
  EXPECT_NEAR(glm::length(framed.camera.position), distance, 1e-9);
  scene.camera.cx = -3;
  try {
    framedScene(scene, data);
    ADD_FAILURE() << "no error";
  } catch (const SceneError& e) {
    EXPECT_STREQ(e.what(), "camera.fit: the principal point (cx, cy) = (-3, 70) is not inside the image, so no "
                           "view centred on it frames the scene");
  }
}

CameraSpec orthographic() {
  CameraSpec c = lookingAlongY();
  c.orthographic = true;
  c.orthoHeight = 2.5;
  c.width = 200;
  c.height = 100;
  return c;
}

TEST(Camera, OrthographicPointsLandAtTheirOffsetTimesTheScaleAtAnyDepth) {
  // 100 px over 2.5 m: 40 px per metre both ways, about the image centre (100, 50), y down.
  const CameraSpec c = orthographic();
  EXPECT_EQ(makeView(c).focal, glm::dvec2(40, 40));
  for (double depth : {0.5, 5.0, 500.0}) {
    const glm::vec2 p = project(c, {1 + 0.5, 2 + depth, 3 - 0.25});
    EXPECT_FLOAT_EQ(p.x, 100 + 40 * 0.5f) << depth;
    EXPECT_FLOAT_EQ(p.y, 50 + 40 * 0.25f) << depth;
  }
  // Resized and supersampled, it keeps its height in metres.
  EXPECT_EQ(makeView(withImageSize(c, 400, 50)).focal, glm::dvec2(20, 20));
  EXPECT_EQ(supersampled(makeView(c), 2).focal, glm::dvec2(80, 80));
}

TEST(Camera, AFittedOrthographicCameraSpansTheBoundingSphereAcrossItsNarrowerSide) {
  SceneSpec scene;
  scene.camera = orthographic();
  scene.camera.fit = true;
  scene.camera.aspect = 2;
  SceneData data;
  data.boundsMin = {-1, -1, -1};
  data.boundsMax = {1, 1, 1};
  const SceneSpec framed = framedScene(scene, data);
  EXPECT_NEAR(framed.camera.orthoHeight, 2 * 1.05 * std::sqrt(3.0), 1e-12);  // the height is the narrower side
  EXPECT_NEAR(glm::length(framed.camera.position), 1.05 * std::sqrt(3.0) / std::sin(glm::radians(30.0)), 1e-9);
  scene.camera.aspect = 0.5;  // portrait: the width is
  EXPECT_NEAR(framedScene(scene, data).camera.orthoHeight, 2 * 1.05 * std::sqrt(3.0) / 0.5, 1e-12);
}

}  // namespace
}  // namespace phongvk
