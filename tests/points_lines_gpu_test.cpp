// points_lines_gpu_test.cpp — points and lines (docs/DESIGN.md "Points and lines"): the pixels a
// point's square and a line's quad cover under the top-left rule, to the pixel; their depth, ids,
// colours lit and unlit; hostile sizes and geometry; and both renderers giving the same bytes and
// keys in every shading mode, with samples, both projections and a line through the near plane.
#include "scene/scene.h"
#include "test_util.h"

#include <phongvk/phongvk.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace phongvk {
namespace {

// Both renderers' output for `scene`, which must be the same bytes and keys.
RenderOutput both(const Scene& scene) {
  Renderer cpu(Backend::Cpu), gpu(RendererOptions{Backend::Gpu, -1, true});
  RenderOutput a = cpu.renderWithKeys(scene);
  const RenderOutput b = gpu.renderWithKeys(scene);
  EXPECT_TRUE(a.image.rgb == b.image.rgb) << "the renderers' images differ";
  EXPECT_TRUE(a.keys == b.keys) << "the renderers' keys differ";
  EXPECT_EQ(gpu.stats().validationMessages, 0u);
  return a;
}

// A 16x16 orthographic view down -z at one pixel a metre: world (x, y) is screen (8 + x, 8 - y).
const std::string kPixelCamera =
    R"("camera": {"position": [0, 0, 10], "look_at": [0, 0, 0], "up": [0, 1, 0], "projection": "orthographic",
                  "ortho_height": 16, "width": 16, "height": 16})";

// World coordinates of screen position (sx, sy) in kPixelCamera's view, as JSON.
std::string at(double sx, double sy, double z = 0) {
  return "[" + std::to_string(sx - 8) + ", " + std::to_string(8 - sy) + ", " + std::to_string(z) + "]";
}

Scene pixelScene(const std::string& objects, const std::string& render = "{}") {
  return parseScene("{" + kPixelCamera + R"(, "lights": [], "ambient": [1, 1, 1], "render": )" + render +
                    R"(, "objects": [)" + objects + "]}");
}

// The covered pixels of an output, as "x,y" in row order.
std::vector<std::string> covered(const RenderOutput& out) {
  std::vector<std::string> pixels;
  for (size_t i = 0; i < out.keys.size(); ++i) {
    if (out.keys[i] != ~uint64_t(0)) pixels.push_back(std::to_string(i % 16) + "," + std::to_string(i / 16));
  }
  return pixels;
}

std::string pointMesh(const std::string& vertices, double size) {
  return R"({"shape": "mesh", "vertices": [)" + vertices + R"(], "point_size": )" + std::to_string(size) + "}";
}

TEST(PointsLines, APointCoversThePixelCentresInItsSquareByTheTopLeftRule) {
  // Size 1 centred on a pixel centre: that pixel.
  EXPECT_EQ(covered(both(pixelScene(pointMesh(at(3.5, 4.5), 1)))), std::vector<std::string>{"3,4"});
  // Size 3: the 3x3 pixels around it.
  EXPECT_EQ(covered(both(pixelScene(pointMesh(at(3.5, 4.5), 3)))),
            (std::vector<std::string>{"2,3", "3,3", "4,3", "2,4", "3,4", "4,4", "2,5", "3,5", "4,5"}));
  // Size 1 centred between two pixel centres: its left edge holds one of them and takes it, its
  // right edge holds the other and leaves it; likewise its top edge and bottom edge.
  EXPECT_EQ(covered(both(pixelScene(pointMesh(at(4.0, 4.5), 1)))), std::vector<std::string>{"3,4"});
  EXPECT_EQ(covered(both(pixelScene(pointMesh(at(3.5, 5.0), 1)))), std::vector<std::string>{"3,4"});
  // Size 2 on a pixel corner: the four pixels around it.
  EXPECT_EQ(covered(both(pixelScene(pointMesh(at(4.0, 4.0), 2)))),
            (std::vector<std::string>{"3,3", "4,3", "3,4", "4,4"}));
  // Size 0.5 between centres: none.
  EXPECT_TRUE(covered(both(pixelScene(pointMesh(at(4.0, 4.0), 0.5)))).empty());
}

