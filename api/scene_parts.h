// scene_parts.h — the typed camera, lights and poses (include/phongvk/scene_parts.h) to and from
// the scene model: a camera or lights become the scene file's section and go through its checks
// (scene.h withCameraSection, withLightsSection), so a typed value and a file say the same and
// fail with the same messages.
#pragma once

#include "phongvk/scene_parts.h"
#include "scene/scene.h"

#include <string>
#include <vector>

namespace phongvk {

// `scene` with `camera` (its size, where 0 x 0, the scene's own); SceneError as a file's camera.
SceneSpec withCamera(const SceneSpec& scene, const Camera& camera);
// The scene's camera as a value: a fitted camera ("fit") gives its view direction from where it
// stood before fitting, since where it stands is known only once the meshes are built.
Camera cameraOf(const SceneSpec& scene);

SceneSpec withLights(const SceneSpec& scene, const std::vector<Light>& lights);
std::vector<Light> lightsOf(const SceneSpec& scene);

// `object` placed by `pose` (its linear part and translation), replacing its own; ArgumentError
// naming "pose" for a matrix that is not an affine map (non-finite, last row not 0 0 0 1, linear
// part not invertible) or a translation beyond the coordinates a scene may use.
void placeObject(Object& object, const Matrix4& pose);

}  // namespace phongvk
