// hostile_input_test.cpp — inputs made to crash, hang or outgrow the memory limit: glTF files whose
// accessors lie about their buffers or whose nodes share children, files that are FIFOs or
// devices, mesh files cut short, damaged frames, memory limits set to nonsense, scenes that grow
// between frames. Each gets a clear error naming the file (or renders where it is legal), in
// well under a second, and nothing partial is written.
#include "meshio/gltf_import.h"
#include "meshio/mesh_file.h"
#include "phongvk/image.h"
#include "phongvk/phongvk.h"
#include "prepare/memory_estimate.h"
#include "scene/scene.h"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "test_util.h"
#include "tools/png_check.h"

namespace phongvk {
namespace {

namespace fs = std::filesystem;

// ---- glTF files made to order ----

// One triangle's positions (36 bytes) then its indices: a .gltf with the buffer in `buf.bin`
// beside it. `indices` is the indices accessor's JSON; `nodes` and `meshExtra` change the rest.
struct Gltf {
  std::string indices = R"({"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"})";
  std::string indexBytes = std::string("\0\0\1\0\2\0\0\0", 8);  // uint16 0, 1, 2 and padding
  std::string views = R"([{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 8}])";
  std::string nodes = R"([{"mesh": 0}])";
  std::string sceneNodes = "[0]";
  std::string primitiveExtra;
  std::string top;  // more top-level members, each followed by ", "

  std::string write(const std::string& dir, const std::string& name = "m.gltf") const {
    const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    std::string buffer(reinterpret_cast<const char*>(positions), sizeof positions);
    buffer += indexBytes;
    test::writeFile(dir + "/buf.bin", buffer);
    const std::string json = "{" + top + R"("asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": )" + sceneNodes +
                             R"(}], "nodes": )" + nodes +
                             R"(, "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1)" + primitiveExtra +
                             R"(}]}], "buffers": [{"uri": "buf.bin", "byteLength": )" + std::to_string(buffer.size()) +
                             R"(}], "bufferViews": )" + views +
                             R"(, "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]}, )" +
                             indices + "]}";
    test::writeFile(dir + "/" + name, json);
    return dir + "/" + name;
  }
};

// What importing `path` throws ("(no error)" when it loads), and that it took under a second.
std::string importError(const std::string& path, bool binary = false) {
  const auto start = std::chrono::steady_clock::now();
  std::string message = "(no error)";
  try {
    importGltf(path, binary, false, "objects[0].file");
  } catch (const SceneError& error) {
    message = error.what();
  }
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0) << path;
  return message;
}

std::string gltfError(const Gltf& gltf) {
  const std::string dir = test::makeTempDir();
  const std::string path = gltf.write(dir);
  const std::string message = importError(path);
  const std::string prefix = "objects[0].file: " + path + ": ";
  return message.rfind(prefix, 0) == 0 ? message.substr(prefix.size()) : message;
}

TEST(HostileGltf, TheTriangleLoads) { EXPECT_EQ(gltfError(Gltf()), "(no error)"); }

// The specification allows unsigned index types only. A signed one holding -2 was read as a huge
// unsigned index (a crash); every signed type is refused, whatever its values.
TEST(HostileGltf, SignedIndexTypesAreRefused) {
  for (const char* type : {"5120", "5122"}) {
    Gltf g;
    g.indices = std::string(R"({"bufferView": 1, "componentType": )") + type + R"(, "count": 3, "type": "SCALAR"})";
    g.indexBytes = std::string("\0\0\1\0\xFE\xFF\0\0", 8);  // short 0, 1, -2 (and bytes that read as small values)
    EXPECT_EQ(gltfError(g), "indices (accessor 1) are not unsigned integers (5121, 5123 or 5125 scalars)") << type;
  }
}

