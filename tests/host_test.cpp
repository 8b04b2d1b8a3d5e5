// host_test.cpp — the Vulkan side's logic that needs no device: the device choice and its messages,
// the list `phongvk devices` prints, VK_CHECK's message, workgroup counts.
#include "vulkan/context.h"
#include "vulkan/pipelines.h"
#include "vulkan/vk_check.h"

#include "tests/test_util.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace phongvk {
namespace {

TEST(VkCheck, MessageNamesFileLineCallAndResult) {
  auto failingCall = [] { return VK_ERROR_OUT_OF_DEVICE_MEMORY; };
  const int line = __LINE__ + 1;
  std::string message = test::thrownMessage<VulkanError>([&] { VK_CHECK(failingCall()); });
  EXPECT_NE(message.find("tests/host_test.cpp:" + std::to_string(line) + ":"), std::string::npos) << message;
  EXPECT_NE(message.find(": failingCall() failed: VK_ERROR_OUT_OF_DEVICE_MEMORY"), std::string::npos) << message;
}

TEST(DeviceList, FormatSaysWhyADeviceIsRejected) {
  DeviceInfo report{3, "Old GPU", "discrete GPU", "1.1.0", false, {"Vulkan 1.2", "shaderBufferInt64Atomics"}};
  EXPECT_EQ(formatDeviceList({report}),
            "[3] Old GPU \u2014 discrete GPU, Vulkan 1.1.0 \u2014 rejected: missing Vulkan 1.2, "
            "shaderBufferInt64Atomics\n");
}

DeviceInfo fakeDevice(uint32_t index, std::string type, std::vector<std::string> missing) {
  return {index, "Device" + std::to_string(index), std::move(type), "1.3.0", missing.empty(), std::move(missing)};
}

TEST(ChooseDevice, PrefersADiscreteGpuOverAnEarlierCpu) {
  std::vector<DeviceInfo> devices = {fakeDevice(0, "CPU", {}), fakeDevice(1, "integrated GPU", {}),
                                       fakeDevice(2, "discrete GPU", {}), fakeDevice(3, "discrete GPU", {})};
  EXPECT_EQ(chooseDevice(devices, -1), 2u);  // the first of equal rank
  EXPECT_EQ(chooseDevice(devices, 0), 0u);   // an explicit index wins over rank
}

TEST(ChooseDevice, SkipsUnsuitableDevicesWhateverTheirRank) {
  std::vector<DeviceInfo> devices = {fakeDevice(0, "discrete GPU", {"shaderBufferInt64Atomics"}),
                                       fakeDevice(1, "CPU", {})};
  EXPECT_EQ(chooseDevice(devices, -1), 1u);
}

TEST(ChooseDevice, NoUsableDeviceListsEveryDeviceAndWhy) {
  std::vector<DeviceInfo> devices = {fakeDevice(0, "CPU", {"shaderInt64 (PHONGVK_KEY_PATH=64)"}),
                                       fakeDevice(1, "discrete GPU", {"Vulkan 1.2", "a compute queue"})};
  EXPECT_EQ(test::thrownMessage<NoDeviceError>([&] { chooseDevice(devices, -1); }),
            "no usable Vulkan device (phongvk needs Vulkan 1.2 and a compute queue): [0] Device0 (missing "
            "shaderInt64 (PHONGVK_KEY_PATH=64)); [1] Device1 (missing Vulkan 1.2, a compute queue)");
}

TEST(ChooseDevice, RequestedUnsuitableDeviceSaysWhatItLacks) {
  std::vector<DeviceInfo> devices = {fakeDevice(0, "CPU", {}), fakeDevice(1, "discrete GPU", {"shaderInt64"})};
  EXPECT_EQ(test::thrownMessage<NoDeviceError>([&] { chooseDevice(devices, 1); }),
            "Vulkan device 1 (Device1) is not usable: missing shaderInt64");
}

TEST(DeviceList, NamesEachDevicesKeyPath) {
  DeviceInfo gpu = fakeDevice(0, "discrete GPU", {});
  DeviceInfo swiftShader = fakeDevice(1, "CPU", {});
  swiftShader.keys32 = true;
  swiftShader.lacks64 = {"shaderInt64", "shaderBufferInt64Atomics"};
  DeviceInfo forced = fakeDevice(2, "CPU", {});
  forced.keys32 = true;
  EXPECT_EQ(keyPathWords(gpu), "64-bit atomics");
  EXPECT_EQ(keyPathWords(swiftShader), "32-bit atomics, two passes (no shaderInt64, shaderBufferInt64Atomics)");
  EXPECT_EQ(keyPathWords(forced), "32-bit atomics, two passes (PHONGVK_KEY_PATH=32)");
  const std::string list = formatDeviceList({gpu, swiftShader});
  EXPECT_NE(list.find("[0] Device0 \u2014 discrete GPU, Vulkan 1.3.0 \u2014 usable \u2014 keys: 64-bit atomics\n"),
            std::string::npos) << list;
  EXPECT_NE(list.find("usable \u2014 keys: 32-bit atomics, two passes (no shaderInt64"), std::string::npos) << list;
}

TEST(ChooseDevice, NoDevicesAtAll) {
  std::string message = test::thrownMessage<NoDeviceError>([] { chooseDevice({}, -1); });
  EXPECT_NE(message.find("install mesa-vulkan-drivers"), std::string::npos) << message;
}

TEST(GroupCount, RoundsUpWithoutOverflow) {
  EXPECT_EQ(groupCount(0, 64), 0u);
  EXPECT_EQ(groupCount(1, 64), 1u);
  EXPECT_EQ(groupCount(64, 64), 1u);
  EXPECT_EQ(groupCount(65, 64), 2u);
  EXPECT_EQ(groupCount(UINT32_MAX, 64), 67108864u);  // (2^32 - 1 + 63) / 64 would overflow
}

}  // namespace
}  // namespace phongvk
