// raycast.h — the analytic ground truth for a scene of one sphere: per pixel, the ray through the
// pixel centre meets the exact sphere (in double) and Phong is evaluated at that point with the
// exact normal. The benchmark's error sweep measures how far the tessellated, per-vertex-lit,
// Gouraud-interpolated renders are from this picture (bench/error_sweep.h).
#pragma once

#include "scene/camera.h"
#include "phongvk/image.h"
#include "scene/scene.h"

namespace phongvk {

// Renders `scene` — exactly one `sphere` or `icosphere` object, taken as the exact sphere of its
// center and radius — as seen through `view` (same pixel centres, basis and focal length as the
// rasterizers). A pixel shows the sphere where its ray's nearer hit lies between the near and far
// planes (view-space depth, as the renderers clip); elsewhere the background. Colours follow
// docs/DESIGN.md's Phong formula with the scene's material, ambient and lights, clamped to [0, 1] and
// written as round(c * 255). Throws std::invalid_argument for any other kind of scene.
Image raycastSphere(const SceneSpec& scene, const View& view);

}  // namespace phongvk