// Counts and offsets near 2^64 wrapped around the bounds check and passed: a crash, or the bytes
// before the buffer rendered with exit 0.
TEST(HostileGltf, CountsAndOffsetsThatWrapAroundAreRefused) {
  Gltf count;  // 4-byte indices: (2^62 + 1 - 1) * 4 + 4 wraps to 4
  count.indices = R"({"bufferView": 1, "componentType": 5125, "count": 4611686018427387905, "type": "SCALAR"})";
  EXPECT_EQ(gltfError(count), "indices (accessor 1): runs past the end of its buffer view (4611686018427387905 elements)");
  Gltf offset;
  offset.indices = R"({"bufferView": 1, "byteOffset": 18446744073709551608, "componentType": 5123, "count": 3, "type": "SCALAR"})";
  EXPECT_EQ(gltfError(offset), "indices (accessor 1): runs past the end of its buffer view");
  Gltf viewOffset;
  viewOffset.views = R"([{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 18446744073709551580, "byteLength": 8}])";
  EXPECT_EQ(gltfError(viewOffset), "indices (accessor 1): its buffer view runs past the end of its buffer");
  Gltf viewLength;
  viewLength.views = R"([{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 18446744073709551612}])";
  EXPECT_EQ(gltfError(viewLength), "indices (accessor 1): its buffer view runs past the end of its buffer");
}

// 40 levels of nodes, each naming the next twice: 2^40 paths to the mesh (a hang). The
// specification asks for a tree; a node reached twice, or its own ancestor, is refused.
TEST(HostileGltf, SharedAndCyclicNodesAreRefused) {
  Gltf shared;
  shared.nodes = "[";
  for (int k = 0; k < 40; ++k) shared.nodes += R"({"children": [)" + std::to_string(k + 1) + ", " + std::to_string(k + 1) + "]}, ";
  shared.nodes += R"({"mesh": 0}])";
  EXPECT_EQ(gltfError(shared),
            "nodes[40] is reached twice (nodes must form a tree: no node may have two parents or be its own ancestor)");
  Gltf cycle;
  cycle.nodes = R"([{"mesh": 0, "children": [1]}, {"children": [0]}])";
  EXPECT_EQ(gltfError(cycle),
            "nodes[0] is reached twice (nodes must form a tree: no node may have two parents or be its own ancestor)");
  Gltf rootTwice;
  rootTwice.sceneNodes = "[0, 0]";
  EXPECT_NE(gltfError(rootTwice).find("nodes[0] is reached twice"), std::string::npos);
}

TEST(HostileGltf, IllegalFilesAreRefusedByName) {
  {
    Gltf v1;
    const std::string dir = test::makeTempDir();
    const std::string path = v1.write(dir);
    std::string json = test::readBytes(path);
    json.replace(json.find(R"("version": "2.0")"), 16, R"("version": "1.0")");
    test::writeFile(path, json);
    EXPECT_EQ(importError(path), "objects[0].file: " + path +
                                     ": asset.version is '1.0'; phongvk reads glTF 2.0 files (convert a glTF 1.0 file to 2.0 first)");
  }
  {
    // glTF 1.0 without an asset.version tinygltf reads: lists as objects of named entries (as
    // assimp-testmodels' CesiumMilkTruck.gltf has them), and the binary form's version 1 header.
    const std::string dir = test::makeTempDir();
    const std::string named = dir + "/named.gltf";
    test::writeFile(named, R"({"accessors": {"a": {"count": 3}}, "meshes": {"m": {"primitives": []}}})");
    EXPECT_EQ(importError(named), "objects[0].file: " + named +
                                      ": 'accessors' is an object of named entries (glTF 1.0's form); phongvk reads glTF 2.0 "
                                      "files (convert a glTF 1.0 file to 2.0 first)");
    const std::string binary = dir + "/one.glb";
    const std::string json = R"({"accessors": {}})";
    std::string glb = "glTF";
    for (uint32_t word : {1u, uint32_t(20 + json.size()), uint32_t(json.size()), 0u}) glb.append(reinterpret_cast<const char*>(&word), 4);
    test::writeFile(binary, glb + json);
    EXPECT_EQ(importError(binary, true), "objects[0].file: " + binary +
                                       ": a GLB of version 1 (glTF 1.0's binary form); phongvk reads glTF 2.0 files (convert a "
                                       "glTF 1.0 file to 2.0 first)");
  }
  {
    // A mesh whose "primitives" is not a list (assimp-testmodels' wrongTypes/badArray.gltf) and a
    // default scene of a file without scenes (TestNoRootNode/NoScene.gltf): refused by what is wrong.
    const std::string dir = test::makeTempDir();
    const std::string notList = dir + "/not_list.gltf";
    test::writeFile(notList, R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
                                 "nodes": [{"mesh": 0}], "meshes": [{"primitives": {"not a list": {}}}]})");
    EXPECT_EQ(importError(notList), "objects[0].file: " + notList +
                                        ": nothing to draw (no triangles, lines or points): meshes[0] has no primitives "
                                        "(glTF 2.0 asks for a list of one or more)");
    const std::string noScenes = dir + "/no_scenes.gltf";
    test::writeFile(noScenes, R"({"asset": {"version": "2.0"}, "scene": 0})");
    EXPECT_EQ(importError(noScenes), "objects[0].file: " + noScenes + ": no scene (its 'scenes' is missing or empty)");
  }
  Gltf mode;
  mode.primitiveExtra = R"(, "mode": -5)";
  EXPECT_EQ(gltfError(mode), "a primitive's mode is -5, not a glTF primitive mode (0 to 6)");
  Gltf zeroRotation;
  zeroRotation.nodes = R"([{"mesh": 0, "rotation": [0, 0, 0, 0]}])";
  EXPECT_EQ(gltfError(zeroRotation), "nodes[0].rotation is not a unit quaternion (its length is 0)");
  Gltf shortMatrix;
  shortMatrix.nodes = R"([{"mesh": 0, "matrix": [1, 0, 0]}])";
  EXPECT_EQ(gltfError(shortMatrix), "nodes[0].matrix has 3 numbers, not 16");
  Gltf meshopt;
  meshopt.top = R"("extensionsUsed": ["EXT_meshopt_compression"], "extensionsRequired": ["EXT_meshopt_compression"], )";
  EXPECT_EQ(gltfError(meshopt), "requires the extension EXT_meshopt_compression, which phongvk does not implement");
  // A rotation written with a few digits is a unit quaternion still.
  Gltf rounded;
  rounded.nodes = R"([{"mesh": 0, "rotation": [0, 0, 0.7071, 0.7071]}])";
  EXPECT_EQ(gltfError(rounded), "(no error)");
}

