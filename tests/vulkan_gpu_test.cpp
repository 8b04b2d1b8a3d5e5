// vulkan_gpu_test.cpp — the Vulkan foundation: context, device choice, buffers, pipelines,
// 64-bit atomics, timestamps. Every test runs with validation on and fails on any message.
#include "vulkan/context.h"
#include "vulkan/pipelines.h"
#include "vulkan/resources.h"
#include "vulkan/submit.h"
#include "vulkan/vk_check.h"

#include <cstdint>  // the generated SPIR-V header uses uint32_t without including it
#include "shaders/selftest_atomic64.spv.h"

#include "tests/test_util.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace phongvk {
namespace {

// A context with validation on, for every test that needs a device.
VulkanContext createTestContext() { return createContext({.deviceIndex = -1, .validate = true}); }

// One validated context per test. TearDown destroys it first and checks the log afterwards, so
// objects a test forgot to destroy (reported by the layer at vkDestroyDevice) fail the test too.
class VulkanTest : public ::testing::Test {
 protected:
  void SetUp() override {
    context = createTestContext();
    log = context.validation;
    ASSERT_NE(log, nullptr);
  }

  void TearDown() override {
    destroyContext(context);
    if (log) {  // null when SetUp failed
      EXPECT_EQ(log->count(), 0u) << "validation messages:\n" << joinedMessages();
    }
  }

  std::string joinedMessages() const {
    std::string text;
    for (const std::string& message : log->messages()) text += message + "\n";
    return text;
  }

