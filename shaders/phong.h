// phong.h — per-vertex transform and Phong illumination (docs/DESIGN.md "Phong, per vertex").
// Shared by shade_vertices.comp and the C++ reference; see glsl_cpp.h for the dialect rules.
#ifndef PHONGVK_PHONG_H
#define PHONGVK_PHONG_H

#include "glsl_cpp.h"
#include "shared.h"
#include "exact_float.h"
#include "vector_math.h"

SHARED_BEGIN

// Homogeneous pixel-space position of a vertex: (focalX * x_view, -focalY * y_view, z_view).
// The view position is rotate(local) + viewOffset, where viewOffset = rotate(origin - eye) was
// computed in double on the host: far-away objects keep their float precision.
FN vec3 toHomogeneous(vec3 local, vec3 viewOffset, FrameData frame) {
  PRECISE vec3 view = vec3(dot3(vec3(frame.right), local), dot3(vec3(frame.up), local),
                           dot3(vec3(frame.forward), local)) + viewOffset;
  PRECISE vec3 h = vec3(frame.focalX * view.x, -frame.focalY * view.y, view.z);
  return h;
}

// Vertex colours are not clamped to [0, 1] (docs/DESIGN.md), but every factor and product is held
// below COLOR_MAX: a million times brighter than saturation (a channel shows 1 at most), and
// small enough that a product of two held values and a sum over many lights stay finite and that
// interpolating between a held vertex and a dark one keeps float precision (also in a graphics
// pipeline's varyings). So no valid input (a light 1e-20 m from a vertex with a = 0, intensities
// of 1e30) makes inf * 0 or inf - inf, i.e. NaN: such a vertex is just saturated. Ordinary
// values pass through unchanged: min(x, M) = x.
PHONGVK_CONST float COLOR_MAX = 1.0e6f;

FN float held(float x) { return min(x, COLOR_MAX); }
FN vec3 held3(vec3 v) { return min(v, vec3(COLOR_MAX)); }

// |v|. When |v|^2 falls below the smallest normal float, devices disagree: some keep the
// subnormal square, others flush it to 0 (and would call a light 1e-20 m away "at the vertex").
// Rescaling by the largest component first gives every device the same, exact-enough length.
FN float lightDistance(vec3 v) {
  PRECISE float dd = dot3(v, v);
  if (dd >= 1.17549435e-38f) return squareRoot(dd);
  PRECISE float m = max(abs(v.x), max(abs(v.y), abs(v.z)));
  if (m == 0.0f) return 0.0f;
  PRECISE vec3 u = divide(v, m);
  PRECISE float d = m * squareRoot(dot3(u, u));
  return d;
}

// x^n for x > 0 (up to a hair above 1) and n > 0, from additions, multiplications, one division
// and exponent bits only. GLSL's pow is exp2(n * log2(x)) with device-specific precision and
// C++'s powf is correctly rounded; they disagreed by one 8-bit level on a few pixels. This one
// gives the reference and every device the same bits (its one division is `divide`), accurate to
// about 2e-7.
FN float log2Positive(float x) {
  int bits = floatBitsToInt(x);
  int e = ((bits >> 23) & 255) - 127;
  PRECISE float m = intBitsToFloat((bits & 0x007FFFFF) | 0x3F800000);  // x = m 2^e, m in [1, 2)
  if (m > 1.41421356f) {
    m = m * 0.5f;
    e = e + 1;
  }
  // log2(m) = (2 / ln 2) (t + t^3/3 + t^5/5 + t^7/7 + t^9/9 + ...), t = (m - 1)/(m + 1), |t| <= 0.172
  PRECISE float t = divide(m - 1.0f, m + 1.0f);
  PRECISE float t2 = t * t;
  PRECISE float series =
      t * (2.88539008f + t2 * (0.961796694f + t2 * (0.577078016f + t2 * (0.412198583f + t2 * 0.320598898f))));
  PRECISE float result = float(e) + series;
  return result;
}

FN float exp2Small(float y) {  // y < 0.5; results below 2^-125 are 0 (never subnormal)
  if (y < -125.0f) return 0.0f;
  PRECISE float i = floor(y + 0.5f);
  PRECISE float f = y - i;  // in [-0.5, 0.5]: 2^f = e^(f ln 2), Taylor to degree 7
  PRECISE float p =
      1.0f + f * (0.693147181f +
                  f * (0.240226507f +
                       f * (0.0555041087f +
                            f * (0.00961812911f + f * (0.00133335581f + f * (0.000154035304f + f * 0.0000152527338f))))));
  PRECISE float result = p * intBitsToFloat((int(i) + 127) << 23);
  return result;
}

