// shadow_rays.h — whether a shading point sees a light (docs/DESIGN.md "Shadows"): a ray from the
// point toward the light, tested against the scene's triangles through the host's bounding volume
// hierarchy (prepare/shadow_bvh.h) with Woop, Benthin and Wald's watertight ray-triangle test, in
// the same float operations on both renderers. Shared by the shade pass, resolve_lit and the
// reference; see glsl_cpp.h for the dialect rules. A shader includes it after bindings.glsl, which
// defines bvhNode(scene, i) and shadowTriangle(scene, i) over its texel buffers (`scene` unused);
// the reference passes the ShadowGeometry it built.
#ifndef PHONGVK_SHADOW_RAYS_H
#define PHONGVK_SHADOW_RAYS_H

#include "glsl_cpp.h"
#include "exact_float.h"
#include "shared.h"
#include "vector_math.h"

#ifdef __cplusplus
#include <vector>
namespace phongvk::gpu {
// The tree and its triangles as the host built them and the device reads them.
struct ShadowGeometry {
  std::vector<BvhNode> nodes;
  std::vector<ShadowTriangle> triangles;
};
inline BvhNode bvhNode(const ShadowGeometry& s, uint32_t i) { return s.nodes[i]; }
inline ShadowTriangle shadowTriangle(const ShadowGeometry& s, uint32_t i) { return s.triangles[i]; }
}  // namespace phongvk::gpu
#define SHADOW_SCENE const ShadowGeometry&
#else
#define SHADOW_SCENE uint
#endif

SHARED_BEGIN

// Triangles a leaf holds at most (prepare/shadow_bvh.h).
PHONGVK_CONST uint BVH_LEAF_SIZE = 4;
// The deepest path a traversal keeps: the host's trees are at most 30 + log2(N / 4) + 2 levels
// deep, 62 for 2^32 triangles (prepare/shadow_bvh.h).
PHONGVK_CONST uint SHADOW_STACK = 64;
// A direction component smaller than this counts as 0 (and a ray whose largest one is, as none):
// a device that flushes subnormal floats to zero then computes what every other does.
PHONGVK_CONST float SHADOW_TINY = 1e-30f;
// No vertex: an unused place among a ray's owners.
PHONGVK_CONST uint SHADOW_NO_OWNER = 0xFFFFFFFFu;
// How much a box's far distance is widened before it is compared (Ize, "Robust BVH Ray
// Traversal", 2013: 1 + 2 gamma(3) covers the rounding of the slab distances).
PHONGVK_CONST float SHADOW_BOX_SLACK = 1.00000036f;

// A ray from `org` along `dir`: toward a point light dir = light - org and it reaches the light at
// t = 1 (a segment: hits at 0 < t < 1 block it); toward a directional light dir = l and every hit
// at t > 0 blocks it. A triangle with one of its owner vertices never blocks it: the point lies on
// them (a vertex on its own triangles; a pixel's point on its triangle, and maybe, after rounding,
// on a neighbour that shares an edge or a corner with it).
struct ShadowRay {
  vec3 org;
  vec3 dir;
  vec3 inv;        // 1 / dir per axis, 0 where the component counts as 0 (SHADOW_TINY)
  float sx;        // Woop's shear: dir[kx] / dir[kz], dir[ky] / dir[kz], 1 / dir[kz]
  float sy;
  float sz;
  uint kx;
  uint ky;
  uint kz;         // the axis along which dir is longest
  bool segment;
  uvec3 owners;    // vertex indices, SHADOW_NO_OWNER where unused
};

FN float component(vec3 v, uint k) { return k == 0u ? v.x : (k == 1u ? v.y : v.z); }

// A component of a shear factor or an inverse that would be subnormal, as 0 (SHADOW_TINY).
FN float unlessTiny(float x) { return abs(x) < SHADOW_TINY ? 0.0f : x; }

FN ShadowRay shadowRay(vec3 org, vec3 dir, bool segment, uvec3 owners) {
  ShadowRay r;
  r.org = org;
  r.dir = vec3(unlessTiny(dir.x), unlessTiny(dir.y), unlessTiny(dir.z));
  r.segment = segment;
  r.owners = owners;
  vec3 a = abs(r.dir);
  r.kz = a.x >= a.y ? (a.x >= a.z ? 0u : 2u) : (a.y >= a.z ? 1u : 2u);
  r.kx = r.kz == 2u ? 0u : r.kz + 1u;
  r.ky = r.kx == 2u ? 0u : r.kx + 1u;
  PRECISE float dz = component(r.dir, r.kz);
  r.sx = dz != 0.0f ? unlessTiny(divide(component(r.dir, r.kx), dz)) : 0.0f;
  r.sy = dz != 0.0f ? unlessTiny(divide(component(r.dir, r.ky), dz)) : 0.0f;
  r.sz = dz != 0.0f ? divide(1.0f, dz) : 0.0f;
  r.inv = vec3(r.dir.x != 0.0f ? divide(1.0f, r.dir.x) : 0.0f, r.dir.y != 0.0f ? divide(1.0f, r.dir.y) : 0.0f,
               r.dir.z != 0.0f ? divide(1.0f, r.dir.z) : 0.0f);
  return r;
}

// The distances along the ray between which it is within the slab [lo, hi] of one axis: where the
// ray moves along the axis, those of the slab's sides; where it does not (inv 0), every distance
// when the origin is within the slab, none when outside.
FN vec2 slabSpan(float o, float lo, float hi, float inv) {
  if (inv == 0.0f) return o >= lo && o <= hi ? vec2(-3.0e38f, 3.0e38f) : vec2(3.0e38f, -3.0e38f);
  PRECISE float t0 = (lo - o) * inv;
  PRECISE float t1 = (hi - o) * inv;
  return vec2(min(t0, t1), max(t0, t1));
}

