// mesh_files_gpu_test.cpp — PLY, STL and glTF beside OBJ (mesh_file.h): real files made by other
// tools (Debian's assimp-testmodels) with their known counts, the same mesh in all four formats
// rendering the same bytes, object transforms (up axis, rotation, mirroring scale), vertex
// colours, the fitted camera and a model file alone as a scene, each on both backends, and bad
// files failing with the scene file, the JSON path and the mesh file named.
#include <phongvk/phongvk.h>

#include "base/base64.h"
#include "base/number_text.h"
#include "geometry/polygon.h"
#include "meshio/mesh_file.h"
#include "meshio/mesh_import.h"
#include "scene/object_mesh.h"
#include "tests/test_util.h"

#include <gtest/gtest.h>

#include <sys/stat.h>

#include <bit>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace phongvk {
namespace {

using namespace test;

const std::string kModels = "/usr/share/assimp/models/";

Mesh loaded(const std::string& path) {
  return importMeshFile(path, meshFormat(path, "objects[0].file"), false, "objects[0].file");
}

// A scene around one mesh object `object` (JSON), 96x72, the camera fitted.
Scene meshScene(const std::string& object, const std::string& camera = R"({"fit": true, "width": 96, "height": 72})") {
  return parseScene(R"({"camera": )" + camera + R"(, "lights": [{"position": "camera"}, {"position": [3, -2, 4]}],
                       "objects": [)" + object + "]}",
                    "scene.json", "/");
}

std::string meshObject(const std::string& file, const std::string& more = R"(, "closed": true)") {
  return R"({"shape": "mesh", "file": ")" + file + R"(")" + more + "}";
}

// Renders on both backends, expects the same bytes and keys, returns the image.
Image renderBoth(const Scene& scene) {
  const DiffResult result = diff(scene, RendererOptions{Backend::Gpu, -1, true});
  EXPECT_EQ(result.stats.differing, 0u);
  EXPECT_EQ(result.stats.triangleMismatch, 0u);
  EXPECT_TRUE(result.reference.keys == result.gpu.keys);
  return result.gpu.image;
}

size_t coveredPixels(const Image& image, const std::array<uint8_t, 3>& background) {
  size_t covered = 0;
  for (size_t i = 0; i < image.rgb.size(); i += 3)
    covered += image.rgb[i] != background[0] || image.rgb[i + 1] != background[1] || image.rgb[i + 2] != background[2];
  return covered;
}

TEST(MeshFiles, RealFilesHaveTheirKnownCounts) {
  struct Known {
    std::string file;
    MeshFormat format;
    size_t triangles;
  };
  const std::vector<Known> files = {
      {"PLY/cube.ply", MeshFormat::Ply, 12},                     // ASCII, quads
      {"PLY/cube_binary.ply", MeshFormat::Ply, 12},              // binary little-endian
      {"PLY/Wuson.ply", MeshFormat::Ply, 3732},
      {"STL/Spider_ascii.stl", MeshFormat::Stl, 1368},
      {"STL/Spider_binary.stl", MeshFormat::Stl, 1368},
      {"glTF2/BoxTextured-glTF/BoxTextured.gltf", MeshFormat::Gltf, 12},  // with its .bin buffer
      {"glTF2/BoxTextured-glTF-Binary/BoxTextured.glb", MeshFormat::Glb, 12},
      {"glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb", MeshFormat::Glb, 121496},  // 110336 with area
  };
  for (const Known& k : files) {
    SCOPED_TRACE(k.file);
    EXPECT_EQ(meshFormat(kModels + k.file, "f"), k.format);
    EXPECT_EQ(loaded(kModels + k.file).triangles.size(), k.triangles);
  }
  // ASCII and binary STL of the same spider: the same triangles, to the ASCII file's 6 digits.
  const Mesh ascii = loaded(kModels + "STL/Spider_ascii.stl"), binary = loaded(kModels + "STL/Spider_binary.stl");
  ASSERT_EQ(ascii.positions.size(), binary.positions.size());
  for (size_t v = 0; v < ascii.positions.size(); ++v)
    EXPECT_LT(glm::length(ascii.positions[v] - binary.positions[v]), 1e-4f) << v;
}

