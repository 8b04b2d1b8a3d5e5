// camera_fit.h — a camera that frames what is there ("fit": true) and lights placed at the camera
// ("position": "camera"), resolved once the meshes are built and their bounds known.
#pragma once

#include "prepare/scene_data.h"
#include "scene/scene.h"

namespace phongvk {

// True when `scene` has a fitted camera or a light at the camera.
bool needsFraming(const SceneSpec& scene);

// `scene` with its camera fitted to data's bounds and its camera lights at the camera's position.
// The fit (docs/DESIGN.md "Camera"): the sphere around the bounding box, of radius r about its
// centre c, fills the narrower of the two fields of view with a 5% margin: the eye is at
// c - d·f, d = 1.05·r / sin(half the narrower field), f the unit view direction; near = (d - r) / 2,
// far = 2·(d + r). With intrinsics the half field is the narrowest angle from the view axis (through
// the principal point) to a side of the image. An orthographic camera stands where a perspective
// one of its fov (default 60°) would, and its view spans the sphere's diameter with the margin
// across the narrower side of the image. Throws SceneError when that puts the eye beyond the
// coordinates a scene may use, or when the principal point is not inside the image.
SceneSpec framedScene(const SceneSpec& scene, const SceneData& data);

}  // namespace phongvk
