// The 64-bit integers in two 32-bit words (shaders/wide_int.h) against int64_t: every operation
// gives int64_t's bits, at the extremes of the edge functions' range and on random values.
#include "shaders/edges.h"
#include "shaders/wide_int.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

namespace phongvk::gpu {
namespace {

int64_t valueOf(Wide w) { return int64_t((uint64_t(w.hi) << 32) | w.lo); }

Wide wideOf64(int64_t v) {
  Wide w;
  w.lo = uint32_t(uint64_t(v));
  w.hi = uint32_t(uint64_t(v) >> 32);
  return w;
}

// Snapped coordinates lie within +-2^28 (shared.h GUARD_BAND): the corners of that range, zero,
// one either side of it, and random values in it.
std::vector<int> snappedValues() {
  const int edge = 1 << 28;
  std::vector<int> values = {0, 1, -1, 2, -2, edge - 1, -(edge - 1), edge, -edge, 65535, -65536, 12345678};
  std::mt19937 random(46);
  std::uniform_int_distribution<int> any(-edge, edge);
  for (int i = 0; i < 200; ++i) values.push_back(any(random));
  return values;
}

TEST(WideInt, ProductsOfIntsAreExact) {
  const int extremes[] = {0, 1, -1, std::numeric_limits<int>::max(), std::numeric_limits<int>::min(), 1 << 29, -(1 << 29)};
  for (int a : extremes)
    for (int b : extremes) EXPECT_EQ(valueOf(wideProduct(a, b)), int64_t(a) * int64_t(b)) << a << " x " << b;
  const std::vector<int> values = snappedValues();
  for (int a : values)
    for (int b : values) ASSERT_EQ(valueOf(wideProduct(a, b)), int64_t(a) * int64_t(b)) << a << " x " << b;
}

TEST(WideInt, SumsDifferencesAndComparisonsCarryAcrossTheWords) {
  std::vector<int64_t> values = {0, 1, -1, 0xFFFFFFFFll, 0x100000000ll, -0x100000000ll, -0xFFFFFFFFll,
                                 int64_t(1) << 58, -(int64_t(1) << 58), (int64_t(1) << 58) - 1};
  std::mt19937_64 random(46);
  for (int i = 0; i < 300; ++i) values.push_back(int64_t(random()) >> 5);  // within +-2^58
  for (int64_t a : values) {
    EXPECT_EQ(wideNegative(wideOf64(a)), a < 0);
    EXPECT_EQ(wideSign(wideOf64(a)), (a > 0) - (a < 0));
    for (int64_t b : values) {
      ASSERT_EQ(valueOf(wideAdd(wideOf64(a), wideOf64(b))), a + b) << a << " + " << b;
      ASSERT_EQ(valueOf(wideSub(wideOf64(a), wideOf64(b))), a - b) << a << " - " << b;
      ASSERT_EQ(wideLess(wideOf64(a), wideOf64(b)), a < b) << a << " < " << b;
    }
  }
  for (int v : {0, 1, -1, std::numeric_limits<int>::max(), std::numeric_limits<int>::min()}) {
    EXPECT_EQ(valueOf(wideOf(v)), int64_t(v));
  }
}

TEST(WideInt, FloorsOfA256thClampsAndEstimates) {
  std::vector<int64_t> values = {0, 1, -1, 255, 256, -255, -256, -257, 0xFFFFFFFFll, 0x100000000ll, -0x100000000ll,
                                 int64_t(1) << 58, -(int64_t(1) << 58), (int64_t(1) << 58) - 1};
  std::mt19937_64 random(47);
  for (int i = 0; i < 2000; ++i) values.push_back(int64_t(random()) >> (5 + i % 30));
  for (int64_t v : values) {
    ASSERT_EQ(valueOf(wideFloorDiv256(wideOf64(v))), v >> 8) << v;  // toward minus infinity
    ASSERT_EQ(wideClampToUint(wideOf64(v)), uint32_t(std::clamp<int64_t>(v, 0, 0xFFFFFFFFll))) << v;
    // large_triangles.h EdgeEstimate counts on the estimate being within 2^9 + 2^-22 |v|.
    const double error = std::abs(double(wideEstimate(wideOf64(v))) - double(v));
    ASSERT_LE(error, 512.0 + std::ldexp(std::abs(double(v)), -22)) << v;
  }
}

// The edge function in two words equals edges.h's int64 one over the whole snapped range.
TEST(WideInt, EdgeFunctionMatchesTheInt64One) {
  const std::vector<int> v = snappedValues();
  const auto point = [&](size_t k) { return ivec2(v[k % v.size()], v[(k * 7 + 3) % v.size()]); };
  for (size_t k = 0; k < 20000; ++k) {
    const ivec2 a = point(k), b = point(k * 13 + 5), p = point(k * 31 + 11);
    ASSERT_EQ(valueOf(wideEdgeFunction(a, b, p)), edgeFunction(i64vec2(a), i64vec2(b), i64vec2(p)));
  }
}

}  // namespace
}  // namespace phongvk::gpu