TEST(MeshFiles, RealFilesRenderTheSameOnBothBackends) {
  for (const std::string file : {"PLY/Wuson.ply", "STL/Spider_binary.stl", "glTF2/BoxTextured-glTF/BoxTextured.gltf",
                                 "glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb", "PLY/float-color.ply"}) {
    SCOPED_TRACE(file);
    const Image image = renderBoth(meshScene(meshObject(kModels + file, R"(, "closed": false)")));
    EXPECT_GT(coveredPixels(image, {0, 0, 0}), 200u);
  }
}

// One mesh of unshared triangles (every normal then the face's), written as OBJ, PLY (binary,
// big-endian), STL (ASCII) and glTF (embedded buffer): the same floats, the same triangles.
struct Tri {
  float p[3][3];
};

const std::vector<Tri> kTris = {
    {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}},       {{{0, 0, 0}, {0, 1, 0}, {0, 0, 1.5f}}},
    {{{0, 0, 0}, {0, 0, 1.5f}, {1, 0, 0}}},    {{{1, 0, 0}, {0, 0, 1.5f}, {0, 1, 0}}},
    {{{1, 0, 0}, {0.25f, 1, 0.5f}, {0, 1, 0}}}};

std::string objText() {
  std::string s;
  for (const Tri& t : kTris)
    for (const auto& p : t.p) s += "v " + std::to_string(p[0]) + " " + std::to_string(p[1]) + " " + std::to_string(p[2]) + "\n";
  for (size_t i = 0; i < kTris.size(); ++i)
    s += "f " + std::to_string(3 * i + 1) + " " + std::to_string(3 * i + 2) + " " + std::to_string(3 * i + 3) + "\n";
  return s;
}

std::string stlText() {
  std::string s = "solid test\n";
  for (const Tri& t : kTris) {
    s += "facet normal 0 0 0\nouter loop\n";
    for (const auto& p : t.p) s += "vertex " + std::to_string(p[0]) + " " + std::to_string(p[1]) + " " + std::to_string(p[2]) + "\n";
    s += "endloop\nendfacet\n";
  }
  return s + "endsolid test\n";
}

template <typename T>
void putBigEndian(std::string& out, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  for (size_t i = sizeof(T); i-- > 0;) out += bytes[i];
}

std::string plyBigEndian() {
  const size_t n = kTris.size();
  std::string s = "ply\nformat binary_big_endian 1.0\ncomment written by mesh_files_gpu_test\nelement vertex " +
                  std::to_string(3 * n) + "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
                  std::to_string(n) + "\nproperty list uchar int vertex_indices\nend_header\n";
  for (const Tri& t : kTris)
    for (const auto& p : t.p)
      for (float c : p) putBigEndian(s, c);
  for (size_t i = 0; i < n; ++i) {
    s += char(3);
    for (int k = 0; k < 3; ++k) putBigEndian(s, int32_t(3 * i + k));
  }
  return s;
}

