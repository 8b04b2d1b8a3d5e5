// bad_input_test.cpp — every kind of bad input gets its exact, clear error, never a crash, a hang
// or a NaN image. Complements scene_test.cpp (which covers the loader's basic cases): here are
// the syntax corner cases, out-of-range values that used to reach the renderers as Inf/NaN,
// broken OBJ files, unreadable and odd files, and the CLI's exit codes and output files.
#include "tools/contact_sheet.h"
#include "phongvk/image.h"
#include "prepare/scene_data.h"
#include "scene/scene.h"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "test_util.h"

namespace phongvk {
namespace {

namespace fs = std::filesystem;

const char* kCamera = R"("camera": {"position": [0, 0, 0], "direction": [1, 0, 0]})";

// A scene with the minimal camera, `rest` (JSON members) and a default sphere unless rest has
// its own objects.
std::string sceneWith(const std::string& rest) {
  const bool hasObjects = rest.find("\"objects\"") != std::string::npos;
  return std::string("{") + kCamera + (rest.empty() ? "" : ", " + rest) +
         (hasObjects ? "" : R"(, "objects": [{"shape": "sphere"}])") + "}";
}

// The message of the SceneError `call` throws, or "(no error)".
template <typename F>
std::string sceneErrorOf(F&& call) {
  try {
    call();
  } catch (const SceneError& error) {
    return error.what();
  }
  return "(no error)";
}

// The error for scene text whose relative files resolve against `dir`.
std::string errorFor(const std::string& text, const std::string& dir = ".") {
  return sceneErrorOf([&] { parseSceneSpec(text, "a.json", dir); });
}

std::string loadError(const std::string& path) {
  return sceneErrorOf([&] { loadSceneSpec(path); });
}

// ---- JSON syntax ----

TEST(BadInputSyntax, ErrorsNameLineAndColumn) {
  EXPECT_EQ(errorFor("{\n  \"camera\": \"abc\n}"),
            "a.json: JSON syntax error at line 2, column 17: invalid string: control character U+000A (LF) must be "
            "escaped to \\u000A or \\n");
  EXPECT_EQ(errorFor("{\"camera\": {}} {}"),
            "a.json: JSON syntax error at line 1, column 16: unexpected '{'; expected end of input");
  // Windows line endings: the line count is the same.
  EXPECT_EQ(errorFor("{\r\n\"objects\": [\r\n  1,,\r\n]}"),
            "a.json: JSON syntax error at line 3, column 5: unexpected ','; expected '[', '{', or a literal");
}

// JSON has no NaN or Infinity: they are syntax errors, never numbers that reach the renderer.
TEST(BadInputSyntax, NanAndInfinityLiterals) {
  EXPECT_EQ(errorFor(R"({"camera": {"fov": NaN}})"), "a.json: JSON syntax error at line 1, column 20: invalid literal");
  EXPECT_EQ(errorFor(R"({"camera": {"fov": Infinity}})"),
            "a.json: JSON syntax error at line 1, column 20: invalid literal");
  EXPECT_EQ(errorFor(R"({"camera": {"fov": -Infinity}})"),
            "a.json: JSON syntax error at line 1, column 21: invalid number; expected digit after '-'");
}

TEST(BadInputSyntax, EmptyAndWhitespaceOnlyFiles) {
  EXPECT_EQ(errorFor("  \n\t\n"),
            "a.json: JSON syntax error at line 3, column 1: unexpected end of input; expected '[', '{', or a literal");
  EXPECT_EQ(errorFor("null"), "a.json: top level: must be an object, got null");
  EXPECT_EQ(errorFor("{}"), "a.json: top level: missing required field 'camera'");
}

// ---- types and keys the other suite does not reach ----

TEST(BadInputTypes, WrongTypesNameTheirPath) {
  EXPECT_EQ(errorFor(sceneWith(R"("objects": {})")), "a.json: objects: must be an array, got object");
  EXPECT_EQ(errorFor(sceneWith(R"("materials": [])")), "a.json: materials: must be an object, got array");
  EXPECT_EQ(errorFor(sceneWith(R"("lights": [{"position": [0, 0, 1], "color": "white"}])")),
            "a.json: lights[0].color: must be an array of 3 numbers, got string");
  EXPECT_EQ(errorFor(sceneWith(R"("objects": [{"shape": "polyhedron", "points": [[0,0,0],[1,0,0],[0,1,0],7]}])")),
            "a.json: objects[0].points[3]: must be an array of 3 numbers, got number");
  EXPECT_EQ(errorFor(sceneWith(R"("objects": [{"shape": "cube", "subdivide": "2"}])")),
            "a.json: objects[0].subdivide: must be an integer, got string");
  EXPECT_EQ(errorFor(sceneWith(R"("objects": [{"shape": 3}])")), "a.json: objects[0].shape: must be a string, got number");
  EXPECT_EQ(errorFor(sceneWith(R"("render": "screen")")), "a.json: render: must be an object, got string");
  EXPECT_EQ(errorFor(R"({"camera": {"position": [0, 0, 0], "direction": [1, 0, 0], "up": {"z": 1}},
                         "objects": [{"shape": "sphere"}]})"),
            "a.json: camera.up: must be an array of 3 numbers, got object");
}

TEST(BadInputTypes, UnknownKeysInRenderAndInlineMaterials) {
  EXPECT_EQ(errorFor(sceneWith(R"("render": {"mode": "screen"})")),
            "a.json: render.mode: unknown key (allowed: interpolation, shading, specular, samples, texture_filter, point_size, line_width)");
  EXPECT_EQ(errorFor(sceneWith(R"("objects": [{"shape": "sphere"}, {"shape": "cube", "material": {"shine": 1}}])")),
            "a.json: objects[1].material.shine: unknown key (allowed: ka, kd, ks, n, attenuation, color, texture)");
}

// ---- numbers: out of range, overflowing, too large for the renderers ----

TEST(BadInputNumbers, OverflowingLiteralsAnywhere) {
  EXPECT_EQ(errorFor(sceneWith(R"("materials": {"m": {"kd": 1e999}})")),
            "a.json: materials.m.kd: must be finite, got 1e999");
  EXPECT_EQ(errorFor(sceneWith(R"("lights": [{"position": [0, 0, 1], "color": [1, -1e400, 1]}])")),
            "a.json: lights[0].color[1]: must be finite, got -1e400");
  EXPECT_EQ(errorFor(sceneWith(R"("lights": [{"position": [0, 0, 1], "intensity": 1e39}])")),
            "a.json: lights[0].intensity: too large for a 32-bit float, got 1e+39");
}

TEST(BadInputNumbers, NegativeMaterialCoefficients) {
  EXPECT_EQ(errorFor(sceneWith(R"("materials": {"m": {"ka": -0.1}})")), "a.json: materials.m.ka: must be >= 0, got -0.1");
  EXPECT_EQ(errorFor(sceneWith(R"("materials": {"m": {"kd": -1}})")), "a.json: materials.m.kd: must be >= 0, got -1");
  EXPECT_EQ(errorFor(sceneWith(R"("materials": {"m": {"n": -2}})")), "a.json: materials.m.n: must be >= 0, got -2");
  EXPECT_EQ(errorFor(sceneWith(R"("materials": {"m": {"color": [0.5, -0.5, 0.5]}})")),
            "a.json: materials.m.color[1]: must be >= 0, got -0.5");
}

// 0 - d + d^2 is negative for 0 < d < 1: no constant term to keep it positive near the light.
TEST(BadInputNumbers, AttenuationNegativeNearTheLight) {
  EXPECT_EQ(errorFor(sceneWith(R"("materials": {"m": {"attenuation": [0, -1, 1]}})")),
            "a.json: materials.m.attenuation: a + b*d + c*d^2 must stay positive for all distances d > 0, got [0, "
            "-1, 1]");
}

TEST(BadInputNumbers, FieldOfViewOutOfRange) {
  EXPECT_EQ(errorFor(R"({"camera": {"position": [0, 0, 0], "direction": [1, 0, 0], "fov": -10},
                         "objects": [{"shape": "sphere"}]})"),
            "a.json: camera.fov: must be > 0 and < 180, got -10");
  EXPECT_EQ(errorFor(R"({"camera": {"position": [0, 0, 0], "direction": [1, 0, 0], "fov": 200},
                         "objects": [{"shape": "sphere"}]})"),
            "a.json: camera.fov: must be > 0 and < 180, got 200");
}

