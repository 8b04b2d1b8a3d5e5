// SceneSpec sequences without a GPU: the expression evaluator's values and messages, the "animate"
// block's rules, applying a track, and a ka sweep rendered by the reference.
#include "tools/contact_sheet.h"
#include "prepare/scene_data.h"
#include "reference/render_reference.h"
#include "scene/animate.h"
#include "scene/expression.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <nlohmann/json.hpp>

#include "test_util.h"

namespace phongvk {
namespace {

using nlohmann::ordered_json;

double eval(const std::string& text, double i = 0, double n = 1) { return evaluateExpression(text, {i, n}); }

// The message of the E that `call` throws, or "(no error)".
template <typename E>
std::string thrownMessage(const std::function<void()>& call) {
  try {
    call();
  } catch (const E& error) {
    return error.what();
  }
  return "(no error)";
}

std::string expressionError(const std::string& text) {
  return thrownMessage<ExpressionError>([&] { eval(text); });
}

TEST(Expression, NumbersAndVariables) {
  EXPECT_EQ(eval("42"), 42);
  EXPECT_EQ(eval("2.5e2"), 250);
  EXPECT_EQ(eval(".5"), 0.5);
  EXPECT_EQ(eval("i", 7, 120), 7);
  EXPECT_EQ(eval("n", 7, 120), 120);
  EXPECT_EQ(eval("pi"), std::numbers::pi);
  EXPECT_EQ(eval("  i / n ", 30, 120), 0.25);  // spaces anywhere between tokens
}

TEST(Expression, PrecedenceAndAssociativity) {
  EXPECT_EQ(eval("1 + 2 * 3"), 7);
  EXPECT_EQ(eval("(1 + 2) * 3"), 9);
  EXPECT_EQ(eval("10 - 4 - 3"), 3);    // left-associative
  EXPECT_EQ(eval("12 / 3 / 2"), 2);    // left-associative
  EXPECT_EQ(eval("2 ^ 3 ^ 2"), 512);   // right-associative: 2^(3^2)
  EXPECT_EQ(eval("-2 ^ 2"), -4);       // unary minus binds looser than ^, as in maths
  EXPECT_EQ(eval("2 ^ -1"), 0.5);      // but a negative exponent needs no parentheses
  EXPECT_EQ(eval("2 * -3"), -6);
  EXPECT_EQ(eval("--3"), 3);
  EXPECT_EQ(eval("+3 - -3"), 6);
  EXPECT_EQ(eval("2 * 3 ^ 2"), 18);
}

TEST(Expression, Functions) {
  EXPECT_DOUBLE_EQ(eval("sin(pi / 2)"), 1);
  EXPECT_DOUBLE_EQ(eval("cos(0)"), 1);
  EXPECT_DOUBLE_EQ(eval("tan(pi / 4)"), 1);
  EXPECT_DOUBLE_EQ(eval("asin(1)"), std::numbers::pi / 2);
  EXPECT_DOUBLE_EQ(eval("acos(1)"), 0);
  EXPECT_DOUBLE_EQ(eval("atan(1)"), std::numbers::pi / 4);
  EXPECT_EQ(eval("sqrt(16)"), 4);
  EXPECT_EQ(eval("abs(-3)"), 3);
  EXPECT_EQ(eval("floor(-2.5)"), -3);
  EXPECT_EQ(eval("min(3, -1)"), -1);
  EXPECT_EQ(eval("max(3, -1)"), 3);
  EXPECT_EQ(eval("pow(2, 10)"), 1024);
  EXPECT_EQ(eval("max(min(i, 5), 2)", 9, 10), 5);
  // The paper's orbit and ks sweep.
  EXPECT_NEAR(eval("5*cos(2*pi*i/n)", 30, 120), 0, 1e-14);
  EXPECT_DOUBLE_EQ(eval("(sin(2*pi*i/n)+1)/2", 30, 120), 1);
}

TEST(Expression, NonFiniteResultsAreReturnedForTheCallerToJudge) {
  EXPECT_TRUE(std::isnan(eval("sqrt(-1)")));
  EXPECT_TRUE(std::isinf(eval("1 / 0")));
}

TEST(Expression, ErrorMessagesSayWhatAndWhere) {
  const std::pair<std::string, std::string> cases[] = {
      {"2*sine(i)", "unknown function 'sine' at column 3"},
      {"x + 1", "unknown variable 'x' (known: i, n, pi) at column 1"},
      {"", "empty expression at column 1"},
      {"   ", "empty expression at column 1"},
      {"1 +", "unexpected end of expression at column 4"},
      {"(1 + 2", "expected ')' before the end of the expression at column 7"},
      {"min(1 2)", "expected ')', got '2' at column 7"},
      {"1 + 2)", "unexpected ')' at column 6"},
      {"2i", "unexpected 'i' at column 2"},  // no implicit multiplication
      {"3 $ 4", "unexpected '$' at column 3"},
      {"min(1)", "'min' takes 2 arguments, got 1 at column 1"},
      {"sin(1, 2)", "'sin' takes 1 argument, got 2 at column 1"},
      {"1 + sin", "'sin' is a function: write sin(...) at column 5"},
      {".", "malformed number at column 1"},
      {"1e999", "number out of range at column 1"},
      // Deep nesting is refused rather than allowed to exhaust the stack (64 levels are fine).
      {std::string(100, '(') + "1" + std::string(100, ')'), "nested too deeply at column 65"},
  };
  for (const auto& [text, message] : cases) EXPECT_EQ(expressionError(text), message) << text;
  EXPECT_EQ(eval(std::string(63, '(') + "1" + std::string(63, ')')), 1);
}

// ---- the "animate" block ----

const char* kScene = R"({
  "camera": {"position": [-3, 0, 1], "look_at": [0, 0, 0], "width": 48, "height": 32},
  "lights": [{"position": [-1, -1, 2]}],
  "materials": {"grey": {"ka": 0.15}},
  "objects": [{"shape": "sphere", "radius": 0.5, "segments": 12, "material": {"ks": 0.8}},
              {"shape": "cube", "center": [0, 0, -1], "material": "grey"}]
})";

