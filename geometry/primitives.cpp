// primitives.cpp — see primitives.h. Positions and normals are computed in double and stored as
// float; a position that two parts share (a cube corner, a cylinder rim vertex) is computed once
// and copied, so the copies are bit-identical.
#include "geometry/primitives.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cassert>
#include <cmath>

namespace phongvk {
namespace {

// Surface tags of the cylinder and the cone (SurfaceVertex::surface).
constexpr uint8_t kFlat = 0;  // a cap's interior: midpoints stay in the plane
constexpr uint8_t kSide = 1;  // the curved side: midpoints go onto the surface
constexpr uint8_t kRim = 2;  // a cap's rim: midpoints go onto the rim circle, exactly as the side's

uint32_t addVertex(SurfaceMesh& m, glm::vec3 position, glm::dvec3 normal, uint8_t surface = kFlat) {
  m.mesh.positions.push_back(position);
  m.mesh.normals.push_back(glm::vec3(glm::normalize(normal)));
  m.surfaces.push_back(surface);
  return uint32_t(m.mesh.positions.size() - 1);
}

double angle(int j, int segments) { return glm::two_pi<double>() * j / segments; }

// ---- sphere ----

SurfaceVertex sphereMidpoint(const SurfaceVertex& a, const SurfaceVertex& b, double radius) {
  glm::dvec3 direction = glm::normalize(glm::dvec3(a.position) + glm::dvec3(b.position));
  return {glm::vec3(direction * radius), glm::vec3(direction), a.surface};
}

MidpointRule sphereRule(double radius) {
  return [radius](const SurfaceVertex& a, const SurfaceVertex& b) {
    return sphereMidpoint(a, b, radius);
  };
}

// ---- cylinder and cone: midpoints on the side and on the rims ----

// `m` moved in xy (z kept) to distance `rho` from the axis; `direction` gets the unit xy direction.
// Side and cap both call this on the same (a + b) * 0.5f, so a rim midpoint is the same bits.
glm::vec3 toRadius(glm::vec3 m, double rho, glm::dvec2& direction) {
  glm::dvec2 xy(m.x, m.y);
  double length = glm::length(xy);
  direction = length > 0.0 ? xy / length : glm::dvec2(1.0, 0.0);
  return {float(direction.x * rho), float(direction.y * rho), m.z};
}

// The cone's radius at height z (apex at +height/2, base radius `radius` at -height/2).
double coneRadiusAt(double z, double radius, double height) {
  return std::max(0.0, radius * (height * 0.5 - z) / height);
}

glm::dvec3 coneNormal(glm::dvec2 direction, double radius, double height) {
  return glm::normalize(glm::dvec3(height * direction.x, height * direction.y, radius));
}

// The rule shared by cylinder and cone: `onSide` places a side midpoint and returns its normal.
template <typename OnSide>
SurfaceVertex roundMidpoint(const SurfaceVertex& a, const SurfaceVertex& b, OnSide onSide) {
  SurfaceVertex mid = flatMidpoint(a, b);  // position (a + b) * 0.5f, normal and tag where flat
  if (a.surface == kSide && b.surface == kSide) {
    mid.normal = glm::vec3(onSide(mid.position));
  } else if (a.surface == kRim && b.surface == kRim) {
    onSide(mid.position);  // the cap keeps its flat normal (and flatMidpoint kept kRim)
  }
  return mid;
}

MidpointRule cylinderRule(double radius) {
  return [radius](const SurfaceVertex& a, const SurfaceVertex& b) {
    return roundMidpoint(a, b, [radius](glm::vec3& p) {
      glm::dvec2 direction;
      p = toRadius(p, radius, direction);
      return glm::dvec3(direction, 0.0);
    });
  };
}

MidpointRule coneRule(double radius, double height) {
  return [radius, height](const SurfaceVertex& a, const SurfaceVertex& b) {
    return roundMidpoint(a, b, [radius, height](glm::vec3& p) {
      glm::dvec2 direction;
      p = toRadius(p, coneRadiusAt(p.z, radius, height), direction);
      return coneNormal(direction, radius, height);
    });
  };
}

// A cap: centre + fan over `rim` (positions shared with the side), normal +z or -z.
void addCap(SurfaceMesh& m, const std::vector<glm::vec3>& rim, float z, bool up) {
  const glm::dvec3 normal(0.0, 0.0, up ? 1.0 : -1.0);
  const uint32_t centre = addVertex(m, glm::vec3(0.0f, 0.0f, z), normal);
  const uint32_t first = uint32_t(m.mesh.positions.size());
  for (const glm::vec3& p : rim) addVertex(m, p, normal, kRim);
  const uint32_t n = uint32_t(rim.size());
  for (uint32_t j = 0; j < n; ++j) {
    uint32_t a = first + j, b = first + (j + 1) % n;
    // Seen from +z the rim runs counter-clockwise, so the top fans (c, a, b), the bottom (c, b, a).
    m.mesh.triangles.push_back(up ? glm::uvec3(centre, a, b) : glm::uvec3(centre, b, a));
  }
}

// Quads between two rings of `segments` vertices starting at `lower` and `upper` (upper is nearer
// +z), wound counter-clockwise seen from outside.
void addBand(SurfaceMesh& m, uint32_t lower, uint32_t upper, uint32_t segments) {
  for (uint32_t j = 0; j < segments; ++j) {
    uint32_t next = (j + 1) % segments;
    m.mesh.triangles.push_back({lower + j, lower + next, upper + next});
    m.mesh.triangles.push_back({lower + j, upper + next, upper + j});
  }
}

}  // namespace

SurfaceMesh makeCube(double size) {
  assert(size > 0.0);
  struct Face {
    glm::dvec3 normal, u, v;  // cross(u, v) == normal, so corners in (u, v) order wind outward
  };
  static const Face kFaces[6] = {
      {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
      {{0, 1, 0}, {0, 0, 1}, {1, 0, 0}}, {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
      {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}}, {{0, 0, -1}, {0, 1, 0}, {1, 0, 0}},
  };
  static const double kCorners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  const double half = size * 0.5;
  SurfaceMesh m;  // flat rule
  for (const Face& face : kFaces) {
    const uint32_t first = uint32_t(m.mesh.positions.size());
    for (const auto& c : kCorners)
      addVertex(m, glm::vec3(half * (face.normal + c[0] * face.u + c[1] * face.v)), face.normal);
    m.mesh.triangles.push_back({first, first + 1, first + 2});
    m.mesh.triangles.push_back({first, first + 2, first + 3});
  }
  return m;
}

SurfaceMesh makeUvSphere(double radius, int segments) {
  assert(radius > 0.0 && segments >= 3);
  const int bands = std::max(2, segments / 2);
  const uint32_t s = uint32_t(segments);
  SurfaceMesh m;
  m.midpoint = sphereRule(radius);
  const uint32_t north = addVertex(m, glm::vec3(0.0f, 0.0f, float(radius)), {0, 0, 1});
  for (int i = 1; i < bands; ++i) {  // rings from north to south
    const double theta = glm::pi<double>() * i / bands;
    for (int j = 0; j < segments; ++j) {
      const double phi = angle(j, segments);
      glm::dvec3 direction(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                           std::cos(theta));
      addVertex(m, glm::vec3(direction * radius), direction);
    }
  }
  const uint32_t south = addVertex(m, glm::vec3(0.0f, 0.0f, float(-radius)), {0, 0, -1});
  auto ring = [s](int i) { return 1 + uint32_t(i - 1) * s; };  // first vertex of ring i
  for (uint32_t j = 0; j < s; ++j)
    m.mesh.triangles.push_back({north, ring(1) + j, ring(1) + (j + 1) % s});
  for (int i = 1; i + 1 < bands; ++i) addBand(m, ring(i + 1), ring(i), s);
  for (uint32_t j = 0; j < s; ++j)
    m.mesh.triangles.push_back({south, ring(bands - 1) + (j + 1) % s, ring(bands - 1) + j});
  return m;
}

SurfaceMesh makeIcosphere(double radius) {
  assert(radius > 0.0);
  // The corners of three orthogonal golden rectangles (t is the golden ratio).
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  static const int kTriangles[20][3] = {
      {0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
      {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
      {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1},
  };
  const glm::dvec3 corners[12] = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                                  {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                                  {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  SurfaceMesh m;
  m.midpoint = sphereRule(radius);
  for (const glm::dvec3& c : corners) addVertex(m, glm::vec3(glm::normalize(c) * radius), c);
  for (const auto& tri : kTriangles) m.mesh.triangles.push_back(glm::uvec3(tri[0], tri[1], tri[2]));
  return m;
}

SurfaceMesh makeCylinder(double radius, double height, int segments) {
  assert(radius > 0.0 && height > 0.0 && segments >= 3);
  const uint32_t s = uint32_t(segments);
  const float top = float(height * 0.5), bottom = float(-height * 0.5);
  std::vector<glm::vec3> bottomRim, topRim;
  for (int j = 0; j < segments; ++j) {
    const double phi = angle(j, segments);
    const float x = float(radius * std::cos(phi)), y = float(radius * std::sin(phi));
    bottomRim.push_back({x, y, bottom});
    topRim.push_back({x, y, top});
  }
  SurfaceMesh m;
  m.midpoint = cylinderRule(radius);
  for (const auto* rim : {&bottomRim, &topRim})
    for (int j = 0; j < segments; ++j) {
      const double phi = angle(j, segments);
      addVertex(m, (*rim)[j], {std::cos(phi), std::sin(phi), 0.0}, kSide);
    }
  addBand(m, 0, s, s);
  addCap(m, topRim, top, true);
  addCap(m, bottomRim, bottom, false);
  return m;
}

SurfaceMesh makeCone(double radius, double height, int segments, int rings) {
  assert(radius > 0.0 && height > 0.0 && segments >= 3 && rings >= 1);
  const uint32_t s = uint32_t(segments);
  SurfaceMesh m;
  m.midpoint = coneRule(radius, height);
  std::vector<glm::vec3> baseRim;
  for (int i = 0; i < rings; ++i) {  // ring 0 is the base rim; the apex is ring `rings`
    const double rho = radius * (rings - i) / rings, z = -height * 0.5 + height * i / rings;
    for (int j = 0; j < segments; ++j) {
      const double phi = angle(j, segments);
      const glm::dvec2 direction(std::cos(phi), std::sin(phi));
      const glm::vec3 p(float(rho * direction.x), float(rho * direction.y), float(z));
      if (i == 0) baseRim.push_back(p);
      addVertex(m, p, coneNormal(direction, radius, height), kSide);
    }
  }
  for (int i = 0; i + 1 < rings; ++i) addBand(m, uint32_t(i) * s, uint32_t(i + 1) * s, s);
  const uint32_t lastRing = uint32_t(rings - 1) * s;
  const glm::vec3 apex(0.0f, 0.0f, float(height * 0.5));
  for (uint32_t j = 0; j < s; ++j) {
    const double mid = glm::pi<double>() * (2 * j + 1) / segments;  // this segment's mid-angle
    const uint32_t copy =
        addVertex(m, apex, coneNormal({std::cos(mid), std::sin(mid)}, radius, height), kSide);
    m.mesh.triangles.push_back({lastRing + j, lastRing + (j + 1) % s, copy});
  }
  addCap(m, baseRim, float(-height * 0.5), false);
  return m;
}

}  // namespace phongvk