TEST(PointsLines, ALineCoversItsWidthAcrossItsMinorAxisWithoutCaps) {
  const auto line = [](const std::string& a, const std::string& b, double width) {
    return R"({"shape": "mesh", "vertices": [)" + a + ", " + b + R"(], "lines": [[0, 1]], "line_width": )" +
           std::to_string(width) + "}";
  };
  // x-major, width 1 on row 4's centres, from x = 2 to 10: pixels 2..9 of row 4.
  std::vector<std::string> row;
  for (int x = 2; x < 10; ++x) row.push_back(std::to_string(x) + ",4");
  EXPECT_EQ(covered(both(pixelScene(line(at(2, 4.5), at(10, 4.5), 1)))), row);
  // Width 3: rows 3..5.
  EXPECT_EQ(covered(both(pixelScene(line(at(2, 4.5), at(10, 4.5), 3)))).size(), 24u);
  // y-major (steeper than 45 degrees): widened in x, one pixel a row.
  const std::vector<std::string> steep = covered(both(pixelScene(line(at(6.5, 2), at(7.5, 12), 1))));
  ASSERT_EQ(steep.size(), 10u);
  for (size_t k = 0; k < steep.size(); ++k) EXPECT_EQ(steep[k].substr(steep[k].find(',') + 1), std::to_string(2 + k));
}

TEST(PointsLines, DepthIsTheCentresAndTheLinesAndIdsNumberPrimitivesAfterTriangles) {
  // A triangle at z = -1 (11 m away), a line at z = 0 (10 m) across it, a point at z = 2 (8 m).
  const Scene scene = pixelScene(
      R"({"shape": "mesh", "vertices": [[-8, -8, -1], [8, -8, -1], [0, 8, -1]], "faces": [[0, 1, 2]]},
         {"shape": "mesh", "vertices": [[-6, 0.5, 0], [6, -0.5, 2]], "lines": [[0, 1]], "line_width": 2},
         {"shape": "mesh", "vertices": )" + std::string("[") + at(12.5, 12.5, 2) + "], \"point_size\": 2}");
  const RenderOutput out = both(scene);
  const Visibility v = visibilityOf(out);
  Renderer gpu(Backend::Gpu);
  Outputs wanted;
  wanted.triangleIds = true;
  wanted.depth = true;
  const RenderedFrame frame = gpu.renderOutputs(scene, wanted);
  int line = 0, point = 0;
  for (size_t i = 0; i < v.triangle.size(); ++i) {
    const int id = frame.triangleIds[i];
    if (id == 1) {  // the line: its depth along it, 10 m at its start to 8 m at its end
      ++line;
      EXPECT_GE(frame.depth[i], 8.0f);
      EXPECT_LE(frame.depth[i], 10.0f);
    }
    if (id == 2) {
      ++point;
      EXPECT_EQ(frame.depth[i], 8.0f);  // the centre's view depth, exactly
    }
    EXPECT_TRUE(id == -1 || id <= 2) << id;
  }
  EXPECT_GT(line, 12);
  EXPECT_EQ(point, 4);
  // The triangles() companions say which is which.
  const SceneTriangles t = scene.triangles();
  EXPECT_EQ(t.objects.size(), 1u);
  EXPECT_EQ(t.mesh.lines, (std::vector<int64_t>{3, 4}));
  EXPECT_EQ(t.mesh.points, (std::vector<int64_t>{5}));
  EXPECT_EQ(t.lineObjects, std::vector<int32_t>{1});
  EXPECT_EQ(t.pointObjects, std::vector<int32_t>{2});
}

TEST(PointsLines, WithoutNormalsTheyShowTheirColourUnlitWithNormalsTheyAreLit) {
  const std::string objects =
      R"({"shape": "mesh", "vertices": [)" + at(4.5, 4.5) + "], \"colors\": [[200, 100, 50, 255]], \"point_size\": 3," +
      R"( "material": {"color": [1, 1, 1], "ka": 0.1, "kd": 0.5, "ks": 0}},
         {"shape": "mesh", "vertices": [)" + at(10.5, 10.5) + R"(], "normals": [[0, 0, 1]], "point_size": 3,
          "material": {"color": [1, 1, 1], "ka": 0.1, "kd": 0.5, "ks": 0}})";
  for (const char* shading : {"gouraud", "flat", "phong"}) {
    const std::string render = std::string(R"({"shading": ")") + shading + "\"}";
    const Scene scene = parseScene("{" + kPixelCamera + R"(, "lights": [{"direction": [0, 0, -1], "intensity": 1}],
        "ambient": [1, 1, 1], "render": )" + render + R"(, "objects": [)" + objects + "]}");
    const RenderOutput out = both(scene);
    const uint8_t* unlit = &out.image.rgb[3 * (4 * 16 + 4)];
    EXPECT_EQ(int(unlit[0]), 200) << shading;
    EXPECT_EQ(int(unlit[1]), 100) << shading;
    EXPECT_EQ(int(unlit[2]), 50) << shading;
    const uint8_t* lit = &out.image.rgb[3 * (10 * 16 + 10)];
    EXPECT_EQ(int(lit[0]), 153) << shading;  // (0.1 + 0.5) * 255, facing the light
  }
}