// A mesh placed by many nodes is legal (instancing): every placement is built, and the memory
// estimate counts every placement from the JSON, before the buffers are read.
TEST(HostileGltf, InstancesAreBuiltAndEstimated) {
  Gltf instanced;
  instanced.nodes = "[{\"children\": [";
  for (int k = 1; k <= 24; ++k) instanced.nodes += (k > 1 ? ", " : "") + std::to_string(k);
  instanced.nodes += "]}";
  for (int k = 1; k <= 24; ++k) instanced.nodes += R"(, {"mesh": 0, "translation": [)" + std::to_string(2 * k) + ", 0, 0]}";
  instanced.nodes += "]";
  const std::string path = instanced.write(test::makeTempDir());
  EXPECT_EQ(importGltf(path, false, false, "m").triangles.size(), 24u);
  EXPECT_EQ(gltfTriangles(path, false), std::optional<uint64_t>(24));
}

// A small .gltf with a large external buffer is estimated from its accessors, not its own size:
// under a limit its buffer does not fit, it fails before the buffer is read.
TEST(HostileGltf, ExternalBuffersCountInTheEstimate) {
  Gltf big;
  const uint64_t triangles = 2'000'000;  // 6M uint32 indices, never written: the estimate reads counts
  big.indices = R"({"bufferView": 1, "componentType": 5125, "count": )" + std::to_string(3 * triangles) + R"(, "type": "SCALAR"})";
  const std::string dir = test::makeTempDir();
  const std::string path = big.write(dir);
  EXPECT_LT(fs::file_size(path), 1000u);
  EXPECT_EQ(gltfTriangles(path, false), std::optional<uint64_t>(triangles));
  EXPECT_EQ(meshFileTriangles(path, MeshFormat::Gltf, fs::file_size(path)), triangles);
  test::writeFile(dir + "/s.json", R"({"camera": {"position": [0, -3, 0], "look_at": [0, 0, 0], "width": 64, "height": 48},
                                       "objects": [{"shape": "mesh", "file": "m.gltf"}]})");
  const test::CommandResult run = test::runCli("render " + dir + "/s.json --max-memory-gb 0.1 --backend cpu -o " + dir + "/x.png");
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find("the scene needs about 0.209 GiB (2000000 triangles, 3072 pixels), more than the 0.100 GiB limit"),
            std::string::npos)
      << run.output;
  EXPECT_FALSE(fs::exists(dir + "/x.png"));
}

// ---- files that are not regular files ----

