// outputs_cli_gpu_test.cpp — `phongvk render --rgba --depth --ids --normals`: the files hold what
// Renderer::renderOutputs gives for the same scene (16-bit PNGs in millimetres and index + 1, an
// 8-bit normal map, .npy files in metres, indices and unit vectors), the same bytes on both
// backends, and every refusal (a bad extension, also with --mpi, the graphics backend, too many
// objects for a PNG) comes before any file.
#include <phongvk/npy.h>
#include <phongvk/phongvk.h>

#include "tests/test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

namespace phongvk {
namespace {

using namespace test;

// A sphere 3 m ahead, another about 80 m away (beyond a 16-bit PNG's 65.535 m) and empty corners.
const char* const kNearAndFar = R"({
  "camera": {"position": [0, -3, 0], "look_at": [0, 0, 0], "width": 40, "height": 30},
  "lights": [{"position": [0, -3, 2]}],
  "objects": [{"shape": "sphere", "center": [0, 0, 0], "radius": 0.8},
              {"shape": "sphere", "center": [30, 100, 0], "radius": 20}]})";

struct Npy {
  std::string header;
  std::string data;
};

// A .npy file's header dict (the text between the length and the data) and its data bytes.
Npy readNpy(const std::string& path) {
  const std::string bytes = readBytes(path);
  EXPECT_EQ(bytes.substr(0, 8), std::string("\x93NUMPY\x01\x00", 8));
  const size_t length = uint8_t(bytes[8]) | size_t(uint8_t(bytes[9])) << 8;
  EXPECT_EQ((10 + length) % 64, 0u) << "the header is padded to 64 bytes";
  return {bytes.substr(10, length), bytes.substr(10 + length)};
}

template <typename T>
std::vector<T> npyValues(const Npy& npy) {
  std::vector<T> values(npy.data.size() / sizeof(T));
  std::memcpy(values.data(), npy.data.data(), npy.data.size());
  return values;
}

uint16_t expectedMillimetres(float metres) {
  if (std::isinf(metres)) return 0;
  return uint16_t(std::min(65535.0, std::floor(double(metres) * 1000.0 + 0.5)));
}

class OutputsCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = makeTempDir();
    scene = dir + "/near_and_far.json";
    writeFile(scene, kNearAndFar);
  }
  CommandResult render(const std::string& args) { return runCli("render '" + scene + "' " + args); }
  // Renders with `args` on `backend`, "OUT" in them standing for dir/backend; returns that prefix.
  std::string renderOn(const std::string& backend, std::string args) {
    const std::string out = dir + "/" + backend;
    for (size_t at = args.find("OUT"); at != std::string::npos; at = args.find("OUT", at)) args.replace(at, 3, out);
    const CommandResult cli = render("--backend " + backend + " " + args);
    EXPECT_EQ(cli.exitCode, 0) << cli.output;
    return out;
  }
  std::string dir, scene;
};

TEST_F(OutputsCli, PngFilesHoldRenderOutputsInMillimetresAndIdsPlusOneOnBothBackends) {
  const Outputs all{true, true, true, false};
  const RenderedFrame frame = Renderer(Backend::Cpu).renderOutputs(loadScene(scene), all);
  for (const std::string backend : {"gpu", "cpu"}) {
    const std::string out = renderOn(backend, "-o OUT.png --rgba --depth OUT_depth.png --ids OUT_ids.png");
    const ImageGrey16 depth = readPngGrey16(out + "_depth.png"), ids = readPngGrey16(out + "_ids.png");
    const ImageRGBA rgba = readPngRGBA(out + ".png");
    ASSERT_EQ(depth.grey.size(), frame.depth.size());
    int empty = 0, clamped = 0;
    for (size_t i = 0; i < frame.depth.size(); ++i) {
      EXPECT_EQ(depth.grey[i], expectedMillimetres(frame.depth[i])) << backend << " pixel " << i;
      EXPECT_EQ(ids.grey[i], frame.objectIds[i] + 1) << backend << " pixel " << i;
      EXPECT_EQ(rgba.rgba[i * 4 + 3], frame.alpha[i]) << backend << " pixel " << i;
      EXPECT_EQ(rgba.rgba[i * 4], frame.image.rgb[i * 3]) << backend << " pixel " << i;
      empty += depth.grey[i] == 0 && ids.grey[i] == 0 && frame.alpha[i] == 0;
      clamped += depth.grey[i] == 65535 && ids.grey[i] == 2;
    }
    EXPECT_GT(empty, 0) << "the corners are empty";
    EXPECT_GT(clamped, 0) << "the far sphere lies beyond 65.535 m";
  }
  EXPECT_EQ(readBytes(dir + "/gpu_depth.png"), readBytes(dir + "/cpu_depth.png"));
  EXPECT_EQ(readBytes(dir + "/gpu_ids.png"), readBytes(dir + "/cpu_ids.png"));
  EXPECT_EQ(readBytes(dir + "/gpu.png"), readBytes(dir + "/cpu.png"));
}

