// subdivide.cpp — see subdivide.h. The edge -> midpoint table is a bucket per lower vertex index
// (counting sort), each bucket sorted by the higher index: sequential memory, no std::map, no hash.
#include "geometry/subdivide.h"

#include "base/huge_pages.h"

#include <algorithm>
#include <cassert>
#include <cstddef>
#include <limits>

namespace phongvk {

SurfaceVertex flatMidpoint(const SurfaceVertex& a, const SurfaceVertex& b) {
  SurfaceVertex mid;
  mid.position = (a.position + b.position) * 0.5f;
  mid.normal = a.normal;
  if (a.normal != b.normal) {
    glm::vec3 sum = a.normal + b.normal;
    float length = glm::length(sum);
    if (length > 0.0f) mid.normal = sum / length;  // opposite normals: keep a's, any is as good
  }
  mid.surface = a.surface == b.surface ? a.surface : 0;
  for (int shift = 0; shift < 32; shift += 8) {
    const uint32_t sum = ((a.color >> shift) & 255u) + ((b.color >> shift) & 255u);
    mid.color = (mid.color & ~(255u << shift)) | (((sum + 1u) / 2u) << shift);
  }
  return mid;
}

namespace {

// The unique edges of a triangle list and, for every half-edge 3t+k (from corner k to corner
// k+1 of triangle t), the index of its edge.
struct EdgeTable {
  std::vector<uint32_t> lo, hi;          // per edge: its end vertices, lo < hi
  std::vector<uint32_t> edgeOfHalfEdge;  // per half-edge
};

EdgeTable buildEdgeTable(const std::vector<glm::uvec3>& triangles, size_t vertexCount) {
  const size_t halfEdgeCount = triangles.size() * 3;
  assert(halfEdgeCount < std::numeric_limits<uint32_t>::max());

  // Bucket offsets by lower end (counting sort).
  std::vector<uint32_t> offsets;
  reserveLarge(offsets, vertexCount + 1);
  offsets.resize(vertexCount + 1, 0);
  for (const glm::uvec3& t : triangles)
    for (int k = 0; k < 3; ++k) offsets[std::min(t[k], t[(k + 1) % 3]) + 1]++;
  for (size_t v = 0; v < vertexCount; ++v) offsets[v + 1] += offsets[v];

  // Each entry: higher end in the top 32 bits, half-edge id below, so sorting a bucket groups
  // equal edges and keeps their half-edges in order.
  std::vector<uint64_t> entries;
  reserveLarge(entries, halfEdgeCount);
  entries.resize(halfEdgeCount);
  std::vector<uint32_t> cursor;
  reserveLarge(cursor, vertexCount);
  cursor.assign(offsets.begin(), offsets.end() - 1);
  for (size_t t = 0; t < triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      uint32_t a = triangles[t][k], b = triangles[t][(k + 1) % 3];
      entries[cursor[std::min(a, b)]++] = (uint64_t(std::max(a, b)) << 32) | uint64_t(t * 3 + k);
    }
  }

