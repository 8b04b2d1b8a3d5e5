// shadow_bvh.cpp — see shadow_bvh.h.
#include "prepare/shadow_bvh.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>

namespace phongvk {
namespace {

// Spreads the low 10 bits of v over every third bit (for a Morton code).
uint32_t spread(uint32_t v) {
  v &= 0x3FFu;
  v = (v | (v << 16)) & 0x030000FFu;
  v = (v | (v << 8)) & 0x0300F00Fu;
  v = (v | (v << 4)) & 0x030C30C3u;
  v = (v | (v << 2)) & 0x09249249u;
  return v;
}

// Each triangle's 30-bit Morton code: its centroid's place in the centroids' box, 1024 steps an axis.
std::vector<uint32_t> mortonCodes(const std::vector<gpu::ShadowTriangle>& triangles) {
  std::vector<glm::vec3> centroids(triangles.size());
  glm::vec3 low(HUGE_VALF), high(-HUGE_VALF);
  for (size_t i = 0; i < triangles.size(); ++i) {
    centroids[i] = (triangles[i].a + triangles[i].b + triangles[i].c) / 3.0f;
    low = glm::min(low, centroids[i]);
    high = glm::max(high, centroids[i]);
  }
  const glm::dvec3 extent = glm::dvec3(high) - glm::dvec3(low);
  std::vector<uint32_t> codes(triangles.size());
  for (size_t i = 0; i < triangles.size(); ++i) {
    uint32_t q[3];
    for (int k = 0; k < 3; ++k) {
      const double t = extent[k] > 0 ? (double(centroids[i][k]) - double(low[k])) / extent[k] : 0.0;
      q[k] = uint32_t(std::clamp(t * 1023.0, 0.0, 1023.0));  // NaN-free: the centroids are finite
    }
    codes[i] = spread(q[0]) << 2 | spread(q[1]) << 1 | spread(q[2]);
  }
  return codes;
}

// The triangles' indices sorted by code, stably (equal codes keep the input's order): three
// counting passes of 10 bits.
std::vector<uint32_t> mortonOrder(const std::vector<uint32_t>& codes) {
  std::vector<uint32_t> order(codes.size()), next(codes.size());
  for (uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  for (int shift = 0; shift < 30; shift += 10) {
    std::array<size_t, 1025> start{};
    for (uint32_t i : order) ++start[((codes[i] >> shift) & 1023u) + 1];
    for (size_t b = 1; b < start.size(); ++b) start[b] += start[b - 1];
    for (uint32_t i : order) next[start[(codes[i] >> shift) & 1023u]++] = i;
    order.swap(next);
  }
  return order;
}

struct Builder {
  const std::vector<gpu::ShadowTriangle>& triangles;  // in leaf order
  const std::vector<uint32_t>& codes;                 // theirs, sorted
  std::vector<gpu::BvhNode> nodes;

  // Where [begin, end) splits: at the first code with the highest bit in which the run's codes
  // differ (an octree's cut), or at the middle where they are all the same.
  size_t split(size_t begin, size_t end) const {
    const uint32_t first = codes[begin], last = codes[end - 1];
    if (first == last) return begin + (end - begin) / 2;
    const uint32_t bit = 1u << (31 - std::countl_zero(first ^ last));
    return size_t(std::partition_point(codes.begin() + std::ptrdiff_t(begin), codes.begin() + std::ptrdiff_t(end),
                                       [&](uint32_t c) { return (c & bit) == 0; }) - codes.begin());
  }

  // Node for triangles [begin, end) and its subtree, depth first, split at the middle; its index.
  uint32_t build(size_t begin, size_t end) {
    const uint32_t node = uint32_t(nodes.size());
    nodes.push_back({});
    if (end - begin <= BVH_LEAF_TRIANGLES) {
      glm::vec3 low(HUGE_VALF), high(-HUGE_VALF);
      for (size_t i = begin; i < end; ++i) {
        const gpu::ShadowTriangle& t = triangles[i];
        low = glm::min(low, glm::min(t.a, glm::min(t.b, t.c)));
        high = glm::max(high, glm::max(t.a, glm::max(t.b, t.c)));
      }
      nodes[node] = {low, uint32_t(end - begin), high, uint32_t(begin)};
      return node;
    }
    const size_t middle = split(begin, end);
    build(begin, middle);
    const uint32_t second = build(middle, end);
    const gpu::BvhNode& a = nodes[node + 1];
    const gpu::BvhNode& b = nodes[second];
    nodes[node] = {glm::min(a.low, b.low), 0u, glm::max(a.high, b.high), second};
    return node;
  }
};

}  // namespace

gpu::ShadowGeometry buildShadowBvh(std::vector<gpu::ShadowTriangle> triangles) {
  if (triangles.empty()) {
    gpu::ShadowTriangle none{};
    none.id = none.v0 = none.v1 = none.v2 = gpu::SHADOW_NO_OWNER;
    triangles.push_back(none);
  }
  gpu::ShadowGeometry geometry;
  const std::vector<uint32_t> codes = mortonCodes(triangles);
  const std::vector<uint32_t> order = mortonOrder(codes);
  geometry.triangles.reserve(triangles.size());
  std::vector<uint32_t> sorted;
  sorted.reserve(triangles.size());
  for (uint32_t i : order) {
    geometry.triangles.push_back(triangles[i]);
    sorted.push_back(codes[i]);
  }
  Builder builder{geometry.triangles, sorted, {}};
  builder.nodes.reserve(2 * (triangles.size() / BVH_LEAF_TRIANGLES + 1));
  builder.build(0, geometry.triangles.size());
  geometry.nodes = std::move(builder.nodes);
  return geometry;
}

}  // namespace phongvk
