// disk_cache_gpu_test.cpp — what a process keeps for the next under $XDG_CACHE_HOME/phongvk (the
// pipeline cache and the float probe's answer): used when whole, ignored and replaced when
// truncated, corrupt or for another device, never a reason for a render to fail, and never a
// change to the image.
#include "phongvk/phongvk.h"
#include "test_util.h"
#include "vulkan/disk_cache.h"
#include "vulkan/float_probe.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace phongvk {
namespace {

namespace fs = std::filesystem;
using test::makeTempDir;

// Points XDG_CACHE_HOME at a fresh folder for one test, and back after.
class CacheFolder : public ::testing::Test {
 protected:
  void SetUp() override {
    const char* old = std::getenv("XDG_CACHE_HOME");
    if (old) saved_ = old;
    hadOld_ = old != nullptr;
    root_ = makeTempDir();
    setenv("XDG_CACHE_HOME", root_.c_str(), 1);
  }
  void TearDown() override {
    if (hadOld_) setenv("XDG_CACHE_HOME", saved_.c_str(), 1);
    else unsetenv("XDG_CACHE_HOME");
  }

  fs::path folder() const { return fs::path(root_) / "phongvk"; }
  // The one file whose name starts with `prefix`.
  fs::path file(const std::string& prefix) const {
    for (const auto& entry : fs::directory_iterator(folder())) {
      if (entry.path().filename().string().rfind(prefix, 0) == 0) return entry.path();
    }
    ADD_FAILURE() << "no " << prefix << " file in " << folder();
    return {};
  }
  static std::vector<uint8_t> bytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }
  static void overwrite(const fs::path& path, const std::vector<uint8_t>& content) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(content.data()), std::streamsize(content.size()));
  }

  static Scene scene() { return loadScene(test::sourcePath("scenes/paper/fig3_two_lights.json")).withImageSize(160, 107); }

  std::string root_, saved_;
  bool hadOld_ = false;
};

TEST_F(CacheFolder, FirstRendererSavesSecondUsesAndTheImageIsTheSame) {
  Renderer first(Backend::Gpu);
  const Image a = first.render(scene());
  EXPECT_FALSE(first.stats().probeCached);
  EXPECT_GT(first.stats().pipelinesMs, 0.0);
  const fs::path probe = file("float-probe-"), pipelines = file("pipelines-");
  EXPECT_GT(fs::file_size(pipelines), 32u);
  Renderer second(Backend::Gpu);
  EXPECT_TRUE(second.stats().probeCached);
  EXPECT_EQ(second.stats().probeMs, 0.0);
  EXPECT_EQ(second.render(scene()).rgb, a.rgb);
}

TEST_F(CacheFolder, CorruptOrForeignFilesAreIgnoredAndReplaced) {
  Image reference;
  {
    Renderer renderer(Backend::Gpu);
    reference = renderer.render(scene());
  }
  const fs::path probe = file("float-probe-"), pipelines = file("pipelines-");
  const std::vector<uint8_t> goodProbe = bytes(probe), goodPipelines = bytes(pipelines);

  // A truncated pipeline cache, and a probe file with one payload byte flipped (checksum fails).
  overwrite(pipelines, std::vector<uint8_t>(goodPipelines.begin(), goodPipelines.begin() + 20));
  std::vector<uint8_t> flipped = goodProbe;
  flipped.back() ^= 1;
  overwrite(probe, flipped);
  {
    Renderer renderer(Backend::Gpu);
    EXPECT_FALSE(renderer.stats().probeCached);
    EXPECT_EQ(renderer.render(scene()).rgb, reference.rgb);
  }
  EXPECT_EQ(bytes(probe), goodProbe);
  EXPECT_EQ(bytes(pipelines).size(), goodPipelines.size());

  // Whole files for another device: a pipeline cache whose Vulkan header names another vendor,
  // and a probe answer that is neither of the two.
  std::vector<uint8_t> foreign(goodPipelines.begin() + 32, goodPipelines.end());  // the payload
  foreign[8] ^= 0xFF;                                                             // vendorID
  writeCacheFile(pipelines.filename().string(), foreign);
  const std::string maybe = "use exact: maybe\n";
  writeCacheFile(probe.filename().string(), std::vector<uint8_t>(maybe.begin(), maybe.end()));
  {
    Renderer renderer(Backend::Gpu);
    EXPECT_FALSE(renderer.stats().probeCached);
    EXPECT_EQ(renderer.render(scene()).rgb, reference.rgb);
  }
  EXPECT_EQ(bytes(probe), goodProbe);
}

TEST_F(CacheFolder, AFolderThatCannotBeMadeOnlyMeansNoCache) {
  test::writeFile(root_ + "/blocker", "a file where the cache folder would go");
  setenv("XDG_CACHE_HOME", (root_ + "/blocker").c_str(), 1);
  Renderer renderer(Backend::Gpu);
  EXPECT_FALSE(renderer.stats().probeCached);
  EXPECT_EQ(renderer.render(scene()).width, 160);
}

TEST_F(CacheFolder, RelativeXdgCacheHomeIsIgnoredAsTheSpecAsks) {
  setenv("XDG_CACHE_HOME", "relative/cache", 1);
  const char* home = std::getenv("HOME");
  ASSERT_NE(home, nullptr);
  EXPECT_EQ(cacheFolder(), fs::path(home) / ".cache" / "phongvk");
  setenv("XDG_CACHE_HOME", root_.c_str(), 1);
  EXPECT_EQ(cacheFolder(), folder());
}

TEST_F(CacheFolder, FilesRoundTripAndAChangedByteIsCaught) {
  const std::vector<uint8_t> payload = {1, 2, 3, 250, 0, 7};
  writeCacheFile("x.bin", payload);
  EXPECT_EQ(readCacheFile("x.bin"), payload);
  std::vector<uint8_t> raw = bytes(folder() / "x.bin");
  raw[raw.size() - 2] ^= 0x10;
  overwrite(folder() / "x.bin", raw);
  EXPECT_FALSE(readCacheFile("x.bin").has_value());
  EXPECT_FALSE(readCacheFile("missing.bin").has_value());
  EXPECT_EQ(std::distance(fs::directory_iterator(folder()), {}), 1);  // no temporary file left
}

TEST_F(CacheFolder, RenderCommandSaysWhereStartUpWent) {
  const std::string env = "XDG_CACHE_HOME=" + root_;
  const std::string args = "render " + test::sourcePath("scenes/basic.json") + " -o " + root_ + "/out.png";
  const auto first = test::runCliWithEnvironment(env, args);
  ASSERT_EQ(first.exitCode, 0) << first.output;
  EXPECT_NE(first.output.find("(start-up: Vulkan "), std::string::npos) << first.output;
  EXPECT_NE(first.output.find(", float probe "), std::string::npos) << first.output;
  const auto second = test::runCliWithEnvironment(env, args);
  EXPECT_NE(second.output.find(", float probe cached, pipelines "), std::string::npos) << second.output;
}

}  // namespace
}  // namespace phongvk