// A scene of every kind of primitive, seen in perspective; `render` its render section.
Scene mixedScene(const std::string& render, const std::string& camera) {
  return parseScene(R"({"camera": )" + camera + R"(, "lights": [{"position": [2, -3, 4], "intensity": 1}],
    "render": )" + render + R"(, "objects": [
      {"shape": "sphere", "center": [0, 0, 0.5], "radius": 0.5},
      {"shape": "mesh", "vertices": [[-1,-1,0],[1,-1,0],[1,1,0],[-1,1,0],[0,0,1.5],[0.3,-0.2,1.2]],
       "lines": [[0,1],[1,2],[2,3],[3,0],[0,4],[2,4]], "point_indices": [4, 5],
       "colors": [[255,0,0,255],[0,255,0,255],[0,0,255,255],[255,255,0,255],[255,255,255,255],[0,255,255,255]],
       "line_width": 2.5, "point_size": 6},
      {"shape": "mesh", "vertices": [[-0.5,-0.5,-0.5],[0.5,-0.6,1.8],[0.7,0.4,0.2],[-0.8,0.8,0.9]],
       "normals": [[0,0,1],[1,0,0],[0,-1,0],[0,1,1]], "point_size": 4.25}]})");
}

const std::string kPerspective = R"({"position": [0, -4, 2], "look_at": [0, 0, 0], "fov": 45, "resolution": 90})";

TEST(PointsLines, BothRenderersAgreeInEveryModeWithSamplesAndBothProjections) {
  for (const char* render : {R"({"shading": "gouraud"})", R"({"shading": "flat"})", R"({"shading": "phong"})",
                             R"({"samples": 4, "point_size": 2})", R"({"interpolation": "screen", "line_width": 3})"}) {
    SCOPED_TRACE(render);
    const RenderOutput out = both(mixedScene(render, kPerspective));
    EXPECT_GT(covered(out).size(), 100u);
  }
  both(mixedScene("{}", R"({"position": [0, -4, 2], "look_at": [0, 0, 0], "projection": "orthographic",
                           "ortho_height": 3, "width": 80, "height": 60})"));
}

TEST(PointsLines, LinesThroughTheNearPlaneAndTheEyeAndZeroLengthOnesAreBounded) {
  // The camera at (0, -4, 2): one line passes through the eye, one from behind it to the far
  // side, one has zero length, one point is behind the eye; the rest of the scene still renders.
  const Scene scene = parseScene(R"({"camera": )" + kPerspective + R"(, "lights": [], "objects": [
      {"shape": "sphere", "center": [0, 0, 0.5], "radius": 0.5},
      {"shape": "mesh", "vertices": [[0, -8, 4], [0, 0, 0], [3, -6, 2], [-1, 2, 0], [0.2, 0, 1], [0.2, 0, 1], [0, -9, 2]],
       "lines": [[0, 1], [2, 3], [4, 5]], "point_indices": [6], "line_width": 5, "point_size": 64}]})");
  const RenderOutput out = both(scene);
  EXPECT_GT(covered(out).size(), 200u);
}