// A positive fov so small that the focal length overflows float (it made Inf/NaN vertices), and
// a near plane that rounds to 0 as a float (the renderers would divide by w = 0).
TEST(BadInputNumbers, FovAndNearTooSmallForFloats) {
  EXPECT_EQ(errorFor(R"({"camera": {"position": [0, 0, 0], "direction": [1, 0, 0], "fov": 1e-40, "width": 64,
                                    "height": 48}, "objects": [{"shape": "sphere"}]})"),
            "a.json: camera.fov: must be >= 1e-06 degrees (a narrower view overflows 32-bit floats), got 1e-40");
  EXPECT_EQ(errorFor(R"({"camera": {"position": [0, 0, 0], "direction": [1, 0, 0], "near": 1e-50},
                         "objects": [{"shape": "sphere"}]})"),
            "a.json: camera.near: must be >= 1.1754944e-38 (the smallest normal 32-bit float), got 1e-50");
}

// Finite doubles that are no usable world coordinate: 1e300 m became an infinite float offset
// from the eye and NaN vertex positions.
TEST(BadInputNumbers, CoordinatesBeyondTheSceneRange) {
  const std::string range = "must be between -1e+15 and 1e+15, got ";
  EXPECT_EQ(errorFor(sceneWith(R"("objects": [{"shape": "sphere", "center": [1e300, 0, 0]}])")),
            "a.json: objects[0].center[0]: " + range + "1e+300");
  EXPECT_EQ(errorFor(sceneWith(R"("lights": [{"position": [0, -2e15, 0]}])")),
            "a.json: lights[0].position[1]: " + range + "-2e+15");
  EXPECT_EQ(errorFor(R"({"camera": {"position": [0, 0, 1e16], "direction": [1, 0, 0]}, "objects": [{"shape": "sphere"}]})"),
            "a.json: camera.position[2]: " + range + "1e+16");
  EXPECT_EQ(errorFor(R"({"camera": {"position": [0, 0, 0], "look_at": [1e20, 0, 0]}, "objects": [{"shape": "sphere"}]})"),
            "a.json: camera.look_at[0]: " + range + "1e+20");
  EXPECT_EQ(errorFor(sceneWith(R"("objects": [{"shape": "polyhedron", "points": [[0,0,0],[1,0,0],[0,1,0],[0,0,5e15]]}])")),
            "a.json: objects[0].points[3][2]: " + range + "5e+15");
  EXPECT_EQ(errorFor(sceneWith(R"("objects": [{"shape": "sphere", "radius": 1e300}])")),
            "a.json: objects[0].radius: must be <= 1e+15, got 1e+300");
}