// kScene with `animate` added.
ordered_json animated(const ordered_json& animate) {
  ordered_json scene = ordered_json::parse(kScene);
  scene["animate"] = animate;
  return scene;
}

SceneSequence sequenceOf(const ordered_json& scene) { return SceneSequence(scene, "a.json", "."); }

std::string sceneError(const std::function<void()>& call) { return thrownMessage<SceneError>(call); }

std::string animateError(const ordered_json& animate) {
  return sceneError([&] { sequenceOf(animated(animate)); });
}

ordered_json oneTrack(const ordered_json& track, int frames = 3) {
  return {{"frames", frames}, {"tracks", ordered_json::array({track})}};
}

TEST(Animate, SceneWithoutAnimateIsOneFrame) {
  const SceneSequence sequence = sequenceOf(ordered_json::parse(kScene));
  EXPECT_EQ(sequence.frameCount(), 1);
  EXPECT_EQ(sequence.frame(0).camera.position, glm::dvec3(-3, 0, 1));
}

TEST(Animate, TrackChangesExactlyItsValue) {
  const ordered_json scene = animated(oneTrack({{"path", "objects[0].material.ks"}, {"values", {0, 0.5, 1}}}));
  const SceneSequence sequence = sequenceOf(scene);
  ASSERT_EQ(sequence.frameCount(), 3);
  for (int i = 0; i < 3; ++i) {
    ordered_json expected = ordered_json::parse(kScene);
    expected["objects"][0]["material"]["ks"] = 0.5 * i;
    EXPECT_EQ(sequence.frameJson(i), expected) << "frame " << i;
  }
  EXPECT_EQ(sequence.frame(1).materials[sequence.frame(1).objects[0].material].ks, 0.5f);
}

TEST(Animate, TrackMayAddAKeyLeftToItsDefault) {
  const SceneSequence sequence = sequenceOf(animated(oneTrack({{"path", "materials.grey.kd"}, {"expression", "i/2"}})));
  EXPECT_EQ(sequence.frameJson(2)["materials"]["grey"]["kd"], 1.0);
  EXPECT_EQ(sequence.frame(2).materials[0].kd, 1.0f);
}

