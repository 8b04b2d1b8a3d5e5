// textures_gpu_test.cpp — base-colour textures (docs/DESIGN.md "Textures"): the sampling maths of
// texture.h on fixed cases (wrapping, taps, the integer blend), real textured files made by other
// tools (Debian's assimp-testmodels: glTF's BoxTextured three ways, an OBJ with JPEG maps) and the
// committed textured scene rendering the reference's keys and bytes on the compute port in every
// shading mode, filter and sample count, a stress case of coordinates far outside [0, 1],
// degenerate coordinates and the largest texture side, and bad textures failing with the scene
// file, the JSON path, the model and the image named.
#include <phongvk/phongvk.h>

#include "shaders/texture.h"
#include "tests/test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <set>
#include <string>
#include <vector>

namespace phongvk {
namespace {

using namespace gpu;
using namespace test;

const std::string kModels = "/usr/share/assimp/models/";

TEST(TextureMaths, WrapModesTakeEveryCoordinateIntoTheUnitInterval) {
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  EXPECT_EQ(wrapUnit(0.25f, TEXTURE_WRAP_REPEAT), 0.25f);
  EXPECT_EQ(wrapUnit(-0.25f, TEXTURE_WRAP_REPEAT), 0.75f);
  EXPECT_EQ(wrapUnit(3.5f, TEXTURE_WRAP_REPEAT), 0.5f);
  EXPECT_EQ(wrapUnit(1e10f, TEXTURE_WRAP_REPEAT), 0.0f);  // an integer: every float this large is
  EXPECT_EQ(wrapUnit(1.25f, TEXTURE_WRAP_MIRROR), 0.75f);
  EXPECT_EQ(wrapUnit(-0.25f, TEXTURE_WRAP_MIRROR), 0.25f);
  EXPECT_EQ(wrapUnit(2.25f, TEXTURE_WRAP_MIRROR), 0.25f);
  EXPECT_EQ(wrapUnit(1e30f, TEXTURE_WRAP_MIRROR), 0.0f);  // even
  EXPECT_EQ(wrapUnit(2.0f, TEXTURE_WRAP_CLAMP), 1.0f);
  EXPECT_EQ(wrapUnit(-1e30f, TEXTURE_WRAP_CLAMP), 0.0f);
  for (uint mode : {TEXTURE_WRAP_REPEAT, TEXTURE_WRAP_CLAMP, TEXTURE_WRAP_MIRROR}) {
    EXPECT_EQ(wrapUnit(nan, mode), 0.0f) << mode;
    const float w = wrapUnit(-inf, mode);
    EXPECT_TRUE(w >= 0.0f && w <= 1.0f) << mode;
    EXPECT_EQ(wrapUnit(-1e-12f, mode) <= 1.0f, true) << mode;  // may round to 1: one past the end, wrapped
  }
}

TEST(TextureMaths, TapsSitBetweenTexelCentresAndWrapAtTheEdges) {
  const TextureData t{100, 4, 2, TEXTURE_WRAP_REPEAT | TEXTURE_WRAP_CLAMP << 8};
  // u = 0.5 is the boundary between texels 1 and 2: bilinear halfway between them (fx = 0.5 of 256)...
  TextureTaps k = textureTaps(t, vec2(0.5f, 0.25f), TEXTURE_FILTER_BILINEAR);
  EXPECT_EQ(k.i00, 100u + 1u);
  EXPECT_EQ(k.i10, 100u + 2u);
  EXPECT_EQ(k.fx, 128u);
  EXPECT_EQ(k.fy, 0u);  // v = 0.25 is row 0's centre
  EXPECT_EQ(k.i01, 100u + 4u + 1u);
  // ...nearest takes texel 2, with no blend.
  k = textureTaps(t, vec2(0.5f, 0.25f), TEXTURE_FILTER_NEAREST);
  EXPECT_EQ(k.i00, 100u + 2u);
  EXPECT_EQ(k.fx, 0u);
  // Left of the first centre: repeat blends with the last column; clamp (v) stays on the first row.
  k = textureTaps(t, vec2(0.0f, 0.0f), TEXTURE_FILTER_BILINEAR);
  EXPECT_EQ(k.i00, 100u + 3u);
  EXPECT_EQ(k.i10, 100u + 0u);
  EXPECT_EQ(k.fx, 128u);
  EXPECT_EQ(k.i01, k.i00);  // row -1 clamps to row 0
}

TEST(TextureMaths, TheBlendIsExactIntegerArithmetic) {
  TextureTaps k{};
  k.fx = 128;
  k.fy = 0;
  // Halfway between 0 and 255 rounds 127.5 up.
  EXPECT_EQ(blendTaps(0xFF000000u, 0xFFFFFFFFu, 0u, 0u, k), 0xFF808080u);
  k.fx = 64;
  k.fy = 192;
  // Weights 192*64, 64*64, 192*192, 64*192 (of 65536) of red 0, 255, 255, 0: 255 * 40960 / 65536 = 159.375.
  EXPECT_EQ(blendTaps(0u, 255u, 255u, 0u, k) & 255u, 159u);
  k.fx = k.fy = 0;
  EXPECT_EQ(blendTaps(0xFF123456u, 0u, 0u, 0u, k), 0xFF123456u);  // nearest: the texel itself
}

// Renders on both backends; expects the same bytes and keys; returns the image.
Image renderBoth(const Scene& scene, const std::string& what) {
  const DiffResult result = diff(scene, RendererOptions{Backend::Gpu, -1, true});
  EXPECT_EQ(result.stats.differing, 0u) << what;
  EXPECT_EQ(result.stats.triangleMismatch, 0u) << what;
  EXPECT_TRUE(result.reference.keys == result.gpu.keys) << what;
  EXPECT_TRUE(result.reference.image.rgb == result.gpu.image.rgb) << what;
  return result.gpu.image;
}

size_t distinctColours(const Image& image) {
  std::set<uint32_t> colours;
  for (size_t i = 0; i < image.rgb.size(); i += 3) colours.insert(image.rgb[i] | image.rgb[i + 1] << 8 | image.rgb[i + 2] << 16);
  return colours.size();
}

TEST(Textures, TexturedFilesRenderTheReferenceBytesInEveryModeFilterAndSampleCount) {
  const std::vector<std::string> files = {sourcePath("scenes/textured.json"),
                                          kModels + "glTF2/BoxTextured-glTF-Binary/BoxTextured.glb",
                                          kModels + "OBJ/spider.obj"};
  const std::vector<std::string> modes = {R"({"shading": "gouraud"})", R"({"shading": "flat"})",
                                          R"({"shading": "phong"})", R"({"interpolation": "screen"})",
                                          R"({"samples": 4, "shading": "phong"})"};
  for (const std::string& file : files) {
    const Scene scene = loadScene(file).withImageSize(160, 120);
    for (const std::string& mode : modes) {
      for (const char* filter : {"nearest", "bilinear"}) {
        const std::string options = mode.substr(0, mode.size() - 1) + R"(, "texture_filter": ")" + filter + R"("})";
        renderBoth(withRenderOptions(scene, options), file + " " + options);
      }
    }
  }
}

TEST(Textures, EveryTexturedSampleModelRendersTheReferenceBytes) {
  // Debian's assimp-testmodels: every glTF 2.0 file with a base-colour texture that phongvk reads
  // (the others require an extension, or are broken on purpose: below), and its OBJs with map_Kd.
  for (const char* model : {"glTF2/BoxTextured-glTF/BoxTextured.gltf", "glTF2/BoxTextured-glTF-Embedded/BoxTextured.gltf",
                            "glTF2/BoxTextured-glTF-Binary/BoxTextured.glb",
                            "glTF2/BoxTextured-glTF-pbrSpecularGlossiness/BoxTextured.gltf",
                            "glTF2/BoxTexcoords-glTF/boxTexcoords.gltf", "glTF2/textureTransform/TextureTransformTest.gltf",
                            "glTF2/ClearCoat-glTF/ClearCoatTest.gltf", "OBJ/spider.obj"}) {
    const Image image = renderBoth(loadScene(kModels + model).withImageSize(240, 180), model);
    EXPECT_GT(distinctColours(image), 100u) << model;
  }
  // A material whose texture reads TEXCOORD_0 on a primitive without it (assimp's crash case).
  EXPECT_EQ(thrownMessage<SceneError>([&] { Renderer(Backend::Cpu).render(loadScene(kModels + "glTF2/issue_3269/texcoord_crash.gltf")); }),
            kModels + "glTF2/issue_3269/texcoord_crash.gltf: materials[4]'s base colour texture reads TEXCOORD_0, which a primitive lacks");
}

TEST(Textures, BoxTexturedReadsItsTextureEmbeddedInADataUriInAGlbOrBesideTheFile) {
  const Image glb = renderBoth(loadScene(kModels + "glTF2/BoxTextured-glTF-Binary/BoxTextured.glb"), "glb");
  const Image embedded = renderBoth(loadScene(kModels + "glTF2/BoxTextured-glTF-Embedded/BoxTextured.gltf"), "data URI");
  const Image beside = renderBoth(loadScene(kModels + "glTF2/BoxTextured-glTF/BoxTextured.gltf"), "PNG file");
  EXPECT_TRUE(glb.rgb == embedded.rgb);
  // assimp's copy beside its PNG has a sampler of its own: u mirrored (MIRRORED_REPEAT) over
  // coordinates that run to 6, so the faces whose u lies in [1, 2], [3, 4] or [5, 6] show the logo
  // mirrored; with the GLB's REPEAT they show it as it is.
  EXPECT_FALSE(glb.rgb == beside.rgb);
  EXPECT_GT(distinctColours(beside), 3000u);
  // Without its texture the box is one lit grey per face, a few hundred shades; the logo adds thousands.
  EXPECT_GT(distinctColours(glb), 3000u);
}

// A scene of the committed textured cube with `obj` in place of its OBJ file, written beside a copy
// of its material library and texture.
std::string sceneWithObj(const std::string& dir, const std::string& obj) {
  std::filesystem::copy_file(sourcePath("scenes/meshes/checker.png"), dir + "/checker.png");
  std::filesystem::copy_file(sourcePath("scenes/meshes/textured_cube.mtl"), dir + "/textured_cube.mtl");
  writeFile(dir + "/model.obj", obj);
  const std::string scene = dir + "/scene.json";
  writeFile(scene, R"({"camera": {"position": [0.3, -3, 0.4], "look_at": [0, 0, 0], "width": 120, "height": 90},
                       "objects": [{"shape": "mesh", "file": "model.obj"}]})");
  return scene;
}

TEST(Textures, CoordinatesFarOutsideTheUnitSquareAndDegenerateOnesRenderTheSameOnBothBackends) {
  const std::string dir = makeTempDir();
  const std::string obj = R"(mtllib textured_cube.mtl
usemtl checker
v -1 0 -1
v 1 0 -1
v 1 0 1
v -1 0 1
v -1 0.5 -1
v 1 0.5 1
vt 1e30 -3e9
vt -1e10 7.25
vt 16777217.5 -0.001
vt 0.3 0.3
f 1/1 2/2 3/3
f 1/4 3/4 4/4
f 5/3 6/2 4/1
)";
  const Scene scene = loadScene(sceneWithObj(dir, obj));
  for (const char* wrap : {"nearest", "bilinear"}) {
    renderBoth(withRenderOptions(scene, std::string(R"({"texture_filter": ")") + wrap + "\"}"), wrap);
  }
}