  VulkanContext context;
  std::shared_ptr<ValidationLog> log;
};

// Fills `count` bytes with a pattern whose every byte depends on its position.
std::vector<uint8_t> pattern(size_t count, uint8_t seed) {
  std::vector<uint8_t> bytes(count);
  for (size_t i = 0; i < count; ++i) bytes[i] = static_cast<uint8_t>(i * 31 + seed);
  return bytes;
}

TEST_F(VulkanTest, ContextHasASuitableDeviceWithComputeQueue) {
  EXPECT_TRUE(context.info.suitable);
  EXPECT_TRUE(context.info.missing.empty());
  EXPECT_FALSE(context.info.name.empty());
  EXPECT_NE(context.device, VK_NULL_HANDLE);
  EXPECT_NE(context.queue, VK_NULL_HANDLE);
  EXPECT_NE(context.commandPool, VK_NULL_HANDLE);
  EXPECT_NE(context.messenger, VK_NULL_HANDLE);  // validation was asked for
  EXPECT_GE(context.properties.apiVersion, VK_API_VERSION_1_2);
}

TEST_F(VulkanTest, ListDevicesMarksTheChosenDeviceUsable) {
  std::vector<DeviceInfo> devices = listDevices();  // a second instance while the context lives
  ASSERT_LT(context.info.index, devices.size());
  const DeviceInfo& chosen = devices[context.info.index];
  EXPECT_TRUE(chosen.suitable);
  EXPECT_EQ(chosen.name, context.info.name);

  std::string text = formatDeviceList(devices);
  std::string line = "[" + std::to_string(chosen.index) + "] " + chosen.name + " \u2014 " + chosen.type + ", Vulkan " +
                     chosen.apiVersion + " \u2014 usable \u2014 keys: " + keyPathWords(chosen) + "\n";
  EXPECT_NE(text.find(line), std::string::npos) << text;

  // The context still works after listDevices loaded (and destroyed) its own instance.
  VkCommandBuffer cmd = beginOneTimeCommands(context);
  submitAndWait(context, cmd);
}

TEST_F(VulkanTest, OutOfRangeDeviceIndexIsNamedInTheError) {
  std::string message = test::thrownMessage<NoDeviceError>([] { createContext({.deviceIndex = 99, .validate = true}); });
  EXPECT_NE(message.find("Vulkan device index 99 is out of range"), std::string::npos) << message;
  EXPECT_NE(message.find("usable"), std::string::npos) << "the message lists the devices: " << message;
}

TEST_F(VulkanTest, HostVisibleBufferRoundTripsAndIsMapped) {
  Buffer buffer;
  createBuffer(buffer, context, 1000, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryKind::HostVisible);
  EXPECT_NE(buffer.mapped, nullptr);
  EXPECT_EQ(buffer.size, 1000u);

  std::vector<uint8_t> data = pattern(1000, 7), back(1000);
  uploadToBuffer(context, buffer, data.data(), data.size());
  readFromBuffer(context, buffer, back.data(), back.size());
  EXPECT_EQ(back, data);
  destroyBuffer(buffer, context);
  EXPECT_EQ(buffer.buffer, VK_NULL_HANDLE);
}

// DeviceLocal is never mapped, so this exercises both staging copies even on lavapipe.
TEST_F(VulkanTest, DeviceLocalBufferRoundTripsThroughStaging) {
  Buffer buffer;
  createBuffer(buffer, context, 4099, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryKind::DeviceLocal);
  EXPECT_EQ(buffer.mapped, nullptr);
  EXPECT_EQ(buffer.size, 4100u);  // rounded up to a multiple of 4

  std::vector<uint8_t> data = pattern(4099, 3), back(4099);
  uploadToBuffer(context, buffer, data.data(), 4000);
  uploadToBuffer(context, buffer, data.data() + 4000, 99, 4000);  // at an offset
  readFromBuffer(context, buffer, back.data(), back.size());
  EXPECT_EQ(back, data);

  EXPECT_THROW(uploadToBuffer(context, buffer, data.data(), 8, 4096), RangeError);
  destroyBuffer(buffer, context);
}

// Copies larger than the 64 MiB staging buffer go through in parts: every part lands at its place,
// from an offset too, and reads back whole.
TEST_F(VulkanTest, CopiesLargerThanTheStagingBufferGoInParts) {
  const size_t bytes = (size_t(64) << 20) * 2 + 1000, offset = 12;
  Buffer buffer;
  createBuffer(buffer, context, offset + bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryKind::DeviceLocal);
  std::vector<uint8_t> data(bytes), back(offset + bytes);
  for (size_t i = 0; i < bytes; ++i) data[i] = uint8_t(i * 31 + (i >> 26) * 101);  // differs from 64 MiB on
  uploadToBuffer(context, buffer, data.data(), bytes, offset);
  uploadToBuffer(context, buffer, data.data(), offset);
  readFromBuffer(context, buffer, back.data(), back.size());
  EXPECT_TRUE(std::equal(data.begin(), data.begin() + offset, back.begin()));
  EXPECT_TRUE(std::equal(data.begin(), data.end(), back.begin() + offset));
  destroyBuffer(buffer, context);
}

TEST_F(VulkanTest, ZeroSizeBufferIsValidAndZeroByteCopiesDoNothing) {
  Buffer buffer;
  createBuffer(buffer, context, 0, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryKind::DeviceLocal);
  EXPECT_EQ(buffer.size, 4u);  // Vulkan forbids size 0
  uploadToBuffer(context, buffer, nullptr, 0);
  readFromBuffer(context, buffer, nullptr, 0);
  destroyBuffer(buffer, context);
  destroyBuffer(buffer, context);  // twice: safe on an empty Buffer
}

TEST_F(VulkanTest, DeviceBytesCountsLiveBuffers) {
  VkDeviceSize before = deviceBytes(context);
  Buffer a, b;
  createBuffer(a, context, 1 << 20, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryKind::DeviceLocal);
  createBuffer(b, context, 1 << 10, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryKind::HostVisible);
  EXPECT_GE(deviceBytes(context), before + (1 << 20) + (1 << 10));
  EXPECT_GE(peakDeviceBytes(context), deviceBytes(context));
  destroyBuffer(a, context);
  destroyBuffer(b, context);
  EXPECT_EQ(deviceBytes(context), before);
}

// Records the selftest dispatch (keys in binding 0, `invocations` threads).
void recordAtomicMin(VkCommandBuffer cmd, const ComputePipeline& pipeline, VkDescriptorSet set, uint32_t invocations) {
  vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.pipeline);
  vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline.layout, 0, 1, &set, 0, nullptr);
  vkCmdPushConstants(cmd, pipeline.layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(uint32_t), &invocations);
  vkCmdDispatch(cmd, groupCount(invocations, 64), 1, 1);
}