TEST(Animate, VectorExpressionMixesNumbersAndStrings) {
  const ordered_json track = {{"path", "camera.position"}, {"expression", {"5*cos(2*pi*i/n)", "5*sin(2*pi*i/n)", 2.5}}};
  const SceneSequence sequence = sequenceOf(animated(oneTrack(track, 4)));
  const glm::dvec3 eye = sequence.frame(1).camera.position;
  EXPECT_NEAR(eye.x, 0, 1e-12);
  EXPECT_DOUBLE_EQ(eye.y, 5);
  EXPECT_EQ(eye.z, 2.5);
  // look_at stays fixed in the file, so the view keeps facing the origin.
  EXPECT_NEAR(glm::dot(glm::normalize(sequence.frame(1).camera.direction), glm::normalize(-eye)), 1, 1e-12);
}

TEST(Animate, LaterTrackWinsAtTheSamePath) {
  const ordered_json animate = {{"frames", 2},
                                {"tracks", {{{"path", "materials.grey.ka"}, {"values", {0.1, 0.2}}},
                                            {{"path", "materials.grey.ka"}, {"expression", "0.3"}}}}};
  EXPECT_EQ(sequenceOf(animated(animate)).frame(0).materials[0].ka, 0.3f);
}

TEST(Animate, GeometryTracksAreThoseUnderObjectsButNotTheirMaterial) {
  const ordered_json animate = {{"frames", 3},
                                {"tracks", {{{"path", "objects[0].material.ks"}, {"values", {0, 0.5, 1}}},
                                            {{"path", "objects[1].size"}, {"values", {1, 1, 2}}},
                                            {{"path", "camera.fov"}, {"values", {50, 60, 70}}}}}};
  const SceneSequence sequence = sequenceOf(animated(animate));
  EXPECT_FALSE(sequence.tracks()[0].geometry);
  EXPECT_TRUE(sequence.tracks()[1].geometry);
  EXPECT_FALSE(sequence.tracks()[2].geometry);
  EXPECT_FALSE(sequence.geometryDiffers(0, 1));  // only the size moves, and only at frame 2
  EXPECT_TRUE(sequence.geometryDiffers(1, 2));
}

TEST(Animate, ParseSceneGivesFrameZero) {
  const ordered_json scene = animated(oneTrack({{"path", "camera.fov"}, {"expression", "40 + 10*i"}}));
  EXPECT_EQ(parseSceneSpec(scene.dump(), "a.json", ".").camera.fov, 40);
}

TEST(Animate, BlockErrors) {
  EXPECT_EQ(animateError(ordered_json::array()), "a.json: animate: must be an object, got array");
  EXPECT_EQ(animateError({{"frames", 2}, {"tracks", ordered_json::array()}, {"loop", true}}),
            "a.json: animate.loop: unknown key (allowed: frames, tracks)");
  EXPECT_EQ(animateError({{"tracks", ordered_json::array()}}), "a.json: animate: missing required field 'frames'");
  EXPECT_EQ(animateError({{"frames", 0}, {"tracks", ordered_json::array()}}),
            "a.json: animate.frames: must be between 1 and 100000, got 0");
  EXPECT_EQ(animateError({{"frames", 2}, {"tracks", {}}}), "a.json: animate.tracks: must be an array, got null");
}

