// End to end on the reference: scene file -> PNG, with pixel values worked out by hand, and the
// CLI's exit codes and messages.
#include "scene/camera.h"
#include "image/packed_pixels.h"
#include "phongvk/image.h"
#include "reference/render_reference.h"
#include "test_util.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <vector>

namespace phongvk {
namespace {

using test::makeTempDir;
using test::runCli;
using test::writeFile;

// A unit cube 4 m in front of the camera on a grey background. Ambient-only material
// (ka 1, kd = ks = 0): every covered pixel is exactly round(C * A * 255).
const char* AMBIENT_CUBE = R"({
  "camera": {"position": [0, -4, 0], "look_at": [0, 0, 0], "width": 64, "height": 48, "fov": 40},
  "background": [0.5, 0.5, 0.5],
  "ambient": [1, 0.5, 1],
  "lights": [{"position": [0, -3, 0]}],
  "objects": [{"shape": "cube", "size": 1, "material": {"ka": 1, "kd": 0, "ks": 0, "color": [0.2, 0.4, 0.6]}}]
})";

RenderOutput renderText(const std::string& json) {
  const SceneSpec scene = parseSceneSpec(json, "inline.json", ".");
  const SceneData data = buildSceneData(scene);
  return renderReference(data, makeFrame(data, makeView(scene.camera)));
}

void expectPixel(const Image& image, int x, int y, int r, int g, int b) {
  const uint8_t* p = image.pixel(x, y);
  EXPECT_EQ(int(p[0]), r) << "pixel " << x << "," << y;
  EXPECT_EQ(int(p[1]), g) << "pixel " << x << "," << y;
  EXPECT_EQ(int(p[2]), b) << "pixel " << x << "," << y;
}

TEST(Render, AmbientCubeHasExactColoursAndSilhouette) {
  const Image image = renderText(AMBIENT_CUBE).image;
  ASSERT_EQ(image.width, 64);
  ASSERT_EQ(image.height, 48);
  // Focal = 24 / tan(20 deg) = 65.94 px. The front face (y = -0.5, 3.5 m away) spans
  // +-0.5 * 65.94 / 3.5 = +-9.42 px around the centre (32, 24): pixels 23..40 across.
  expectPixel(image, 32, 24, 51, 51, 153);  // 0.2*1, 0.4*0.5, 0.6*1 -> 51, 51, 153
  expectPixel(image, 23, 24, 51, 51, 153);
  expectPixel(image, 40, 24, 51, 51, 153);
  expectPixel(image, 22, 24, 128, 128, 128);  // background 0.5 -> 127.5 -> 128
  expectPixel(image, 41, 24, 128, 128, 128);
  expectPixel(image, 0, 0, 128, 128, 128);
}

TEST(Render, HeadOnLightGivesAmbientPlusDiffuseOnTheFace) {
  // Light far behind the camera on the axis, no attenuation, kd only: every front-face vertex has
  // N.l within 1e-4 of 1, so the face is ka C + kd C = (0.1 + 0.6) * 0.5 = 0.35 -> 89.25 -> 89.
  const char* scene = R"({
    "camera": {"position": [0, -4, 0], "look_at": [0, 0, 0], "width": 64, "height": 48, "fov": 40},
    "lights": [{"position": [0, -10000, 0]}],
    "objects": [{"shape": "cube", "size": 1,
                 "material": {"ka": 0.1, "kd": 0.6, "ks": 0, "attenuation": [1, 0, 0], "color": [0.5, 0.5, 0.5]}}]
  })";
  const Image image = renderText(scene).image;
  expectPixel(image, 32, 24, 89, 89, 89);
  expectPixel(image, 25, 20, 89, 89, 89);
  expectPixel(image, 2, 2, 0, 0, 0);
}

TEST(Render, KeysNameTheFrontFaceTriangles) {
  const RenderOutput out = renderText(AMBIENT_CUBE);
  // The cube's faces are 2 triangles each; the front face (normal -y) is the only one whose
  // triangles can win the centre pixel, and every background pixel keeps the clear key.
  const uint32_t centre = static_cast<uint32_t>(out.keys[24 * 64 + 32]);
  EXPECT_LT(centre, 12u);
  EXPECT_EQ(out.keys[0], ~0ull);
  const float depth = std::bit_cast<float>(uint32_t(out.keys[24 * 64 + 32] >> 32));
  EXPECT_NEAR(depth, 3.5f, 1e-5f);  // view distance of the front face
}

TEST(Render, SameSceneSameBytes) {
  EXPECT_EQ(renderText(AMBIENT_CUBE).image.rgb, renderText(AMBIENT_CUBE).image.rgb);
}

// ---- CLI ----