FN float powPositive(float x, float n) { return exp2Small(n * log2Positive(x)); }

// The specular highlight's base: the paper's r.V with r = 2(N.l)N - l, or with `blinn` N.h, h the
// unit half vector between l and V (0 where l + V is 0: the light exactly behind the eye's view).
FN float specularBase(vec3 N, vec3 l, vec3 V, float NdotL, bool blinn) {
  if (blinn) {
    PRECISE vec3 sum = l + V;
    PRECISE float len = squareRoot(dot3(sum, sum));
    PRECISE float NdotH = len > 0.0f ? divide(dot3(N, sum), len) : 0.0f;
    return NdotH;
  }
  PRECISE vec3 r = 2.0f * NdotL * N - l;
  PRECISE float rV = dot3(r, V);
  return rV;
}

// A spot light's cone at the unit direction l from P toward the light (glTF KHR_lights_punctual's
// fall-off): t = clamp(cd * scale + offset, 0, 1), cd the cosine between the spot's axis and the
// way from the light to P, and the factor t^2: 1 inside the inner cone, 0 outside the outer one.
// scale and offset are the light's, rounded once from double on the host.
FN float spotCone(LightData light, vec3 l) {
  PRECISE float cd = -dot3(light.spotAxis, l);
  PRECISE float t = min(max(cd * light.spotScale + light.spotOffset, 0.0f), 1.0f);
  PRECISE float cone = t * t;
  return cone;
}

// The inverse-square fall-off of a light at distance d > 0 (glTF KHR_lights_punctual's): 1 / d^2,
// with a range r > 0 times the window clamp(1 - (d/r)^4, 0, 1)^2. d^2 is held at least 1e-30, a
// normal float, so that a device that flushes subnormals computes the same.
FN float inverseSquare(LightData light, float d) {
  PRECISE float S = divide(1.0f, max(d * d, 1e-30f));
  if (light.range > 0.0f) {
    PRECISE float q = divide(d, light.range);
    PRECISE float q2 = q * q;
    PRECISE float w = min(max(1.0f - q2 * q2, 0.0f), 1.0f);
    PRECISE float windowed = S * (w * w);
    S = windowed;
  }
  return S;
}

// One light's diffuse + specular contribution at P (all positions relative to the lighting origin):
// S * I * (C o L) * (kd * max(N.l, 0) + ks * max(r.V, 0)^n), specular only where N.l > 0; with
// `blinn`, max(N.h, 0)^n instead of max(r.V, 0)^n (specularBase). A directional light has the
// same l at every P (its unit direction) and no fall-off: S = 1. A spot light's S is a point light's
// times its cone (spotCone); outside the outer cone it adds nothing. A light with `falloff` falls
// off with the inverse square of d (inverseSquare) instead of the material's attenuation.
// `specular` and `constantAttenuation` let a shader specialized to the scene skip work whose
// result is known: with ks = 0 the specular term adds exactly +0, and with b = c = 0 the
// attenuation 1 / (a + b d + c d^2) is exactly 1 / a. Either way the result is bit-identical to
// the general case (both flags true / false), which the reference uses.
FN vec3 phongLightWith(vec3 P, vec3 N, vec3 V, MaterialData m, LightData light, bool specular,
                       bool constantAttenuation, bool blinn) {
  bool directional = light.directional != 0.0f;
  PRECISE vec3 toLight = light.position - P;
  PRECISE float d = directional ? 1.0f : lightDistance(toLight);
  if (d == 0.0f) return vec3(0.0f);  // a light exactly at the vertex adds nothing
  PRECISE vec3 l = directional ? light.position : divide(toLight, d);
  PRECISE float NdotL = dot3(N, l);
  if (NdotL <= 0.0f) return vec3(0.0f);
  bool spot = (light.flags & LIGHT_SPOT) != 0u;
  PRECISE float cone = spot ? spotCone(light, l) : 1.0f;
  if (cone == 0.0f) return vec3(0.0f);
  PRECISE float S = held(directional ? 1.0f
                         : light.falloff != 0.0f ? inverseSquare(light, d)
                         : constantAttenuation
                             ? divide(1.0f, m.attenuation.x)
                             : divide(1.0f, m.attenuation.x + m.attenuation.y * d + m.attenuation.z * d * d));
  if (spot) S = held(S * cone);
  PRECISE float shade = held(m.kd * NdotL);
  if (specular) {
    PRECISE float rV = max(specularBase(N, l, V, NdotL, blinn), 0.0f);
    // max(r.V, 0)^n with n = 0 is 1; 0^n is 0 for n > 0.
    PRECISE float highlight = m.n == 0.0f ? 1.0f : (rV > 0.0f ? powPositive(rV, m.n) : 0.0f);
    shade = shade + held(m.ks * highlight);
  }
  PRECISE float weight = held(held(S * light.intensity) * shade);
  PRECISE vec3 lit = held3(weight * held3(m.color * light.color));
  return lit;
}

