// scene_parts.h — the typed camera, lights, materials, render settings and poses
// (include/phongvk/scene_parts.h) to and from the scene model: each becomes the scene file's
// section (or material object) and goes through its checks (scene.h withSection, scene_sections.h
// MaterialTable), so a typed value and a file say the same and fail with the same messages.
#pragma once

#include "phongvk/scene_parts.h"
#include "scene/scene.h"
#include "scene/scene_json.h"

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

// `material` as a scene file's material object, for the scene's MaterialTable to read;
// ArgumentError naming material.KEY for a value that is not finite.
scenejson::Json materialJson(const Material& material);

// `scene` with `settings` (its "render" and "background"); SceneError as a file's.
SceneSpec withRenderSettings(const SceneSpec& scene, const RenderSettings& settings);
RenderSettings renderSettingsOf(const SceneSpec& scene);

// The scene Scene(width, height) starts from: the default Camera at that size, one white light at
// the camera, no objects.
SceneSpec sceneInCode(int width, int height);

}  // namespace phongvk
