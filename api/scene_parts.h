// scene_parts.h — the typed camera, lights, materials and render settings
// (include/phongvk/scene_parts.h) to and from the scene model: each goes through the checks a
// scene file's section gets (scene/scene_checks.h), so a typed value and a file say the same and
// fail with the same messages; values no file can hold (NaN, infinity) are ArgumentErrors first.
#pragma once

#include "phongvk/scene_parts.h"
#include "scene/scene.h"
#include "scene/scene_checks.h"

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

SceneSpec withAmbient(const SceneSpec& scene, const Vec3& ambient);
Vec3 ambientOf(const SceneSpec& scene);

// `material` (its texture held in memory, if any, as `textureImage`) as the values a scene file's
// material object gives, for the scene's MaterialTable to check; ArgumentError naming material.KEY
// for a value that is not finite, or for both kinds of texture.
scenejson::MaterialValues materialValues(const Material& material, std::shared_ptr<const TextureImage> textureImage);

// `scene` with `settings` (its "render" and "background"); SceneError as a file's.
SceneSpec withRenderSettings(const SceneSpec& scene, const RenderSettings& settings);

// The scene Scene(width, height) starts from: the default Camera at that size, one white light at
// the camera, no objects.
SceneSpec sceneInCode(int width, int height);

}  // namespace phongvk
