// pixel_shading.h — what flat and Phong shading light at a pixel (docs/DESIGN.md "Shading"): the
// surface point of the pixel's winning triangle, from the triangle's three vertices as the scene
// stores them. The caller lights it with phong.h (ambient, then each light in file order), as the
// shade pass lights a vertex for Gouraud shading. Shared by resolve_small.comp and the reference;
// see glsl_cpp.h for the dialect rules.
#ifndef PHONGVK_PIXEL_SHADING_H
#define PHONGVK_PIXEL_SHADING_H

#include "glsl_cpp.h"
#include "exact_float.h"
#include "shared.h"
#include "phong.h"
#include "vector_math.h"

SHARED_BEGIN

// A point to light: its position relative to the lighting origin, its unit normal (zero where
// none can be had: the lighting is then the ambient term alone) and its material (the colour C
// already times the vertex colours).
struct SurfacePoint {
  vec3 P;
  vec3 N;
  MaterialData m;
};

// x0 + b1 (x1 - x0) + b2 (x2 - x0), as Gouraud interpolates colours.
FN vec3 interpolate3(vec3 x0, vec3 x1, vec3 x2, vec2 b) {
  PRECISE vec3 x = x0 + b.x * (x1 - x0) + b.y * (x2 - x0);
  return x;
}

// Flat: the triangle's centroid, its face normal ((P1 - P0) x (P2 - P0), outward for the
// counter-clockwise front face) and the mean of its vertices' colours; the same at every pixel.
// `m` is the object's material, `lightOffset` its origin relative to the lighting origin.
FN SurfacePoint flatSurface(VertexIn a, VertexIn b, VertexIn c, vec3 lightOffset, MaterialData m) {
  vec3 P0 = lightingPosition(a.position, lightOffset);
  vec3 P1 = lightingPosition(b.position, lightOffset);
  vec3 P2 = lightingPosition(c.position, lightOffset);
  SurfacePoint s;
  PRECISE vec3 sum = P0 + P1 + P2;
  s.P = divide(sum, 3.0f);
  s.N = unitOrZero(cross3(P1 - P0, P2 - P0));
  s.m = m;
  PRECISE vec3 colors = vertexMaterial(m, a.color).color + vertexMaterial(m, b.color).color + vertexMaterial(m, c.color).color;
  s.m.color = divide(colors, 3.0f);
  return s;
}

// Flat for a point or a line (screen_quads.h: its quad half's first two corner vertices are its
// ends a and b): lit at the midpoint of its ends with the mean of their normals made unit, and the
// mean of their colours; a point (a = b) at itself, with its own normal and colour.
FN SurfacePoint flatQuadSurface(VertexIn a, VertexIn b, vec3 lightOffset, MaterialData m) {
  SurfacePoint s;
  PRECISE vec3 sum = lightingPosition(a.position, lightOffset) + lightingPosition(b.position, lightOffset);
  s.P = sum * 0.5f;
  PRECISE vec3 normals = a.normal + b.normal;
  s.N = unitOrZero(normals);
  s.m = m;
  PRECISE vec3 colors = vertexMaterial(m, a.color).color + vertexMaterial(m, b.color).color;
  s.m.color = colors * 0.5f;
  return s;
}

// Phong: position, normal and colour interpolated with the pixel's barycentrics `bary` (gouraud.h
// barycentrics: perspective-correct or linear in screen space, as the scene's interpolation says),
// and the normal normalized.
FN SurfacePoint phongSurface(VertexIn a, VertexIn b, VertexIn c, vec3 lightOffset, MaterialData m, vec2 bary) {
  SurfacePoint s;
  s.P = interpolate3(lightingPosition(a.position, lightOffset), lightingPosition(b.position, lightOffset),
                     lightingPosition(c.position, lightOffset), bary);
  s.N = unitOrZero(interpolate3(a.normal, b.normal, c.normal, bary));
  s.m = m;
  s.m.color = interpolate3(vertexMaterial(m, a.color).color, vertexMaterial(m, b.color).color,
                           vertexMaterial(m, c.color).color, bary);
  return s;
}

SHARED_END

#endif  // PHONGVK_PIXEL_SHADING_H
