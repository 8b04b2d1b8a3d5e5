// mesh_primitives_test.cpp — points and lines from mesh files (meshio/): the counts real files from
// Debian's assimp-testmodels give, small files written here for each way a format says a point or
// a line, Draco-compressed glTF (decoded value for value, and refused by name when damaged), the
// extensions a glTF file may require, and the normals of vertices no triangle uses.
//
// The expected counts of the real files were derived from the files themselves, apart from
// phongvk, with a short Python script: OBJ, per line, 'p': its vertices, 'l': its vertices - 1,
// 'f': its vertices - 2, and a file of 'v' lines alone one point a vertex; glTF, walking the
// default scene's nodes, per primitive by its mode from its indices' (or POSITION's) accessor count
// n: points n, lines n / 2, a loop n (n > 2), a strip n - 1, triangles n / 3.
#include "geometry/normals.h"
#include "meshio/gltf_import.h"
#include "meshio/mesh_file.h"
#include "meshio/mesh_import.h"
#include "phongvk/errors.h"

#include <draco/compression/encode.h>
#include <draco/mesh/triangle_soup_mesh_builder.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <ostream>
#include <string>
#include <vector>

namespace phongvk {
namespace {

namespace fs = std::filesystem;

const std::string kModels = "/usr/share/assimp/models/";
const std::string kWhere = "objects[0].file";

// A file read as a mesh object reads it: imported, then finished (no transform).
Mesh load(const std::string& path) {
  return finishLoadedMesh(importMeshFile(path, meshFormat(path, kWhere), false, kWhere), LinearTransform{}, kWhere + ": " + path);
}

// The SceneError loading `path` throws, without the "<where>: <path>: " every message starts with.
std::string loadError(const std::string& path) {
  try {
    load(path);
  } catch (const SceneError& error) {
    const std::string message = error.what(), prefix = kWhere + ": " + path + ": ";
    return message.rfind(prefix, 0) == 0 ? message.substr(prefix.size()) : message;
  }
  return "(no error)";
}

struct Counts {
  size_t positions = 0, triangles = 0, points = 0, lines = 0;
  bool operator==(const Counts&) const = default;
};

void PrintTo(const Counts& c, std::ostream* out) {
  *out << "{positions " << c.positions << ", triangles " << c.triangles << ", points " << c.points << ", lines " << c.lines << "}";
}

Counts countsOf(const Mesh& mesh) { return {mesh.positions.size(), mesh.triangles.size(), mesh.points.size(), mesh.lines.size()}; }

// Every normal unit length, or (0, 0, 0) where no triangle uses the vertex; how many are zero.
size_t zeroNormals(const Mesh& mesh) {
  EXPECT_EQ(mesh.normals.size(), mesh.positions.size());
  std::vector<bool> onTriangle(mesh.positions.size(), false);
  for (const glm::uvec3& t : mesh.triangles) onTriangle[t.x] = onTriangle[t.y] = onTriangle[t.z] = true;
  size_t zero = 0;
  for (size_t v = 0; v < mesh.normals.size(); ++v) {
    if (mesh.normals[v] == glm::vec3(0.0f) && !onTriangle[v]) {
      ++zero;
    } else {
      EXPECT_NEAR(glm::length(mesh.normals[v]), 1.0f, 1e-6f) << "vertex " << v;
    }
  }
  return zero;
}

// A folder of its own for each test, removed after it.
class MeshFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string pattern = (fs::temp_directory_path() / "phongvk-primitives-XXXXXX").string();
    ASSERT_NE(mkdtemp(pattern.data()), nullptr);
    dir_ = pattern;
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& bytes) const {
    std::ofstream(dir_ + "/" + name, std::ios::binary) << bytes;
    return dir_ + "/" + name;
  }

  std::string dir_;
};

std::string readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// ---- real files (assimp-testmodels) ----

