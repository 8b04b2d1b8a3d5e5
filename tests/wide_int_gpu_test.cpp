// The GLSL side of shaders/wide_int.h on the device the tests run on (selftest_wide_int.comp, which
// uses no 64-bit type): the edge functions, sums, floors of a 256th and values held to a uint's
// range it gives in two words are int64_t's, over the whole range of snapped coordinates. Its module declares no Int64 capability, and its context asks
// for no 64-bit feature, so it runs on a device without shaderInt64: CTest runs it on SwiftShader
// too (tests/CMakeLists.txt, label swiftshader).
#include "shaders/edges.h"
#include "shaders/spirv_words.h"
#include "test_util.h"
#include "vulkan/context.h"
#include "vulkan/pipelines.h"
#include "vulkan/resources.h"
#include "vulkan/submit.h"

#include <cstdint>  // the generated SPIR-V header uses uint32_t without including it
#include "shaders/selftest_wide_int.spv.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <random>
#include <span>
#include <string>
#include <vector>

namespace phongvk {
namespace {

TEST(WideIntGpu, EdgeFunctionsAndSumsAreInt64s) {
  // Points within +-2^28 (the snapped range), its corners among them.
  const int edge = 1 << 28;
  std::vector<glm::ivec2> points = {{edge, -edge}, {-edge, edge}, {edge, edge}, {0, 0}, {1, -1}, {-edge, -edge}};
  std::mt19937 random(46);
  std::uniform_int_distribution<int> any(-edge, edge);
  while (points.size() < 3 * 4096) points.push_back({any(random), any(random)});
  const uint32_t cases = uint32_t(points.size() / 3);

  VulkanContext context = createContext({.deviceIndex = -1, .validate = true});
  // PHONGVK_TEST_DEVICE (tests/CMakeLists.txt's SwiftShader entry): the device the run must be on.
  if (const char* expected = std::getenv("PHONGVK_TEST_DEVICE")) {
    EXPECT_NE(context.info.name.find(expected), std::string::npos) << "ran on " << context.info.name;
  }
  {
    const Binding bindings[] = {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}, {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}};
    ComputePipeline pipeline = createComputePipeline(context, spirv_selftest_wide_int, sizeof(spirv_selftest_wide_int),
                                                     bindings, sizeof(uint32_t), {});
    Buffer inputs, results;
    createBuffer(inputs, context, points.size() * sizeof(glm::ivec2), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryKind::DeviceLocal);
    createBuffer(results, context, 4 * cases * sizeof(glm::uvec2), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryKind::DeviceLocal);
    uploadToBuffer(context, inputs, points.data(), points.size() * sizeof(glm::ivec2));
    DescriptorArena arena;
    createDescriptorArena(arena, context, 1);
    const BufferDescriptor descriptors[] = {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, inputs.buffer},
                                            {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, results.buffer}};
    VkDescriptorSet set = allocateDescriptorSet(context, arena, pipeline.setLayout, descriptors);
    VkCommandBuffer cmd = beginOneTimeCommands(context);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.pipeline);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.layout, 0, 1, &set, 0, nullptr);
    vkCmdPushConstants(cmd, pipeline.layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(uint32_t), &cases);
    vkCmdDispatch(cmd, (cases + 63) / 64, 1, 1);
    submitAndWait(context, cmd);
    std::vector<glm::uvec2> words(4 * cases);
    readFromBuffer(context, results, words.data(), words.size() * sizeof(glm::uvec2));
    const auto value = [](glm::uvec2 w) { return int64_t((uint64_t(w.y) << 32) | w.x); };
    const auto clamped = [](int64_t v) { return uint32_t(std::clamp<int64_t>(v, 0, 0xFFFFFFFFll)); };
    for (uint32_t i = 0; i < cases; ++i) {
      const glm::ivec2 a = points[3 * i], b = points[3 * i + 1], p = points[3 * i + 2];
      const int64_t want = gpu::edgeFunction(glm::i64vec2(a), glm::i64vec2(b), glm::i64vec2(p));
      ASSERT_EQ(value(words[4 * i]), want) << "case " << i;
      ASSERT_EQ(value(words[4 * i + 1]), want + a.x) << "case " << i;
      ASSERT_EQ(value(words[4 * i + 2]), want >> 8) << "case " << i;  // arithmetic: toward minus infinity
      ASSERT_EQ(words[4 * i + 3].x, clamped(want >> 8)) << "case " << i;
      ASSERT_EQ(words[4 * i + 3].y, clamped(int64_t(a.x) + b.y)) << "case " << i;
    }
    destroyDescriptorArena(arena, context);
    destroyBuffer(inputs, context);
    destroyBuffer(results, context);
    destroyComputePipeline(pipeline, context);
  }
  const size_t messages = context.validation->count();
  destroyContext(context);
  EXPECT_EQ(messages, 0u);
}

// The module asks for no 64-bit integer capability (SPIR-V Int64 is capability 11, Int64Atomics 12).
TEST(WideIntGpu, TheModuleNeedsNo64BitIntegers) {
  std::vector<uint32_t> capabilities;
  const std::string error = spirv::forEachInstruction(
      std::span<const uint32_t>(spirv_selftest_wide_int, sizeof(spirv_selftest_wide_int) / sizeof(uint32_t)),
      [&](size_t, uint32_t opcode, std::span<const uint32_t> words) {
        if (opcode == 17) capabilities.push_back(words[1]);  // OpCapability
      });
  ASSERT_EQ(error, "");
  EXPECT_FALSE(capabilities.empty());
  EXPECT_EQ(std::count(capabilities.begin(), capabilities.end(), 11u), 0);
  EXPECT_EQ(std::count(capabilities.begin(), capabilities.end(), 12u), 0);
}

}  // namespace
}  // namespace phongvk