TEST(Textures, TheLargestSideSamplesToItsLastTexel) {
  // 16384 x 2 texels: red everywhere but the last column, green. Nearest sampling of u just below
  // 1 must reach that column: its fixed-point position (u * 16384 * 256) is 2^22 exactly at most.
  const std::string dir = makeTempDir();
  Image wide;
  wide.width = int(TEXTURE_MAX_SIDE);
  wide.height = 2;
  wide.rgb.assign(size_t(wide.width) * 2 * 3, 0);
  for (int y = 0; y < 2; ++y) {
    for (int x = 0; x < wide.width; ++x) wide.rgb[(size_t(y) * wide.width + x) * 3 + (x == wide.width - 1 ? 1 : 0)] = 255;
  }
  writePng(dir + "/checker.png", wide);
  std::filesystem::copy_file(sourcePath("scenes/meshes/textured_cube.mtl"), dir + "/textured_cube.mtl");
  writeFile(dir + "/model.obj", "mtllib textured_cube.mtl\nusemtl checker\nv -1 0 -1\nv 1 0 -1\nv 1 0 1\n"
                                "vt 0.99999 0.5\nvt 0.99999 0.5\nvt 0.99999 0.5\nf 1/1 2/2 3/3\n");
  writeFile(dir + "/scene.json", R"({"camera": {"position": [0.3, -3, -0.3], "look_at": [0.3, 0, -0.3], "width": 16, "height": 12},
    "ambient": [1, 1, 1], "lights": [],
    "materials": {"m": {"ka": 1, "kd": 0, "ks": 0, "color": [1, 1, 1]}},
    "objects": [{"shape": "mesh", "file": "model.obj", "material": "m"}], "render": {"texture_filter": "nearest"}})");
  const Image image = renderBoth(loadScene(dir + "/scene.json"), "16384 texels wide");
  const size_t centre = (size_t(6) * 16 + 8) * 3;
  EXPECT_EQ(image.rgb[centre], 0);
  EXPECT_EQ(image.rgb[centre + 1], 255);
}