std::string gltfText() {
  std::string buffer;
  float lo[3] = {1e9, 1e9, 1e9}, hi[3] = {-1e9, -1e9, -1e9};
  for (const Tri& t : kTris)
    for (const auto& p : t.p)
      for (int c = 0; c < 3; ++c) {
        buffer.append(reinterpret_cast<const char*>(&p[c]), 4);
        lo[c] = std::min(lo[c], p[c]);
        hi[c] = std::max(hi[c], p[c]);
      }
  const size_t count = 3 * kTris.size();
  auto vec = [](const float* v) { return "[" + std::to_string(v[0]) + "," + std::to_string(v[1]) + "," + std::to_string(v[2]) + "]"; };
  return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": )" + std::to_string(count) +
         R"(, "type": "VEC3", "min": )" + vec(lo) + R"(, "max": )" + vec(hi) + R"(}],
    "bufferViews": [{"buffer": 0, "byteLength": )" + std::to_string(buffer.size()) + R"(}],
    "buffers": [{"byteLength": )" + std::to_string(buffer.size()) +
         R"(, "uri": "data:application/octet-stream;base64,)" + base64Encoded(buffer) + R"("}]})";
}

TEST(MeshFiles, TheSameMeshInEveryFormatRendersTheSameBytes) {
  const std::string dir = makeTempDir();
  writeFile(dir + "/m.obj", objText());
  writeFile(dir + "/m.stl", stlText());
  writeFile(dir + "/m.ply", plyBigEndian());
  writeFile(dir + "/m.gltf", gltfText());
  const std::string camera = R"({"position": [3, -2.5, 2], "look_at": [0.3, 0.3, 0.4], "width": 120, "height": 90})";
  const std::string material = R"(, "material": {"color": [0.9, 0.6, 0.3]})";
  const Image obj = renderBoth(meshScene(meshObject(dir + "/m.obj", material + R"(, "closed": true)"), camera));
  EXPECT_GT(coveredPixels(obj, {0, 0, 0}), 200u);
  for (const std::string other : {"m.stl", "m.ply", "m.gltf"}) {
    SCOPED_TRACE(other);
    EXPECT_TRUE(renderBoth(meshScene(meshObject(dir + "/" + other, material + R"(, "closed": true)"), camera)).rgb == obj.rgb);
  }
}

TEST(MeshFiles, YUpModelStandsAsTheSameModelTurnedByHand) {
  const std::string dir = makeTempDir();
  std::string yUp, zUp;  // a wedge, tall along +y in the first, along +z in the second
  const float v[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 2, 0}, {0, 0, 1}};
  for (const auto& p : v) {
    yUp += "v " + std::to_string(p[0]) + " " + std::to_string(p[1]) + " " + std::to_string(p[2]) + "\n";
    zUp += "v " + std::to_string(p[0]) + " " + std::to_string(-p[2]) + " " + std::to_string(p[1]) + "\n";
  }
  const std::string faces = "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
  writeFile(dir + "/y.obj", yUp + faces);
  writeFile(dir + "/z.obj", zUp + faces);
  const std::string camera = R"({"position": [2, -4, 1.5], "look_at": [0.3, 0, 0.8], "width": 100, "height": 80})";
  const Image turned = renderBoth(meshScene(meshObject(dir + "/y.obj", R"(, "up": "y", "closed": true)"), camera));
  const Image byHand = renderBoth(meshScene(meshObject(dir + "/z.obj"), camera));
  EXPECT_GT(coveredPixels(byHand, {0, 0, 0}), 300u);
  EXPECT_TRUE(turned.rgb == byHand.rgb);
}

// A closed cube turned a quarter about z, or mirrored: the same box, so the same silhouette and the
// same depth at every pixel, and with the winding right the front faces (not the back ones) win.
TEST(MeshFiles, RotationsAndMirrorsKeepNormalsAndCulling) {
  const std::string camera = R"({"position": [3, -4, 2.5], "look_at": [0, 0, 0], "width": 96, "height": 72})";
  const auto cube = [&](const std::string& more) {
    const Scene scene = meshScene(R"({"shape": "cube", "size": 1.5)" + more + "}", camera);
    renderBoth(scene);
    return Renderer(Backend::Cpu).renderWithKeys(scene);
  };
  const RenderOutput plain = cube("");
  const std::vector<std::string> variants = {R"(, "rotate": [0, 0, 90])", R"(, "rotate": {"axis": [0, 0, 1], "angle": -90})",
                                             R"(, "scale": [-1, 1, 1])", R"(, "scale": [1, -1, -1], "rotate": [90, 0, 0])"};
  for (const std::string& variant : variants) {
    SCOPED_TRACE(variant);
    const RenderOutput turned = cube(variant);
    ASSERT_EQ(turned.keys.size(), plain.keys.size());
    size_t covered = 0;
    for (size_t i = 0; i < plain.keys.size(); ++i) {
      ASSERT_EQ(turned.keys[i] == UINT64_MAX, plain.keys[i] == UINT64_MAX) << "pixel " << i;
      if (plain.keys[i] == UINT64_MAX) continue;
      ++covered;
      const float a = std::bit_cast<float>(uint32_t(plain.keys[i] >> 32)), b = std::bit_cast<float>(uint32_t(turned.keys[i] >> 32));
      EXPECT_NEAR(a, b, 1e-5f * a) << "pixel " << i;  // the near faces: culling kept the front
    }
    EXPECT_GT(covered, 300u);
    // Same normals on the same faces: the colours agree to a few levels (triangulations differ).
    for (size_t i = 0; i < plain.image.rgb.size(); ++i) EXPECT_NEAR(int(plain.image.rgb[i]), int(turned.image.rgb[i]), 6);
  }
}

