// wide_int.h — exact signed 64-bit integers held in two 32-bit words, for the arithmetic a device
// without 64-bit integers (no shaderInt64: SwiftShader, many mobile GPUs, MoltenVK on older Macs)
// still has to do exactly: the edge functions' products and sums. Every operation is the one a
// 64-bit integer gives, bit for bit, as long as the true result fits in 64 bits (for the edge
// functions of snapped coordinates it fits in 59); tests/wide_int_test.cpp checks it against
// int64_t, and the GPU self-test (selftest_wide_int.comp) checks the GLSL against the same.
// Shared by GLSL and C++ (glsl_cpp.h).
#ifndef PHONGVK_WIDE_INT_H
#define PHONGVK_WIDE_INT_H

#include "glsl_cpp.h"
#include "shared.h"

SHARED_BEGIN

// Two's complement: the value is int(hi) * 2^32 + lo. The high word is kept as a uint so that the
// carries wrap as the hardware's do in both languages (a signed overflow is undefined in C++).
struct Wide {
  uint lo;
  uint hi;
};

FN Wide wideOf(int v) {
  Wide w;
  w.lo = uint(v);
  w.hi = v < 0 ? 0xFFFFFFFFu : 0u;
  return w;
}

FN Wide wideAdd(Wide a, Wide b) {
  uint carry;
  Wide r;
  r.lo = uaddCarry(a.lo, b.lo, carry);
  r.hi = a.hi + b.hi + carry;
  return r;
}

FN Wide wideSub(Wide a, Wide b) {
  uint borrow;
  Wide r;
  r.lo = usubBorrow(a.lo, b.lo, borrow);
  r.hi = a.hi - b.hi - borrow;
  return r;
}

// The exact product of two ints (imulExtended: the full 64 bits of a signed 32 x 32 multiply).
FN Wide wideProduct(int a, int b) {
  int high;
  int low;
  imulExtended(a, b, high, low);
  Wide r;
  r.lo = uint(low);
  r.hi = uint(high);
  return r;
}

FN bool wideNegative(Wide a) { return int(a.hi) < 0; }

FN bool wideIsZero(Wide a) { return a.lo == 0u && a.hi == 0u; }

// -1, 0 or 1 as the value is negative, zero or positive.
FN int wideSign(Wide a) { return wideNegative(a) ? -1 : (wideIsZero(a) ? 0 : 1); }

FN bool wideLess(Wide a, Wide b) { return int(a.hi) < int(b.hi) || (a.hi == b.hi && a.lo < b.lo); }

FN Wide wideNegate(Wide a) { return wideSub(wideOf(0), a); }

// floor(a / 256): an arithmetic shift right by 8 across the words.
FN Wide wideFloorDiv256(Wide a) {
  Wide r;
  r.lo = (a.lo >> 8) | (a.hi << 24);
  r.hi = uint(int(a.hi) >> 8);
  return r;
}

// The value held to [0, 2^32 - 1], as a uint.
FN uint wideClampToUint(Wide a) { return wideNegative(a) ? 0u : (a.hi != 0u ? 0xFFFFFFFFu : a.lo); }

// The value as a float, near enough for an estimate that exact integer steps then correct (not
// rounded as a conversion of the 64-bit integer would be).
FN float wideEstimate(Wide a) { return float(int(a.hi)) * 4294967296.0f + float(a.lo); }

// n / d rounded toward zero (C++'s and GLSL's integer division), for d != 0 and a quotient that fits
// an int: estimated in float, then made exact with integer products (no 64-bit division).
FN int wideQuotient(Wide n, int d) {
  bool negative = wideNegative(n) != (d < 0);
  Wide m = wideNegative(n) ? wideNegate(n) : n;
  int divisor = d < 0 ? -d : d;
  float estimate = min(floor(wideEstimate(m) / float(divisor)), 2147483520.0f);
  int q = int(estimate);
  Wide rest = wideSub(m, wideProduct(q, divisor));  // off by a few thousand divisors at most
  q += int(floor(wideEstimate(rest) / float(divisor)));
  rest = wideSub(m, wideProduct(q, divisor));
  while (wideNegative(rest)) {
    --q;
    rest = wideAdd(rest, wideOf(divisor));
  }
  while (!wideLess(rest, wideOf(divisor))) {
    ++q;
    rest = wideSub(rest, wideOf(divisor));
  }
  return negative ? -q : q;
}

// The edge function of edges.h (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x), exactly, for
// points whose differences fit an int (snapped coordinates are below 2^28 in magnitude).
FN Wide wideEdgeFunction(ivec2 a, ivec2 b, ivec2 p) {
  return wideSub(wideProduct(b.x - a.x, p.y - a.y), wideProduct(b.y - a.y, p.x - a.x));
}

SHARED_END

#endif  // PHONGVK_WIDE_INT_H
