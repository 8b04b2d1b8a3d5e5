// shadow_bvh.cpp — see shadow_bvh.h.
#include "prepare/shadow_bvh.h"

#include "base/huge_pages.h"

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

glm::vec3 centroid(const gpu::ShadowTriangle& t) { return (t.a + t.b + t.c) / 3.0f; }

// Each triangle's 30-bit Morton code: its centroid's place in the centroids' box, 1024 steps an
// axis; as a sort key, the code in the high word and the triangle's index in the low.
std::vector<uint64_t> mortonKeys(const std::vector<gpu::ShadowTriangle>& triangles) {
  glm::vec3 low(HUGE_VALF), high(-HUGE_VALF);
  for (const gpu::ShadowTriangle& t : triangles) {
    const glm::vec3 c = centroid(t);
    low = glm::min(low, c);
    high = glm::max(high, c);
  }
  const glm::dvec3 extent = glm::dvec3(high) - glm::dvec3(low);
  glm::dvec3 steps;  // per axis, steps a metre (0 where the centroids do not spread)
  for (int k = 0; k < 3; ++k) steps[k] = extent[k] > 0 ? 1023.0 / extent[k] : 0.0;
  std::vector<uint64_t> keys;
  reserveLarge(keys, triangles.size());
  for (size_t i = 0; i < triangles.size(); ++i) {
    const glm::vec3 c = centroid(triangles[i]);
    uint32_t q[3];
    for (int k = 0; k < 3; ++k) {
      q[k] = uint32_t(std::clamp((double(c[k]) - double(low[k])) * steps[k], 0.0, 1023.0));  // NaN-free: finite centroids
    }
    const uint32_t code = spread(q[0]) << 2 | spread(q[1]) << 1 | spread(q[2]);
    keys.push_back(uint64_t(code) << 32 | i);
  }
  return keys;
}

// The keys sorted by code, stably (equal codes keep the input's order, which the index in the low
// word already is): three counting passes of 10 bits over the codes, each reading the keys in
// order.
void sortByCode(std::vector<uint64_t>& keys) {
  std::vector<uint64_t> next;
  reserveLarge(next, keys.size());
  next.resize(keys.size());
  for (int shift = 32; shift < 62; shift += 10) {
    std::array<size_t, 1025> start{};
    for (uint64_t key : keys) ++start[((key >> shift) & 1023u) + 1];
    for (size_t b = 1; b < start.size(); ++b) start[b] += start[b - 1];
    for (uint64_t key : keys) next[start[(key >> shift) & 1023u]++] = key;
    keys.swap(next);
  }
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
  std::vector<uint64_t> keys = mortonKeys(triangles);
  sortByCode(keys);
  // The triangles in leaf order on ordinary pages: asked for huge pages, this 64-byte-a-triangle
  // array was at times many times slower to fill (the kernel compacting memory to find them).
  geometry.triangles.reserve(triangles.size());
  std::vector<uint32_t> sorted;  // each leaf-order place's code
  reserveLarge(sorted, keys.size());
  for (uint64_t key : keys) {
    geometry.triangles.push_back(triangles[uint32_t(key)]);
    sorted.push_back(uint32_t(key >> 32));
  }
  Builder builder{geometry.triangles, sorted, {}};
  reserveLarge(builder.nodes, 2 * (triangles.size() / BVH_LEAF_TRIANGLES + 1));
  builder.build(0, geometry.triangles.size());
  geometry.nodes = std::move(builder.nodes);
  return geometry;
}

}  // namespace phongvk
