// Sequences on both backends: every paper scene agrees pixel by pixel, reuse across frames is
// invisible in the images (--frames subsets are byte-identical to the full run) yet real (an
// orbit without specular light shades once), and the CLI refuses bad --frames before writing.
// Every GPU renderer runs with validation on and fails on any message.
#include "phongvk/phongvk.h"

#include <gtest/gtest.h>

#include <chrono>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "test_util.h"

namespace phongvk {
namespace {

namespace fs = std::filesystem;
using nlohmann::ordered_json;

// Small frames keep the reference (and lavapipe) fast; the paper scenes fill them well.
constexpr int kWidth = 240;
constexpr int kHeight = 160;

std::vector<std::string> paperScenes() {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(test::sourcePath("scenes/paper"))) {
    if (entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

// A GPU renderer with validation on; finish() checks it reported nothing.
Renderer validatedGpu() { return Renderer(RendererOptions{.backend = Backend::Gpu, .device = -1, .validate = true}); }

void expectNoValidationMessages(const Renderer& gpu) { EXPECT_EQ(gpu.stats().validationMessages, 0u); }

// Frames start, start + step, ... below end of `sequence`, at the tests' small size.
std::vector<Scene> framesOf(const Scene& sequence, int start, int end, int step) {
  std::vector<Scene> frames;
  for (int i = start; i < end; i += step) frames.push_back(sequence.frame(i).withImageSize(kWidth, kHeight));
  return frames;
}

// Renders `frames` on both backends and checks every frame agrees: the same keys and the same bytes.
void expectBackendsAgree(const std::vector<Scene>& frames, Renderer& gpu) {
  Renderer cpu(Backend::Cpu);
  for (size_t k = 0; k < frames.size(); ++k) {
    const RenderOutput reference = cpu.renderWithKeys(frames[k]);
    const RenderOutput out = gpu.renderWithKeys(frames[k]);
    const DiffStats stats = compareImages(reference.image, out.image, reference.keys, out.keys);
    EXPECT_TRUE(out.keys == reference.keys) << "frame " << k << ": keys differ\n" << formatDiff(stats);
    EXPECT_TRUE(out.image.rgb == reference.image.rgb) << "frame " << k << ": bytes differ\n" << formatDiff(stats);
  }
}

class PaperScene : public ::testing::TestWithParam<std::string> {};

// About a dozen frames spread over each sequence (all of a short one) keep CI time low while
// covering the whole sweep or orbit, and stepping exercises the reuse between frames.
TEST_P(PaperScene, BothBackendsAgreeOnEveryFrameChecked) {
  const Scene sequence = loadScene(test::sourcePath("scenes/paper/" + GetParam() + ".json"));
  const int step = std::max(1, sequence.frameCount() / 12);
  Renderer gpu = validatedGpu();
  expectBackendsAgree(framesOf(sequence, 0, sequence.frameCount(), step), gpu);
  EXPECT_EQ(gpu.stats().sceneBuilds, 1u);  // no paper scene animates geometry
  expectNoValidationMessages(gpu);
}

INSTANTIATE_TEST_SUITE_P(Scenes, PaperScene, ::testing::ValuesIn(paperScenes()),
                         [](const auto& info) { return info.param; });

// The paper's second orbit with every material's ks set to 0: lighting no longer depends on the
// eye, so the renderer computes it for the first frame only and reuses it for the others.
TEST(SequenceReuse, OrbitWithoutSpecularShadesOnce) {
  std::ifstream file(test::sourcePath("scenes/paper/fig7_orbit_white_red.json"));
  ordered_json json = ordered_json::parse(file);
  for (auto& [name, material] : json["materials"].items()) material["ks"] = 0;
  const Scene sequence = parseScene(json.dump(), "orbit_ks0.json", test::sourcePath("scenes/paper"));
  Renderer gpu = validatedGpu();
  expectBackendsAgree(framesOf(sequence, 0, 120, 10), gpu);
  EXPECT_EQ(gpu.stats().framesShaded, 1u);
  expectNoValidationMessages(gpu);
}

// A sequence whose geometry changes twice: the meshes are rebuilt exactly then, and the images
// still match the reference.
TEST(SequenceReuse, GeometryTrackRebuildsOnlyWhenItChanges) {
  std::ifstream file(test::sourcePath("scenes/paper/fig1_cube.json"));
  ordered_json json = ordered_json::parse(file);
  const ordered_json materials = {"grey", "ground", "grey", "grey", "grey"};  // not geometry
  json["animate"] = {{"frames", 5},
                     {"tracks", {{{"path", "objects[0].size"}, {"values", {1, 1, 0.6, 0.6, 0.8}}},
                                 {{"path", "objects[0].material"}, {"values", materials}}}}};
  const Scene sequence = parseScene(json.dump(), "resize.json", test::sourcePath("scenes/paper"));
  Renderer gpu = validatedGpu();
  expectBackendsAgree(framesOf(sequence, 0, 5, 1), gpu);
  EXPECT_EQ(gpu.stats().sceneBuilds, 3u);  // frames 0, 2 and 4
  expectNoValidationMessages(gpu);
}

// ---- the CLI ----

// Eight frames that switch what the GPU may reuse: an orbit, specular light off then on then off
// again, and a light colour that changes once.
std::string writeSwitchingScene(const std::string& dir) {
  const char* scene = R"json({
    "camera": {"position": [3, 0, 1.5], "look_at": [0, 0, 0], "width": 96, "height": 64},
    "lights": [{"position": [-1, -1, 2], "color": [1, 1, 1]}],
    "materials": {"m": {"ks": 0}},
    "objects": [{"shape": "sphere", "segments": 16, "material": "m"},
                {"shape": "cube", "center": [0, 0, -0.8], "size": 0.6, "material": "m"}],
    "animate": {"frames": 8, "tracks": [
      {"path": "camera.position", "expression": ["3*cos(2*pi*i/n)", "3*sin(2*pi*i/n)", 1.5]},
      {"path": "materials.m.ks", "values": [0, 0, 0, 0.8, 0.8, 0, 0, 0]},
      {"path": "lights[0].color", "values": [[1,1,1], [1,1,1], [1,1,1], [1,1,1], [1,1,1], [1,1,1], [0,0,1], [0,0,1]]}
    ]}
  })json";
  test::writeFile(dir + "/switching.json", scene);
  return dir + "/switching.json";
}

test::CommandResult sequenceCli(const std::string& scene, const std::string& out, const std::string& extra) {
  return test::runCli("sequence " + scene + " -o " + out + " " + extra);
}

TEST(SequenceCli, FrameSubsetsAreByteIdenticalToTheFullRun) {
  const std::string dir = test::makeTempDir();
  const std::string scene = writeSwitchingScene(dir);
  const test::CommandResult full = sequenceCli(scene, dir + "/full", "--sheet " + dir + "/sheet.png");
  ASSERT_EQ(full.exitCode, 0) << full.output;
  EXPECT_NE(full.output.find("frames 0:8:1 (8)"), std::string::npos) << full.output;
  EXPECT_TRUE(fs::is_regular_file(dir + "/sheet.png"));
  // The last range is frame 0 alone (its STEP must not overflow).
  for (const char* range : {"0:3", "3:8", "5:", "1:8:3", "0:8:2147483647"}) {
    const test::CommandResult part = sequenceCli(scene, dir + "/part", std::string("--frames ") + range);
    ASSERT_EQ(part.exitCode, 0) << range << "\n" << part.output;
  }
  for (int i = 0; i < 8; ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.png", i);
    EXPECT_EQ(test::readBytes(dir + "/part/" + name), test::readBytes(dir + "/full/" + name)) << name;
  }
  EXPECT_EQ(std::distance(fs::directory_iterator(dir + "/full"), fs::directory_iterator()), 8);
}

// --skip-existing keeps the frames an earlier run wrote whole (not rendered again: their times stay)
// and renders the missing one, the one cut short and the one of another size; the set, and the
// sheet made from the kept files, equal a full run's.
TEST(SequenceCli, SkipExistingRendersOnlyWhatIsMissingOrIncomplete) {
  const std::string dir = test::makeTempDir();
  const std::string scene = writeSwitchingScene(dir);
  ASSERT_EQ(sequenceCli(scene, dir + "/full", "--sheet " + dir + "/full.png").exitCode, 0);
  ASSERT_EQ(sequenceCli(scene, dir + "/part", "").exitCode, 0);
  auto frame = [&](const std::string& folder, int i) {
    char name[32];
    std::snprintf(name, sizeof name, "/frame_%04d.png", i);
    return dir + "/" + folder + name;
  };
  fs::remove(frame("part", 2));
  test::writeFile(frame("part", 4), test::readBytes(frame("full", 4)).substr(0, 100));  // cut short
  ASSERT_EQ(test::runCli("render " + scene + " --width 20 --height 10 -o " + frame("part", 6)).exitCode, 0);
  const auto old = fs::file_time_type::clock::now() - std::chrono::hours(24);
  for (int i : {0, 1, 3, 5, 7}) fs::last_write_time(frame("part", i), old);
  const test::CommandResult again = sequenceCli(scene, dir + "/part", "--skip-existing --sheet " + dir + "/part.png");
  ASSERT_EQ(again.exitCode, 0) << again.output;
  EXPECT_NE(again.output.find("kept 5 frames an earlier run wrote whole"), std::string::npos) << again.output;
  for (int i = 0; i < 8; ++i) EXPECT_EQ(test::readBytes(frame("part", i)), test::readBytes(frame("full", i))) << i;
  for (int i : {0, 1, 3, 5, 7}) EXPECT_EQ(fs::last_write_time(frame("part", i)), old) << "frame " << i << " rendered again";
  EXPECT_EQ(test::readBytes(dir + "/part.png"), test::readBytes(dir + "/full.png"));
}

TEST(SequenceCli, RenderOfAnAnimatedSceneIsFrameZero) {
  const std::string dir = test::makeTempDir();
  const std::string scene = writeSwitchingScene(dir);
  ASSERT_EQ(sequenceCli(scene, dir + "/frames", "--frames 0:1").exitCode, 0);
  const test::CommandResult render = test::runCli("render " + scene + " -o " + dir + "/still.png");
  ASSERT_EQ(render.exitCode, 0) << render.output;
  EXPECT_EQ(test::readBytes(dir + "/still.png"), test::readBytes(dir + "/frames/frame_0000.png"));
}

TEST(SequenceCli, BadFramesExitTwoAndWriteNothing) {
  const std::string dir = test::makeTempDir();
  const std::string scene = writeSwitchingScene(dir);
  const std::string usage = "expected START:END or START:END:STEP (END excluded, like a Python slice)";
  const std::pair<std::string, std::string> cases[] = {
      {"5:3", "error: --frames 5:3: selects no frames (START must be < END)"},
      {"4:4", "error: --frames 4:4: selects no frames (START must be < END)"},
      {"0:9", "error: --frames 0:9: END 9 is out of range: the sequence has 8 frames, so END <= 8"},
      {"8:", "error: --frames 8:: START 8 is out of range: the sequence has 8 frames, so START < 8"},
      {"a:b", "error: --frames a:b: START 'a' is not a non-negative integer"},
      {"1:2x", "error: --frames 1:2x: END '2x' is not a non-negative integer"},
      {"0:4:0", "error: --frames 0:4:0: STEP must be >= 1"},
      {"3", "error: --frames '3': " + usage},
      {"1:2:3:4", "error: --frames '1:2:3:4': " + usage},
      {"''", "--frames"},  // an empty value: CLI11's own usage error
      {"-1:2", "error: --frames -1:2: START '-1' is not a non-negative integer"},
  };
  for (const auto& [range, message] : cases) {
    // "--frames=X", so that "-1:2" is not read as an option.
    const test::CommandResult result = sequenceCli(scene, dir + "/out", "--frames=" + range);
    EXPECT_EQ(result.exitCode, 2) << range << "\n" << result.output;
    EXPECT_NE(result.output.find(message), std::string::npos) << range << "\n" << result.output;
    EXPECT_FALSE(fs::exists(dir + "/out")) << range;
  }
}

TEST(SequenceCli, SceneErrorInALaterFrameWritesNothing) {
  const std::string dir = test::makeTempDir();
  test::writeFile(dir + "/bad.json", R"({
    "camera": {"position": [3, 0, 1], "look_at": [0, 0, 0], "width": 32, "height": 24},
    "objects": [{"shape": "sphere", "material": {"ks": 0.5}}],
    "animate": {"frames": 4, "tracks": [{"path": "objects[0].material.ks", "expression": "0.5 - i/4"}]}
  })");
  const test::CommandResult result = sequenceCli(dir + "/bad.json", dir + "/out", "");
  EXPECT_EQ(result.exitCode, 2) << result.output;
  EXPECT_NE(result.output.find("bad.json: frame 3: objects[0].material.ks: must be >= 0, got -0.25"), std::string::npos)
      << result.output;
  EXPECT_FALSE(fs::exists(dir + "/out"));
}

// --max-memory-gb holds from the first frame checked: a samples track that takes frame 1 past it
// fails before frame 0 is written, naming frame 1.
TEST(SequenceCli, AFrameThatGrowsPastTheMemoryLimitWritesNothing) {
  const std::string dir = test::makeTempDir();
  test::writeFile(dir + "/grows.json", R"({
    "camera": {"position": [3, 0, 1], "look_at": [0, 0, 0], "width": 1000, "height": 1000},
    "objects": [{"shape": "sphere"}],
    "render": {"samples": 1},
    "animate": {"frames": 2, "tracks": [{"path": "render.samples", "values": [1, 16]}]}
  })");
  const test::CommandResult result = sequenceCli(dir + "/grows.json", dir + "/out", "--max-memory-gb 0.3");
  EXPECT_EQ(result.exitCode, 2) << result.output;
  EXPECT_NE(result.output.find("grows.json: frame 1: the scene needs about 0.48 GiB (960 triangles, 16000000 pixels), "
                               "more than the 0.30 GiB limit"),
            std::string::npos)
      << result.output;
  EXPECT_FALSE(fs::exists(dir + "/out"));
}