TEST(Animate, TrackErrors) {
  EXPECT_EQ(animateError(oneTrack({{"path", "camera.fov"}})),
            "a.json: animate.tracks[0]: needs 'values' or 'expression'");
  EXPECT_EQ(animateError(oneTrack({{"path", "camera.fov"}, {"values", {1, 2, 3}}, {"expression", "i"}})),
            "a.json: animate.tracks[0].expression: cannot be given together with 'values'");
  EXPECT_EQ(animateError(oneTrack({{"path", "camera.fov"}, {"values", {60, 70}}})),
            "a.json: animate.tracks[0].values: length must equal frames (3), got 2");
  EXPECT_EQ(animateError(oneTrack({{"path", "camera.fov"}, {"expression", true}})),
            "a.json: animate.tracks[0].expression: must be a string or a non-empty array of numbers and "
            "strings, got boolean");
  EXPECT_EQ(animateError(oneTrack({{"path", "camera.position"}, {"expression", {1, false, 2}}})),
            "a.json: animate.tracks[0].expression[1]: must be a number or a string, got boolean");
  EXPECT_EQ(animateError(oneTrack({{"path", "camera.fov"}, {"expression", "60"}, {"ease", "in"}})),
            "a.json: animate.tracks[0].ease: unknown key (allowed: path, values, expression)");
}

TEST(Animate, ExpressionErrorsNameTheElementAndColumn) {
  const ordered_json animate = {
      {"frames", 3},
      {"tracks", {{{"path", "camera.fov"}, {"expression", "60"}},
                  {{"path", "camera.position"}, {"expression", {"sine(i)", 0, 1}}}}}};
  EXPECT_EQ(animateError(animate), "a.json: animate.tracks[1].expression[0]: unknown function 'sine' at column 1");
}

TEST(Animate, NonFiniteExpressionNamesTheFrame) {
  EXPECT_EQ(animateError(oneTrack({{"path", "camera.fov"}, {"expression", "60 + 1/(i - 17)"}}, 20)),
            "a.json: animate.tracks[0].expression: evaluates to inf at frame 17 (i = 17, n = 20)");
  EXPECT_EQ(animateError(oneTrack({{"path", "camera.position"}, {"expression", {0, "sqrt(1 - i)", 1}}})),
            "a.json: animate.tracks[0].expression[1]: evaluates to nan at frame 2 (i = 2, n = 3)");
}

TEST(Animate, PathErrors) {
  auto pathError = [](const std::string& path) {
    return animateError(oneTrack({{"path", path}, {"values", {1, 2, 3}}}));
  };
  EXPECT_EQ(pathError("objects[9].radius"), "a.json: animate.tracks[0].path: 'objects[9]' does not exist");
  EXPECT_EQ(pathError("camera.lens.focal"), "a.json: animate.tracks[0].path: 'camera.lens' does not exist");
  EXPECT_EQ(pathError("objects[1].material.ks"),
            "a.json: animate.tracks[0].path: 'objects[1].material.ks' does not exist ('objects[1].material' is "
            "string)");
  EXPECT_EQ(pathError("camera[0]"), "a.json: animate.tracks[0].path: 'camera[0]' does not exist ('camera' is object)");
  EXPECT_EQ(pathError(""), "a.json: animate.tracks[0].path: must not be empty");
  EXPECT_EQ(pathError("objects[x]"),
            "a.json: animate.tracks[0].path: malformed path 'objects[x]': expected an index and ']' after column 8");
  EXPECT_EQ(pathError("camera..fov"),
            "a.json: animate.tracks[0].path: malformed path 'camera..fov': expected a key at column 8");
  EXPECT_EQ(pathError("objects[0]radius"),
            "a.json: animate.tracks[0].path: malformed path 'objects[0]radius': unexpected 'r' at column 11");
  EXPECT_EQ(pathError("animate.frames"), "a.json: animate.tracks[0].path: cannot animate the animate block");
}

TEST(Animate, EachFrameIsValidatedLikeASceneFile) {
  const SceneSequence sequence =
      sequenceOf(animated(oneTrack({{"path", "objects[0].material.ks"}, {"expression", "1 - i"}})));
  EXPECT_EQ(sequence.frame(1).materials.size(), 2u);
  EXPECT_EQ(sceneError([&] { sequence.frame(2); }),
            "a.json: frame 2: objects[0].material.ks: must be >= 0, got -1");
  // A value of the wrong type is the scene loader's error, at the animated path.
  const ordered_json badType = oneTrack({{"path", "camera.fov"}, {"values", {60, "wide", 60}}});
  EXPECT_EQ(sceneError([&] { sequenceOf(animated(badType)).frame(1); }),
            "a.json: frame 1: camera.fov: must be a number, got string");
  // parseSceneSpec checks frame 0 of an animated scene the same way.
  const ordered_json badFirst = oneTrack({{"path", "camera.fov"}, {"values", {0, 60, 60}}});
  EXPECT_EQ(sceneError([&] { parseSceneSpec(animated(badFirst).dump(), "a.json", "."); }),
            "a.json: frame 0: camera.fov: must be > 0 and < 180, got 0");
}

