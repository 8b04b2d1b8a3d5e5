// pinned_images_gpu_test.cpp — the contract's bytes, pinned. The reference and the compute port
// share their maths (shaders/phong.h and the other shared headers), so a change there moves both
// renderers together and every reference-against-port diff still passes. Here each case (a scene,
// a frame, a shading mode) renders on both backends, the two must agree, and the hashes of the
// image and of the visibility keys must equal those committed in tests/data/pinned_images.txt
// (docs/DECISIONS.md "Pinned images"). After an intended change to the contract, re-pin:
//
//   scripts/repin.sh        (or: PHONGVK_REPIN=1 build/tests/pinned_images_gpu_test)
//
// and commit the new file with the change that moved it.
#include "phongvk/compare.h"
#include "phongvk/phongvk.h"
#include "test_util.h"
#include "vulkan/disk_cache.h"

#include <gtest/gtest.h>

#include <bit>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <optional>
#include <ostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace phongvk {
namespace {

const char* const PIN_FILE = "tests/data/pinned_images.txt";
const char* const REPIN_HOW =
    "If the change (to the contract, or to the cases pinned) is intended, re-pin with scripts/repin.sh (or "
    "PHONGVK_REPIN=1 build/tests/pinned_images_gpu_test) and commit tests/data/pinned_images.txt "
    "with the change that moved it; otherwise the change moved the contract's bytes by mistake.";

// Every case at this size: the pins hold the contract's arithmetic, which a small image exercises
// as a large one does, and 66 renders on each backend take about a second on lavapipe.
constexpr int WIDTH = 240;
constexpr int HEIGHT = 160;

// A scene file, one of its frames and render options beside its own; each is pinned in every mode.
struct PinCase {
  std::string scene;
  int frame = 0;
  std::string render;  // JSON object of render keys ("" for none), as a scene file's "render"
};

// How GoogleTest names a case in a failure: "scenes/basic.json frame 0 {"specular": "blinn"}".
void PrintTo(const PinCase& c, std::ostream* out) { *out << c.scene << " frame " << c.frame << " " << c.render; }

const char* const SHADINGS[] = {"gouraud", "flat", "phong"};

// The paper's scenes, the animated ones also at a second frame (another light colour, ka, camera
// position; fig5 at ks = 1, as its middle frame has frame 0's ks of 0.5), then one scene for each
// thing the paper's do not show. Frames are numbers here, not found from the file, so that a pin
// keeps naming the same picture.
std::vector<PinCase> pinCases() {
  std::vector<PinCase> cases;
  for (const char* name : {"fig1_cone", "fig1_cube", "fig1_cylinder", "fig1_polyhedron"}) {
    cases.push_back({std::string("scenes/paper/") + name + ".json", 0, ""});
  }
  for (const auto& [name, second] : std::vector<std::pair<const char*, int>>{
           {"fig2_light_colours", 3}, {"fig3_two_lights", 60}, {"fig4_ka_sweep", 60}, {"fig5_ks_sweep", 30},
           {"fig6_orbit_red", 60}, {"fig7_orbit_white_red", 60}}) {
    cases.push_back({std::string("scenes/paper/") + name + ".json", 0, ""});
    cases.push_back({std::string("scenes/paper/") + name + ".json", second, ""});
  }
  cases.push_back({"scenes/basic.json", 0, ""});
  cases.push_back({"scenes/basic.json", 0, R"({"specular": "blinn"})"});           // Blinn's highlight
  cases.push_back({"scenes/screen_interpolation.json", 0, ""});                    // screen barycentrics
  cases.push_back({"scenes/mesh_torus.json", 0, ""});                              // an OBJ file's mesh
  cases.push_back({"scenes/stress/lights_degenerate.json", 0, ""});                // d = 0, n = 0, n = 1000
  cases.push_back({"scenes/shading/samples.json", 0, R"({"samples": 16})"});       // the box filter
  return cases;
}

// "samples:16" for {"samples": 16}: the render options as one word of a pin line.
std::string optionsWord(const std::string& json) {
  std::string word;
  for (char c : json) {
    if (c != '{' && c != '}' && c != '"' && c != ' ') word += c;
  }
  return word.empty() ? "-" : word;
}

std::string render(const PinCase& c, const char* shading) {
  std::string json = std::string(R"({"shading": ")") + shading + "\"";
  if (!c.render.empty()) json += ", " + c.render.substr(1, c.render.size() - 2);
  return json + "}";
}

// What a pin line names: "scenes/basic.json frame=0 options=- shading=flat size=240x160".
std::string caseName(const PinCase& c, const char* shading) {
  return c.scene + " frame=" + std::to_string(c.frame) + " options=" + optionsWord(c.render) + " shading=" + shading +
         " size=" + std::to_string(WIDTH) + "x" + std::to_string(HEIGHT);
}

std::string hex(uint64_t value) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
  return text;
}

