// subdivide.h — 1 -> 4 triangle subdivision with shared edge midpoints, placed by a rule that
// knows the true surface (sphere, cylinder side, ...): curved primitives get rounder, not just
// denser.
#pragma once

#include "geometry/mesh.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <functional>
#include <vector>

namespace phongvk {

// One vertex as a midpoint rule sees it. `surface` is a small tag whose meaning belongs to the code
// that built the mesh (the cylinder's: side, cap, cap rim); flat meshes leave it 0.
struct SurfaceVertex {
  glm::vec3 position{0.0f};
  glm::vec3 normal{0.0f, 0.0f, 1.0f};
  uint8_t surface = 0;
  uint32_t color = 0xFFFFFFFFu;  // RGBA8 (Mesh::colors), white where the mesh has none
};

// Places the new vertex on edge (a, b). It must be symmetric, bit for bit (rule(a, b) equals
// rule(b, a)), and depend only on what it is given: two edges at the same place (a cube's edge
// seen from its two faces, a cylinder's rim seen from the cap and from the side) then get the
// same midpoint and the subdivided surface has no cracks. Write (a + b) * 0.5f, never
// a + (b - a) * 0.5f.
using MidpointRule = std::function<SurfaceVertex(const SurfaceVertex& a, const SurfaceVertex& b)>;

// The rule for planar faces and imported meshes: the plain midpoint; the normal is kept where both
// ends agree (a flat face stays exactly flat-shaded) and averaged otherwise. Keeps a shared tag;
// colours are averaged per channel, rounded up.
SurfaceVertex flatMidpoint(const SurfaceVertex& a, const SurfaceVertex& b);

// A mesh with what subdivision needs to keep new vertices on the true surface.
struct SurfaceMesh {
  Mesh mesh;
  std::vector<uint8_t> surfaces;  // one tag per vertex (see SurfaceVertex::surface)
  MidpointRule midpoint = flatMidpoint;
};

// Splits every triangle into four, `levels` times: triangle (a, b, c) with edge midpoints
// ab, bc, ca becomes (a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca) — same winding, and
// triangle t's children are 4t .. 4t+3. An edge shared by index gets one midpoint; new vertices
// follow the old ones, ordered by edge (lower index, then higher). Linear time, no hashing
// (docs/PERFORMANCE.md, "Mesh loading").
void subdivide(SurfaceMesh& mesh, int levels);

}  // namespace phongvk