TEST(RealMeshFiles, ObjPointsAndLines) {
  // MeshLab's point cloud: 3 'v' lines, each with its 'vn' line: lit points.
  const Mesh cloud = load(kModels + "OBJ/point_cloud.obj");
  EXPECT_EQ(countsOf(cloud), (Counts{3, 0, 3, 0}));
  EXPECT_EQ(zeroNormals(cloud), 0u);
  EXPECT_NEAR(cloud.normals[0].z, 0.957989 / std::sqrt(0.281034 * 0.281034 + 0.057252 * 0.057252 + 0.957989 * 0.957989), 1e-6);
  // Six 'p' lines of 4 vertices over a cube's 8 corners; six 'l' polylines of 4 (3 segments each).
  const Mesh points = load(kModels + "OBJ/testpoints.obj");
  EXPECT_EQ(countsOf(points), (Counts{8, 0, 24, 0}));
  EXPECT_EQ(zeroNormals(points), 8u);  // no normals given: drawn unlit
  const Mesh lines = load(kModels + "OBJ/testline.obj");
  EXPECT_EQ(countsOf(lines), (Counts{8, 0, 0, 18}));
  EXPECT_EQ(zeroNormals(lines), 8u);
  // The first polyline, "l 4 3 2 1": vertices in the order of first use.
  EXPECT_EQ(lines.lines[0], glm::uvec2(0, 1));
  EXPECT_EQ(lines.lines[2], glm::uvec2(2, 3));
  EXPECT_EQ(lines.positions[0], glm::vec3(-0.5f, 0.5f, 0.5f));
  // All three, with 'f' lines between the 'p' lines: the cube's 6 quads, 24 points, 18 segments,
  // every vertex on a face and so lit.
  const Mesh mixed = load(kModels + "OBJ/testmixed.obj");
  EXPECT_EQ(countsOf(mixed), (Counts{8, 12, 24, 18}));
  EXPECT_EQ(zeroNormals(mixed), 0u);
}

TEST(RealMeshFiles, PlyPointClouds) {
  // No face element: four coloured points, with normals.
  const Mesh points = load(kModels + "PLY/points.ply");
  EXPECT_EQ(countsOf(points), (Counts{4, 0, 4, 0}));
  ASSERT_EQ(points.colors.size(), 4u);
  EXPECT_EQ(points.colors[1], 0xFFFF00FFu);  // 255 0 255, opaque
  EXPECT_EQ(points.normals[2], glm::vec3(1, 0, 0));
  EXPECT_NEAR(points.normals[3].x, std::sqrt(0.5), 1e-6);  // (1, 1, 0) made unit
}

TEST_F(MeshFiles, ScannerPlyWithDiffuseColours) {
  // A scanner's binary point cloud (x y z nx ny nz diffuse_red diffuse_green diffuse_blue psz, 31
  // bytes a vertex): its header promises 70051 vertices, 2171512 bytes hold 70048 and 24 bytes.
  const std::string pond = kModels + "PLY/pond.0.ply";
  EXPECT_EQ(loadError(pond), "element 'vertex' 70048 of 70051 runs past the end of the file (2171788 bytes)");
  // Its first 626 rows are whole (from row 626 on the bytes are shifted: the file is damaged): as
  // a file of their own, 626 points with the scanner's colours and unit normals.
  std::string bytes = readBytes(pond);
  const size_t header = bytes.find("end_header\n") + 11;
  ASSERT_EQ(header, 276u);
  std::string head = bytes.substr(0, header);
  head.replace(head.find("70051"), 5, "  626");
  const Mesh mesh = load(write("pond626.ply", head + bytes.substr(header, 626 * 31)));
  EXPECT_EQ(countsOf(mesh), (Counts{626, 0, 626, 0}));
  EXPECT_EQ(zeroNormals(mesh), 0u);
  EXPECT_EQ(mesh.colors[0], 0xFF133B39u);  // diffuse 57 59 19
  EXPECT_NEAR(mesh.normals[0].x, -0.697392f, 1e-6f);
}

struct PrimitiveModeCase {
  int number;
  Counts counts;  // after finishing: flat triangles have 3 vertices each (no NORMAL in these files)
};

