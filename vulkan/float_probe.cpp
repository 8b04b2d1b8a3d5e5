// float_probe.cpp — probe_float.comp's inputs, its run and the comparison with the host.
#include "vulkan/float_probe.h"

#include "shaders/gpu_layout.h"
#include "shaders/probe_float.spv.h"
#include "vulkan/disk_cache.h"
#include "vulkan/pipelines.h"
#include "vulkan/resources.h"
#include "vulkan/submit.h"

#include <bit>
#include <cstdio>
#include <cmath>
#include <optional>
#include <random>
#include <string>

namespace phongvk {

namespace {

// sign * 1.mantissa * 2^exponent (exponent in the normal range).
float makeFloat(uint32_t mantissa, int exponent, bool negative = false) {
  const uint32_t bits = (negative ? 0x80000000u : 0u) | (uint32_t(exponent + 127) << 23) | (mantissa & 0x7FFFFFu);
  return std::bit_cast<float>(bits);
}

// Quotients and roots that approximate operations tend to get wrong or that need the corrected
// operations' scaling: results exactly representable, mantissas of all ones, tiny and huge operands.
const std::vector<std::pair<float, float>>& awkwardQuotients() {
  static const std::vector<std::pair<float, float>> quotients = {
      {1.0f, 3.0f}, {2.0f, 3.0f}, {1.0f, 10.0f}, {7.0f, 10.0f}, {-5.0f, 3.0f}, {355.0f, 113.0f},
      {1.0f, 49.0f}, {6.0f, 3.0f}, {1.0f, makeFloat(0x7FFFFF, 0)}, {makeFloat(0x7FFFFF, 0), 3.0f},
      {makeFloat(0x7FFFFF, 0), makeFloat(0x7FFFFE, 0)}, {makeFloat(0x400000, -100), 7.0f},
      {3.0f, makeFloat(0x266666, 100)}, {makeFloat(0x123456, -90), makeFloat(0x654321, 20)},
      {makeFloat(0x7FFFFF, 60), makeFloat(0x000001, -60)}};
  return quotients;
}

const std::vector<float>& awkwardRoots() {
  static const std::vector<float> roots = {2.0f, 3.0f, 5.0f, 10.0f, 0.5f, 4.0f, 9.0f, 1e-30f, 1e30f,
                                           makeFloat(0x7FFFFF, 0), makeFloat(0x7FFFFF, 1), makeFloat(0x59999A, -120),
                                           makeFloat(0x266666, 120), makeFloat(0, -126), makeFloat(0x7FFFFF, 127)};
  return roots;
}

// c for a probe: -(a b) rounded, so a fused fma returns the product's rounding error; 0 where that
// error would be subnormal (a device may flush it) or the product is huge.
float fmaAddend(float a, float b) {
  const float product = a * b;
  const float magnitude = std::fabs(product);
  return magnitude > 0x1p-80f && magnitude < 0x1p100f ? -product : 0.0f;
}

// A hashed operand: random mantissa and sign, exponent in [lo, hi].
float randomFloat(std::mt19937& random, int lo, int hi, bool allowNegative) {
  const uint32_t mantissa = uint32_t(random());
  const int exponent = lo + int(uint32_t(random()) % uint32_t(hi - lo + 1));
  const bool negative = allowNegative && (random() & 1u);
  return makeFloat(mantissa, exponent, negative);
}

// Random a and b whose quotient is a normal float: most within 2^+-60; every 16th a tiny
// dividend, every 16th + 1 a huge divisor (the corrected division's scaled paths).
std::pair<float, float> randomQuotient(std::mt19937& random, uint32_t i) {
  if (i % 16 == 0) return {randomFloat(random, -100, -61, true), randomFloat(random, -20, 20, true)};
  if (i % 16 == 1) return {randomFloat(random, -20, 20, true), randomFloat(random, 61, 100, true)};
  return {randomFloat(random, -60, 60, true), randomFloat(random, -60, 60, true)};
}

}  // namespace

std::vector<FloatProbeInput> floatProbeInputs(uint32_t randomProbes, uint32_t seed) {
  std::mt19937 random(seed);
  std::vector<FloatProbeInput> inputs;
  const auto& quotients = awkwardQuotients();
  const auto& roots = awkwardRoots();
  const size_t awkward = std::max(quotients.size(), roots.size());
  for (uint32_t i = 0; i < awkward + randomProbes; ++i) {
    const auto [a, b] = i < quotients.size() ? quotients[i] : randomQuotient(random, i);
    const float x = i < roots.size() ? roots[i] : randomFloat(random, -120, 120, false);
    inputs.push_back({a, b, fmaAddend(a, b), x});
  }
  return inputs;
}

FloatReport compareFloatProbe(const std::vector<FloatProbeInput>& inputs, const std::vector<uint32_t>& results) {
  FloatReport report;
  report.probes = uint32_t(inputs.size());
  for (size_t i = 0; i < inputs.size(); ++i) {
    const FloatProbeInput& p = inputs[i];
    const uint32_t* r = &results.at(i * gpu::FLOAT_PROBE_RESULTS);
    const uint32_t quotient = std::bit_cast<uint32_t>(p.a / p.b);
    const uint32_t root = std::bit_cast<uint32_t>(std::sqrt(p.x));
    report.divideOff += r[0] != quotient;
    report.sqrtOff += r[1] != root;
    report.fmaOff += r[2] != std::bit_cast<uint32_t>(std::fma(p.a, p.b, p.c));
    report.exactDivideOff += r[3] != quotient;
    report.exactSqrtOff += r[4] != root;
  }
  return report;
}

namespace {

// What the probe run holds, each freeing itself on every path (the arena before the pipeline
// before the buffers: the reverse of their order here).
struct ProbeRun {
  const VulkanContext& context;
  Buffer inputs, results;
  ComputePipeline pipeline;
  DescriptorArena arena;
};

}  // namespace

FloatReport probeFloatOps(const VulkanContext& context) {
  const std::vector<FloatProbeInput> inputs = floatProbeInputs();
  const uint32_t count = uint32_t(inputs.size());
  std::vector<uint32_t> results(size_t(count) * gpu::FLOAT_PROBE_RESULTS);
  ProbeRun run{context, {}, {}, {}, {}};
  createBuffer(run.inputs, context, count * sizeof(FloatProbeInput), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
               MemoryKind::HostVisible);
  uploadToBuffer(context, run.inputs, inputs.data(), count * sizeof(FloatProbeInput));
  createBuffer(run.results, context, results.size() * sizeof(uint32_t), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
               MemoryKind::HostVisible);
  const Binding bindings[] = {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}, {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}};
  run.pipeline = createComputePipeline(context, spirv_probe_float, sizeof(spirv_probe_float), bindings,
                                       sizeof(uint32_t), {});
  createDescriptorArena(run.arena, context, 1);
  const BufferDescriptor descriptors[] = {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, run.inputs.buffer},
                                          {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, run.results.buffer}};
  const VkDescriptorSet set = allocateDescriptorSet(context, run.arena, run.pipeline.setLayout, descriptors);

  VkCommandBuffer cmd = beginOneTimeCommands(context);
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, run.pipeline.pipeline);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, run.pipeline.layout, 0, 1, &set, 0, nullptr);
  vkCmdPushConstants(cmd, run.pipeline.layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(uint32_t), &count);
  vkCmdDispatch(cmd, groupCount(count, gpu::FLOAT_PROBE_GROUP_SIZE), 1, 1);
  submitAndWait(context, cmd);
  readFromBuffer(context, run.results, results.data(), results.size() * sizeof(uint32_t));
  return compareFloatProbe(inputs, results);
}