uint32_t lowbias32(uint32_t x) {  // the shader's hash
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

// What selftest_atomic64.comp must leave in each slot.
std::vector<uint64_t> expectedMinima(uint32_t invocations, uint32_t slots) {
  std::vector<uint64_t> minima(slots, UINT64_MAX);
  for (uint32_t i = 0; i < invocations; ++i) {
    uint64_t key = (uint64_t(lowbias32(i) & 0xff000000u) << 32) | i;
    minima[i % slots] = std::min(minima[i % slots], key);
  }
  return minima;
}

TEST_F(VulkanTest, Atomic64MinIsExactIncludingTiesAndTheTopBit) {
  constexpr uint32_t kInvocations = 100000, kSlots = 7;
  std::vector<uint64_t> expected = expectedMinima(kInvocations, kSlots);
  // The test is only as strong as its data: a winner that is not its slot's first invocation
  // means a race or a last-writer-wins bug would show. (Dozens of invocations per slot share the
  // winning depth 0, so the low word decides; the keys with bit 63 set catch a signed compare.)
  auto notFirstOfSlot = [](uint64_t key) { return (key & 0xffffffffu) >= kSlots; };
  EXPECT_TRUE(std::any_of(expected.begin(), expected.end(), notFirstOfSlot));

  const Binding bindings[] = {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}};
  const SpecConstant specs[] = {{gpu::SPEC_SELFTEST_SLOTS, kSlots}};
  ComputePipeline pipeline = createComputePipeline(context, spirv_selftest_atomic64, sizeof(spirv_selftest_atomic64),
                                                   bindings, sizeof(uint32_t), specs);
  Buffer keys;
  createBuffer(keys, context, kSlots * sizeof(uint64_t), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryKind::DeviceLocal);
  std::vector<uint64_t> initial(kSlots, UINT64_MAX);
  uploadToBuffer(context, keys, initial.data(), kSlots * sizeof(uint64_t));

  DescriptorArena arena;
  createDescriptorArena(arena, context, 1);
  const BufferDescriptor descriptors[] = {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, keys.buffer}};
  VkDescriptorSet set = allocateDescriptorSet(context, arena, pipeline.setLayout, descriptors);

  VkCommandBuffer cmd = beginOneTimeCommands(context);
  recordAtomicMin(cmd, pipeline, set, kInvocations);
  submitAndWait(context, cmd);

  std::vector<uint64_t> result(kSlots);
  readFromBuffer(context, keys, result.data(), kSlots * sizeof(uint64_t));
  EXPECT_EQ(result, expected);

  destroyDescriptorArena(arena, context);
  destroyBuffer(keys, context);
  destroyComputePipeline(pipeline, context);
}

