// scene_camera.cpp — the scene file's "camera" (docs/DESIGN.md "Camera"): position, view direction,
// up, field of view, image size and depth range, checked so that every loaded camera makes a view
// (camera.h makeView) without a NaN or an overflow.
#include "scene/scene_sections.h"

#include "scene/camera.h"
#include "scene/scene_checks.h"

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
glm::dvec3 viewDirection(const CameraValues& c, glm::dvec3 position, const Where& at) {
  if (c.direction && c.lookAt) at.at("look_at").fail("cannot be given together with 'direction'");
  if (c.direction) return usableDirection(*c.direction, at.at("direction"));
  if (!c.lookAt) at.fail("missing required field 'direction' (or 'look_at')");
  const glm::dvec3 target = point(*c.lookAt, at.at("look_at"));
  if (target == position) at.at("look_at").fail("equals camera.position, so there is no view direction");
  return usableDirection(target - position, at.at("look_at"));
}

// A fitted camera takes its position and depth range from the scene's bounds; only the direction
// (default kFitDirection) is given.
void fitted(const CameraValues& c, CameraSpec& spec, const Where& at) {
  for (auto [given, key] : {std::pair{c.position.has_value(), "position"}, {c.lookAt.has_value(), "look_at"},
                            {c.nearPlane.has_value(), "near"}, {c.farPlane.has_value(), "far"}}) {
    if (given) at.at(key).fail("cannot be given with 'fit': the scene's bounds set it");
  }
  spec.direction = kFitDirection;
  if (c.direction) spec.direction = usableDirection(*c.direction, at.at("direction"));
}

glm::dvec3 upOf(const CameraValues& c, glm::dvec3 direction, const Where& at) {
  glm::dvec3 up = {0, 0, 1};
  if (c.up) up = usableDirection(*c.up, at.at("up"));
  glm::dvec3 side = glm::cross(glm::normalize(direction), glm::normalize(up));
  if (glm::length(side) < kParallelTolerance) at.at("up").fail("parallel to the view direction");
  return up;
}

// docs/DESIGN.md "Camera": H = floor(2·resolution·tan(fov/2)), W = floor(2·resolution·tan(fov/2)·aspect)
// (the same operations as makeView, so a scene that loads also makes a view).
void checkImageSizeFromResolution(const CameraSpec& spec, const Where& at) {
  double planeHeight = 2 * spec.resolution * std::tan(glm::radians(spec.fov) / 2);
  double height = std::floor(planeHeight);
  double width = std::floor(planeHeight * spec.aspect);
  if (width >= 1 && height >= 1 && width <= MAX_IMAGE_SIDE && height <= MAX_IMAGE_SIDE) return;
  std::string size = formatNumber(width) + "x" + formatNumber(height);
  std::string inputs = "resolution " + formatNumber(spec.resolution) + ", fov " +
                       formatNumber(spec.fov) + ", aspect " + formatNumber(spec.aspect);
  at.at("resolution").fail("image would be " + size + " pixels (" + inputs + "); each side must be 1 to " +
                           std::to_string(MAX_IMAGE_SIDE));
}

// Either resolution + aspect, or width + height (which then set the aspect).
void imageSize(const CameraValues& c, CameraSpec& spec, const Where& at) {
  if (!c.width && !c.height) {
    if (c.aspect) spec.aspect = positive(*c.aspect, at.at("aspect"));
    if (c.resolution) spec.resolution = positive(*c.resolution, at.at("resolution"));
    checkImageSizeFromResolution(spec, at);
    return;
  }
  if (!c.height) at.at("width").fail("must be given together with 'height'");
  if (!c.width) at.at("height").fail("must be given together with 'width'");
  for (auto [given, key] : {std::pair{c.resolution.has_value(), "resolution"}, {c.aspect.has_value(), "aspect"}}) {
    if (given) at.at(key).fail("cannot be given together with 'width' and 'height'");
  }
  spec.width = integerInRange(*c.width, 1, MAX_IMAGE_SIDE, at.at("width"));
  spec.height = integerInRange(*c.height, 1, MAX_IMAGE_SIDE, at.at("height"));
  spec.aspect = double(spec.width) / spec.height;
}