// SIGINT (or SIGTERM) stops a long sequence after the frame in flight: exit 128 + the signal, a
// message saying how far it got, every frame file whole, no temporary file and no sheet; the same
// command again completes the set.
TEST(SequenceCli, InterruptedSequenceLeavesOnlyWholeFramesAndSaysHowFar) {
  const std::string dir = test::makeTempDir();
  const std::string scene = test::sourcePath("scenes/paper/fig7_orbit_white_red.json");
  const std::string frames = dir + "/frames";
  // In the background, interrupted once its second frame is on disk.
  std::string script(1, '\'');  // appended, not "'" + ...: GCC 12 warns (-Wrestrict)
  script += std::string(PHONGVK_CLI) + "' sequence '" + scene + "' -o '" + frames +
                             "' --backend cpu --sheet '" + dir + "/sheet.png' > '" + dir + "/log' 2>&1 & pid=$!; " +
                             "while [ ! -e '" + frames + "/frame_0001.png' ]; do sleep 0.05; done; kill -INT $pid; " +
                             "wait $pid; echo exit=$?";
  test::writeFile(dir + "/interrupt.sh", script + "\n");
  FILE* pipe = popen(("bash '" + dir + "/interrupt.sh'").c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  char buffer[256];
  std::string output;
  for (size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) output.append(buffer, n);
  pclose(pipe);
  EXPECT_NE(output.find("exit=130"), std::string::npos) << output;
  std::ifstream logFile(dir + "/log");
  const std::string log((std::istreambuf_iterator<char>(logFile)), std::istreambuf_iterator<char>());
  EXPECT_NE(log.find("interrupted (SIGINT) after "), std::string::npos) << log;
  EXPECT_NE(log.find(" of 120 frames, each written whole"), std::string::npos) << log;
  size_t written = 0;
  for (const auto& entry : fs::directory_iterator(frames)) {
    EXPECT_EQ(entry.path().extension(), ".png") << entry.path();  // no temporary file
    EXPECT_EQ(readPng(entry.path().string()).width, 1385) << entry.path();  // each one whole
    ++written;
  }
  EXPECT_GE(written, 2u);
  EXPECT_LT(written, 120u);
  EXPECT_FALSE(fs::exists(dir + "/sheet.png"));
}

}  // namespace
}  // namespace phongvk