class PrimitiveModes : public ::testing::TestWithParam<PrimitiveModeCase> {};

// glTF-Asset-Generator's Mesh_PrimitiveMode_00 to _15: every mode, without indices (00 to 06) and
// with them (07 to 15). None has NORMAL: points and lines are unlit, triangles flat.
TEST_P(PrimitiveModes, CountsByMode) {
  const PrimitiveModeCase& c = GetParam();
  const std::string number = (c.number < 10 ? "0" : "") + std::to_string(c.number);
  const std::string path = kModels + "glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_" + number + ".gltf";
  const Mesh mesh = load(path);
  EXPECT_EQ(countsOf(mesh), c.counts);
  EXPECT_EQ(zeroNormals(mesh), c.counts.triangles == 0 ? c.counts.positions : 0u);
  // The memory estimate counts a point or a segment as two triangles: its quad's two records.
  EXPECT_EQ(gltfTriangles(path, false), std::optional<uint64_t>(c.counts.triangles + 2 * (c.counts.points + c.counts.lines)));
}

INSTANTIATE_TEST_SUITE_P(AssetGenerator, PrimitiveModes,
                         ::testing::Values(PrimitiveModeCase{0, {1024, 0, 1024, 0}},  // POINTS
                                           PrimitiveModeCase{1, {8, 0, 0, 4}},        // LINES, 8 vertices
                                           PrimitiveModeCase{2, {4, 0, 0, 4}},        // LINE_LOOP of 4
                                           PrimitiveModeCase{3, {5, 0, 0, 4}},        // LINE_STRIP of 5
                                           PrimitiveModeCase{4, {6, 2, 0, 0}},        // TRIANGLE_STRIP of 4
                                           PrimitiveModeCase{5, {6, 2, 0, 0}},        // TRIANGLE_FAN of 4
                                           PrimitiveModeCase{6, {6, 2, 0, 0}},        // TRIANGLES
                                           PrimitiveModeCase{7, {1024, 0, 1024, 0}},  // POINTS [0 - 1023]
                                           PrimitiveModeCase{8, {4, 0, 0, 4}},        // LINES [0 3 3 2 2 1 1 0]
                                           PrimitiveModeCase{9, {4, 0, 0, 4}},        // LINE_LOOP [0 3 2 1]
                                           PrimitiveModeCase{10, {4, 0, 0, 4}},       // LINE_STRIP [0 3 2 1 0]
                                           PrimitiveModeCase{11, {6, 2, 0, 0}}, PrimitiveModeCase{12, {6, 2, 0, 0}},
                                           PrimitiveModeCase{13, {6, 2, 0, 0}}, PrimitiveModeCase{14, {6, 2, 0, 0}},
                                           PrimitiveModeCase{15, {6, 2, 0, 0}}),
                         [](const auto& info) { return "Mode" + std::to_string(info.param.number); });

// The three ways of drawing the same square's outline give the same four segments.
TEST(RealMeshFiles, LineModesWithIndicesAgree) {
  const std::string folder = kModels + "glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_";
  const std::vector<glm::uvec2> outline = {{0, 3}, {3, 2}, {2, 1}, {1, 0}};
  for (const char* number : {"08", "09", "10"}) EXPECT_EQ(load(folder + number + ".gltf").lines, outline) << number;
}

TEST(RealMeshFiles, DracoCompressedGltf) {
  // 29 meshes, 34 primitives, all compressed (POSITION and NORMAL), 115 placed by the nodes.
  const std::string path = kModels + "glTF2/draco/2CylinderEngine.gltf";
  const Mesh imported = importMeshFile(path, MeshFormat::Gltf, false, kWhere);
  EXPECT_EQ(countsOf(imported), (Counts{84716, 110336, 0, 0}));  // the accessors' counts
  EXPECT_EQ(gltfTriangles(path, false), std::optional<uint64_t>(110336));
  size_t zeroArea = 0;
  for (const glm::uvec3& t : imported.triangles) {
    const glm::dvec3 a(imported.positions[t.x]), b(imported.positions[t.y]), c(imported.positions[t.z]);
    zeroArea += glm::cross(b - a, c - a) == glm::dvec3(0.0);
  }
  EXPECT_EQ(zeroArea, 14u);
  const Mesh mesh = load(path);
  EXPECT_EQ(mesh.triangles.size(), 110336u - zeroArea);
  EXPECT_EQ(mesh.positions.size(), 84704u);  // 12 vertices only the zero-area triangles used
  EXPECT_EQ(zeroNormals(mesh), 0u);
}