// The focal lengths a camera's intrinsics may have: the longest a field of view >= kMinFov gives
// a 16384-pixel image is 9.4e11 pixels per metre.
constexpr double kMaxFocalPixels = 1e11;

// Pinhole intrinsics in pixels (OpenCV's convention): "fx" (required with any of them), "fy"
// (default fx), "cx" and "cy" (default the image centre), with "width" and "height" and instead
// of "fov". The principal point may lie outside the image (an off-axis view, a crop of a larger
// one) but within one largest image side of it, which keeps the guard band's subpixel bounds.
void intrinsics(const CameraValues& c, CameraSpec& spec, const Where& at) {
  if (!c.fx && !c.fy && !c.cx && !c.cy) return;
  if (!c.fx) at.fail("missing required field 'fx' (given 'fy', 'cx' or 'cy')");
  for (auto [given, key] : {std::pair{c.fov.has_value(), "fov"}, {c.resolution.has_value(), "resolution"},
                            {c.aspect.has_value(), "aspect"}}) {
    if (given) at.at(key).fail("cannot be given with 'fx': the intrinsics set the field of view");
  }
  if (!c.width || !c.height) at.fail("'fx' needs 'width' and 'height' (the image the intrinsics describe)");
  spec.intrinsics = true;
  spec.fx = inRange(*c.fx, 0.0, kMaxFocalPixels, at.at("fx"));
  spec.fy = c.fy ? inRange(*c.fy, 0.0, kMaxFocalPixels, at.at("fy")) : spec.fx;
  for (auto [key, focal] : {std::pair{"fx", spec.fx}, std::pair{"fy", spec.fy}}) {
    if (!(focal > 0)) at.at(key).fail("must be > 0 (a focal length in pixels), got 0");
  }
  const double lo = -MAX_IMAGE_SIDE, hi = 2.0 * MAX_IMAGE_SIDE;
  spec.cx = c.cx ? inRange(*c.cx, lo, hi, at.at("cx")) : (spec.width - 1) / 2.0;
  spec.cy = c.cy ? inRange(*c.cy, lo, hi, at.at("cy")) : (spec.height - 1) / 2.0;
}

// The narrowest view an orthographic camera may have: 16384 pixels over it are 1.6e10 pixels per
// metre, far below where pixel positions in float overflow for coordinates within MAX_COORDINATE.
constexpr double kMinOrthoHeight = 1e-6;

// "projection": "orthographic" gives "ortho_height" (the metres its image spans from top to bottom;
// a fitted camera's comes from the scene's bounds) and its image's "width" and "height", and none
// of what sets a perspective camera's field of view.
void projection(const CameraValues& c, CameraSpec& spec, const Where& at) {
  spec.orthographic = c.orthographic;
  if (!spec.orthographic) {
    if (c.orthoHeight) at.at("ortho_height").fail("is only used with 'projection': 'orthographic'");
    return;
  }
  for (auto [given, key] : {std::pair{c.fov.has_value(), "fov"}, {c.resolution.has_value(), "resolution"},
                            {c.aspect.has_value(), "aspect"}, {c.fx.has_value(), "fx"}, {c.fy.has_value(), "fy"},
                            {c.cx.has_value(), "cx"}, {c.cy.has_value(), "cy"}}) {
    if (given) at.at(key).fail("cannot be given with 'projection': 'orthographic' (ortho_height sets the view)");
  }
  if (!c.width) at.fail("an orthographic camera needs 'width' and 'height' (its image in pixels)");
  if (spec.fit) {
    if (c.orthoHeight) at.at("ortho_height").fail("cannot be given with 'fit': the scene's bounds set it");
    return;
  }
  if (!c.orthoHeight) at.fail("missing required field 'ortho_height' (the metres the image spans from top to bottom)");
  spec.orthoHeight = inRange(*c.orthoHeight, kMinOrthoHeight, MAX_COORDINATE, at.at("ortho_height"));
}

