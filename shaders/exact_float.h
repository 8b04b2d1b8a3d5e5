// exact_float.h — correctly rounded division and square root on every device.
//
// The reference's float `/` and sqrt are IEEE: correctly rounded. Vulkan lets a device's be off by
// a few ulps (OpFDiv 2.5 ulp; sqrt is built from inversesqrt), and real GPUs use that freedom
// (NVIDIA's division is a reciprocal and a multiply). A depth one ulp off breaks the equal-depth
// tie-break and the key equality with the reference (docs/DESIGN.md "Visibility"), and a snapped vertex
// one ulp off can move coverage. So the shared maths divides with `divide` and takes roots with
// `squareRoot`:
//   - C++: the plain IEEE operations;
//   - GLSL: the device's own operations, or, in the passes' `_exact` builds (EXACT_FLOAT_OPS, see
//     CMakeLists.txt), the device's result corrected to the correctly rounded one with fused
//     multiply-adds (correctedQuotient, correctedRoot). The host takes the `_exact` builds only
//     where the probe (vulkan/float_probe.h) found the device's operations off and the corrected
//     ones exact (which needs a fused fma: lavapipe's is not; its operations are exact).
// The corrections are written once, in the common subset, so the C++ tests check them too.
#ifndef PHONGVK_EXACT_FLOAT_H
#define PHONGVK_EXACT_FLOAT_H

#include "glsl_cpp.h"
#include "shared.h"

SHARED_BEGIN

// 2^e for a normal result (-126 <= e <= 127): GLSL has no hexadecimal float literals.
FN float pow2(int e) { return intBitsToFloat((e + 127) << 23); }

// The float next to q (finite, not zero), above it when `up`, else below.
FN float nextFloat(float q, bool up) { return intBitsToFloat(floatBitsToInt(q) + ((q > 0.0f) == up ? 1 : -1)); }

// a / b correctly rounded, from q = the device's a / b (within a few ulps) and a fused fma: a
// Newton step from the exact residual a - b q brings q within an ulp; then q or its neighbour
// towards the true quotient, whichever leaves the smaller residual (the even one on a tie).
// Scaling by powers of two keeps the residuals normal (a device may flush subnormals).
FN float correctedQuotient(float a, float b, float q) {
  if (q == 0.0f || isinf(q) || isnan(q)) return q;
  PRECISE float scale = 1.0f;
  if (abs(a) < pow2(-60)) {
    a = a * pow2(64);
    q = q * pow2(64);
    scale = pow2(-64);
  }
  if (abs(b) > pow2(60)) {
    b = b * pow2(-64);
    q = q * pow2(64);
    scale = scale * pow2(-64);
  }
  PRECISE float y = 1.0f / b;
  PRECISE float r = fma(-b, q, a);
  q = fma(r, y, q);
  r = fma(-b, q, a);
  if (r != 0.0f) {
    PRECISE float q1 = nextFloat(q, (r > 0.0f) == (b > 0.0f));  // a / b = q + r / b
    PRECISE float r1 = fma(-b, q1, a);
    if (abs(r1) < abs(r) || (abs(r1) == abs(r) && (floatBitsToInt(q1) & 1) == 0)) q = q1;
  }
  PRECISE float result = q * scale;
  return result;
}

// sqrt(x) correctly rounded, from s = the device's sqrt(x) (within a few ulps) and a fused fma. A
// Newton step brings s within an ulp; s is then right when x lies between the squares of the
// midpoints to its neighbours: with the exact residual r = x - s^2, -s u_below < r <= s u_above
// (x on its float grid makes the u^2 / 4 terms drop out).
FN float correctedRoot(float x, float s) {
  if (!(x > 0.0f) || isinf(x)) return s;
  PRECISE float scale = 1.0f;
  if (x < pow2(-60)) {  // keeps the residual (about s ulp(s)) normal
    x = x * pow2(64);
    s = s * pow2(32);
    scale = pow2(-32);
  }
  PRECISE float r = fma(-s, s, x);
  s = fma(r, 0.5f / s, s);
  r = fma(-s, s, x);
  if (r > 0.0f) {
    PRECISE float above = nextFloat(s, true);
    if (r > s * (above - s)) s = above;
  } else if (r < 0.0f) {
    PRECISE float below = nextFloat(s, false);
    if (r <= -(s * (s - below))) s = below;
  }
  PRECISE float result = s * scale;
  return result;
}

SHARED_END

#ifdef __cplusplus

SHARED_BEGIN
FN float divide(float a, float b) { return a / b; }
FN vec3 divide(vec3 v, float d) { return v / d; }
FN float squareRoot(float x) { return std::sqrt(x); }
SHARED_END

#else

#ifndef EXACT_FLOAT_OPS
#define EXACT_FLOAT_OPS 0
#endif
#if EXACT_FLOAT_OPS
float divide(float a, float b) { return correctedQuotient(a, b, a / b); }
vec3 divide(vec3 v, float d) {
  return vec3(correctedQuotient(v.x, d, v.x / d), correctedQuotient(v.y, d, v.y / d), correctedQuotient(v.z, d, v.z / d));
}
float squareRoot(float x) { return correctedRoot(x, sqrt(x)); }
#else
float divide(float a, float b) { return a / b; }
vec3 divide(vec3 v, float d) { return v / d; }
float squareRoot(float x) { return sqrt(x); }
#endif

#endif

#endif  // PHONGVK_EXACT_FLOAT_H