TEST(RealMeshFiles, UnimplementedRequiredExtensionIsNamed) {
  EXPECT_EQ(loadError(kModels + "glTF2/BoxTextured-glTF-techniqueWebGL/BoxTextured.gltf"),
            "requires the extension KHR_technique_webgl, which phongvk does not implement");
}

// ---- files written here ----

TEST_F(MeshFiles, PlyEdgesAndShortFaces) {
  const std::string header = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n";
  const std::string vertices = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n";
  const std::string edges = "element edge 3\nproperty int vertex1\nproperty int vertex2\nproperty uchar red\n";
  // An edge element alone: lines, not a point cloud.
  const Mesh square = load(write("edges.ply", header + edges + "end_header\n" + vertices + "0 1 9\n1 2 9\n2 3 9\n"));
  EXPECT_EQ(countsOf(square), (Counts{4, 0, 0, 3}));
  EXPECT_EQ(square.lines[2], glm::uvec2(2, 3));
  EXPECT_EQ(zeroNormals(square), 4u);
  // Faces of one and two vertices are a point and a line, beside a triangle.
  const std::string faces = "element face 3\nproperty list uchar int vertex_indices\n";
  const Mesh mixed = load(write("faces.ply", header + faces + "end_header\n" + vertices + "3 0 1 2\n1 3\n2 3 0\n"));
  EXPECT_EQ(countsOf(mixed), (Counts{4, 1, 1, 1}));
  EXPECT_EQ(mixed.points[0], 3u);
  EXPECT_EQ(zeroNormals(mixed), 1u);  // vertex 3: a point and a line only
  EXPECT_EQ(loadError(write("bad.ply", header + edges + "end_header\n" + vertices + "0 1 9\n1 7 9\n2 3 9\n")),
            "edge 1 has vertex index 7, but there are 4 vertices");
  EXPECT_EQ(loadError(write("empty.ply", "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
                                         "property float z\nend_header\n")),
            "nothing to draw (no triangles, lines or points)");
}

TEST_F(MeshFiles, ObjPointsLinesAndErrors) {
  const std::string v = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";
  // A negative index counts back from the 'v' lines before it, as a face corner's does.
  const Mesh mesh = load(write("pl.obj", v + "p 1 3\nl 1 2 3 4 1\nl -1 -4\nf 1 2 3\n"));
  EXPECT_EQ(countsOf(mesh), (Counts{4, 1, 2, 5}));
  EXPECT_EQ(mesh.lines[4], glm::uvec2(3, 0));  // "l -1 -4": vertices 4 and 1
  // Vertex 4 (the mesh's 3: vertices come in the order the face, the points and the lines use
  // them) is on no triangle: drawn unlit.
  EXPECT_EQ(zeroNormals(mesh), 1u);
  EXPECT_EQ(mesh.normals[3], glm::vec3(0.0f));
  EXPECT_EQ(loadError(write("short.obj", v + "l 1\n")), "line 5: an 'l' line needs 2 vertices or more, got 1");
  EXPECT_EQ(loadError(write("range.obj", v + "p 1 9\n")), "line 5: 'p' vertex index 9 is out of range (the file has 4 vertices)");
  EXPECT_EQ(loadError(write("before.obj", "v 0 0 0\nl 1 -2\n" + v)),
            "line 2: 'l' vertex index -2 is out of range (the file has 5 vertices)");
  EXPECT_EQ(loadError(write("word.obj", v + "p 1 x\n")), "line 5: 'x' is not a 'p' vertex (v or v/vt, indices 32-bit and not 0)");
  // Only 'v' lines: a point cloud of the four.
  EXPECT_EQ(countsOf(load(write("cloud.obj", v))), (Counts{4, 0, 4, 0}));
  EXPECT_EQ(loadError(write("none.obj", "# nothing\n")), "nothing to draw (no 'f', 'l', 'p' or 'v' lines)");
}

