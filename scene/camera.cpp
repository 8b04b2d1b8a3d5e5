#include "scene/camera.h"

#include <cmath>
#include <string>

namespace phongvk {

namespace {

void checkSide(int pixels, const char* what) {
  if (pixels < 1 || pixels > MAX_IMAGE_SIDE) {
    throw SceneError(std::string("camera: image ") + what + " " + std::to_string(pixels) +
                     " is outside 1.." + std::to_string(MAX_IMAGE_SIDE) + " pixels");
  }
}

}  // namespace

View makeView(const CameraSpec& camera) {
  View view{};
  const double halfHeight = std::tan(glm::radians(camera.fov) / 2);  // at 1 m from the eye
  if (camera.width > 0 && camera.height > 0) {
    view.width = camera.width;
    view.height = camera.height;
    const double focal = camera.height / (2 * halfHeight);
    view.focal = {focal, focal};
  } else {
    const double h = 2 * camera.resolution * halfHeight;
    const double w = h * camera.aspect;
    if (!(h < MAX_IMAGE_SIDE + 1.0) || !(w < MAX_IMAGE_SIDE + 1.0)) checkSide(MAX_IMAGE_SIDE + 1, "size");
    view.height = static_cast<int>(std::floor(h));
    view.width = static_cast<int>(std::floor(w));
    view.focal = {camera.resolution, camera.resolution};
  }
  view.principal = {view.width * 0.5, view.height * 0.5};
  if (camera.intrinsics) {
    view.focal = {camera.fx, camera.fy};
    view.principal = {camera.cx + 0.5, camera.cy + 0.5};
  }
  view.orthographic = camera.orthographic;
  if (camera.orthographic) view.focal = glm::dvec2(view.height / camera.orthoHeight);
  checkSide(view.width, "width");
  checkSide(view.height, "height");

  view.eye = camera.position;
  view.forward = glm::normalize(camera.direction);
  const glm::dvec3 side = glm::cross(view.forward, camera.up);
  if (glm::length(side) <= 1e-9 * glm::length(camera.up)) {
    throw SceneError("camera.up: parallel to the view direction");
  }
  view.right = glm::normalize(side);
  view.up = glm::cross(view.right, view.forward);
  view.nearPlane = camera.nearPlane;
  view.farPlane = camera.farPlane;
  return view;
}

int sampleGridSide(int samples) { return int(std::lround(std::sqrt(double(samples)))); }

View supersampled(View view, int side) {
  view.width *= side;
  view.height *= side;
  view.focal *= double(side);
  view.principal *= double(side);
  view.pixelScale *= side;
  return view;
}

CameraSpec withImageSize(CameraSpec camera, int width, int height) {
  if (camera.intrinsics && camera.width > 0 && camera.height > 0) {
    const double sx = double(width) / camera.width, sy = double(height) / camera.height;
    camera.fx *= sy;
    camera.fy *= sy;
    camera.cx = (camera.cx + 0.5) * sx - 0.5;
    camera.cy = (camera.cy + 0.5) * sy - 0.5;
  }
  camera.width = width;
  camera.height = height;
  camera.aspect = static_cast<double>(width) / height;
  return camera;
}

}  // namespace phongvk