// Every file phongvk reads is opened only if it is a regular file: a FIFO would block forever, a
// character device never end. Each fails at once, naming the file and what it is.
TEST(HostileFiles, FifosAndDevicesAreRefusedWherevertheyAreNamed) {
  const std::string dir = test::makeTempDir();
  ASSERT_EQ(mkfifo((dir + "/fifo.ply").c_str(), 0600), 0);
  const auto start = std::chrono::steady_clock::now();
  const test::CommandResult model = test::runCli("render " + dir + "/fifo.ply --backend cpu -o " + dir + "/x.png");
  EXPECT_EQ(model.exitCode, 2) << model.output;
  EXPECT_NE(model.output.find("error: " + dir + "/fifo.ply: cannot open the file: a FIFO (named pipe), not a regular file"),
            std::string::npos)
      << model.output;
  // An OBJ's material library, a FIFO or a device.
  ASSERT_EQ(mkfifo((dir + "/fifo.mtl").c_str(), 0600), 0);
  fs::create_symlink("/dev/zero", dir + "/zero.mtl");
  for (const char* library : {"fifo.mtl", "zero.mtl"}) {
    test::writeFile(dir + "/m.obj", std::string("mtllib ") + library + "\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const std::string message = test::thrownMessage<SceneError>([&] { importMeshFile(dir + "/m.obj", MeshFormat::Obj, false, "m"); });
    EXPECT_EQ(message, "m: " + dir + "/m.obj: mtllib '" + library + "': " +
                           (std::string(library) == "fifo.mtl" ? "a FIFO (named pipe)" : "a character device") +
                           ", not a regular file");
  }
  // A missing material library is passed over, as every OBJ reader does.
  test::writeFile(dir + "/m.obj", "mtllib missing.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_EQ(importMeshFile(dir + "/m.obj", MeshFormat::Obj, false, "m").triangles.size(), 1u);
  // A glTF buffer.
  Gltf gltf;
  const std::string path = gltf.write(dir);
  fs::remove(dir + "/buf.bin");
  ASSERT_EQ(mkfifo((dir + "/buf.bin").c_str(), 0600), 0);
  EXPECT_NE(importError(path).find("a FIFO (named pipe), not a regular file"), std::string::npos);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
}

// ---- mesh files cut short ----

// An ASCII STL cut after a facet's first line rendered the facets before the cut, exit 0. A cut
// anywhere is an error naming the file and line.
TEST(HostileMeshFiles, AsciiStlCutShortIsAnError) {
  const std::string dir = test::makeTempDir();
  const std::string facet = "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n";
  const auto error = [&](const std::string& text) {
    test::writeFile(dir + "/m.stl", text);
    return test::thrownMessage<SceneError>([&] { importMeshFile(dir + "/m.stl", MeshFormat::Stl, false, "m"); });
  };
  test::writeFile(dir + "/whole.stl", "solid x\n" + facet + "endsolid x\n");
  EXPECT_EQ(importMeshFile(dir + "/whole.stl", MeshFormat::Stl, false, "m").triangles.size(), 1u);
  EXPECT_EQ(error("solid x\n" + facet + "facet normal 0 0 1\n"),
            "m: " + dir + "/m.stl: line 10 (facet 1): the file ends inside a facet (is it cut short?)");
  EXPECT_EQ(error("solid x\n" + facet), "m: " + dir + "/m.stl: line 9 (facet 1): the file ends before 'endsolid' (is it cut short?)");
  EXPECT_EQ(error("solid x\n" + facet + facet.substr(0, 30)),
            "m: " + dir + "/m.stl: line 11 (facet 1): the file ends inside a facet (is it cut short?)");
}

// ---- damaged frames ----

// sequence --skip-existing keeps a frame only if it is whole: a frame whose bytes between its
// header and IEND were zeroed (or changed) fails its chunks' CRCs and is rendered again.
TEST(HostileFrames, ADamagedFrameIsNotKept) {
  const std::string dir = test::makeTempDir();
  Image image(40, 30);
  for (size_t i = 0; i < image.rgb.size(); ++i) image.rgb[i] = uint8_t(i * 7);
  writePng(dir + "/f.png", image, 1);
  EXPECT_TRUE(pngIsComplete(dir + "/f.png", 40, 30));
  EXPECT_FALSE(pngIsComplete(dir + "/f.png", 41, 30));
  std::string bytes = test::readBytes(dir + "/f.png");
  std::string zeroed = bytes;
  std::fill(zeroed.begin() + 40, zeroed.end() - 12, '\0');
  test::writeFile(dir + "/zeroed.png", zeroed);
  EXPECT_FALSE(pngIsComplete(dir + "/zeroed.png", 40, 30));
  std::string flipped = bytes;
  flipped[bytes.size() / 2] ^= 1;
  test::writeFile(dir + "/flipped.png", flipped);
  EXPECT_FALSE(pngIsComplete(dir + "/flipped.png", 40, 30));
  test::writeFile(dir + "/extra.png", bytes + "x");
  EXPECT_FALSE(pngIsComplete(dir + "/extra.png", 40, 30));
}

// ---- the memory limit ----

TEST(HostileMemoryLimit, OnlyANumberOfGibSetsIt) {
  for (const char* bad : {"abc", "-1", "nan", "0", "", "1e-12", "0.0001", "4GB", " ", "inf", "1e400", "-inf"}) {
    EXPECT_EQ(test::thrownMessage<SceneError>([&] { parseMemoryLimit(bad, "PHONGVK_MAX_MEMORY_GB"); }),
              std::string("PHONGVK_MAX_MEMORY_GB is '") + bad + "': expected a number of GiB, at least 0.001 (e.g. 4 or 0.5)")
        << bad;
  }
  EXPECT_EQ(parseMemoryLimit("4", "x"), 4ull << 30);
  EXPECT_EQ(parseMemoryLimit("0.5", "x"), 1ull << 29);
  EXPECT_EQ(parseMemoryLimit("1e11", "x"), UINT64_MAX);  // past 64 bits of bytes: no limit, not 0
  const std::string basic = test::sourcePath("scenes/basic.json");
  for (const char* bad : {"abc", "nan", ""}) {
    const test::CommandResult run =
        test::runCliWithEnvironment(std::string("PHONGVK_MAX_MEMORY_GB='") + bad + "'", "render " + basic + " --backend cpu -o /dev/null");
    EXPECT_EQ(run.exitCode, 2) << run.output;
    EXPECT_NE(run.output.find(std::string("error: PHONGVK_MAX_MEMORY_GB is '") + bad + "'"), std::string::npos) << run.output;
  }
  const test::CommandResult huge = test::runCliWithEnvironment("PHONGVK_MAX_MEMORY_GB=1e11", "render " + basic + " --backend cpu -o /dev/null");
  EXPECT_EQ(huge.exitCode, 0) << huge.output;
  for (const char* bad : {"nan", "1e-12", "-2"}) {
    const test::CommandResult run = test::runCli("render " + basic + " --backend cpu -o /dev/null --max-memory-gb=" + bad);
    EXPECT_EQ(run.exitCode, 2) << run.output;
    EXPECT_NE(run.output.find(std::string("--max-memory-gb: value is '") + bad + "': expected a number of GiB"), std::string::npos)
        << run.output;
  }
}

// A renderer checks every frame: the same scene rendered small, then at a size whose buffers pass
// the limit, fails the second time (it was checked on the first render only).
TEST(HostileMemoryLimit, EveryRenderIsChecked) {
  const Scene scene = loadScene(test::sourcePath("scenes/basic.json"));
  Renderer renderer(Backend::Cpu);
  setMemoryLimit(64ull << 20);  // 64 MiB: 320x240 fits, 4096x4096 (512 MiB of buffers) does not
  const Image small = renderer.render(scene.withImageSize(320, 240));
  EXPECT_EQ(small.width, 320);
  const std::string message = test::thrownMessage<SceneError>([&] { renderer.render(scene.withImageSize(4096, 4096)); });
  setMemoryLimit(0);
  EXPECT_NE(message.find("the scene needs about 0.500 GiB (3840 triangles as built, 16777216 pixels), more than the 0.062 GiB limit"),
            std::string::npos)
      << message;
}

// A sequence whose frames grow past the limit fails before its first frame is written, naming the
// frame; the message names the file and the frame once.
TEST(HostileMemoryLimit, ASequenceThatGrowsFailsBeforeItsFirstFrame) {
  const std::string dir = test::makeTempDir();
  test::writeFile(dir + "/grow.json", R"({"camera": {"position": [0, -3, 0], "look_at": [0, 0, 0], "width": 64, "height": 48},
    "objects": [{"shape": "sphere", "radius": 0.5}],
    "animate": {"frames": 30, "tracks": [{"path": "camera.width", "expression": "64 + i*400"},
                                         {"path": "camera.height", "expression": "48 + i*300"}]}})");
  const test::CommandResult run =
      test::runCliWithEnvironment("PHONGVK_MAX_MEMORY_GB=0.05", "sequence " + dir + "/grow.json --backend cpu -o " + dir + "/frames");
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find("error: " + dir + "/grow.json: frame 4: the scene needs about 0.062 GiB (960 triangles, 2076672 pixels), "
                            "more than the 0.050 GiB limit"),
            std::string::npos)
      << run.output;
  EXPECT_FALSE(fs::exists(dir + "/frames/frame_0000.png"));
  // A frame's own error is named once: "grow.json: frame 25: grow.json: frame 25: ..." no more.
  test::writeFile(dir + "/bad.json", R"({"camera": {"position": [0, -3, 0], "look_at": [0, 0, 0], "width": 64, "height": 48},
    "objects": [{"shape": "sphere", "radius": 0.5}],
    "animate": {"frames": 30, "tracks": [{"path": "objects[0].radius", "expression": "0.5 - i*0.02"}]}})");
  const test::CommandResult bad = test::runCli("sequence " + dir + "/bad.json --backend cpu -o " + dir + "/frames");
  EXPECT_EQ(bad.exitCode, 2) << bad.output;
  EXPECT_NE(bad.output.find("error: " + dir + "/bad.json: frame 25: objects[0].radius: must be > 0, got 0"), std::string::npos)
      << bad.output;
}