// Whether the ray's span (0, 1) or (0, infinity) meets box [low, high]: the three slabs' spans
// overlap it.
FN bool rayMeetsBox(ShadowRay r, vec3 low, vec3 high) {
  vec2 x = slabSpan(r.org.x, low.x, high.x, r.inv.x);
  vec2 y = slabSpan(r.org.y, low.y, high.y, r.inv.y);
  vec2 z = slabSpan(r.org.z, low.z, high.z, r.inv.z);
  PRECISE float tNear = max(max(x.x, y.x), max(z.x, 0.0f));
  PRECISE float tFar = min(min(x.y, y.y), min(z.y, r.segment ? 1.0f : 3.0e38f));
  PRECISE float slack = tFar * SHADOW_BOX_SLACK;
  return tNear <= slack;
}

// Woop, Benthin and Wald's watertight test ("Watertight Ray/Triangle Intersection", JCGT 2013):
// the vertices relative to the origin, sheared so the ray runs along +kz, and the three edge
// functions U, V, W of the origin in that plane. An edge shared by two triangles gives each the
// same function with opposite signs (the products are the same floats), and 0 counts as inside
// both, so no ray slips between them. A hit counts at 0 < t (< 1 for a segment), compared as
// T and det without a division; a triangle seen edge-on (det = 0) is missed.
FN bool ownedBy(uint v, uvec3 owners) { return v == owners.x || v == owners.y || v == owners.z; }

FN bool rayHitsTriangle(ShadowRay r, ShadowTriangle t) {
  if (ownedBy(t.v0, r.owners) || ownedBy(t.v1, r.owners) || ownedBy(t.v2, r.owners)) return false;
  PRECISE vec3 A = t.a - r.org;
  PRECISE vec3 B = t.b - r.org;
  PRECISE vec3 C = t.c - r.org;
  PRECISE float az = component(A, r.kz), bz = component(B, r.kz), cz = component(C, r.kz);
  PRECISE float ax = component(A, r.kx) - r.sx * az;
  PRECISE float ay = component(A, r.ky) - r.sy * az;
  PRECISE float bx = component(B, r.kx) - r.sx * bz;
  PRECISE float by = component(B, r.ky) - r.sy * bz;
  PRECISE float cx = component(C, r.kx) - r.sx * cz;
  PRECISE float cy = component(C, r.ky) - r.sy * cz;
  PRECISE float U = cx * by - cy * bx;
  PRECISE float V = ax * cy - ay * cx;
  PRECISE float W = bx * ay - by * ax;
  if ((U < 0.0f || V < 0.0f || W < 0.0f) && (U > 0.0f || V > 0.0f || W > 0.0f)) return false;
  PRECISE float det = U + V + W;
  if (det == 0.0f) return false;
  PRECISE float T = U * (r.sz * az) + V * (r.sz * bz) + W * (r.sz * cz);
  if (det < 0.0f) {
    T = -T;
    det = -det;
  }
  return T > 0.0f && (!r.segment || T < det);
}

// Whether any triangle of the tree blocks the ray. The answer does not depend on the order the
// tree is walked in (any hit blocks), only on each test, which both renderers make alike.
FN bool shadowRayBlocked(SHADOW_SCENE scene, ShadowRay r) {
  if (r.sz == 0.0f) return false;  // no direction: the point is at the light
  uint stack[SHADOW_STACK];
  uint top = 0u;
  uint node = 0u;
  for (;;) {
    BvhNode n = bvhNode(scene, node);
    if (rayMeetsBox(r, n.low, n.high)) {
      if (n.count == 0u) {
        stack[top] = n.index;
        top = top + 1u;
        node = node + 1u;
        continue;
      }
      // Unrolled: on lavapipe every loop iteration counts against an invocation's budget.
      UNROLL for (uint k = 0u; k < BVH_LEAF_SIZE; ++k) {
        if (k < n.count && rayHitsTriangle(r, shadowTriangle(scene, n.index + k))) return true;
      }
    }
    if (top == 0u) return false;
    top = top - 1u;
    node = stack[top];
  }
  return false;
}

// Whether light `light` reaches P (lighting frame), a point of the triangles with a vertex among
// `owners` (a vertex's own index; a pixel's triangle's three): a light without LIGHT_SHADOWS always does.
FN bool lightReaches(SHADOW_SCENE scene, LightData light, vec3 P, uvec3 owners) {
  if ((light.flags & LIGHT_SHADOWS) == 0u) return true;
  bool directional = light.directional != 0.0f;
  PRECISE vec3 toLight = light.position - P;
  vec3 dir = directional ? light.position : toLight;
  return !shadowRayBlocked(scene, shadowRay(P, dir, !directional, owners));
}

// The owners of vertex i's point: the vertex alone.
FN uvec3 vertexOwners(uint i) { return uvec3(i, SHADOW_NO_OWNER, SHADOW_NO_OWNER); }

// A light's term `lit` at P as a renderer adds it: 0 where the light casts shadows and its ray is
// blocked. The ray is traced only where the term is not already 0.
FN vec3 shadowedTerm(SHADOW_SCENE scene, LightData light, vec3 lit, vec3 P, uvec3 owners) {
  if (lit == vec3(0.0f) || lightReaches(scene, light, P, owners)) return lit;
  return vec3(0.0f);
}

SHARED_END

#endif