// The hashes of one render: FNV-1a 64 (vulkan/disk_cache.h) of the RGB bytes, and of the keys as
// little-endian u64s (depth bits and triangle ids, one per sample).
struct PinHashes {
  std::string image;
  std::string keys;
  bool operator==(const PinHashes&) const = default;
};

static_assert(std::endian::native == std::endian::little, "keys are hashed as their little-endian bytes");

PinHashes hashesOf(const RenderOutput& out) {
  return {hex(fnv1a(out.image.rgb.data(), out.image.rgb.size())),
          hex(fnv1a(out.keys.data(), out.keys.size() * sizeof(uint64_t)))};
}

std::string pinLine(const std::string& name, const PinHashes& h) { return name + " image=" + h.image + " keys=" + h.keys; }

// The committed pins by case name; a line that does not parse is a failure naming it.
std::map<std::string, PinHashes> readPins() {
  std::map<std::string, PinHashes> pins;
  std::ifstream in(test::sourcePath(PIN_FILE));
  EXPECT_TRUE(in.is_open()) << "cannot read " << PIN_FILE << ". " << REPIN_HOW;
  int number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    if (line.empty() || line[0] == '#') continue;
    const size_t image = line.find(" image=");
    const size_t keys = line.find(" keys=");
    if (image == std::string::npos || keys == std::string::npos || keys < image) {
      ADD_FAILURE() << PIN_FILE << ":" << number << ": not 'CASE image=HEX keys=HEX': " << line;
      continue;
    }
    pins[line.substr(0, image)] = {line.substr(image + 7, keys - image - 7), line.substr(keys + 6)};
  }
  return pins;
}

bool repinning() {
  const char* value = std::getenv("PHONGVK_REPIN");
  return value != nullptr && std::strcmp(value, "1") == 0;
}

// One renderer of each backend for every case, as a program keeps one.
class PinnedImages : public ::testing::TestWithParam<PinCase> {
 protected:
  static void SetUpTestSuite() {
    cpu_ = new Renderer(Backend::Cpu);
    gpu_ = new Renderer(Backend::Gpu);
  }
  static void TearDownTestSuite() {
    delete gpu_;
    delete cpu_;
  }

  // The case in `shading` on both backends; a failure, and nullopt, where they differ.
  static std::optional<PinHashes> renderBoth(const PinCase& c, const char* shading) {
    const std::string name = caseName(c, shading);
    const Scene scene = test::withRenderOptions(
        loadScene(test::sourcePath(c.scene)).frame(c.frame).withImageSize(WIDTH, HEIGHT), render(c, shading));
    const RenderOutput reference = cpu_->renderWithKeys(scene);
    const RenderOutput gpu = gpu_->renderWithKeys(scene);
    if (gpu.image.rgb != reference.image.rgb || gpu.keys != reference.keys) {
      ADD_FAILURE() << name << ": the compute port differs from the reference (nothing is pinned that they do not agree on)\n"
                    << formatDiff(compareImages(reference.image, gpu.image, reference.keys, gpu.keys));
      return std::nullopt;
    }
    return hashesOf(reference);
  }

  static Renderer* cpu_;
  static Renderer* gpu_;
};

Renderer* PinnedImages::cpu_ = nullptr;
Renderer* PinnedImages::gpu_ = nullptr;

