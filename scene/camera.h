// camera.h — the camera's image size, focal length and basis (docs/DESIGN.md "Camera").
#pragma once

#include "scene/scene.h"

#include <glm/glm.hpp>

namespace phongvk {

struct View {
  glm::dvec3 eye;
  glm::dvec3 right;    // r = normalize(cross(f, up))
  glm::dvec3 up;       // u = cross(r, f)
  glm::dvec3 forward;  // f = normalize(direction)
  glm::dvec2 focal;      // pixels per metre on the image plane 1 m in front of the eye (x, y);
                         // orthographic: pixels per metre at any depth
  glm::dvec2 principal;  // where the view axis meets the image, in pixels from its top-left corner
  int width;
  int height;
  double nearPlane;
  double farPlane;
  bool orthographic;     // pixel (x, y) looks along forward from eye + its offset from the principal point / focal
  int pixelScale = 1;    // pixels per pixel of the image: the sample grid's side (supersampled)
};

// The largest image either side may be; the loader and the CLI both enforce it.
inline constexpr int MAX_IMAGE_SIDE = 16384;

// H = floor(2 res tan(fov/2)), W = floor(2 res tan(fov/2) aspect), focal = res; or, when the
// camera gives width and height, those and focal = H / (2 tan(fov/2)); the principal point is the
// image centre (W / 2, H / 2). A camera with intrinsics has focal (fx, fy) and principal point
// (cx + 0.5, cy + 0.5). An orthographic camera has focal = H / ortho_height both ways and the
// principal point at the centre. Throws SceneError for an image size out of 1..MAX_IMAGE_SIDE or
// up parallel to the direction.
View makeView(const CameraSpec& camera);

// Samples per pixel (1, 4, 9, 16) as the side of their square grid (1 to 4).
int sampleGridSide(int samples);

// `view` with `side` x `side` samples per pixel: side times the width, height, focal length and
// principal point, so sample (i, j) of pixel (x, y) is pixel (side x + i, side y + j), its centre at
// (x + (i + 0.5) / side, y + (j + 0.5) / side) of the image.
View supersampled(View view, int side);

// The same camera rendered at width x height (the CLI's --width/--height): the vertical field of
// view (an orthographic camera's ortho_height) is kept and the aspect follows the new size.
// Intrinsics are scaled with the height (fx and fy keep their ratio) and the principal point
// stays where it was relative to the image's sides.
CameraSpec withImageSize(CameraSpec camera, int width, int height);

}  // namespace phongvk
