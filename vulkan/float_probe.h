// float_probe.h — does the device divide and take square roots exactly as the host does?
//
// The renderer's key and colour maths must give the reference's bits (docs/DESIGN.md "Visibility"), but
// Vulkan lets a device's division and sqrt be off by a few ulps (shaders/exact_float.h). Whoever
// builds a GPU renderer probes the device first: probe_float.comp runs a fixed set of inputs through
// the device's operations and through exact_float.h's corrected ones, and the host compares every
// result with its own IEEE one. The renderer then uses the corrected operations only where the
// device's own were off (FloatReport::useExact, GpuRendererOptions::exactFloats): lavapipe's are
// exact and pay nothing.
#pragma once

#include "vulkan/context.h"

#include <cstdint>
#include <vector>

namespace phongvk {

// What the device's float division and square root do: off = how many probes differed from the
// host's IEEE result.
struct FloatReport {
  uint32_t probes = 0;
  uint32_t divideOff = 0;       // the device's a / b
  uint32_t sqrtOff = 0;         // the device's sqrt(x)
  uint32_t fmaOff = 0;          // fma(a, b, c): off when it is not fused
  uint32_t exactDivideOff = 0;  // exact_float.h correctedQuotient of the device quotient
  uint32_t exactSqrtOff = 0;    // exact_float.h correctedRoot of the device root
  bool nativeExact() const { return divideOff == 0 && sqrtOff == 0; }
  bool correctionExact() const { return fmaOff == 0 && exactDivideOff == 0 && exactSqrtOff == 0; }
  // Whether the renderer takes its passes' `_exact` builds, which correct the device's operations:
  // only where they are off and the corrected ones are exact.
  bool useExact() const { return !nativeExact() && correctionExact(); }
};

// One probe: a / b, sqrt(x) and fma(a, b, c) (c = -(a b) rounded: fused gives the product's
// rounding error, unfused 0).
struct FloatProbeInput {
  float a, b, c, x;
};

// The fixed probes: ordinary and awkward quotients and roots (mantissas of all ones, exact
// results, ties, tiny and huge operands), then `randomProbes` random ones drawn from `seed`. Every
// result is a normal float. The defaults are what the device is probed with.
std::vector<FloatProbeInput> floatProbeInputs(uint32_t randomProbes = 4096, uint32_t seed = 20261122u);

// Compares the device's results (FLOAT_PROBE_RESULTS bit patterns per probe, in probe_float.comp's
// order) with the host's IEEE results.
FloatReport compareFloatProbe(const std::vector<FloatProbeInput>& inputs, const std::vector<uint32_t>& results);

// Runs probe_float.comp on the context's device and compares.
FloatReport probeFloatOps(const VulkanContext& context);

// FloatReport::useExact for the context's device: from the disk cache (vulkan/disk_cache.h) when
// the same probe (its shader and inputs) ran on this device and driver before, else probed now
// and the answer saved. `cached` (if given) says which.
bool useExactFloats(const VulkanContext& context, bool* cached = nullptr);

}  // namespace phongvk