// A glTF of one primitive over a square's 4 corners (z = 0), in `bytes`, its buffer a file beside
// it: positions (48 bytes) then `indices` (uint8) as accessor 1 when given.
struct SquareGltf {
  int mode = 2;
  std::vector<uint8_t> indices;
  std::string extra;  // more primitives, each starting with ", "
  std::string top;    // more top-level members, each followed by ", "

  std::string write(const std::string& dir) const {
    const float corners[12] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    std::string buffer(reinterpret_cast<const char*>(corners), sizeof corners);
    buffer.append(indices.begin(), indices.end());
    if (indices.empty()) buffer += '\0';  // the second view's byte
    std::ofstream(dir + "/square.bin", std::ios::binary) << buffer;
    const std::string indexed = indices.empty() ? "" : R"(, "indices": 1)";
    const std::string json =
        "{" + top + R"("asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "mode": )" + std::to_string(mode) + indexed + "}" + extra + R"(]}],
        "buffers": [{"uri": "square.bin", "byteLength": )" + std::to_string(buffer.size()) + R"(}],
        "bufferViews": [{"buffer": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": )" +
        std::to_string(std::max<size_t>(indices.size(), 1)) + R"(}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]},
                      {"bufferView": 1, "componentType": 5121, "count": )" + std::to_string(indices.size()) + R"(, "type": "SCALAR"}]})";
    std::ofstream(dir + "/square.gltf") << json;
    return dir + "/square.gltf";
  }
};

TEST_F(MeshFiles, GltfLineLoopWithIndices) {
  SquareGltf loop;
  loop.indices = {0, 2, 1, 3};  // a bow tie: the diagonals and two sides, closed back to 0
  const Mesh mesh = load(loop.write(dir_));
  EXPECT_EQ(countsOf(mesh), (Counts{4, 0, 0, 4}));
  EXPECT_EQ(mesh.lines, (std::vector<glm::uvec2>{{0, 2}, {2, 1}, {1, 3}, {3, 0}}));
  EXPECT_EQ(zeroNormals(mesh), 4u);
  // Two indices make one segment, not a segment and its way back.
  loop.indices = {1, 2};
  EXPECT_EQ(countsOf(load(loop.write(dir_))), (Counts{2, 0, 0, 1}));
  // A loop of points beside a flat triangle: the triangle's vertices of its own, the points' unlit.
  SquareGltf both;
  both.mode = 0;
  both.extra = R"(, {"attributes": {"POSITION": 0}, "mode": 4, "indices": 1})";
  both.indices = {0, 1, 2};
  const Mesh mixed = load(both.write(dir_));
  EXPECT_EQ(countsOf(mixed), (Counts{3 + 3, 1, 3, 0}));
  EXPECT_EQ(zeroNormals(mixed), 3u);
}

TEST_F(MeshFiles, GltfRequiredExtensions) {
  SquareGltf square;
  square.top = R"("extensionsRequired": ["KHR_draco_mesh_compression", "KHR_lights_punctual"], )";
  EXPECT_EQ(loadError(square.write(dir_)), "(no error)");  // both implemented (and here unused)
  square.top = R"("extensionsRequired": ["KHR_lights_punctual", "KHR_texture_transform", "EXT_mesh_gpu_instancing"], )";
  EXPECT_EQ(loadError(square.write(dir_)),
            "requires the extensions KHR_texture_transform, EXT_mesh_gpu_instancing, which phongvk does not implement");
  // Named even where tinygltf cannot load the file: meshopt's fallback buffer has no URI.
  square.top = R"("extensionsRequired": ["EXT_meshopt_compression"], )";
  std::string json = readBytes(square.write(dir_));
  json.replace(json.find(R"("uri": "square.bin", )"), 21, "");
  EXPECT_EQ(loadError(write("square.gltf", json)), "requires the extension EXT_meshopt_compression, which phongvk does not implement");
}

