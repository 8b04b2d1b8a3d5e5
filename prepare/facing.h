// facing.h — which side of its triangles a camera sees: a model whose normals all face away from
// the camera (a one-sided polygon or an open mesh seen from its back) is drawn dark, lit from
// behind, and a user should be told why (RendererStats::notice).
#pragma once

#include "prepare/scene_data.h"

#include <glm/glm.hpp>

namespace phongvk {

// True when `data` has triangles and an eye at `eye` (world coordinates) sees the back of every
// one of them: each is wound clockwise as seen from the eye, i.e. its face normal
// ((P1 - P0) x (P2 - P0), outward for counter-clockwise front faces) points away. Degenerate
// triangles and those whose plane passes through the eye count for neither side.
bool seenOnlyFromBehind(const SceneData& data, const glm::dvec3& eye);

}  // namespace phongvk
