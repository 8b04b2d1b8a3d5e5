// shadow_bvh.cpp — see shadow_bvh.h.
#include "prepare/shadow_bvh.h"

#include <algorithm>
#include <array>
#include <cstdint>

namespace phongvk {
namespace {

// A triangle's centroid and its place in the input, what the splits sort.
struct Item {
  std::array<float, 3> centroid;
  uint32_t index;
};

struct Builder {
  const std::vector<gpu::ShadowTriangle>& triangles;
  std::vector<Item> items;
  std::vector<gpu::BvhNode> nodes;

  void bound(gpu::BvhNode& node, size_t begin, size_t end) const {
    glm::vec3 low(HUGE_VALF), high(-HUGE_VALF);
    for (size_t i = begin; i < end; ++i) {
      const gpu::ShadowTriangle& t = triangles[items[i].index];
      low = glm::min(low, glm::min(t.a, glm::min(t.b, t.c)));
      high = glm::max(high, glm::max(t.a, glm::max(t.b, t.c)));
    }
    node.low = low;
    node.high = high;
  }

  // The axis along which the centroids of [begin, end) spread most (x before y before z on ties).
  int splitAxis(size_t begin, size_t end) const {
    std::array<float, 3> low = items[begin].centroid, high = low;
    for (size_t i = begin + 1; i < end; ++i) {
      for (int k = 0; k < 3; ++k) {
        low[k] = std::min(low[k], items[i].centroid[k]);
        high[k] = std::max(high[k], items[i].centroid[k]);
      }
    }
    int axis = 0;
    for (int k = 1; k < 3; ++k) {
      if (high[k] - low[k] > high[axis] - low[axis]) axis = k;
    }
    return axis;
  }

  // Node for [begin, end) and its subtree, depth first; its index.
  uint32_t build(size_t begin, size_t end) {
    const uint32_t node = uint32_t(nodes.size());
    nodes.push_back({});
    bound(nodes[node], begin, end);
    if (end - begin <= BVH_LEAF_TRIANGLES) {
      // A total order within the leaf too, so its triangles' order is the same everywhere.
      std::sort(items.begin() + std::ptrdiff_t(begin), items.begin() + std::ptrdiff_t(end),
                [](const Item& a, const Item& b) { return a.index < b.index; });
      nodes[node].count = uint32_t(end - begin);
      nodes[node].index = uint32_t(begin);
      return node;
    }
    const int axis = splitAxis(begin, end);
    const size_t middle = begin + (end - begin) / 2;
    // (centroid, index) orders the items totally: the half below the median is one set everywhere.
    std::nth_element(items.begin() + std::ptrdiff_t(begin), items.begin() + std::ptrdiff_t(middle),
                     items.begin() + std::ptrdiff_t(end), [axis](const Item& a, const Item& b) {
                       return a.centroid[axis] != b.centroid[axis] ? a.centroid[axis] < b.centroid[axis] : a.index < b.index;
                     });
    build(begin, middle);
    const uint32_t second = build(middle, end);
    nodes[node].count = 0;
    nodes[node].index = second;
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
  Builder builder{triangles, {}, {}};
  builder.items.resize(triangles.size());
  for (size_t i = 0; i < triangles.size(); ++i) {
    const gpu::ShadowTriangle& t = triangles[i];
    const glm::vec3 c = (t.a + t.b + t.c) / 3.0f;
    builder.items[i] = {{c.x, c.y, c.z}, uint32_t(i)};
  }
  builder.nodes.reserve(2 * (triangles.size() / BVH_LEAF_TRIANGLES + 1));
  builder.build(0, triangles.size());
  gpu::ShadowGeometry geometry;
  geometry.nodes = std::move(builder.nodes);
  geometry.triangles.reserve(triangles.size());
  for (const Item& item : builder.items) geometry.triangles.push_back(triangles[item.index]);
  return geometry;
}

}  // namespace phongvk