// ---- limits and messages ----

TEST(HostileScenes, LightsBeyondTheLimitAreAnError) {
  std::string lights;
  for (size_t i = 0; i <= MAX_LIGHTS; ++i) lights += std::string(i ? ", " : "") + R"({"position": [0, -2, 1]})";
  const std::string text = R"({"camera": {"position": [0, -3, 0], "look_at": [0, 0, 0]}, "lights": [)" + lights +
                           R"(], "objects": [{"shape": "sphere"}]})";
  EXPECT_EQ(test::thrownMessage<SceneError>([&] { parseSceneSpec(text, "a.json", "."); }),
            "a.json: lights: a scene has at most 1024 lights, this one 1025");
}

TEST(HostileCli, OptionMessagesAreShortAndExitTwo) {
  const std::string basic = test::sourcePath("scenes/basic.json");
  const test::CommandResult device = test::runCli("render " + basic + " -o /dev/null --device -1");
  EXPECT_EQ(device.exitCode, 2);
  EXPECT_NE(device.output.find("--device: must be a device index, 0 or more (see 'phongvk devices'), got -1"), std::string::npos)
      << device.output;
  const test::CommandResult tolerance = test::runCli("diff " + basic + " --tolerance nan");
  EXPECT_EQ(tolerance.exitCode, 2);
  EXPECT_NE(tolerance.output.find("--tolerance: must be a number from 0 to 255, got nan"), std::string::npos) << tolerance.output;
  for (const test::CommandResult& r : {device, tolerance}) EXPECT_LT(r.output.size(), 400u) << r.output;
}