TEST(MeshFiles, NonUniformScaleTurnsNormalsByTheInverseTranspose) {
  Object object;
  object.shape = Shape::Sphere;
  object.radius = 1;
  object.scale = {2, 2, 0.5};
  object.jsonPath = "objects[0]";
  const ObjectMesh m = buildObjectMesh(object);
  for (size_t v = 0; v < m.mesh.positions.size(); ++v) {
    const glm::dvec3 p(m.mesh.positions[v]);
    // The ellipsoid x²/4 + y²/4 + z²/0.25 = 1 has its normal along (x/4, y/4, z/0.25).
    const glm::dvec3 expected = glm::normalize(glm::dvec3(p.x / 4, p.y / 4, p.z / 0.25));
    EXPECT_GT(glm::dot(expected, glm::dvec3(m.mesh.normals[v])), 0.9999) << v;
  }
}

TEST(MeshFiles, VertexColoursMultiplyTheMaterialColour) {
  const std::string dir = makeTempDir();
  writeFile(dir + "/red.ply",
            "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
            "property uchar red\nproperty uchar green\nproperty uchar blue\nelement face 2\n"
            "property list uchar int vertex_indices\nend_header\n"
            "0 0 0 255 0 0\n1 0 0 255 0 0\n1 0 1 255 0 0\n0 0 1 255 0 0\n3 0 1 2\n3 0 2 3\n");
  const std::string camera = R"({"position": [0.5, -3, 0.5], "look_at": [0.5, 0, 0.5], "width": 64, "height": 48})";
  const Image image = renderBoth(meshScene(meshObject(dir + "/red.ply", R"(, "material": {"color": [1, 1, 1]})"), camera));
  const size_t centre = (24 * 64 + 32) * 3;
  EXPECT_GT(image.rgb[centre], 100);
  EXPECT_EQ(image.rgb[centre + 1], 0);
  EXPECT_EQ(image.rgb[centre + 2], 0);
}

// The fitted camera sees the whole model with a margin: nothing touches the image's border.
TEST(MeshFiles, FittedCameraFramesTheWholeModel) {
  for (const std::string file : {"glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb", "STL/Spider_binary.stl"}) {
    SCOPED_TRACE(file);
    const Image image = renderBoth(loadScene(kModels + file));  // a model file alone is a scene
    ASSERT_EQ(image.width, 960);
    const std::array<uint8_t, 3> background = {image.rgb[0], image.rgb[1], image.rgb[2]};
    size_t border = 0;
    for (int x = 0; x < image.width; ++x)
      for (int y : {0, image.height - 1}) border += image.rgb[(size_t(y) * image.width + x) * 3] != background[0];
    for (int y = 0; y < image.height; ++y)
      for (int x : {0, image.width - 1}) border += image.rgb[(size_t(y) * image.width + x) * 3] != background[0];
    EXPECT_EQ(border, 0u);
    EXPECT_GT(coveredPixels(image, background), size_t(image.width) * image.height / 20);
  }
}

// A concave face (an L of six corners, from a PLY file) is cut by ear clipping: four triangles,
// wound as the face, covering exactly its area (a fan from corner 0 would cover the notch).
TEST(MeshFiles, ConcavePolygonsAreCutIntoTheirOwnArea) {
  const std::vector<glm::vec3> positions = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}};
  for (uint32_t start = 0; start < 6; ++start) {  // every rotation of the corner list
    std::vector<uint32_t> corners;
    for (uint32_t k = 0; k < 6; ++k) corners.push_back((start + k) % 6);
    std::vector<glm::uvec3> triangles;
    triangulatePolygon(positions, corners, triangles);
    ASSERT_EQ(triangles.size(), 4u);
    double area = 0;
    for (const glm::uvec3& t : triangles) {
      const glm::dvec3 n = glm::cross(glm::dvec3(positions[t.y] - positions[t.x]), glm::dvec3(positions[t.z] - positions[t.x]));
      EXPECT_GT(n.z, 0.0);  // counter-clockwise, as the face
      area += n.z / 2;
      const glm::vec3 centroid = (positions[t.x] + positions[t.y] + positions[t.z]) / 3.0f;
      EXPECT_FALSE(centroid.x > 1 && centroid.y > 1) << "a triangle in the notch";
    }
    EXPECT_DOUBLE_EQ(area, 3.0);
  }
}

