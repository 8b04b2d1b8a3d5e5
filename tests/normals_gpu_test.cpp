// normals_gpu_test.cpp — the normals output (Outputs::normals): the same bytes on both backends in
// every shading mode and sample count; unit length where a triangle covers the pixel and zero
// where none does; the ray-cast sphere's normal within the tessellation's bound; back faces of an
// open object keep their stored normal.
#include "phongvk/phongvk.h"
#include "test_util.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <tuple>
#include <vector>

namespace phongvk {
namespace {

using namespace test;

constexpr double PI = 3.14159265358979323846;

double length(const float* n) { return std::sqrt(double(n[0]) * n[0] + double(n[1]) * n[1] + double(n[2]) * n[2]); }

class NormalsBothBackends : public ::testing::TestWithParam<std::tuple<std::string, std::string, int>> {};

TEST_P(NormalsBothBackends, AreTheSameBytesAndUnitWhereCovered) {
  const auto& [path, shading, samples] = GetParam();
  const Scene scene = withRenderOptions(loadScene(sourcePath(path)).withImageSize(160, 120),
                                        R"({"shading": ")" + shading + R"(", "samples": )" + std::to_string(samples) + "}");
  Outputs outputs;
  outputs.normals = outputs.triangleIds = true;
  const RenderedFrame cpu = Renderer(Backend::Cpu).renderOutputs(scene, outputs);
  const RenderedFrame gpu = Renderer(Backend::Gpu).renderOutputs(scene, outputs);
  ASSERT_EQ(cpu.normals.size(), size_t(160 * 120 * 3));
  ASSERT_EQ(gpu.normals.size(), cpu.normals.size());
  EXPECT_EQ(std::memcmp(gpu.normals.data(), cpu.normals.data(), cpu.normals.size() * sizeof(float)), 0);
  int covered = 0;
  for (size_t i = 0; i < cpu.triangleIds.size(); ++i) {
    const float* n = &cpu.normals[3 * i];
    if (cpu.triangleIds[i] < 0) {
      EXPECT_TRUE(n[0] == 0 && n[1] == 0 && n[2] == 0) << "empty pixel " << i;
      continue;
    }
    ++covered;
    EXPECT_NEAR(length(n), 1.0, 1e-6) << "pixel " << i;
  }
  EXPECT_GT(covered, 100);
}

INSTANTIATE_TEST_SUITE_P(Scenes, NormalsBothBackends,
                         ::testing::Combine(::testing::Values("scenes/basic.json", "scenes/paper/fig1_cube.json",
                                                              "scenes/mesh_torus.json", "scenes/floor_and_walls.json",
                                                              "scenes/stress/inside_object.json"),
                                            ::testing::Values("gouraud", "flat", "phong"), ::testing::Values(1, 4)),
                         [](const auto& info) {
                           std::string name = std::get<0>(info.param).substr(7) + "_" + std::get<1>(info.param) + "_" +
                                              std::to_string(std::get<2>(info.param));
                           std::replace_if(name.begin(), name.end(), [](char c) { return !std::isalnum(c); }, '_');
                           return name;
                         });

// An icosphere of radius 1 at 4 m, seen down +y: the camera's x is the world's x, its y the world's z.
constexpr double DISTANCE = 4.0, FOV = 40.0;
constexpr int SIDE = 96;

Scene sphereScene(const std::string& shading, int samples) {
  return parseScene(R"({"camera": {"position": [0, -4, 0], "look_at": [0, 0, 0], "fov": 40, "width": 96, "height": 96},
                        "objects": [{"shape": "icosphere", "radius": 1, "subdivide": 5}],
                        "render": {"shading": ")" + shading + R"(", "samples": )" + std::to_string(samples) + "}}");
}

// The angle (degrees) between `n` and the analytic sphere's normal where the ray through (px, py)
// (in pixels from the image's top-left corner) meets it; NaN where the ray passes farther than 95%
// of the radius from the centre (the mesh's silhouette lies inside the sphere's).
double angleToSphere(const float* n, double px, double py) {
  const double focal = SIDE / (2 * std::tan(FOV / 2 * PI / 180));
  // The ray (rx, ry, 1) in camera axes (x right, y up, z forward); the sphere's centre (0, 0, 4).
  const double rx = (px - SIDE / 2.0) / focal, ry = -(py - SIDE / 2.0) / focal;
  const double a = rx * rx + ry * ry + 1, b = -2 * DISTANCE, c = DISTANCE * DISTANCE - 1;
  if (DISTANCE * DISTANCE * (1 - 1 / a) > 0.95 * 0.95) return NAN;  // the ray's distance from the centre, squared
  const double t = (-b - std::sqrt(b * b - 4 * a * c)) / (2 * a);
  const double expected[3] = {t * rx, t * ry, t - DISTANCE};  // (P - centre) / radius
  const double cosine = (expected[0] * n[0] + expected[1] * n[1] + expected[2] * n[2]) / length(n);
  return std::acos(std::min(1.0, cosine)) * 180 / PI;
}

// Over the pixels whose samples all see the sphere well inside its silhouette: the largest angle
// between a pixel's normal and the analytic normal at the best-matching of its side x side
// samples (at the pixel centre without samples), and how many such pixels there were.
std::pair<double, int> worstAngle(const RenderedFrame& frame, int side) {
  double worst = 0;
  int pixels = 0;
  for (int y = 0; y < SIDE; ++y) {
    for (int x = 0; x < SIDE; ++x) {
      const float* n = &frame.normals[3 * (size_t(y) * SIDE + x)];
      double best = INFINITY;
      bool inside = true;
      for (int j = 0; j < side * side; ++j) {
        const double angle = angleToSphere(n, x + (j % side + 0.5) / side, y + (j / side + 0.5) / side);
        inside = inside && !std::isnan(angle);
        best = std::min(best, angle);
      }
      if (!inside) continue;
      worst = std::max(worst, best);
      ++pixels;
    }
  }
  return {worst, pixels};
}

// Measured on subdivide 5 (20,480 faces, edges about 2 degrees of arc), over 3,260 pixels: Gouraud
// and Phong (vertex normals interpolated) 0.044 degrees at most, flat (the faces' own normals)
// 1.26; the bounds leave some room. A normal in the wrong axes, unrotated or flipped misses by tens
// of degrees.
TEST(Normals, FollowTheRayCastSphere) {
  for (const auto& [shading, bound] : {std::pair<std::string, double>{"phong", 0.1}, {"gouraud", 0.1}, {"flat", 1.5}}) {
    const RenderedFrame frame = Renderer(Backend::Cpu).renderOutputs(sphereScene(shading, 1), Outputs{.normals = true});
    const auto [worst, pixels] = worstAngle(frame, 1);
    EXPECT_GT(pixels, 3000);
    EXPECT_LT(worst, bound) << shading;
    std::printf("%s: worst angle %.4f degrees over %d pixels\n", shading.c_str(), worst, pixels);
  }
}

// With 16 samples a pixel's normal is its nearest sample's, taken where that sample lies: within
// the bound of the analytic normal at one of the pixel's samples, while the pixel centre's is
// farther off (the sphere's normal turns by up to two degrees across a pixel near its rim).
TEST(Normals, WithSamplesAreTakenAtTheNearestSample) {
  const RenderedFrame frame = Renderer(Backend::Cpu).renderOutputs(sphereScene("phong", 16), Outputs{.normals = true});
  const auto [worst, pixels] = worstAngle(frame, 4);
  EXPECT_GT(pixels, 3000);
  EXPECT_LT(worst, 0.1);
  const auto [atCentre, centrePixels] = worstAngle(frame, 1);
  EXPECT_GT(atCentre, 0.2) << "the test could not tell a sample from the pixel centre";
  std::printf("samples: worst angle %.4f degrees at a sample, %.4f at the centre\n", worst, atCentre);
}

// A camera inside an open cube sees the insides of its faces, whose stored normals point outward:
// away from the camera (z > 0 in camera space), as the shading lights them.
TEST(Normals, BackFacesOfAnOpenObjectKeepTheirStoredNormal) {
  const Scene scene = parseScene(R"({"camera": {"position": [0, 0, 0], "direction": [0, 1, 0], "fov": 60, "width": 32, "height": 24},
                                     "objects": [{"shape": "cube", "size": 4, "closed": false}],
                                     "render": {"shading": "flat"}})");
  const RenderedFrame frame = Renderer(Backend::Gpu).renderOutputs(scene, Outputs{.normals = true});
  for (size_t i = 0; i < frame.normals.size(); i += 3) {
    EXPECT_FLOAT_EQ(frame.normals[i + 2], 1.0f) << "pixel " << i / 3;  // the far face, seen from inside
  }
}

}  // namespace
}  // namespace phongvk