// Direction lengths that cannot be normalized: one whose square underflows, one overflowing.
TEST(BadInputNumbers, DirectionsThatCannotBeNormalized) {
  EXPECT_EQ(errorFor(R"({"camera": {"position": [0, 0, 0], "direction": [1e-320, 0, 0]}, "objects": [{"shape": "sphere"}]})"),
            "a.json: camera.direction: must have a non-zero finite length, got length 0");
  EXPECT_EQ(errorFor(R"({"camera": {"position": [0, 0, 0], "direction": [1e308, 1e308, 0]}, "objects": [{"shape": "sphere"}]})"),
            "a.json: camera.direction: must have a non-zero finite length, got length inf");
}

TEST(BadInputNumbers, IntegersOutOfRange) {
  EXPECT_EQ(errorFor(sceneWith(R"("objects": [{"shape": "sphere", "segments": 1e10}])")),
            "a.json: objects[0].segments: must be between 3 and 4096, got 1e+10");
  EXPECT_EQ(errorFor(sceneWith(R"("objects": [{"shape": "icosphere", "subdivide": -1}])")),
            "a.json: objects[0].subdivide: must be between 0 and 10, got -1");
}

// ---- OBJ meshes ----

class BadMesh : public ::testing::Test {
 protected:
  // The error for a scene whose only object is `obj` (written to mesh.obj) at `scale`.
  std::string meshError(const std::string& obj, double scale = 1) {
    test::writeFile(dir_ + "/mesh.obj", obj);
    const std::string scene = sceneWith(R"("objects": [{"shape": "mesh", "file": "mesh.obj", "scale": )" +
                                        std::to_string(scale) + "}]");
    return sceneErrorOf([&] { buildSceneData(parseSceneSpec(scene, "a.json", dir_)); });
  }