TEST(MeshFiles, BadFilesNameTheSceneTheJsonPathAndTheFile) {
  const std::string dir = makeTempDir();
  const std::string header = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                             "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
  std::string vertices;
  for (float c : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) vertices.append(reinterpret_cast<const char*>(&c), 4);
  const auto face = [](int32_t a, int32_t b, int32_t c) {
    std::string s(1, char(3));
    for (int32_t i : {a, b, c}) s.append(reinterpret_cast<const char*>(&i), 4);
    return s;
  };
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"truncated.ply", header + vertices.substr(0, 20)},
      {"index.ply", header + vertices + face(0, 1, 7)},
      {"nan.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                  "element face 1\nproperty list uchar int vertex_indices\nend_header\nnan 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"},
      {"empty.ply", "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\nproperty float z\n"
                    "element face 0\nproperty list uchar int vertex_indices\nend_header\n"},
      {"lies.stl", std::string(80, 'x') + std::string("\x10\x00\x00\x00", 4) + std::string(50, '\0')},
      {"notply.ply", "solid x\nendsolid x\n"},
      {"asciilist.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                        "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n"
                        "4000000000 0 1 2\n"},
      {"asciiword.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                        "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 zero 0\n0 1 0\n3 0 1 2\n"},
      {"floatlength.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                          "property float z\nelement face 1\nproperty list float int vertex_indices\nend_header\n"},
      {"broken.glb", "glTF\x02\x00\x00\x00garbage"},
      {"empty.glb", ""},
      {"broken.gltf", "{\"asset\": {\"version\": \"2.0\"}, \"meshes\": [{\"primitives\": [{\"attributes\": {}}]}]}"},
  };
  for (const auto& [name, content] : cases) {
    SCOPED_TRACE(name);
    writeFile(dir + "/" + name, content);
    const std::string message = thrownMessage<SceneError>([&] {
      const Scene scene = parseScene(R"({"camera": {"fit": true}, "objects": [{"shape": "cube"}, )" +
                                         meshObject(dir + "/" + name) + "]}",
                                     "scene.json", "/");
      Renderer(Backend::Cpu).render(scene);
    });
    EXPECT_EQ(message.rfind("scene.json: objects[1].file", 0), 0u) << message;
    EXPECT_NE(message.find(name), std::string::npos) << message;
  }
  // A buffer that names a FIFO: refused, not read (the read would wait for a writer forever).
  ASSERT_EQ(mkfifo((dir + "/fifo.bin").c_str(), 0644), 0);
  writeFile(dir + "/fifo.gltf", R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}], "accessors": [{"bufferView": 0, "componentType": 5126,
    "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]}], "bufferViews": [{"buffer": 0, "byteLength": 36}],
    "buffers": [{"byteLength": 36, "uri": "fifo.bin"}]})");
  const std::string fifo = thrownMessage<SceneError>([&] { loaded(dir + "/fifo.gltf"); });
  EXPECT_NE(fifo.find("not a valid glTF file"), std::string::npos) << fifo;
  // A GLB whose BIN chunk claims 8 bytes more than the file holds (tinygltf's own check misses the
  // chunk's header and would copy past the end): refused, naming where the chunk would end.
  const auto word = [](uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
  const std::string json = R"({"asset": {"version": "2.0"}, "buffers": [{"byteLength": 16}]})";
  const std::string padded = json + std::string((4 - json.size() % 4) % 4, ' ');
  const uint32_t length = uint32_t(20 + padded.size() + 8 + 8);
  writeFile(dir + "/overrun.glb", "glTF" + word(2) + word(length) + word(uint32_t(padded.size())) + "JSON" + padded +
                                      word(16) + std::string("BIN\0", 4) + std::string(8, '\x7f'));
  const std::string overrun = thrownMessage<SceneError>([&] { loaded(dir + "/overrun.glb"); });
  EXPECT_NE(overrun.find("its BIN chunk would end at byte " + std::to_string(length + 8) + ", past the file's length of " +
                         std::to_string(length) + " bytes"),
            std::string::npos)
      << overrun;
  std::filesystem::create_directory(dir + "/folder.ply");
  const CommandResult cli = runCli("render '" + dir + "/folder.ply' -o '" + dir + "/out.png'");
  EXPECT_EQ(cli.exitCode, 2) << cli.output;
  EXPECT_FALSE(std::filesystem::exists(dir + "/out.png"));
}

TEST(MeshFiles, ModelFileAloneRendersFromTheCommandLine) {
  const std::string dir = makeTempDir();
  const CommandResult cli = runCli("render " + kModels + "glTF2/BoxTextured-glTF-Binary/BoxTextured.glb -o '" + dir + "/box.png'");
  EXPECT_EQ(cli.exitCode, 0) << cli.output;
  EXPECT_TRUE(std::filesystem::exists(dir + "/box.png"));
  const CommandResult diffed = runCli("diff " + kModels + "PLY/Wuson.ply");
  EXPECT_EQ(diffed.exitCode, 0) << diffed.output;
}

// A model exported y-up renders, with --up y (LoadOptions), exactly as the same model exported z-up
// renders by default: the file's (a, c, -b) stood up is (a, b, c). Asked of a scene file, an up
// axis is an error (exit 2): a scene file gives each object its own "up".
TEST(MeshFiles, UpAxisOfAModelAlone) {
  const std::string dir = makeTempDir();
  const std::vector<glm::vec3> zUp = {{0, 0, 0}, {1, 0, 0}, {0, 0.5f, 0}, {0.25f, 0.2f, 1.5f}};
  const auto writePly = [&](const std::string& name, bool yUp) {
    std::string text = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                       "property float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n";
    for (const glm::vec3& p : zUp) {
      const glm::vec3 q = yUp ? glm::vec3(p.x, p.z, -p.y) : p;
      text += formatNumber(q.x) + " " + formatNumber(q.y) + " " + formatNumber(q.z) + "\n";
    }
    writeFile(dir + "/" + name, text + "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 2 0 3\n");
  };
  writePly("z_up.ply", false);
  writePly("y_up.ply", true);
  const Image expected = renderBoth(loadScene(dir + "/z_up.ply"));
  EXPECT_TRUE(renderBoth(loadScene(dir + "/y_up.ply", {.up = ModelUp::Y})).rgb == expected.rgb);
  EXPECT_FALSE(renderBoth(loadScene(dir + "/y_up.ply")).rgb == expected.rgb);  // lying on its side
  EXPECT_TRUE(renderBoth(loadScene(dir + "/z_up.ply", {.up = ModelUp::Z})).rgb == expected.rgb);

  const CommandResult cli = runCli("render '" + dir + "/y_up.ply' --up y -o '" + dir + "/y.png'");
  EXPECT_EQ(cli.exitCode, 0) << cli.output;
  EXPECT_TRUE(readPng(dir + "/y.png").rgb == expected.rgb);
  const CommandResult scene = runCli("render " + test::sourcePath("scenes/basic.json") + " --up y -o '" + dir + "/s.png'");
  EXPECT_EQ(scene.exitCode, 2) << scene.output;
  EXPECT_NE(scene.output.find("basic.json: an up axis applies to a model file rendered alone"), std::string::npos)
      << scene.output;
  EXPECT_FALSE(std::filesystem::exists(dir + "/s.png"));
}

// --projection orthographic (LoadOptions::orthographic): a model alone seen by a fitted
// orthographic camera, the same bytes on both renderers and from the CLI; a scene file's camera
// says its own projection, so asked of one it is an error (exit 2).
TEST(MeshFiles, OrthographicViewOfAModelAlone) {
  const std::string model = test::sourcePath("scenes/meshes/torus.obj");
  const Scene scene = loadScene(model, {.orthographic = true});
  ASSERT_TRUE(scene.camera().orthoHeight.has_value());
  EXPECT_GT(*scene.camera().orthoHeight, 0.0);
  const Image expected = renderBoth(scene);
  EXPECT_FALSE(renderBoth(loadScene(model)).rgb == expected.rgb);  // the perspective view differs
  const std::string dir = makeTempDir();
  const CommandResult cli = runCli("render '" + model + "' --projection orthographic -o '" + dir + "/o.png'");
  EXPECT_EQ(cli.exitCode, 0) << cli.output;
  EXPECT_TRUE(readPng(dir + "/o.png").rgb == expected.rgb);
  const CommandResult withScene =
      runCli("render " + test::sourcePath("scenes/basic.json") + " --projection orthographic -o '" + dir + "/s.png'");
  EXPECT_EQ(withScene.exitCode, 2) << withScene.output;
  EXPECT_NE(withScene.output.find("basic.json: a projection applies to a model file rendered alone"), std::string::npos)
      << withScene.output;
  // perspective too: a scene file's camera says its own projection, whichever is asked.
  const CommandResult perspective =
      runCli("render " + test::sourcePath("scenes/orthographic.json") + " --projection perspective -o '" + dir + "/s.png'");
  EXPECT_EQ(perspective.exitCode, 2) << perspective.output;
  EXPECT_NE(perspective.output.find("orthographic.json: a projection applies to a model file rendered alone"), std::string::npos)
      << perspective.output;
  EXPECT_FALSE(std::filesystem::exists(dir + "/s.png"));
}

}  // namespace
}  // namespace phongvk