// The GPU's packed RGBA8 words to RGB bytes: four pixels at a time, then the rest one by one; the
// alpha byte dropped. Every count from 0 to 9 pixels, so each remainder is covered.
TEST(Render, ImageFromPackedKeepsRgbOfEveryPixelAndDropsAlpha) {
  for (int n = 0; n <= 9; ++n) {
    std::vector<uint32_t> packed;
    for (int i = 0; i < n; ++i) packed.push_back(0xA0000000u | uint32_t(i * 0x030201 + 0x102030));
    const Image image = imageFromPacked(packed, n, 1);
    ASSERT_EQ(image.rgb.size(), size_t(3 * n));
    for (int i = 0; i < n; ++i) {
      const uint8_t* p = image.pixel(i, 0);
      EXPECT_EQ(p[0], uint8_t(packed[i])) << n << " pixels, pixel " << i;
      EXPECT_EQ(p[1], uint8_t(packed[i] >> 8)) << n << " pixels, pixel " << i;
      EXPECT_EQ(p[2], uint8_t(packed[i] >> 16)) << n << " pixels, pixel " << i;
    }
  }
}

TEST(Cli, RenderWritesThePngAndSaysWhatItDid) {
  const std::string dir = makeTempDir();
  writeFile(dir + "/cube.json", AMBIENT_CUBE);
  const auto r = runCli("render " + dir + "/cube.json -o " + dir + "/out.png --backend cpu");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("64x48"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(" ms"), std::string::npos) << r.output;
  const Image image = readPng(dir + "/out.png");
  EXPECT_EQ(image.rgb, renderText(AMBIENT_CUBE).image.rgb);
}

TEST(Cli, WidthAndHeightOverrideTheSceneSize) {
  const std::string dir = makeTempDir();
  writeFile(dir + "/cube.json", AMBIENT_CUBE);
  const auto r = runCli("render " + dir + "/cube.json -o " + dir + "/out.png --backend cpu --width 32 --height 20");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const Image image = readPng(dir + "/out.png");
  EXPECT_EQ(image.width, 32);
  EXPECT_EQ(image.height, 20);
}

TEST(Cli, BadSceneExitsTwoNamingFileAndFieldAndWritesNothing) {
  const std::string dir = makeTempDir();
  writeFile(dir + "/bad.json", R"({"camera": {"position": [0, 0, 0], "direction": [0, 1, 0], "fov": 200},
                                    "objects": [{"shape": "cube"}]})");
  const auto r = runCli("render " + dir + "/bad.json -o " + dir + "/out.png --backend cpu");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.output.find("bad.json: camera.fov"), std::string::npos) << r.output;
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), {}), 1);  // only bad.json
}

TEST(Cli, UnwritableOutputExitsTwoBeforeRendering) {
  const std::string dir = makeTempDir();
  writeFile(dir + "/cube.json", AMBIENT_CUBE);
  const auto r = runCli("render " + dir + "/cube.json -o " + dir + "/no/such/folder/out.png --backend cpu");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.output.find("does not exist"), std::string::npos) << r.output;
}

TEST(Cli, PngLevelChangesTheFileNotThePixels) {
  const std::string dir = makeTempDir();
  const std::string scene = test::sourcePath("scenes/paper/fig3_two_lights.json");
  std::vector<uintmax_t> sizes;
  for (const std::string level : {"0", "1", "6", "12"}) {
    const std::string out = dir + "/level" + level + ".png";
    const auto r = runCli("render " + scene + " -o " + out + " --backend cpu --width 240 --height 160 --png-level " + level);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_EQ(readPng(out).rgb, readPng(dir + "/level0.png").rgb) << "level " << level;
    sizes.push_back(std::filesystem::file_size(out));
  }
  EXPECT_TRUE(std::is_sorted(sizes.rbegin(), sizes.rend())) << sizes[0] << " " << sizes[1] << " " << sizes[2];
  const auto bad = runCli("render " + scene + " -o " + dir + "/bad.png --backend cpu --png-level 13");
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_NE(bad.output.find("--png-level"), std::string::npos) << bad.output;
  EXPECT_FALSE(std::filesystem::exists(dir + "/bad.png"));
}

TEST(Cli, UnknownOptionExitsTwo) {
  const auto r = runCli("render scenes/basic.json -o x.png --fast");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.output.find("--fast"), std::string::npos) << r.output;
}

TEST(Cli, UnknownCommandIsNamed) {
  const auto r = runCli("frob scenes/basic.json");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.output.find("unknown command 'frob' (commands: render, diff, sequence, devices"), std::string::npos)
      << r.output;
}

TEST(Cli, HelpOnEverySubcommandExitsZero) {
  for (const char* command : {"--help", "render --help", "diff --help", "sequence --help", "devices --help"}) {
    const auto r = runCli(command);
    EXPECT_EQ(r.exitCode, 0) << command << "\n" << r.output;
    EXPECT_NE(r.output.find("Usage"), std::string::npos) << command;
  }
}

}  // namespace
}  // namespace phongvk