// Synchronization validation is what catches a renderer pass that forgot a barrier; prove it is on
// by clearing the keys and running the atomicMin pass without transferToComputeBarrier between.
TEST(ValidationLog, MissingBarrierIsReportedAsASyncHazard) {
  VulkanContext context = createTestContext();
  std::shared_ptr<ValidationLog> log = context.validation;
  const Binding bindings[] = {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}};
  ComputePipeline pipeline = createComputePipeline(context, spirv_selftest_atomic64, sizeof(spirv_selftest_atomic64),
                                                   bindings, sizeof(uint32_t), {});
  Buffer keys;
  createBuffer(keys, context, 4 * sizeof(uint64_t), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryKind::DeviceLocal);
  DescriptorArena arena;
  createDescriptorArena(arena, context, 1);
  const BufferDescriptor descriptors[] = {{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, keys.buffer}};
  VkDescriptorSet set = allocateDescriptorSet(context, arena, pipeline.setLayout, descriptors);

  VkCommandBuffer cmd = beginOneTimeCommands(context);
  vkCmdFillBuffer(cmd, keys.buffer, 0, VK_WHOLE_SIZE, 0xffffffffu);
  recordAtomicMin(cmd, pipeline, set, 64);  // no transferToComputeBarrier in between
  submitAndWait(context, cmd);

  destroyDescriptorArena(arena, context);
  destroyBuffer(keys, context);
  destroyComputePipeline(pipeline, context);
  destroyContext(context);
  std::vector<std::string> messages = log->messages();
  EXPECT_TRUE(std::any_of(messages.begin(), messages.end(),
                          [](const std::string& m) { return m.find("SYNC-HAZARD-") != std::string::npos; }))
      << messages.size() << " messages";
}

TEST_F(VulkanTest, TimestampsMeasureNonNegativeMilliseconds) {
  ASSERT_TRUE(context.timestamps) << "lavapipe writes timestamps; a GPU without them would skip this";
  TimestampPool timestamps;
  createTimestampPool(timestamps, context, 3);

  Buffer buffer;
  createBuffer(buffer, context, 1 << 20, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryKind::DeviceLocal);
  VkCommandBuffer cmd = beginOneTimeCommands(context);
  resetTimestamps(cmd, timestamps);
  writeTimestamp(cmd, timestamps, 0);
  vkCmdFillBuffer(cmd, buffer.buffer, 0, VK_WHOLE_SIZE, 0);  // some work to time
  writeTimestamp(cmd, timestamps, 1);
  submitAndWait(context, cmd);  // slot 2 is never written

  std::vector<double> ms = readTimestamps(context, timestamps);
  ASSERT_EQ(ms.size(), 3u);
  EXPECT_EQ(ms[0], 0.0);
  EXPECT_GE(ms[1], 0.0);
  EXPECT_LT(ms[1], 10000.0);
  EXPECT_TRUE(std::isnan(ms[2]));

  destroyBuffer(buffer, context);
  destroyTimestampPool(timestamps, context);
}

// The fixture's teardown check is only worth something if a leak really shows up in the log.
TEST(ValidationLog, ForgottenBufferIsReportedAtDestroy) {
  VulkanContext context = createTestContext();
  std::shared_ptr<ValidationLog> log = context.validation;
  Buffer leaked;
  createBuffer(leaked, context, 64, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryKind::HostVisible);
  destroyContext(context);
  leaked.disown();  // its device is gone: nothing left to free
  EXPECT_GT(log->count(), 0u);
}

// CTest turns validation on for every GPU test this way, without the code asking for it.
TEST(ValidationLog, EnvironmentVariableTurnsValidationOn) {
  test::ScopedEnv validate("PHONGVK_VALIDATE", "1");
  VulkanContext context = createContext({.deviceIndex = -1, .validate = false});
  EXPECT_NE(context.validation, nullptr);
  EXPECT_NE(context.messenger, VK_NULL_HANDLE);
  destroyContext(context);
}

// With no driver the loader fails vkCreateInstance; the error must say what to install.
TEST(VulkanContextNoDriver, SaysToInstallADriver) {
  test::ScopedEnv noDriver("VK_DRIVER_FILES", "/nonexistent/phongvk_no_driver.json");
  std::string message = test::thrownMessage<NoDeviceError>([] { createContext({}); });
  EXPECT_NE(message.find("no Vulkan driver found"), std::string::npos) << message;
  EXPECT_NE(message.find("install mesa-vulkan-drivers"), std::string::npos) << message;
}

}  // namespace
}  // namespace phongvk