TEST(Animate, LoadReadsTheFileAndResolvesAgainstItsFolder) {
  const std::string dir = test::makeTempDir();
  test::writeFile(dir + "/s.json", animated(oneTrack({{"path", "camera.fov"}, {"values", {50, 60, 70}}})).dump());
  const SceneSequence sequence = SceneSequence::load(dir + "/s.json");
  EXPECT_EQ(sequence.frameCount(), 3);
  EXPECT_EQ(sequence.frame(2).camera.fov, 70);
  EXPECT_EQ(sequence.frame(2).path, dir + "/s.json");
  EXPECT_EQ(sceneError([&] { SceneSequence::load(dir + "/missing.json"); }),
            dir + "/missing.json: cannot read file: No such file or directory");
}

// ---- rendering a sweep with the reference ----

double meanBrightness(const Image& image) {
  double sum = 0;
  for (uint8_t v : image.rgb) sum += v;
  return sum / double(image.rgb.size());
}

// More ambient light can only brighten: every frame of a ka sweep is brighter than the one before
// (the sphere covers enough pixels that each 0.1 step moves the mean).
TEST(Animate, KaSweepBrightnessIsStrictlyMonotone) {
  const SceneSequence sequence = SceneSequence::load(test::sourcePath("scenes/paper/fig4_ka_sweep.json"));
  double previous = -1;
  for (int i = 0; i < sequence.frameCount(); i += sequence.frameCount() / 10) {
    const SceneSpec scene = sequence.frame(i);
    const SceneData data = buildSceneData(scene);
    const View view = makeView(withImageSize(scene.camera, 96, 64));
    const double mean = meanBrightness(renderReference(data, makeFrame(data, view)).image);
    EXPECT_GT(mean, previous) << "frame " << i;
    previous = mean;
  }
}

// ---- contact sheets ----

TEST(ContactSheet, BoxFilterAveragesEachBlock) {
  Image image(4, 2);
  const uint8_t values[8] = {0, 100, 10, 20, 200, 30, 40, 50};  // row-major, one grey per pixel
  for (int k = 0; k < 8; ++k) std::fill_n(image.pixel(k % 4, k / 4), 3, values[k]);
  const Image small = downscale(image, 2, 1);
  EXPECT_EQ(small.pixel(0, 0)[0], 83);  // (0 + 100 + 200 + 30) / 4 = 82.5, rounded
  EXPECT_EQ(small.pixel(1, 0)[0], 30);  // (10 + 20 + 40 + 50) / 4
}

TEST(ContactSheet, GridOfLabelledThumbnails) {
  std::vector<Thumbnail> thumbnails;
  for (int k = 0; k < 5; ++k) {
    Image image(40, 30);
    std::fill(image.rgb.begin(), image.rgb.end(), uint8_t(100 + k));
    thumbnails.push_back({k * 10, image});
  }
  const Image sheet = contactSheet(thumbnails, sheetColumns(5));  // 3 columns, 2 rows
  EXPECT_EQ(sheetColumns(5), 3);
  EXPECT_EQ(sheet.width, 4 + 3 * (40 + 4));
  EXPECT_EQ(sheet.height, 4 + 2 * (30 + 4));
  EXPECT_EQ(sheet.pixel(4 + 44 + 39, 4 + 29)[0], 101);  // frame 10's thumbnail, bottom-right pixel
  EXPECT_EQ(sheet.pixel(4, 4)[0], 0);                   // its label's box, top-left of frame 0
  EXPECT_EQ(sheet.pixel(sheet.width - 5, sheet.height - 5)[0], 40);  // the empty sixth cell
}

}  // namespace
}  // namespace phongvk