TEST_F(OutputsCli, NpyFilesHoldMetresAndIndicesWithSamplesOnBothBackends) {
  const Scene sampled = withRenderOptions(loadScene(scene), R"({"samples": 4})");
  const RenderedFrame frame = Renderer(Backend::Cpu).renderOutputs(sampled, Outputs{false, true, true, false});
  for (const std::string backend : {"gpu", "cpu"}) {
    const std::string out = renderOn(backend, "--samples 4 -o OUT.png --depth OUT.npy --ids OUT_ids.npy");
    const Npy depth = readNpy(out + ".npy"), ids = readNpy(out + "_ids.npy");
    EXPECT_EQ(depth.header.find("{'descr': '<f4', 'fortran_order': False, 'shape': (30, 40), }"), 0u)
        << depth.header;
    EXPECT_EQ(ids.header.find("{'descr': '<i4', 'fortran_order': False, 'shape': (30, 40), }"), 0u) << ids.header;
    EXPECT_EQ(depth.header.back(), '\n');
    EXPECT_TRUE(npyValues<float>(depth) == frame.depth) << backend;  // +inf where empty, as renderOutputs
    EXPECT_TRUE(npyValues<int32_t>(ids) == frame.objectIds) << backend;
  }
  EXPECT_EQ(readBytes(dir + "/gpu.npy"), readBytes(dir + "/cpu.npy"));
  const std::vector<uint8_t> encoded = encodeNpy(frame.depth, 40, 30);
  EXPECT_EQ(std::string(encoded.begin(), encoded.end()), readBytes(dir + "/cpu.npy"));
}

// A normal map's byte: (n + 1) / 2 * 255 rounded, 0 for an empty pixel's 0, 0, 0.
uint8_t expectedNormalByte(const float* n, int channel) {
  if (n[0] == 0 && n[1] == 0 && n[2] == 0) return 0;
  return uint8_t(std::floor((double(n[channel]) + 1) / 2 * 255 + 0.5));
}

TEST_F(OutputsCli, NormalsAreANormalMapOrFloatsOnBothBackends) {
  const Scene phong = withRenderOptions(loadScene(scene), R"({"shading": "phong", "samples": 4})");
  const RenderedFrame frame = Renderer(Backend::Cpu).renderOutputs(phong, Outputs{.normals = true});
  for (const std::string backend : {"gpu", "cpu"}) {
    const std::string out = renderOn(backend, "--shading phong --samples 4 -o OUT.png --normals OUT_n.png");
    renderOn(backend, "--shading phong --samples 4 -o OUT.png --normals OUT_n.NPY");  // the extension in any case
    const Npy npy = readNpy(out + "_n.NPY");
    EXPECT_EQ(npy.header.find("{'descr': '<f4', 'fortran_order': False, 'shape': (30, 40, 3), }"), 0u) << npy.header;
    EXPECT_TRUE(npyValues<float>(npy) == frame.normals) << backend;
    const Image map = readPng(out + "_n.png");
    ASSERT_EQ(map.rgb.size(), frame.normals.size());
    int empty = 0, facing = 0;
    for (size_t i = 0; i < map.rgb.size(); ++i) {
      EXPECT_EQ(map.rgb[i], expectedNormalByte(&frame.normals[i - i % 3], int(i % 3))) << backend << " value " << i;
      empty += i % 3 == 0 && map.rgb[i] == 0 && map.rgb[i + 1] == 0 && map.rgb[i + 2] == 0;
      facing += i % 3 == 2 && map.rgb[i] < 40;  // z toward -1: the sphere facing the camera
    }
    EXPECT_GT(empty, 0) << "the corners are empty";
    EXPECT_GT(facing, 100);
  }
  EXPECT_EQ(readBytes(dir + "/gpu_n.png"), readBytes(dir + "/cpu_n.png"));
  EXPECT_EQ(readBytes(dir + "/gpu_n.NPY"), readBytes(dir + "/cpu_n.NPY"));
}

// Each refusal: its exit code, its message, and not one file written.
void expectRefused(const CommandResult& cli, const std::string& message, const std::string& dir) {
  EXPECT_EQ(cli.exitCode, 2) << cli.output;
  EXPECT_NE(cli.output.find(message), std::string::npos) << cli.output;
  EXPECT_TRUE(std::filesystem::is_empty(dir)) << cli.output;
}

