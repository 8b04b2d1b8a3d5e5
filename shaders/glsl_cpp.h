// glsl_cpp.h — lets one maths header compile as GLSL and as C++ (GLM).
//
// phong.h, edges.h and the other shared maths headers are written once, in the common subset of
// the two languages, and included by the compute shaders and by the C++ reference. Both renderers therefore evaluate the same
// float operations in the same order; `PRECISE` forbids FMA contraction in GLSL and the C++ side is
// built with -ffp-contract=off. Rules for code in those headers:
//   - float literals carry an `f` suffix (a bare 0.5 is a double in C++ and would promote);
//   - dot/cross products are spelled out (dot3, cross3) so the association order is fixed;
//   - functions are declared with FN; out/inout parameters with OUT/INOUT and OUT_ARRAY/INOUT_ARRAY;
//   - a loop the shader must not keep as a loop is marked UNROLL (UNROLL_KEYS64: only on the 64-bit
//     key path's builds; UNROLL_TEXELS: only on the builds that read texel buffers).
#ifndef PHONGVK_GLSL_CPP_H
#define PHONGVK_GLSL_CPP_H

#ifdef __cplusplus
#include <bit>
#include <cmath>
#include <cstdint>
#include <glm/glm.hpp>
#include <glm/gtc/type_precision.hpp>
#define FN inline
#define PRECISE
#define OUT(T) T&
#define INOUT(T) T&
#define OUT_ARRAY(T, name, n) T (&name)[n]
#define INOUT_ARRAY(T, name, n) T (&name)[n]
#define UNROLL
#define DONT_UNROLL
#define UNROLL_KEYS64
#define UNROLL_TEXELS
#define SHARED_BEGIN namespace phongvk::gpu {
#define SHARED_END }
namespace phongvk::gpu {
using glm::abs;
using glm::clamp;
using glm::floor;
using glm::max;
using glm::min;
using glm::sqrt;
using std::fma;
using std::isinf;
using std::isnan;
using ivec2 = glm::ivec2;
using ivec4 = glm::ivec4;
using i64vec2 = glm::i64vec2;
inline uint32_t floatBitsToUint(float f) { return std::bit_cast<uint32_t>(f); }
inline int32_t floatBitsToInt(float f) { return std::bit_cast<int32_t>(f); }
inline float intBitsToFloat(int32_t i) { return std::bit_cast<float>(i); }
// GLSL's extended integer built-ins (glm's usubBorrow returns y - x where x < y: not GLSL's).
inline uint32_t uaddCarry(uint32_t x, uint32_t y, uint32_t& carry) {
  carry = uint32_t(x + y < x);
  return x + y;
}
inline uint32_t usubBorrow(uint32_t x, uint32_t y, uint32_t& borrow) {
  borrow = uint32_t(x < y);
  return x - y;
}
inline void imulExtended(int32_t x, int32_t y, int32_t& msb, int32_t& lsb) {
  const int64_t product = int64_t(x) * int64_t(y);
  msb = int32_t(product >> 32);
  lsb = int32_t(uint32_t(uint64_t(product)));
}
}  // namespace phongvk::gpu
#else
#extension GL_EXT_control_flow_attributes : require
#define FN
#define UNROLL [[unroll]]
#define DONT_UNROLL [[dont_unroll]]
// UNROLL on the 64-bit key path's builds, a loop on the 32-bit path's (PHONGVK_KEYS32): SwiftShader's
// shader compiler took 269 s for the unrolled large-triangle resolve and 22 s for the clip pass, under
// a second each as loops (docs/DECISIONS.md, "The 32-bit key path").
#ifdef PHONGVK_KEYS32
#define UNROLL_KEYS64 DONT_UNROLL
#else
#define UNROLL_KEYS64 UNROLL
#endif
// UNROLL on the builds that read the scene's arrays from texel buffers, a loop on the storage-array
// builds (PHONGVK_STORAGE_ARRAYS, the _k32s ones SwiftShader takes): SwiftShader's compiler took
// 35 to 42 s for the clip pass with the clipper's Sutherland-Hodgman step unrolled, 0.3 s with it
// a loop, while lavapipe, given the loop, keeps the polygon in memory and takes seconds to generate
// the pass (docs/DECISIONS.md, "The 32-bit key path").
#ifdef PHONGVK_STORAGE_ARRAYS
#define UNROLL_TEXELS DONT_UNROLL
#else
#define UNROLL_TEXELS UNROLL
#endif
#define PRECISE precise
#define OUT(T) out T
#define INOUT(T) inout T
#define OUT_ARRAY(T, name, n) out T name[n]
#define INOUT_ARRAY(T, name, n) inout T name[n]
#define SHARED_BEGIN
#define SHARED_END
#endif

#endif  // PHONGVK_GLSL_CPP_H