  // What every OBJ error starts with: the scene file, the JSON path, the OBJ file.
  std::string prefix() const { return "a.json: objects[0].file: " + dir_ + "/mesh.obj: "; }

  const std::string dir_ = test::makeTempDir();
};

TEST_F(BadMesh, IndicesOutOfRange) {
  EXPECT_EQ(meshError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n"),
            prefix() + "line 4: face corner '9': vertex index 9 is out of range (the file has 3 vertices)");
  EXPECT_EQ(meshError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -9 1 2\n"),
            prefix() + "line 4: face corner '-9': vertex index -9 is out of range (the file has 3 vertices)");
  EXPECT_EQ(meshError("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//4\n"),
            prefix() + "line 5: face corner '3//4': normal index 4 is out of range (the file has 1 normals)");
  // A negative index counts back from the 'v' lines before it: -4 on line 5 reaches before the first.
  EXPECT_EQ(meshError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -3\nf -1 -2 -4\nv 1 1 0\n"),
            prefix() + "line 5: face corner '-4': vertex index -4 is out of range (the file has 4 vertices)");
}

TEST_F(BadMesh, NonFiniteOrOverflowingPositions) {
  // 1e39 overflows the float tinyobjloader reads it into. ("nan" and other non-numbers it reads as 0.)
  EXPECT_EQ(meshError("v 1e39 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"), prefix() + "a vertex position is not a finite number");
  // Finite floats, but 1e10 * 1e10 m is beyond any scene (as a float it used to become inf).
  EXPECT_EQ(meshError("v 1e10 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\n", 1e10),
            prefix() + "a vertex coordinate after the object's scale and rotation is 1e+20, beyond the 1e+15 m a scene may use");
}

// (A file of 'v' lines alone is a point cloud: mesh_primitives_test.)
TEST_F(BadMesh, NothingToDraw) {
  EXPECT_EQ(meshError(""), prefix() + "nothing to draw (no 'f', 'l', 'p' or 'v' lines)");
  EXPECT_EQ(meshError("vn 0 0 1\nvt 0 0\n"), prefix() + "nothing to draw (no 'f', 'l', 'p' or 'v' lines)");
  EXPECT_EQ(meshError("v 0 0 0\nv 1 1 1\nv 2 2 2\nf 1 2 3\nf 1 1 2\n"),
            prefix() + "every triangle is degenerate (zero area)");
}

TEST_F(BadMesh, BinaryGarbage) {
  std::string garbage = "\x7f" "ELF\x02\x01\x01";
  for (int i = 0; i < 256; ++i) garbage += char(i);
  EXPECT_EQ(meshError(garbage), prefix() + "not a text file (it holds NUL bytes: binary, or UTF-16 text, which OBJ is not)");
}

// ---- files ----

TEST(BadInputFiles, SceneFileThatIsAFolderOrAFifo) {
  const std::string dir = test::makeTempDir();
  EXPECT_EQ(loadError(dir), dir + ": cannot read file: Is a directory");
  const std::string fifo = dir + "/pipe.json";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  // Opening a FIFO for reading would block until a writer comes: refused before opening.
  EXPECT_EQ(loadError(fifo), fifo + ": cannot read file: a FIFO (named pipe), not a regular file");
}