TEST_F(OutputsCli, RefusalsComeBeforeAnyFileIsWritten) {
  const std::string out = dir + "/out";
  std::filesystem::create_directory(out);
  expectRefused(render("-o " + out + "/c.png --depth " + out + "/d.exr"),
                "--depth " + out + "/d.exr: the file must end in .png (16-bit grey) or .npy (NumPy)", out);
  expectRefused(render("-o " + out + "/c.png --depth " + out + "/d.png --ids " + out + "/ids"),
                "--ids " + out + "/ids: the file must end in .png (16-bit grey) or .npy (NumPy)", out);
  expectRefused(render("--backend graphics -o " + out + "/c.png --depth " + out + "/d.npy"),
                "the graphics backend has no visibility keys, so no alpha, depth, ids or normals; use the gpu or cpu "
                "backend",
                out);
  expectRefused(render("--backend graphics -o " + out + "/c.png --normals " + out + "/n.png"),
                "the graphics backend has no visibility keys", out);
  expectRefused(render("-o " + out + "/c.png --normals " + out + "/n.jpg"),
                "--normals " + out + "/n.jpg: the file must end in .png (8-bit RGB) or .npy (NumPy)", out);
  expectRefused(render("--backend graphics -o " + out + "/c.png --rgba"), "the graphics backend has no visibility keys",
                out);
  // Two outputs in one file (as named, or through another spelling of its path), or an empty name.
  expectRefused(render("-o " + out + "/x.png --depth " + out + "/x.png"),
                "--depth " + out + "/x.png: the same file as -o; each output needs a file of its own", out);
  expectRefused(render("-o " + out + "/c.png --depth " + out + "/a.npy --ids " + out + "/../out/a.npy"),
                "--ids " + out + "/../out/a.npy: the same file as --depth; each output needs a file of its own", out);
  expectRefused(render("-o " + out + "/c.png --depth ''"), "--depth: must name a file, got an empty name", out);
  expectRefused(render("-o ''"), "--output: must name a file, got an empty name", out);
  // With --mpi (which otherwise gives these files too: tests/mpi_render_test.sh), before MPI starts.
  expectRefused(render("--mpi -o " + out + "/c.png --normals " + out + "/n.exr"),
                "--normals " + out + "/n.exr: the file must end in .png (8-bit RGB) or .npy (NumPy)", out);
  std::string many = R"({"camera": {"position": [0, -3, 0], "look_at": [0, 0, 0], "width": 8, "height": 6}, "objects": [)";
  for (int i = 0; i < 65535; ++i) many += std::string(i ? "," : "") + R"({"shape": "cube", "size": 0.001})";
  writeFile(dir + "/many.json", many + "]}");
  expectRefused(runCli("render '" + dir + "/many.json' -o " + out + "/c.png --ids " + out + "/i.png"),
                "--ids " + out + "/i.png: a 16-bit PNG holds at most 65534 objects' ids, the scene has 65535: write "
                ".npy instead",
                out);
}

TEST(Npy, HeaderIsPaddedAndMismatchedArraysAreRejected) {
  const std::vector<uint8_t> bytes = encodeNpy(std::vector<int32_t>{1, -1, 258}, 3, 1);
  const std::string dict = "{'descr': '<i4', 'fortran_order': False, 'shape': (1, 3), }";  // 59 characters
  ASSERT_EQ(bytes.size(), 128u + 12u);  // 10 + 59 + a newline pass 64: the header fills 128 bytes
  EXPECT_EQ(bytes[8] | bytes[9] << 8, 118);
  EXPECT_EQ(std::string(bytes.begin() + 10, bytes.begin() + 128), dict + std::string(128 - 10 - 59 - 1, ' ') + "\n");
  EXPECT_EQ(std::vector<uint8_t>(bytes.begin() + 128, bytes.end()),
            (std::vector<uint8_t>{1, 0, 0, 0, 255, 255, 255, 255, 2, 1, 0, 0}));
  EXPECT_EQ(thrownMessage<ArgumentError>([] { encodeNpy(std::vector<float>(5), 2, 3); }),
            "cannot write a 2x3 array holding 5 values as .npy");
  const std::string dir = makeTempDir();
  EXPECT_EQ(thrownMessage<OutputError>([&] { writeNpy(dir + "/x.npy", std::vector<float>(5), 2, 3); }),
            "cannot write '" + dir + "/x.npy': cannot write a 2x3 array holding 5 values as .npy");
  EXPECT_TRUE(std::filesystem::is_empty(dir));
  const std::vector<uint8_t> rgb = encodeNpy(std::vector<float>(6, 0.5f), 1, 2, 3);
  EXPECT_EQ(std::string(rgb.begin() + 10, rgb.begin() + 10 + 62), "{'descr': '<f4', 'fortran_order': False, 'shape': (2, 1, 3), }");
  EXPECT_EQ(rgb.size(), 128u + 24u);
  EXPECT_EQ(thrownMessage<ArgumentError>([] { encodeNpy(std::vector<float>(5), 1, 2, 3); }),
            "cannot write a 1x2x3 array holding 5 values as .npy");
}

}  // namespace
}  // namespace phongvk