// ---- Draco ----

// A quad (two triangles over 4 points) with positions, normals, RGBA8 colours (stored as plain
// integers: the accessor's `normalized` scales them) and texture coordinates (a 1x1 base-colour
// texture samples them), Draco-encoded without quantization (lossless) and in sequential order
// (points and faces as built).
struct DracoQuad {
  std::array<std::array<float, 3>, 4> positions = {{{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}}};
  std::array<std::array<float, 3>, 4> normals = {{{0, 0, 1}, {0, 0, 1}, {0, 0.6f, 0.8f}, {0, 0.6f, 0.8f}}};
  std::array<std::array<uint8_t, 4>, 4> colors = {{{255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}, {51, 102, 153, 255}}};
  std::array<std::array<float, 2>, 4> uvs = {{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
  std::array<std::array<int, 3>, 2> faces = {{{0, 1, 2}, {0, 2, 3}}};
  std::array<int, 4> ids{};  // each attribute's unique id: POSITION, NORMAL, COLOR_0, TEXCOORD_0

  std::string encode() {
    draco::TriangleSoupMeshBuilder builder;
    builder.Start(2);
    const int attributes[4] = {builder.AddAttribute(draco::GeometryAttribute::POSITION, 3, draco::DT_FLOAT32),
                               builder.AddAttribute(draco::GeometryAttribute::NORMAL, 3, draco::DT_FLOAT32),
                               builder.AddAttribute(draco::GeometryAttribute::COLOR, 4, draco::DT_UINT8),
                               builder.AddAttribute(draco::GeometryAttribute::TEX_COORD, 2, draco::DT_FLOAT32)};
    for (int f = 0; f < 2; ++f) {
      const auto& c = faces[size_t(f)];
      const auto set = [&](int a, const auto& values) {
        builder.SetAttributeValuesForFace(attributes[a], draco::FaceIndex(f), values[size_t(c[0])].data(), values[size_t(c[1])].data(),
                                          values[size_t(c[2])].data());
      };
      set(0, positions), set(1, normals), set(2, colors), set(3, uvs);
    }
    const std::unique_ptr<draco::Mesh> mesh = builder.Finalize();
    for (int a = 0; a < 4; ++a) ids[size_t(a)] = int(mesh->attribute(attributes[a])->unique_id());
    draco::Encoder encoder;
    encoder.SetEncodingMethod(draco::MESH_SEQUENTIAL_ENCODING);
    draco::EncoderBuffer out;
    EXPECT_TRUE(encoder.EncodeMeshToBuffer(*mesh, &out).ok());
    EXPECT_EQ(mesh->num_points(), 4u);  // the six corners' equal values deduplicated
    return std::string(out.data(), out.size());
  }

  // The .gltf (with `draco.bin` beside it, holding `compressed`): the quad compressed, its accessors
  // without buffer views, as the extension asks.
  std::string gltf(size_t compressedBytes, const std::string& primitiveExtra = "") const {
    return R"({"asset": {"version": "2.0"}, "extensionsUsed": ["KHR_draco_mesh_compression"],
      "extensionsRequired": ["KHR_draco_mesh_compression"], "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
      "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1, "COLOR_0": 2, "TEXCOORD_0": 3}, "indices": 4,
        "material": 0, "extensions": {"KHR_draco_mesh_compression": {"bufferView": 0, "attributes": {"POSITION": )" +
           std::to_string(ids[0]) + R"(, "NORMAL": )" + std::to_string(ids[1]) + R"(, "COLOR_0": )" + std::to_string(ids[2]) +
           R"(, "TEXCOORD_0": )" + std::to_string(ids[3]) + "}}}" + primitiveExtra + R"(}]}],
      "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}], "textures": [{"source": 0}],
      "images": [{"uri": "data:image/png;base64,iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAYAAAAfFcSJAAAADUlEQVR42mP8z8BQDwAEhQGAhKmMIQAAAABJRU5ErkJggg=="}],
      "buffers": [{"uri": "draco.bin", "byteLength": )" + std::to_string(compressedBytes) + R"(}],
      "bufferViews": [{"buffer": 0, "byteLength": )" + std::to_string(compressedBytes) + R"(}],
      "accessors": [{"componentType": 5126, "count": 4, "type": "VEC3", "min": [0, 0, 0], "max": [2, 1, 0]},
                    {"componentType": 5126, "count": 4, "type": "VEC3"},
                    {"componentType": 5121, "normalized": true, "count": 4, "type": "VEC4"},
                    {"componentType": 5126, "count": 4, "type": "VEC2"},
                    {"componentType": 5123, "count": 6, "type": "SCALAR"}]})";
  }
};

class Draco : public MeshFiles {
 protected:
  // The quad written as a .gltf; its compressed bytes damaged by `damage` first.
  std::string writeQuad(DracoQuad& quad, const std::function<void(std::string&)>& damage = {}, const std::string& primitiveExtra = "") {
    std::string compressed = quad.encode();
    if (damage) damage(compressed);
    write("draco.bin", compressed);
    return write("draco.gltf", quad.gltf(compressed.size(), primitiveExtra));
  }
};

TEST_F(Draco, DecodesEveryAttributeExactly) {
  DracoQuad quad;
  const std::string path = writeQuad(quad);
  const Mesh imported = importMeshFile(path, MeshFormat::Gltf, false, kWhere);
  ASSERT_EQ(countsOf(imported), (Counts{4, 2, 0, 0}));
  for (size_t f = 0; f < 2; ++f) {
    for (int k = 0; k < 3; ++k) {
      const uint32_t v = imported.triangles[f][k];
      const size_t source = size_t(quad.faces[f][size_t(k)]);
      const auto& p = quad.positions[source];
      EXPECT_EQ(imported.positions[v], glm::vec3(p[0], p[1], p[2]));
      const auto& n = quad.normals[source];
      EXPECT_EQ(imported.normals[v], glm::vec3(n[0], n[1], n[2]));
      const auto& c = quad.colors[source];
      EXPECT_EQ(imported.colors[v], uint32_t(c[0]) | uint32_t(c[1]) << 8 | uint32_t(c[2]) << 16 | uint32_t(c[3]) << 24);
      const auto& uv = quad.uvs[source];
      EXPECT_EQ(imported.uvs[v], glm::vec2(uv[0], uv[1]));
    }
  }
  EXPECT_EQ(gltfTriangles(path, false), std::optional<uint64_t>(2));
}

// A GLB of `json` and the BIN chunk `bin`, each padded to 4 bytes as the format asks.
std::string glb(std::string json, std::string bin) {
  json.resize((json.size() + 3) / 4 * 4, ' ');
  bin.resize((bin.size() + 3) / 4 * 4, '\0');
  const auto u32 = [](size_t value) {
    const uint32_t v = uint32_t(value);
    return std::string(reinterpret_cast<const char*>(&v), 4);
  };
  return "glTF" + u32(2) + u32(12 + 8 + json.size() + 8 + bin.size()) + u32(json.size()) + "JSON" + json + u32(bin.size()) + "BIN" +
         std::string(1, '\0') + bin;
}

TEST_F(Draco, DecodesFromGlb) {
  // The same quad in one GLB: its buffer is the BIN chunk (no URI), its JSON chunk rewritten to
  // give the indices accessor a buffer view before tinygltf reads it (gltf_draco.h).
  DracoQuad quad;
  const std::string compressed = quad.encode();
  std::string json = quad.gltf(compressed.size());
  json.replace(json.find(R"("uri": "draco.bin", )"), 20, "");
  const std::string path = write("draco.glb", glb(json, compressed));
  const Mesh mesh = load(path);
  EXPECT_EQ(countsOf(mesh), (Counts{4, 2, 0, 0}));
  EXPECT_EQ(mesh.positions[mesh.triangles[0][1]], glm::vec3(2, 0, 0));
  EXPECT_EQ(gltfTriangles(path, true), std::optional<uint64_t>(2));
}

TEST_F(Draco, DamagedDataIsRefusedByName) {
  const std::string prefix = "meshes[0].primitives[0]: KHR_draco_mesh_compression: ";
  DracoQuad quad;
  // Not Draco's header ("DRACO" first).
  std::string message = loadError(writeQuad(quad, [](std::string& bytes) { bytes[0] = 'X'; }));
  EXPECT_EQ(message.rfind(prefix + "the compressed data cannot be decoded (Draco: ", 0), 0u) << message;
  // Cut short.
  message = loadError(writeQuad(quad, [](std::string& bytes) { bytes.resize(bytes.size() / 2); }));
  EXPECT_EQ(message.rfind(prefix + "the compressed data cannot be decoded (Draco: ", 0), 0u) << message;
  // Every byte after the header flipped in turn: decoded (the values may be wrong: a position
  // that is no longer finite is refused as any file's is) or refused by name, never a crash or a
  // read out of bounds.
  const size_t size = quad.encode().size();
  for (size_t at = 5; at < size; ++at) {
    message = loadError(writeQuad(quad, [&](std::string& bytes) { bytes[at] = char(~bytes[at]); }));
    const bool named = message.rfind(prefix, 0) == 0 || message.find(" is not finite or beyond the coordinates") != std::string::npos;
    EXPECT_TRUE(message == "(no error)" || named) << "byte " << at << ": " << message;
  }
}

TEST_F(Draco, WhatTheExtensionNamesMustBeThere) {
  const std::string prefix = "meshes[0].primitives[0]: KHR_draco_mesh_compression: ";
  DracoQuad quad;
  const std::string compressed = quad.encode();
  write("draco.bin", compressed);
  const int normal = quad.ids[1];
  quad.ids[1] = 7;  // NORMAL's id: not in the data
  EXPECT_EQ(loadError(write("draco.gltf", quad.gltf(compressed.size()))), prefix + "NORMAL's attribute id 7 is not in the compressed data");
  quad.ids[1] = normal;
  EXPECT_EQ(loadError(writeQuad(quad, {}, R"(, "mode": 0)")),
            prefix + "the primitive's mode is 0; compressed primitives are triangles (4) or a triangle strip (5)");
  // The decoded counts must be what the accessors say (the memory estimate reads those).
  std::string json = quad.gltf(compressed.size());
  json.replace(json.find(R"("count": 6)"), 10, R"("count": 9)");
  EXPECT_EQ(loadError(write("draco.gltf", json)), prefix + "the triangles decode to 6 indices, but the indices accessor says 9");
  json = quad.gltf(compressed.size());
  json.replace(json.find(R"("bufferView": 0, "attributes")"), 15, R"("bufferView": 5)");
  EXPECT_EQ(loadError(write("draco.gltf", json)), prefix + "bufferView 5 does not exist");
}

// ---- normals ----

TEST(ComputedNormals, VerticesNoTriangleUsesAreZero) {
  Mesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 5, 5}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}};
  mesh.triangles = {{0, 1, 2}, {4, 5, 6}};  // the second has zero area
  mesh.points = {3};
  computeVertexNormals(mesh);
  EXPECT_EQ(mesh.normals[0], glm::vec3(0, 0, 1));
  EXPECT_EQ(mesh.normals[3], glm::vec3(0, 0, 0));  // a point's alone: unlit
  EXPECT_EQ(mesh.normals[5], glm::vec3(0, 0, 1));  // on a zero-area triangle only: +z, as ever
}

}  // namespace
}  // namespace phongvk