TEST(Textures, BadTexturesNameTheSceneTheObjectTheModelAndTheImage) {
  const std::string dir = makeTempDir();
  const std::string scene = sceneWithObj(dir, "mtllib textured_cube.mtl\nusemtl checker\nv 0 0 0\nv 1 0 0\nv 0 0 1\n"
                                              "vt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n");
  std::filesystem::remove(dir + "/checker.png");
  std::string message = thrownMessage<SceneError>([&] { Renderer(Backend::Cpu).render(loadScene(scene)); });
  EXPECT_NE(message.find(scene + ": objects[0].file: " + dir + "/model.obj: map_Kd 'checker.png': cannot open"), std::string::npos)
      << message;
  writeFile(dir + "/checker.png", "\x89PNG\r\n\x1a\n not really");
  message = thrownMessage<SceneError>([&] { Renderer(Backend::Cpu).render(loadScene(scene)); });
  EXPECT_NE(message.find("map_Kd 'checker.png': PNG: cannot read its header: [20]rea: invalid chunk type"), std::string::npos) << message;
  writeFile(dir + "/checker.png", "GIF89a not a texture");
  message = thrownMessage<SceneError>([&] { Renderer(Backend::Cpu).render(loadScene(scene)); });
  EXPECT_NE(message.find("map_Kd 'checker.png': not a PNG or JPEG image (it starts 47 49 46 38 39 61 20 6e)"), std::string::npos) << message;
  Image huge;
  huge.width = int(TEXTURE_MAX_SIDE) + 1;
  huge.height = 1;
  huge.rgb.assign(size_t(huge.width) * 3, 128);
  writePng(dir + "/checker.png", huge);
  message = thrownMessage<SceneError>([&] { Renderer(Backend::Cpu).render(loadScene(scene)); });
  EXPECT_NE(message.find("map_Kd 'checker.png': the image is 16385x1 pixels; a texture's sides are 1 to 16384"), std::string::npos)
      << message;
}

