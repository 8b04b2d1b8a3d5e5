// devices_cli_gpu_test.cpp — which key path each device takes, as `phongvk devices` and a render's
// summary name it, PHONGVK_KEY_PATH forcing one, and `phongvk diff --devices` comparing several
// devices with one reference render (lavapipe twice here; lavapipe and SwiftShader together is the
// CTest entry swiftshader_diff_devices).
#include "test_util.h"

#include <gtest/gtest.h>

#include <string>

namespace phongvk {
namespace {

const std::string SCENE = " " + test::sourcePath("scenes/basic.json") + " --width 96 --height 64";

TEST(KeyPaths, DevicesNamesEachDevicesPath) {
  const test::CommandResult natural = test::runCli("devices");
  EXPECT_EQ(natural.exitCode, 0) << natural.output;
  EXPECT_NE(natural.output.find("usable \u2014 keys: 64-bit atomics"), std::string::npos) << natural.output;
  const test::CommandResult forced = test::runCliWithEnvironment("PHONGVK_KEY_PATH=32", "devices");
  EXPECT_EQ(forced.exitCode, 0) << forced.output;
  EXPECT_NE(forced.output.find("usable \u2014 keys: 32-bit atomics, two passes (PHONGVK_KEY_PATH=32)"), std::string::npos)
      << forced.output;
}

TEST(KeyPaths, TheForcedPathRendersTheReferenceBytesAndSaysSo) {
  const test::CommandResult result = test::runCliWithEnvironment("PHONGVK_KEY_PATH=32", "diff" + SCENE);
  EXPECT_EQ(result.exitCode, 0) << result.output;
  EXPECT_NE(result.output.find("keys: 32-bit atomics, two passes"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("pixels differing:    0 "), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("winning triangle differs: 0 pixels"), std::string::npos) << result.output;
}

TEST(KeyPaths, AnUnknownPathIsAnErrorNamingTheVariable) {
  const std::string output = " -o " + ::testing::TempDir() + "unknown.png";
  const test::CommandResult result = test::runCliWithEnvironment("PHONGVK_KEY_PATH=48", "render" + SCENE + output);
  EXPECT_EQ(result.exitCode, 2) << result.output;
  EXPECT_NE(result.output.find("PHONGVK_KEY_PATH is '48': expected 32"), std::string::npos) << result.output;
}

TEST(DiffDevices, EachDeviceIsComparedWithOneReference) {
  const test::CommandResult result = test::runCli("diff" + SCENE + " --devices 0,0");
  EXPECT_EQ(result.exitCode, 0) << result.output;
  const size_t first = result.output.find("device 0:");
  ASSERT_NE(first, std::string::npos) << result.output;
  EXPECT_NE(result.output.find("device 0:", first + 1), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("every device gave the same bytes and keys"), std::string::npos) << result.output;
  EXPECT_NE(result.output.find("result:              PASS"), std::string::npos) << result.output;
}

TEST(DiffDevices, BadDeviceListsAreRefused) {
  const test::CommandResult both = test::runCli("diff" + SCENE + " --devices 0 --device 0");
  EXPECT_EQ(both.exitCode, 2) << both.output;
  EXPECT_NE(both.output.find("excludes"), std::string::npos) << both.output;
  const test::CommandResult negative = test::runCli("diff" + SCENE + " --devices 0,-1");
  EXPECT_EQ(negative.exitCode, 2) << negative.output;
  const test::CommandResult missing = test::runCli("diff" + SCENE + " --devices 0,7");
  EXPECT_EQ(missing.exitCode, 3) << missing.output;
  EXPECT_NE(missing.output.find("Vulkan device index 7 is out of range"), std::string::npos) << missing.output;
}

}  // namespace
}  // namespace phongvk
