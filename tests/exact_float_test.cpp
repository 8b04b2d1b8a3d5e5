// Correctly rounded division and square root (shaders/exact_float.h) and the comparison of the
// float probe (vulkan/float_probe.h), on the host alone: the corrections are shared maths, so their
// C++ build is checked here: from any starting value a few ulps off (what a GPU's division or sqrt
// may return), they must give the IEEE result. The probe's comparison is checked with planted
// differences. The device's own probe is exact_float_gpu_test's.
#include "compute/gpu_renderer.h"
#include "phongvk/compare.h"
#include "prepare/scene_data.h"
#include "reference/render_reference.h"
#include "scene/camera.h"
#include "scene/scene.h"
#include "shaders/exact_float.h"
#include "test_util.h"
#include "vulkan/context.h"
#include "vulkan/float_probe.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>

namespace phongvk {
namespace {

// v moved k ulps (away from zero for k > 0).
float ulpsAway(float v, int k) { return std::bit_cast<float>(std::bit_cast<int32_t>(v) + k); }

uint32_t bits(float v) { return std::bit_cast<uint32_t>(v); }

// The probe's awkward inputs and a million random ones (another seed than the device's probe).
std::vector<FloatProbeInput> manyInputs() { return floatProbeInputs(1000000, 7u); }

TEST(ExactFloat, CorrectedQuotientIsTheIeeeQuotientFromUpToThreeUlpsOff) {
  size_t wrong = 0;
  for (const FloatProbeInput& p : manyInputs()) {
    const float q = p.a / p.b;
    for (int k = -3; k <= 3; ++k) {
      const float corrected = gpu::correctedQuotient(p.a, p.b, ulpsAway(q, k));
      if (bits(corrected) != bits(q) && wrong++ < 5) {
        ADD_FAILURE() << p.a << " / " << p.b << " from " << k << " ulps: " << corrected << " instead of " << q;
      }
    }
  }
  EXPECT_EQ(wrong, 0u);
}

TEST(ExactFloat, CorrectedRootIsTheIeeeRootFromUpToThreeUlpsOff) {
  size_t wrong = 0;
  for (const FloatProbeInput& p : manyInputs()) {
    const float s = std::sqrt(p.x);
    for (int k = -3; k <= 3; ++k) {
      const float corrected = gpu::correctedRoot(p.x, ulpsAway(s, k));
      if (bits(corrected) != bits(s) && wrong++ < 5) {
        ADD_FAILURE() << "sqrt " << p.x << " from " << k << " ulps: " << corrected << " instead of " << s;
      }
    }
  }
  EXPECT_EQ(wrong, 0u);
}

TEST(ExactFloat, SpecialValuesPassThrough) {
  EXPECT_EQ(gpu::correctedQuotient(0.0f, 3.0f, 0.0f), 0.0f);
  EXPECT_TRUE(std::isinf(gpu::correctedQuotient(1.0f, 0.0f, INFINITY)));
  EXPECT_TRUE(std::isnan(gpu::correctedQuotient(0.0f, 0.0f, NAN)));
  EXPECT_EQ(gpu::correctedRoot(0.0f, 0.0f), 0.0f);
  EXPECT_TRUE(std::isinf(gpu::correctedRoot(INFINITY, INFINITY)));
}

// The host's own IEEE results, laid out as probe_float.comp writes them.
std::vector<uint32_t> hostResults(const std::vector<FloatProbeInput>& inputs) {
  std::vector<uint32_t> results;
  for (const FloatProbeInput& p : inputs) {
    const uint32_t q = bits(p.a / p.b), s = bits(std::sqrt(p.x));
    results.insert(results.end(), {q, s, bits(std::fma(p.a, p.b, p.c)), q, s});
  }
  return results;
}

TEST(FloatProbe, InputsHaveNormalQuotientsRootsAndFusedResidues) {
  const std::vector<FloatProbeInput> inputs = floatProbeInputs();
  ASSERT_GT(inputs.size(), 4000u);
  size_t fusedDiffers = 0;
  for (const FloatProbeInput& p : inputs) {
    EXPECT_TRUE(std::isnormal(p.a / p.b)) << p.a << " / " << p.b;
    EXPECT_TRUE(std::isnormal(std::sqrt(p.x))) << p.x;
    fusedDiffers += std::fma(p.a, p.b, p.c) != (p.a * p.b + p.c);  // -ffp-contract=off: two roundings
  }
  EXPECT_GT(fusedDiffers, inputs.size() / 2);  // so an unfused fma shows
}

TEST(FloatProbe, CountsEveryDifferenceInItsOwnColumn) {
  const std::vector<FloatProbeInput> inputs = floatProbeInputs();
  std::vector<uint32_t> results = hostResults(inputs);
  FloatReport same = compareFloatProbe(inputs, results);
  EXPECT_EQ(same.probes, inputs.size());
  EXPECT_TRUE(same.nativeExact());
  EXPECT_TRUE(same.correctionExact());
  EXPECT_FALSE(same.useExact());

  const size_t n = gpu::FLOAT_PROBE_RESULTS;
  results[0] ^= 1u;              // probe 0's quotient one ulp off
  results[1 * n + 1] ^= 1u;      // probe 1's root
  results[2 * n + 1] ^= 1u;      // probe 2's root
  results[3 * n + 2] ^= 1u;      // probe 3's fma
  FloatReport off = compareFloatProbe(inputs, results);
  EXPECT_EQ(off.divideOff, 1u);
  EXPECT_EQ(off.sqrtOff, 2u);
  EXPECT_EQ(off.fmaOff, 1u);
  EXPECT_EQ(off.exactDivideOff, 0u);
  EXPECT_EQ(off.exactSqrtOff, 0u);
  EXPECT_FALSE(off.useExact());  // the fma is not fused, so the corrections cannot be trusted

  results[3 * n + 2] ^= 1u;
  EXPECT_TRUE(compareFloatProbe(inputs, results).useExact());  // off, but correctable
  results[4 * n + 3] ^= 1u;
  EXPECT_EQ(compareFloatProbe(inputs, results).exactDivideOff, 1u);
  EXPECT_FALSE(compareFloatProbe(inputs, results).useExact());
}

}  // namespace
}  // namespace phongvk