TEST(Textures, APlyTextureFileCommentTexturesItsUvCoordinates) {
  // Blender's cube_uv.ply has s and t per vertex but names no texture: given one, it is sampled.
  const std::string dir = makeTempDir();
  std::string ply = readBytes(kModels + "PLY/cube_uv.ply");
  ply.insert(ply.find("element vertex"), "comment TextureFile checker.png\n");
  writeFile(dir + "/cube.ply", ply);
  const Scene plain = loadScene(kModels + "PLY/cube_uv.ply");
  EXPECT_THROW(loadScene(dir + "/cube.ply"); Renderer(Backend::Cpu).render(loadScene(dir + "/cube.ply")), SceneError);
  std::filesystem::copy_file(sourcePath("scenes/meshes/checker.png"), dir + "/checker.png");
  const Image textured = renderBoth(loadScene(dir + "/cube.ply"), "cube_uv.ply with a TextureFile");
  EXPECT_GT(distinctColours(textured), 4 * distinctColours(renderBoth(plain, "cube_uv.ply")));
  // MeshLab's per-face coordinates are not read, and the notice says so.
  writeFile(dir + "/faces.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                                "element face 1\nproperty list uchar int vertex_indices\nproperty list uchar float texcoord\n"
                                "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 6 0 0 1 0 0 1\n");
  Renderer renderer(Backend::Cpu);
  renderer.render(loadScene(dir + "/faces.ply"));
  EXPECT_EQ(renderer.stats().notice, dir + "/faces.ply: its per-face texture coordinates (texcoord lists) are not read "
                                           "(phongvk reads u and v per vertex)");
}