// The general case, the paper's specular model or (`blinn`) Blinn's.
FN vec3 phongLightModel(vec3 P, vec3 N, vec3 V, MaterialData m, LightData light, bool blinn) {
  return phongLightWith(P, N, V, m, light, true, false, blinn);
}

FN vec3 phongLight(vec3 P, vec3 N, vec3 V, MaterialData m, LightData light) {
  return phongLightModel(P, N, V, m, light, false);
}

// An RGBA8 colour's red, green and blue (red in the low byte; alpha unused) as c / 255, correctly
// rounded, so that white is exactly 1: a vertex's colour and a texel multiply C by this.
FN vec3 unitColor(uint color) {
  PRECISE vec3 c = vec3(divide(float(color & 255u), 255.0f), divide(float((color >> 8u) & 255u), 255.0f),
                        divide(float((color >> 16u) & 255u), 255.0f));
  return c;
}

// The material as a vertex sees it: C times the vertex's colour, so VERTEX_WHITE leaves C exactly
// as it is.
FN MaterialData vertexMaterial(MaterialData m, uint color) {
  m.color = m.color * unitColor(color);
  return m;
}

// ka * C * A: the ambient term every vertex gets.
FN vec3 phongAmbient(MaterialData m, vec3 ambient) {
  PRECISE vec3 a = held3(held3(m.ka * m.color) * ambient);
  return a;
}

// Whether normal N is zero: a point's or a line's vertex given none, drawn unlit (its colour C as it
// is: docs/DESIGN.md "Points and lines"), and where the normals of a line's ends cancel.
FN bool isUnlit(vec3 N) { return N.x == 0.0f && N.y == 0.0f && N.z == 0.0f; }

// v / |v|, or 0 for a zero vector.
FN vec3 unitOrZero(vec3 v) {
  PRECISE float len = squareRoot(dot3(v, v));
  PRECISE vec3 u = len > 0.0f ? divide(v, len) : vec3(0.0f);
  return u;
}

// Vertex `v` of `object` as every pass uses it: of an object placed by a pose (OBJECT_POSED), its
// position turned by the pose's linear part (still relative to the object's origin, now in world
// axes) and its normal by the inverse transpose, made unit again; of any other, as stored (its
// transform was applied when its mesh was built). The same float operations in every pass, on
// both renderers.
FN VertexIn posedVertex(VertexIn v, ObjectData object) {
  if ((object.flags & OBJECT_POSED) == 0u) return v;
  VertexIn p = v;
  PRECISE vec3 position = vec3(dot3(vec3(object.linear0), v.position), dot3(vec3(object.linear1), v.position),
                               dot3(vec3(object.linear2), v.position));
  PRECISE vec3 normal = vec3(dot3(vec3(object.normal0), v.normal), dot3(vec3(object.normal1), v.normal),
                             dot3(vec3(object.normal2), v.normal));
  p.position = position;
  p.normal = unitOrZero(normal);
  return p;
}

// A vertex's position relative to the lighting origin, in world axes. Lighting is computed in
// this frame, fixed per scene, so when only the camera moves and no material has a specular term
// the colours are bitwise the same and a sequence may skip recomputing them.
FN vec3 lightingPosition(vec3 local, vec3 lightOffset) {
  PRECISE vec3 P = local + lightOffset;
  return P;
}

// Unit vector from P towards the eye; zero when P is the eye itself.
FN vec3 toEye(vec3 P, vec3 eye) {
  PRECISE vec3 v = eye - P;
  PRECISE float len = squareRoot(dot3(v, v));
  PRECISE vec3 V = len > 0.0f ? divide(v, len) : vec3(0.0f);
  return V;
}

// The view vector V of the Phong model at P: toward the eye with a perspective camera; with an
// orthographic one every point is seen along the view axis, so V is -forward (the host's unit
// vector, rounded to float) everywhere.
FN vec3 viewVector(vec3 P, FrameData frame) {
  if (frame.projection == PROJECTION_ORTHOGRAPHIC) return -vec3(frame.forward);
  return toEye(P, frame.eye);
}

SHARED_END

#endif  // PHONGVK_PHONG_H