namespace {

const std::string USE_EXACT = "use exact: yes\n";
const std::string USE_NATIVE = "use exact: no\n";

// The probe's file for this device: named after the device, the driver and the probe itself, so
// a changed probe asks the device again.
std::string probeFileName(const VulkanContext& context) {
  const std::vector<FloatProbeInput> inputs = floatProbeInputs();
  uint64_t probe = fnv1a(spirv_probe_float, sizeof(spirv_probe_float));
  probe = fnv1a(inputs.data(), inputs.size() * sizeof(FloatProbeInput), probe);
  char hash[17];
  std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(probe));
  return "float-probe-" + deviceCacheKey(context) + "-" + hash + ".txt";
}

}  // namespace

bool useExactFloats(const VulkanContext& context, bool* cached) {
  const std::string name = probeFileName(context);
  if (const std::optional<std::vector<uint8_t>> saved = readCacheFile(name)) {
    const std::string text(saved->begin(), saved->end());
    if (text == USE_EXACT || text == USE_NATIVE) {
      if (cached) *cached = true;
      return text == USE_EXACT;
    }
  }
  const bool exact = probeFloatOps(context).useExact();
  const std::string& text = exact ? USE_EXACT : USE_NATIVE;
  writeCacheFile(name, std::vector<uint8_t>(text.begin(), text.end()));
  if (cached) *cached = false;
  return exact;
}

}  // namespace phongvk
