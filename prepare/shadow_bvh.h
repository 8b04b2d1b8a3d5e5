// shadow_bvh.h — the bounding volume hierarchy shadow rays walk (shaders/shadow_rays.h): built on
// the host from the triangles that cast shadows, in the lighting frame the shade pass lights in,
// the same tree for the same scene on every machine.
#pragma once

#include "shaders/shadow_rays.h"

#include <vector>

namespace phongvk {

// Triangles a leaf holds at most.
inline constexpr uint32_t BVH_LEAF_TRIANGLES = gpu::BVH_LEAF_SIZE;

// The tree over `triangles` (each with its vertices, id and vertex indices filled in), their order
// changed to the leaves'. Top down: a node's triangles are split at the median of their centroids
// along the axis where the centroids spread most (ties by triangle id), down to
// BVH_LEAF_TRIANGLES, so the tree is at most log2(N / 4) + 2 levels deep and its shape depends on N
// alone; each node's box holds its triangles' vertices. A scene without triangles gets one leaf of
// one triangle no ray can hit (all vertices at the origin). Linear memory, O(N log N) time.
gpu::ShadowGeometry buildShadowBvh(std::vector<gpu::ShadowTriangle> triangles);

}  // namespace phongvk