TEST(PointsLines, BadSizesAndVerticesAreRefusedByName) {
  const auto error = [](const std::string& render, const std::string& object = "") {
    return test::thrownMessage<SceneError>([&] {
      parseScene(R"({"camera": {"position": [0, -4, 2], "look_at": [0, 0, 0]}, "render": )" + render +
                 R"(, "objects": [{"shape": "mesh", "vertices": [[0, 0, 0]])" + object + "}]}");
    });
  };
  EXPECT_NE(error(R"({"point_size": 0})").find("render.point_size: must be at least 1/256 pixel"), std::string::npos);
  EXPECT_NE(error(R"({"point_size": 10000})").find("render.point_size"), std::string::npos);
  EXPECT_NE(error(R"({"line_width": -1})").find("render.line_width"), std::string::npos);
  EXPECT_NE(error("{}", R"(, "point_size": 65)").find("objects[0].point_size"), std::string::npos);
  EXPECT_NE(error("{}", R"(, "lines": [[0, 3]])").find("objects[0].lines: row 0 has index 3"), std::string::npos);
  EXPECT_NE(error("{}", R"(, "point_indices": [-1])").find("objects[0].point_indices: row 0 has index -1"),
            std::string::npos);
  MeshArrays nan;
  nan.positions = {0, 0, std::nanf("")};
  EXPECT_NE(test::thrownMessage<ArgumentError>([&] { Scene(8, 8).addMesh(nan); }).find("vertices: row 0 is not finite"),
            std::string::npos);
}

// 307 points of six sizes (a hundredth of a pixel to 64) scattered from behind the eye, across the
// near plane and the edges of the view, to beyond the far plane, in a 96x64 view with `projection`.
Scene scatteredCloud(const std::string& projection) {
  const double sizes[] = {0.01, 1, 2.5, 7, 20, 64};
  std::string objects;
  uint32_t h = 12345u;
  const auto next = [&h](double lo, double hi) {
    h = h * 1664525u + 1013904223u;
    return lo + (hi - lo) * double(h >> 8) / double(1u << 24);
  };
  for (int o = 0; o < 6; ++o) {
    std::string vertices;
    for (int i = 0; i < (o == 0 ? 52 : 51); ++i) {
      vertices += std::string(i ? ", [" : "[") + std::to_string(next(-7, 7)) + ", " + std::to_string(next(-5, 14)) + ", " +
                  std::to_string(next(-3, 6)) + "]";
    }
    objects += std::string(o ? ", " : "") + R"({"shape": "mesh", "vertices": [)" + vertices +
               R"(], "point_size": )" + std::to_string(sizes[o]) + "}";
  }
  return parseScene(R"({"camera": {"position": [0, -4, 2], "look_at": [0, 0, 0], "near": 0.5, "far": 12,
      "width": 96, "height": 64)" + projection + R"(}, "lights": [], "objects": [)" + objects + "]}");
}

TEST(PointsLines, APointCloudAcrossEveryPlaneAndInSharesThatSplitItsQuadsGivesTheReferencesKeys) {
  // The GPU draws a point's two quad halves in one invocation (raster_triangles.comp drawPoint),
  // handing the halves of one that needs clipping or is not small to the clip pass; the reference
  // draws each half as a triangle. 614 records in three shares: the second ends on a first half,
  // the third begins on the second half of the same point.
  for (const char* projection : {"", R"(, "projection": "orthographic", "ortho_height": 9)"}) {
    SCOPED_TRACE(projection);
    const Scene scene = scatteredCloud(projection);
    EXPECT_GT(covered(both(scene)).size(), 500u);
    for (int part = 0; part < 3; ++part) {
      SCOPED_TRACE(part);
      EXPECT_GT(covered(both(scene.share(part, 3))).size(), 10u);
    }
  }
}

TEST(PointsLines, APointCloudIsFramedByTheFittedCamera) {
  std::string vertices;
  for (int i = 0; i < 100; ++i) {
    vertices += (i ? ", [" : "[") + std::to_string(i % 10) + ", " + std::to_string(i / 10) + ", " + std::to_string(i % 7) + "]";
  }
  const Scene scene = parseScene(R"({"camera": {"fit": true, "direction": [-1, 2, -1], "width": 64, "height": 48},
      "objects": [{"shape": "mesh", "vertices": [)" + vertices + "]}]}");
  const RenderOutput out = both(scene);
  // Framed as a mesh is: the covered pixels span most of the image one way, with a margin.
  int x0 = 64, x1 = -1, y0 = 48, y1 = -1;
  for (size_t i = 0; i < out.keys.size(); ++i) {
    if (out.keys[i] == ~uint64_t(0)) continue;
    const int x = int(i % 64), y = int(i / 64);
    x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
  }
  EXPECT_TRUE(x1 - x0 >= 32 || y1 - y0 >= 24) << x0 << " " << x1 << " " << y0 << " " << y1;
  EXPECT_TRUE(x0 > 0 && y0 > 0 && x1 < 63 && y1 < 47) << x0 << " " << x1 << " " << y0 << " " << y1;
}

}  // namespace
}  // namespace phongvk