TEST(BadInputFiles, MeshFileThatIsAFifo) {
  const std::string dir = test::makeTempDir();
  ASSERT_EQ(mkfifo((dir + "/mesh.obj").c_str(), 0600), 0);
  EXPECT_EQ(errorFor(sceneWith(R"("objects": [{"shape": "mesh", "file": "mesh.obj"}])"), dir),
            "a.json: objects[0].file: cannot read 'mesh.obj': a FIFO (named pipe), not a regular file");
}

// chmod 000 stops reads for everyone but root, and tests may run as root (CI containers do): the
// CLI then runs as an unprivileged user (runCliUnprivileged), so the check is real either way.
TEST(BadInputFiles, UnreadableSceneAndMeshFiles) {
  const std::string dir = test::makeTempDir();
  chmod(dir.c_str(), 0777);  // the unprivileged CLI may look for its output folder here
  test::writeFile(dir + "/scene.json", sceneWith(R"("objects": [{"shape": "mesh", "file": "mesh.obj"}])"));
  test::writeFile(dir + "/mesh.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  chmod((dir + "/scene.json").c_str(), 0644);
  chmod((dir + "/mesh.obj").c_str(), 0);
  const std::string render = "render " + dir + "/scene.json -o " + dir + "/x.png --backend cpu";
  test::CommandResult r = test::runCliUnprivileged(render);
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find(dir + "/scene.json: objects[0].file: cannot read 'mesh.obj': Permission denied"),
            std::string::npos)
      << r.output;
  chmod((dir + "/scene.json").c_str(), 0);
  r = test::runCliUnprivileged(render);
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find(dir + "/scene.json: cannot read file: Permission denied"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir + "/x.png"));
}

// ---- the CLI: exit codes, messages, and no file left behind ----

// Files in `dir` (temporary files of an interrupted write included).
std::vector<std::string> filesIn(const std::string& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename().string());
  return names;
}

class BadCli : public ::testing::Test {
 protected:
  // Runs `phongvk args`, expecting `exitCode` and `message` in the output and no file in out_.
  void expectFailure(const std::string& args, int exitCode, const std::string& message) {
    const test::CommandResult result = test::runCli(args);
    EXPECT_EQ(result.exitCode, exitCode) << args << "\n" << result.output;
    EXPECT_NE(result.output.find(message), std::string::npos) << args << "\n" << result.output;
    EXPECT_EQ(filesIn(out_), std::vector<std::string>{}) << args << ": a file was left behind";
  }

  std::string scene(const std::string& name) const { return test::sourcePath("scenes/stress/" + name); }

  const std::string out_ = test::makeTempDir();
};

TEST_F(BadCli, UnwritableOutputPaths) {
  const std::string one = scene("one_pixel.json");
  expectFailure("render " + one + " -o " + out_ + "/missing/x.png", 2,
                "error: cannot write '" + out_ + "/missing/x.png': folder '" + out_ + "/missing' does not exist");
  expectFailure("render " + one + " -o " + out_, 2, "error: cannot write '" + out_ + "': it is a folder");
  const std::string file = test::makeTempDir() + "/file";
  test::writeFile(file, "");
  expectFailure("render " + one + " -o " + file + "/x.png", 2,
                "error: cannot write '" + file + "/x.png': '" + file + "' is a file, not a folder");
  expectFailure("diff " + one + " --heatmap " + out_ + "/missing/h.png", 2, "error: cannot write");
}

TEST_F(BadCli, ReadOnlyOutputFolder) {
  // As root the CLI runs unprivileged (runCliUnprivileged), so the read-only folder really stops it.
  chmod(out_.c_str(), 0555);
  const test::CommandResult r =
      test::runCliUnprivileged("render " + scene("one_pixel.json") + " -o " + out_ + "/x.png --backend cpu");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("is not writable"), std::string::npos) << r.output;
  chmod(out_.c_str(), 0755);
  EXPECT_EQ(filesIn(out_), std::vector<std::string>{});
}

