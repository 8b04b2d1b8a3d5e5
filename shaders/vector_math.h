// vector_math.h — dot and cross products spelled out, so that GLSL and C++ associate them the same
// way (glsl_cpp.h: the shared maths is written once for both).
#ifndef PHONGVK_VECTOR_MATH_H
#define PHONGVK_VECTOR_MATH_H

#include "glsl_cpp.h"
#include "shared.h"

SHARED_BEGIN

FN float dot3(vec3 a, vec3 b) {
  PRECISE float r = a.x * b.x + a.y * b.y + a.z * b.z;
  return r;
}

FN vec3 cross3(vec3 a, vec3 b) {
  PRECISE vec3 r = vec3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
  return r;
}

SHARED_END

#endif  // PHONGVK_VECTOR_MATH_H