// An output name the system refuses (longer than NAME_MAX) is an output error, exit 2, as
// docs/CLI.md "Exit codes" promises, with the system's reason.
TEST(HostileCli, AnOutputNameTooLongExitsTwo) {
  const std::string dir = test::makeTempDir();
  const std::string name = dir + "/" + std::string(300, 'a') + ".png";
  const test::CommandResult run = test::runCli("render " + test::sourcePath("scenes/basic.json") + " --backend cpu -o " + name);
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find("': File name too long"), std::string::npos) << run.output;
}

// A model given alone names itself, not the scene phongvk made around it.
TEST(HostileCli, AModelAloneIsNamedOnce) {
  const std::string dir = test::makeTempDir();
  Gltf meshopt;
  meshopt.top = R"("extensionsRequired": ["EXT_meshopt_compression"], )";
  const std::string path = meshopt.write(dir);
  const test::CommandResult run = test::runCli("render " + path + " --backend cpu -o " + dir + "/x.png");
  EXPECT_EQ(run.exitCode, 2) << run.output;
  EXPECT_NE(run.output.find("error: " + path + ": requires the extension EXT_meshopt_compression, which phongvk does not implement\n"),
            std::string::npos)
      << run.output;
  EXPECT_EQ(run.output.find("objects[0]"), std::string::npos) << run.output;
}

}  // namespace
}  // namespace phongvk