TEST_F(BadCli, UnknownOrBadOptions) {
  const std::string render = "render " + scene("one_pixel.json") + " -o " + out_ + "/x.png";
  expectFailure(render + " --frobnicate", 2, "The following argument was not expected: --frobnicate");
  expectFailure(render + " --width 0 --height 3", 2, "--width: Value 0 not in range 1 to 16384");
  expectFailure(render + " --width 30", 2, "--width requires --height");
  expectFailure(render + " --backend opengl", 2, "--backend");
  expectFailure("render", 2, "scene is required");
  expectFailure("", 2, "A subcommand is required");
}

TEST_F(BadCli, BadSceneWritesNothing) {
  const std::string dir = test::makeTempDir();
  test::writeFile(dir + "/bad.json", sceneWith(R"("objects": [{"shape": "sphere", "radius": -1}])"));
  for (const char* backend : {"cpu", "gpu"}) {
    expectFailure("render " + dir + "/bad.json --backend " + backend + " -o " + out_ + "/x.png", 2,
                  "error: " + dir + "/bad.json: objects[0].radius: must be > 0, got -1");
  }
}

}  // namespace
}  // namespace phongvk

namespace phongvk {
namespace {

// Every frame of an animated scene is validated before anything is rendered, by render and diff
// as by sequence: a radius that turns negative at frame 25 fails a one-frame render of frame 0.
TEST_F(BadCli, RenderAndDiffValidateEveryFrame) {
  const std::string dir = test::makeTempDir();
  test::writeFile(dir + "/shrinks.json", R"({"camera": {"position": [3, 0, 0], "look_at": [0, 0, 0], "width": 8, "height": 6},
    "objects": [{"shape": "sphere", "radius": 1}],
    "animate": {"frames": 30, "tracks": [{"path": "objects[0].radius", "expression": "1 - i/24.5"}]}})");
  const std::string message = "error: " + dir + "/shrinks.json: frame 25: ";
  expectFailure("render " + dir + "/shrinks.json --backend cpu -o " + out_ + "/x.png", 2, message);
  expectFailure("diff " + dir + "/shrinks.json --heatmap " + out_ + "/h.png", 2, message);
  expectFailure("sequence " + dir + "/shrinks.json --backend cpu -o " + out_, 2, message);
}

// Errors found while building meshes (a hull, a mesh file) name the scene file first, like every other.
TEST_F(BadCli, MeshBuildingErrorsNameTheSceneFile) {
  const std::string dir = test::makeTempDir();
  test::writeFile(dir + "/flat.json", sceneWith(R"("objects": [{"shape": "polyhedron",
    "points": [[0, 0, 1], [1, 0, 1], [0, 1, 1], [1, 1, 1]]}])"));
  expectFailure("render " + dir + "/flat.json --backend cpu -o " + out_ + "/x.png", 2,
                "error: " + dir + "/flat.json: objects[0].points: the points are coplanar");
}

TEST_F(BadCli, OptionsThatCannotApply) {
  const std::string one = scene("one_pixel.json");
  expectFailure("diff " + one + " --tolerance nan", 2, "--tolerance: must be a number from 0 to 255, got nan");
  expectFailure("diff " + one + " --tolerance -1", 2, "--tolerance");
  expectFailure("render " + one + " --backend cpu --device 0 -o " + out_ + "/x.png", 2,
                "error: --device 0 selects a Vulkan device, and --backend cpu uses none");
}

}  // namespace
}  // namespace phongvk