TEST_P(PinnedImages, BothBackendsGiveThePinnedBytes) {
  if (repinning()) GTEST_SKIP() << "PHONGVK_REPIN=1: PinnedImagesRepin writes the pins instead";
  test::expectTestDevice(gpu_->deviceName());  // where CTest's keys32 and swiftshader entries ask
  const std::map<std::string, PinHashes> pins = readPins();
  for (const char* shading : SHADINGS) {
    const std::string name = caseName(GetParam(), shading);
    const std::optional<PinHashes> got = renderBoth(GetParam(), shading);
    if (!got) continue;
    const auto pin = pins.find(name);
    if (pin == pins.end()) {
      ADD_FAILURE() << name << ": no pin in " << PIN_FILE << " (got " << pinLine(name, *got) << "). " << REPIN_HOW;
      continue;
    }
    EXPECT_EQ(got->image, pin->second.image) << name << ": the image's bytes are not the pinned ones. " << REPIN_HOW;
    EXPECT_EQ(got->keys, pin->second.keys) << name << ": the visibility keys are not the pinned ones. " << REPIN_HOW;
  }
}

std::string paramName(const ::testing::TestParamInfo<PinCase>& info) {
  std::string name = info.param.scene + "_frame" + std::to_string(info.param.frame);
  if (!info.param.render.empty()) {
    name += '_';
    name += optionsWord(info.param.render);
  }
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return name;
}

INSTANTIATE_TEST_SUITE_P(Cases, PinnedImages, ::testing::ValuesIn(pinCases()), paramName);

// A pin for a case no longer rendered would pin nothing: the file holds exactly the cases.
TEST(PinnedImagesFile, HoldsExactlyTheCases) {
  if (repinning()) GTEST_SKIP() << "PHONGVK_REPIN=1: the file is being rewritten";
  std::map<std::string, PinHashes> pins = readPins();
  for (const PinCase& c : pinCases()) {
    for (const char* shading : SHADINGS) pins.erase(caseName(c, shading));
  }
  for (const auto& [name, hashes] : pins) ADD_FAILURE() << PIN_FILE << " pins a case the test does not render: " << name << ". " << REPIN_HOW;
}

// The pins mean FNV-1a 64 (the published test vectors): a change to the hash is not a change to the images.
TEST(PinnedImagesFile, HashIsFnv1a64) {
  EXPECT_EQ(fnv1a("", 0), 0xcbf29ce484222325ull);
  EXPECT_EQ(fnv1a("a", 1), 0xaf63dc4c8601ec8cull);
  EXPECT_EQ(fnv1a("foobar", 6), 0x85944171f73967e8ull);
}

// PHONGVK_REPIN=1 only: renders every case on both backends and, where all agree, rewrites the pin
// file. Nothing is written when any case differs between the backends.
class PinnedImagesRepin : public PinnedImages {
 protected:
  static void SetUpTestSuite() {
    if (repinning()) PinnedImages::SetUpTestSuite();
  }
};

TEST_F(PinnedImagesRepin, WritesThePinFile) {
  if (!repinning()) GTEST_SKIP() << "re-pins only with PHONGVK_REPIN=1 (scripts/repin.sh)";
  std::ostringstream text;
  text << "# Pinned images: tests/pinned_images_gpu_test.cpp renders each case on the reference and the\n"
          "# compute port and requires these FNV-1a 64 hashes of the RGB bytes and of the visibility keys\n"
          "# (little-endian u64, one per sample). Written by scripts/repin.sh (PHONGVK_REPIN=1); never edit\n"
          "# by hand. Re-pin only after an intended change to the contract (docs/DECISIONS.md \"Pinned images\").\n";
  bool agreed = true;
  int count = 0;
  for (const PinCase& c : pinCases()) {
    for (const char* shading : SHADINGS) {
      const std::optional<PinHashes> got = renderBoth(c, shading);
      if (!got) {
        agreed = false;
        continue;
      }
      text << pinLine(caseName(c, shading), *got) << "\n";
      ++count;
    }
  }
  ASSERT_TRUE(agreed) << "the backends differ: " << PIN_FILE << " is left as it was";
  test::writeFile(test::sourcePath(PIN_FILE), text.str());
  std::printf("re-pinned %d cases in %s (reference and %s agree on each)\n", count, PIN_FILE, gpu_->deviceName().c_str());
}

}  // namespace
}  // namespace phongvk