void depthRange(const CameraValues& c, CameraSpec& spec, const Where& at) {
  if (c.nearPlane) spec.nearPlane = positive(*c.nearPlane, at.at("near"));
  // The renderers clip at near as a float: one that rounds to 0 would let them divide by w = 0.
  if (static_cast<float>(spec.nearPlane) < FLT_MIN) {
    at.at("near").fail("must be >= " + formatNumber(FLT_MIN) + " (the smallest normal 32-bit float), got " +
                       formatNumber(spec.nearPlane));
  }
  if (c.farPlane) spec.farPlane = *c.farPlane;
  if (!(spec.farPlane > spec.nearPlane)) {
    at.at("far").fail("must be > near (" + formatNumber(spec.nearPlane) + "), got " + formatNumber(spec.farPlane));
  }
}

// The file's camera as values, its keys and types checked (the values are cameraSpec's).
CameraValues cameraValues(const Node& camera) {
  requireObject(camera);
  checkKeys(camera, kCameraKeys);
  CameraValues c;
  const auto vector = [&](std::string_view key) -> std::optional<glm::dvec3> {
    if (auto node = camera.find(key)) return vec3(*node);
    return std::nullopt;
  };
  const auto scalar = [&](std::string_view key) -> std::optional<double> {
    if (auto node = camera.find(key)) return number(*node);
    return std::nullopt;
  };
  if (auto fit = camera.find("fit")) c.fit = boolean(*fit);
  for (auto [key, field] : {std::pair{"position", &c.position}, {"direction", &c.direction}, {"look_at", &c.lookAt},
                            {"up", &c.up}})
    *field = vector(key);
  for (auto [key, field] : {std::pair{"fov", &c.fov}, {"aspect", &c.aspect}, {"resolution", &c.resolution},
                            {"near", &c.nearPlane}, {"far", &c.farPlane}, {"fx", &c.fx}, {"fy", &c.fy}, {"cx", &c.cx},
                            {"cy", &c.cy}, {"ortho_height", &c.orthoHeight}})
    *field = scalar(key);
  if (auto width = camera.find("width")) c.width = integer(*width, 1, MAX_IMAGE_SIDE);
  if (auto height = camera.find("height")) c.height = integer(*height, 1, MAX_IMAGE_SIDE);
  if (auto projection = camera.find("projection")) {
    const std::string name = string(*projection);
    if (name != "perspective" && name != "orthographic")
      projection->fail("must be one of perspective, orthographic, got '" + name + "'");
    c.orthographic = name == "orthographic";
  }
  return c;
}

}  // namespace

CameraSpec cameraSpec(const CameraValues& c, const Where& at) {
  CameraSpec spec;
  spec.fit = c.fit;
  if (spec.fit) {
    fitted(c, spec, at);
  } else {
    if (!c.position) at.fail("missing required field 'position'");
    spec.position = point(*c.position, at.at("position"));
    spec.direction = viewDirection(c, spec.position, at);
  }
  spec.up = upOf(c, spec.direction, at);
  if (c.fov) spec.fov = inOpenRange(*c.fov, 0, 180, at.at("fov"));
  if (spec.fov < kMinFov) {
    at.at("fov").fail("must be >= " + formatNumber(kMinFov) + " degrees (a narrower view overflows 32-bit floats), got " +
                      formatNumber(spec.fov));
  }
  imageSize(c, spec, at);
  intrinsics(c, spec, at);
  projection(c, spec, at);
  if (!spec.fit) depthRange(c, spec, at);
  return spec;
}

CameraSpec readCamera(const Node& camera) { return cameraSpec(cameraValues(camera), camera.where()); }

}  // namespace phongvk::scenejson