namespace phongvk {
namespace {

// Nesting is bounded before anything is built, and messages stay short whatever the file holds: a
// 200 KB file of 100,000 brackets cost gigabytes when every level kept its full path.
TEST(BadInputLimits, DeepNestingAndHugeKeysGiveShortErrors) {
  const std::string deep = R"({"camera": {"position": [1, 0, 0], "look_at": [0, 0, 0]}, "objects": )" +
                           std::string(100000, '[') + std::string(100000, ']') + "}";
  const std::string nested = errorFor(deep);
  EXPECT_EQ(nested.rfind("a.json: objects[0][0][0]", 0), 0u) << nested;
  EXPECT_NE(nested.find("nested deeper than 64 levels of objects and arrays"), std::string::npos) << nested;
  EXPECT_LT(nested.size(), 600u);
  const std::string key(1 << 20, 'k');
  const std::string unknown = errorFor(sceneWith(R"("objects": [{"shape": "sphere"}], ")" + key + R"(": 1)"));
  EXPECT_NE(unknown.find("kkk...: unknown key"), std::string::npos) << unknown.substr(0, 200);
  EXPECT_LT(unknown.size(), 1200u);
}

}  // namespace
}  // namespace phongvk

namespace phongvk {
namespace {

// Output paths that are not plain files: written through (symbolic links), into (character
// devices), refused (FIFOs), or reported with the system's reason and cleaned up after (a full
// device, a file-size limit). The device nodes are made here, in a temporary folder, never the
// system's own.
TEST_F(BadCli, OutputPathsThatAreNotPlainFiles) {
  const std::string one = scene("one_pixel.json") + " --backend cpu -o ";
  const std::string dir = test::makeTempDir();
  ASSERT_EQ(mkfifo((dir + "/fifo").c_str(), 0644), 0);
  const test::CommandResult fifo = test::runCli("render " + one + dir + "/fifo");
  EXPECT_EQ(fifo.exitCode, 2) << fifo.output;
  EXPECT_NE(fifo.output.find("it is a FIFO (named pipe), not a regular file"), std::string::npos) << fifo.output;
  EXPECT_TRUE(fs::is_fifo(dir + "/fifo"));

  if (mknod((dir + "/null").c_str(), S_IFCHR | 0666, makedev(1, 3)) != 0 ||
      mknod((dir + "/full").c_str(), S_IFCHR | 0666, makedev(1, 7)) != 0)
    GTEST_SKIP() << "making device nodes needs root (CI runs as root): " << std::strerror(errno);
  const test::CommandResult null = test::runCli("render " + one + dir + "/null");
  EXPECT_EQ(null.exitCode, 0) << null.output;
  EXPECT_TRUE(fs::is_character_file(dir + "/null"));
  const test::CommandResult full = test::runCli("render " + one + dir + "/full");
  EXPECT_EQ(full.exitCode, 4) << full.output;
  EXPECT_NE(full.output.find("cannot write '" + dir + "/full': No space left on device"), std::string::npos) << full.output;
  EXPECT_TRUE(fs::is_character_file(dir + "/full"));
  EXPECT_EQ(filesIn(dir).size(), 3u);  // fifo, null, full: no temporary file left
}

TEST_F(BadCli, LinksLongNamesLimitsAndStandardOutput) {
  const std::string one = scene("one_pixel.json") + " --backend cpu -o ";
  fs::create_symlink("target.png", out_ + "/link.png");
  EXPECT_EQ(test::runCli("render " + one + out_ + "/link.png").exitCode, 0);
  EXPECT_TRUE(fs::is_symlink(out_ + "/link.png"));  // written through, not replaced
  EXPECT_EQ(readPng(out_ + "/target.png").width, 1);
  const std::string longName = std::string(251, 'a') + ".png";  // 255 characters, NAME_MAX
  EXPECT_EQ(test::runCli("render " + one + out_ + "/" + longName).exitCode, 0);
  EXPECT_TRUE(fs::exists(out_ + "/" + longName));
  // A file-size limit (ulimit -f: 1 block) stops the write with EFBIG: exit 4, no temporary file.
  const std::string shell = "ulimit -f 1; '" + std::string(PHONGVK_CLI) + "' render '" +
                            test::sourcePath("scenes/basic.json") + "' --backend cpu -o '" + out_ + "/big.png' 2>&1";
  FILE* pipe = popen(("bash -c \"" + shell + "\"").c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  char buffer[512];
  std::string output;
  for (size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) output.append(buffer, n);
  EXPECT_EQ(WEXITSTATUS(pclose(pipe)), 4) << output;
  EXPECT_NE(output.find("File too large"), std::string::npos) << output;
  EXPECT_EQ(filesIn(out_).size(), 3u) << "link, target and the long name only";
  const test::CommandResult toStdout = test::runCli("render " + one + "- 2>/dev/null | head -c 8 | od -c | head -1");
  EXPECT_NE(toStdout.output.find("P   N   G"), std::string::npos) << toStdout.output;
}

}  // namespace
}  // namespace phongvk

namespace phongvk {
namespace {

// A scene too large for the memory it may use fails before anything is built (so in well under a
// second, without allocating it), naming the estimate, the limit and the objects that take most.
TEST_F(BadCli, SceneBeyondTheMemoryLimitFailsBeforeBuilding) {
  std::string objects;
  for (int i = 0; i < 6; ++i) {
    objects += std::string(i ? ", " : "") + R"({"shape": "icosphere", "center": [0, )" + std::to_string(i) + R"(, 0], "subdivide": 10})";
  }
  const std::string dir = test::makeTempDir();
  test::writeFile(dir + "/six.json", sceneWith(R"("objects": [)" + objects + "]"));
  const std::string message = "error: " + dir + "/six.json: the scene needs about 13.2 GiB (125829120 triangles, ";
  expectFailure("render " + dir + "/six.json --max-memory-gb 6 -o " + out_ + "/x.png", 2, message);
  expectFailure("render " + dir + "/six.json --max-memory-gb 6 -o " + out_ + "/x.png", 2,
                "more than the 6.0 GiB limit (by default the machine's memory; PHONGVK_MAX_MEMORY_GB or --max-memory-gb "
                "sets it); most of it: objects[0] (20971520 triangles), objects[1] (20971520 triangles), objects[2]");
  const test::CommandResult env = test::runCliWithEnvironment(
      "PHONGVK_MAX_MEMORY_GB=2", "diff " + dir + "/six.json");
  EXPECT_EQ(env.exitCode, 2) << env.output;
  EXPECT_NE(env.output.find("more than the 2.0 GiB limit"), std::string::npos) << env.output;
}

// A contact sheet is held until the last frame: one too large for the limit fails before the
// first frame (no frames folder, no frame), naming its size, the limit and what would fit. The
// orbit's 120 frames at 1385x923 and --thumb-width 4096 (kept at 1385: thumbnails are never
// enlarged): 120 x 1385 x 923 x 3 bytes of thumbnails, and the sheet twice.
TEST_F(BadCli, ContactSheetBeyondTheMemoryLimitFailsBeforeTheFirstFrame) {
  const std::string orbit = test::sourcePath("scenes/paper/fig6_orbit_red.json");
  const std::string frames = out_ + "/frames";
  const uint64_t sheet = contactSheetBytes(120, {1385, 923});
  EXPECT_EQ(sheet, 120ull * 1385 * 923 * 3 + 2ull * (4 + 11 * 1389) * (4 + 11 * 927) * 3);
  expectFailure("sequence " + orbit + " --backend cpu --max-memory-gb 1 --thumb-width 4096 --sheet " + out_ +
                    "/sheet.png -o " + frames,
                2,
                "error: " + orbit + ": the contact sheet needs about 1.3 GiB (120 thumbnails of 1385x923), more than the "
                "1.0 GiB limit (by default the machine's memory; PHONGVK_MAX_MEMORY_GB or --max-memory-gb sets it); a "
                "smaller --thumb-width or fewer --frames fit");
  const std::string elsewhere = test::makeTempDir();  // the default 160-wide thumbnails fit
  const test::CommandResult fits = test::runCli("sequence " + orbit + " --backend cpu --max-memory-gb 1 --sheet " +
                                                elsewhere + "/sheet.png -o " + elsewhere + " --frames 0:2");
  EXPECT_EQ(fits.exitCode, 0) << fits.output;
}

}  // namespace
}  // namespace phongvk