TEST(Textures, TheSceneApiTakesATextureOnAMaterialAndUvsOnAMesh) {
  Scene scene(96, 72);
  scene.setAmbient({0.6, 0.6, 0.6});
  MeshArrays square;
  square.positions = {-1, 0, -1, 1, 0, -1, 1, 0, 1, -1, 0, 1};
  square.triangles = {0, 1, 2, 0, 2, 3};
  square.uvs = {0, 2, 2, 2, 2, 0, 0, 0};  // the texture twice across and down
  Material material;
  material.texture = sourcePath("scenes/meshes/checker.png");
  scene.add(square, IDENTITY_POSE, material);
  const Image image = renderBoth(scene, "a material's texture on arrays with uvs");
  EXPECT_GT(distinctColours(image), 50u);
  // Written back and read again: the same bytes.
  EXPECT_TRUE(renderBoth(parseScene(scene.toJson(), "again.json", "/"), "written back").rgb == image.rgb);
  // A material's texture needs coordinates; a missing file is named with the material's path.
  Scene bare(96, 72);
  square.uvs.clear();
  bare.add(square, IDENTITY_POSE, material);
  EXPECT_EQ(thrownMessage<SceneError>([&] { Renderer(Backend::Cpu).render(bare); }),
            "objects[0].material.texture: the object's mesh has no texture coordinates to sample it with");
  material.texture = "/nonexistent/wood.png";
  EXPECT_EQ(thrownMessage<SceneError>([&] { bare.add(square, IDENTITY_POSE, material); }),
            "objects[1].material.texture: '/nonexistent/wood.png': cannot open '/nonexistent/wood.png': No such file or directory");
  EXPECT_NE(thrownMessage<SceneError>([&] {
              parseScene(R"({"camera": {"position": [0, -3, 0], "look_at": [0, 0, 0]}, "materials": {"m": {"texture": "data:image/gif;base64,R0lG"}},
                            "objects": [{"shape": "sphere", "material": "m"}]})", "a.json", "/");
            }).find("a.json: materials.m.texture: the data URI: a data URI of a texture starts data:image/png;base64,"),
            std::string::npos);
}

TEST(Textures, MapsThatAreNotRenderedAreNamedInTheNotice) {
  const std::string dir = makeTempDir();
  const std::string scene = sceneWithObj(dir, "mtllib textured_cube.mtl\nusemtl checker\nv 0 0 0\nv 1 0 0\nv 0 0 1\n"
                                              "vt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n");
  writeFile(dir + "/textured_cube.mtl", "newmtl checker\nmap_Kd checker.png\nmap_Ks shiny.png\nbump -bm 2 bumps.png\nmap_Bump bumps.png\n");
  Renderer renderer(Backend::Cpu);
  renderer.render(loadScene(scene));
  EXPECT_EQ(renderer.stats().notice,
            dir + "/model.obj: its map_Ks and bump maps are not rendered (phongvk samples base-colour textures only)");
  renderer.render(loadScene(sourcePath("scenes/textured.json")));
  EXPECT_EQ(renderer.stats().notice, "");
}

TEST(Textures, AGltfImageFileThatIsMissingIsNamed) {
  const std::string dir = makeTempDir();
  for (const char* file : {"BoxTextured.gltf", "BoxTextured0.bin"})
    std::filesystem::copy_file(kModels + "glTF2/BoxTextured-glTF/" + file, dir + "/" + file);
  const std::string message = thrownMessage<SceneError>([&] { Renderer(Backend::Cpu).render(loadScene(dir + "/BoxTextured.gltf")); });
  EXPECT_NE(message.find("BoxTextured.gltf: images[0] ('CesiumLogoFlat.png'): cannot open '" + dir + "/CesiumLogoFlat.png'"),
            std::string::npos)
      << message;
}

}  // namespace
}  // namespace phongvk