  EdgeTable table;
  reserveLarge(table.edgeOfHalfEdge, halfEdgeCount);
  table.edgeOfHalfEdge.resize(halfEdgeCount);
  reserveLarge(table.lo, halfEdgeCount / 2 + 3);
  reserveLarge(table.hi, halfEdgeCount / 2 + 3);
  for (size_t v = 0; v < vertexCount; ++v) {
    auto first = entries.begin() + offsets[v], last = entries.begin() + offsets[v + 1];
    std::sort(first, last);
    uint32_t previousHi = std::numeric_limits<uint32_t>::max();  // never a higher end: lo < hi
    for (auto it = first; it != last; ++it) {
      uint32_t hi = uint32_t(*it >> 32);
      if (hi != previousHi) {
        table.lo.push_back(uint32_t(v));
        table.hi.push_back(hi);
        previousHi = hi;
      }
      table.edgeOfHalfEdge[uint32_t(*it)] = uint32_t(table.lo.size() - 1);
    }
  }
  return table;
}

SurfaceVertex vertexAt(const SurfaceMesh& m, uint32_t i) {
  return {m.mesh.positions[i], m.mesh.normals[i], m.surfaces[i], m.mesh.colors.empty() ? 0xFFFFFFFFu : m.mesh.colors[i]};
}

void appendMidpoints(SurfaceMesh& m, const EdgeTable& edges) {
  const size_t vertexCount = m.mesh.positions.size(), edgeCount = edges.lo.size();
  reserveLarge(m.mesh.positions, vertexCount + edgeCount);
  reserveLarge(m.mesh.normals, vertexCount + edgeCount);
  reserveLarge(m.surfaces, vertexCount + edgeCount);
  m.mesh.positions.resize(vertexCount + edgeCount);
  m.mesh.normals.resize(vertexCount + edgeCount);
  m.surfaces.resize(vertexCount + edgeCount);
  const bool colors = !m.mesh.colors.empty();
  if (colors) m.mesh.colors.resize(vertexCount + edgeCount);
  // Texture coordinates halfway; an edge's ends sample the same texture (a mesh part's vertices).
  const bool textured = !m.mesh.uvs.empty();
  if (textured) m.mesh.uvs.resize(vertexCount + edgeCount);
  if (textured) m.mesh.textureIds.resize(vertexCount + edgeCount);
  for (size_t e = 0; e < edgeCount; ++e) {
    SurfaceVertex mid = m.midpoint(vertexAt(m, edges.lo[e]), vertexAt(m, edges.hi[e]));
    m.mesh.positions[vertexCount + e] = mid.position;
    m.mesh.normals[vertexCount + e] = mid.normal;
    m.surfaces[vertexCount + e] = mid.surface;
    if (colors) m.mesh.colors[vertexCount + e] = mid.color;
    if (textured) m.mesh.uvs[vertexCount + e] = (m.mesh.uvs[edges.lo[e]] + m.mesh.uvs[edges.hi[e]]) * 0.5f;
    if (textured) m.mesh.textureIds[vertexCount + e] = m.mesh.textureIds[edges.lo[e]];
  }
}

void subdivideOnce(SurfaceMesh& m) {
  const uint32_t firstMidpoint = uint32_t(m.mesh.positions.size());
  EdgeTable edges = buildEdgeTable(m.mesh.triangles, m.mesh.positions.size());
  assert(size_t(firstMidpoint) + edges.lo.size() < std::numeric_limits<uint32_t>::max());
  appendMidpoints(m, edges);

  const std::vector<glm::uvec3>& old = m.mesh.triangles;
  std::vector<glm::uvec3> split;
  reserveLarge(split, old.size() * 4);
  split.resize(old.size() * 4);
  for (size_t t = 0; t < old.size(); ++t) {
    uint32_t a = old[t].x, b = old[t].y, c = old[t].z;
    uint32_t ab = firstMidpoint + edges.edgeOfHalfEdge[t * 3 + 0];
    uint32_t bc = firstMidpoint + edges.edgeOfHalfEdge[t * 3 + 1];
    uint32_t ca = firstMidpoint + edges.edgeOfHalfEdge[t * 3 + 2];
    split[t * 4 + 0] = {a, ab, ca};
    split[t * 4 + 1] = {ab, b, bc};
    split[t * 4 + 2] = {ca, bc, c};
    split[t * 4 + 3] = {ab, bc, ca};
  }
  m.mesh.triangles = std::move(split);
}

}  // namespace

void subdivide(SurfaceMesh& mesh, int levels) {
  assert(levels >= 0);
  assert(mesh.surfaces.size() == mesh.mesh.positions.size());
  assert(mesh.mesh.normals.size() == mesh.mesh.positions.size());
  for (int level = 0; level < levels; ++level) subdivideOnce(mesh);
}

}  // namespace phongvk
