// scene_camera.cpp — the scene file's "camera" (docs/DESIGN.md "Camera"): position, view direction,
// up, field of view, image size and depth range, checked so that every loaded camera makes a view
// (camera.h makeView) without a NaN or an overflow.
#include "scene/scene_sections.h"

#include "scene/camera.h"

#include <cfloat>
#include <cmath>

namespace phongvk::scenejson {
namespace {

const Keys kCameraKeys = {"position", "direction", "look_at", "up", "fov", "aspect", "resolution", "width", "height",
                          "near",     "far",       "fit",     "fx", "fy",  "cx",     "cy",         "projection",
                          "ortho_height"};

// The view direction of a fitted camera given none: from the front (-y), to the left and above.
const glm::dvec3 kFitDirection = {0.5, 1.0, -0.5};

// Below this |cross(f, up)| the camera's right vector is numerically meaningless.
constexpr double kParallelTolerance = 1e-6;

// A narrower field of view makes the focal length (up to 8192 / tan(fov / 2) pixels per metre)
// large enough that focal times a distance overflows a 32-bit float in the shaders.
constexpr double kMinFov = 1e-6;

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

// A fitted camera takes its position and depth range from the scene's bounds; only the direction
// (default kFitDirection) is given.
void readFitted(const Node& camera, CameraSpec& spec) {
  for (std::string_view key : {"position", "look_at", "near", "far"}) {
    if (camera.find(key)) camera.failAt(key, "cannot be given with 'fit': the scene's bounds set it");
  }
  spec.direction = kFitDirection;
  if (auto direction = camera.find("direction")) spec.direction = usableDirection(*direction, vec3(*direction));
}

glm::dvec3 readUp(const Node& camera, glm::dvec3 direction) {
  glm::dvec3 up = {0, 0, 1};
  auto node = camera.find("up");
  if (node) up = usableDirection(*node, vec3(*node));
  glm::dvec3 side = glm::cross(glm::normalize(direction), glm::normalize(up));
  if (glm::length(side) < kParallelTolerance) camera.failAt("up", "parallel to the view direction");
  return up;
}

// docs/DESIGN.md "Camera": H = floor(2·resolution·tan(fov/2)), W = floor(2·resolution·tan(fov/2)·aspect)
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

// The focal lengths a camera's intrinsics may have: the longest a field of view >= kMinFov gives
// a 16384-pixel image is 9.4e11 pixels per metre.
constexpr double kMaxFocalPixels = 1e11;

// Pinhole intrinsics in pixels (OpenCV's convention): "fx" (required with any of them), "fy"
// (default fx), "cx" and "cy" (default the image centre), with "width" and "height" and instead
// of "fov". The principal point may lie outside the image (an off-axis view, a crop of a larger
// one) but within one largest image side of it, which keeps the guard band's subpixel bounds.
void readIntrinsics(const Node& camera, CameraSpec& spec) {
  if (!camera.find("fx") && !camera.find("fy") && !camera.find("cx") && !camera.find("cy")) return;
  if (!camera.find("fx")) camera.fail("missing required field 'fx' (given 'fy', 'cx' or 'cy')");
  for (std::string_view key : {"fov", "resolution", "aspect"}) {
    if (camera.find(key)) camera.failAt(key, "cannot be given with 'fx': the intrinsics set the field of view");
  }
  if (!camera.find("width") || !camera.find("height"))
    camera.fail("'fx' needs 'width' and 'height' (the image the intrinsics describe)");
  spec.intrinsics = true;
  spec.fx = inRange(camera.require("fx"), 0, kMaxFocalPixels);
  spec.fy = spec.fx;
  if (auto node = camera.find("fy")) spec.fy = inRange(*node, 0, kMaxFocalPixels);
  for (auto [key, focal] : {std::pair{"fx", spec.fx}, std::pair{"fy", spec.fy}}) {
    if (!(focal > 0)) camera.failAt(key, "must be > 0 (a focal length in pixels), got 0");
  }
  spec.cx = (spec.width - 1) / 2.0;
  spec.cy = (spec.height - 1) / 2.0;
  const double lo = -MAX_IMAGE_SIDE, hi = 2.0 * MAX_IMAGE_SIDE;
  if (auto node = camera.find("cx")) spec.cx = inRange(*node, lo, hi);
  if (auto node = camera.find("cy")) spec.cy = inRange(*node, lo, hi);
}

// The narrowest view an orthographic camera may have: 16384 pixels over it are 1.6e10 pixels per
// metre, far below where pixel positions in float overflow for coordinates within MAX_COORDINATE.
constexpr double kMinOrthoHeight = 1e-6;

// "projection": "perspective" (the default) or "orthographic". An orthographic camera gives
// "ortho_height" (the metres its image spans from top to bottom; a fitted camera's comes from the
// scene's bounds) and its image's "width" and "height", and none of what sets a perspective
// camera's field of view.
void readProjection(const Node& camera, CameraSpec& spec) {
  auto projection = camera.find("projection");
  const std::string name = projection ? string(*projection) : "perspective";
  if (name != "perspective" && name != "orthographic")
    projection->fail("must be one of perspective, orthographic, got '" + name + "'");
  spec.orthographic = name == "orthographic";
  auto height = camera.find("ortho_height");
  if (!spec.orthographic) {
    if (height) height->fail("is only used with 'projection': 'orthographic'");
    return;
  }
  for (std::string_view key : {"fov", "resolution", "aspect", "fx", "fy", "cx", "cy"}) {
    if (camera.find(key)) camera.failAt(key, "cannot be given with 'projection': 'orthographic' (ortho_height sets the view)");
  }
  if (!camera.find("width")) camera.fail("an orthographic camera needs 'width' and 'height' (its image in pixels)");
  if (spec.fit) {
    if (height) height->fail("cannot be given with 'fit': the scene's bounds set it");
    return;
  }
  if (!height) camera.fail("missing required field 'ortho_height' (the metres the image spans from top to bottom)");
  spec.orthoHeight = inRange(*height, kMinOrthoHeight, MAX_COORDINATE);
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

}  // namespace

CameraSpec readCamera(const Node& camera) {
  requireObject(camera);
  checkKeys(camera, kCameraKeys);
  CameraSpec spec;
  if (auto fit = camera.find("fit")) spec.fit = boolean(*fit);
  if (spec.fit) {
    readFitted(camera, spec);
  } else {
    spec.position = point(camera.require("position"));
    spec.direction = readViewDirection(camera, spec.position);
  }
  spec.up = readUp(camera, spec.direction);
  if (auto node = camera.find("fov")) spec.fov = inOpenRange(*node, 0, 180);
  if (spec.fov < kMinFov) {
    camera.failAt("fov", "must be >= " + formatNumber(kMinFov) +
                             " degrees (a narrower view overflows 32-bit floats), got " + formatNumber(spec.fov));
  }
  readImageSize(camera, spec);
  readIntrinsics(camera, spec);
  readProjection(camera, spec);
  if (!spec.fit) readDepthRange(camera, spec);
  return spec;
}

}  // namespace phongvk::scenejson
