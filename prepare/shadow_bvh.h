// shadow_bvh.h — the bounding volume hierarchy shadow rays walk (shaders/shadow_rays.h): built on
// the host from the triangles that cast shadows, in the lighting frame the shade pass lights in,
// the same tree for the same scene on every machine.
#pragma once

#include "shaders/shadow_rays.h"

#include <algorithm>
#include <vector>

namespace phongvk {

// Triangles a leaf holds at most.
inline constexpr uint32_t BVH_LEAF_TRIANGLES = gpu::BVH_LEAF_SIZE;

// The tree over `triangles` (each with its vertices, id and vertex indices filled in), their order
// changed to the leaves'. The triangles are put in the Morton order of their centroids (30-bit
// codes over the centroids' box, sorted stably by three counting passes, so equal codes keep the
// input's order), then each node's run of them is split where the highest bit in which its codes
// differ turns 1 (an octree's cut), or at its middle where they are all equal, down to
// BVH_LEAF_TRIANGLES. So the tree is at most 30 + log2(N / 4) + 2 levels deep and has at most
// 2N - 1 nodes (shadowBvhNodeCapacity), and every step is integer or exact float work, the same on
// every machine. Each node's box holds its triangles' vertices (a leaf's from them, an inner
// node's from its children's). A scene without triangles gets one leaf of one triangle no ray can
// hit (all vertices at the origin). Linear time and memory.
gpu::ShadowGeometry buildShadowBvh(std::vector<gpu::ShadowTriangle> triangles);

// The most nodes a tree over `triangles` triangles has, whatever their places: what the device
// holds room for, so a tree built again for moved objects fits where the first was.
inline size_t shadowBvhNodeCapacity(size_t triangles) { return 2 * std::max<size_t>(triangles, 1); }

}  // namespace phongvk
