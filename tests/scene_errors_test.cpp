// scene_errors_test.cpp — every kind of bad scene input gets a message naming the file, the JSON
// path and what is wrong.
#include "scene/scene.h"
#include "tests/scene_fixtures.h"
#include "test_util.h"

#include <gtest/gtest.h>

#include <functional>
#include <nlohmann/json.hpp>

namespace phongvk {
namespace {

using namespace test;
using nlohmann::ordered_json;

// The message parseSceneSpec throws for `text`, or "(no error)".
std::string errorFor(const std::string& text) {
  try {
    parse(text);
  } catch (const SceneError& error) {
    return error.what();
  }
  return "(no error)";
}

std::string errorFor(const std::function<void(ordered_json&)>& edit) {
  return errorFor(minimalWith(edit).dump());
}

// Replaces the minimal scene's camera.
std::string cameraError(const char* camera) {
  return errorFor([&](ordered_json& s) { s["camera"] = ordered_json::parse(camera); });
}

// Replaces the minimal scene's only object.
std::string objectError(const char* object) {
  return errorFor([&](ordered_json& s) { s["objects"][0] = ordered_json::parse(object); });
}

// The minimal scene with one material named "m".
std::string materialError(const char* material) {
  return errorFor([&](ordered_json& s) { s["materials"]["m"] = ordered_json::parse(material); });
}

TEST(SceneErrors, MissingFile) {
  std::string path = test::makeTempDir() + "/none.json";
  try {
    loadSceneSpec(path);
    FAIL() << "no error";
  } catch (const SceneError& error) {
    EXPECT_EQ(std::string(error.what()), path + ": cannot read file: No such file or directory");
  }
}

TEST(SceneErrors, SyntaxErrorNamesLineAndColumn) {
  // "tru" is read up to the comma, line 2 column 16.
  EXPECT_EQ(errorFor("{\n  \"camera\": tru,\n}"),
            "a.json: JSON syntax error at line 2, column 16: invalid literal");
  // A trailing comma: the parser stops at the '}' on line 3.
  EXPECT_EQ(
      errorFor("{\n  \"objects\": [],\n}"),
      "a.json: JSON syntax error at line 3, column 1: unexpected '}'; expected string literal");
  // Truncated input: the position is just past the end.
  EXPECT_EQ(errorFor("{\"a\": 1\n"),
            "a.json: JSON syntax error at line 2, column 1: unexpected end of input; expected '}'");
}

TEST(SceneErrors, EmptyFileIsASyntaxError) {
  EXPECT_EQ(errorFor(""),
            "a.json: JSON syntax error at line 1, column 1: unexpected end of input; expected '[', "
            "'{', or a literal");
}

TEST(SceneErrors, NumberTooLargeForADouble) {
  EXPECT_EQ(errorFor(R"({"camera": {"fov": 1e999}})"),
            "a.json: camera.fov: must be finite, got 1e999");
  EXPECT_EQ(errorFor(R"({"camera": {"position": [0, -1e999, 0]}})"),
            "a.json: camera.position[1]: must be finite, got -1e999");
}

TEST(SceneErrors, DuplicateKey) {
  EXPECT_EQ(errorFor(R"({"objects": [{"shape": "sphere", "radius": 1, "radius": 2}]})"),
            "a.json: objects[0].radius: duplicate key");
}

TEST(SceneErrors, TopLevelMustBeAnObject) {
  EXPECT_EQ(errorFor("[1, 2]"), "a.json: top level: must be an object, got array");
}

// ---- structure ----

TEST(SceneErrors, UnknownKeyAtTopLevel) {
  EXPECT_EQ(errorFor([](ordered_json& s) { s["lighting"] = 1; }),
            "a.json: lighting: unknown key (allowed: camera, background, ambient, lights, "
            "materials, objects, render, animate)");
}

TEST(SceneErrors, SpotLightCones) {
  const auto spot = [](ordered_json light) {
    return errorFor([&](ordered_json& s) { s["lights"] = ordered_json::array({light}); });
  };
  const ordered_json at = {{"position", {0, 0, 3}}, {"direction", {0, 0, -1}}};
  auto with = [&](const char* key, double value) {
    ordered_json light = at;
    light[key] = value;
    return light;
  };
  EXPECT_EQ(spot(with("outer_cone", 95)), "a.json: lights[0].outer_cone: must be more than 0 and at most 90 degrees, got 95");
  EXPECT_EQ(spot(with("outer_cone", 0)), "a.json: lights[0].outer_cone: must be more than 0 and at most 90 degrees, got 0");
  EXPECT_EQ(spot(with("inner_cone", 45)),
            "a.json: lights[0].inner_cone: must be at least 0 and less than outer_cone (45 degrees), got 45");
  EXPECT_EQ(spot(with("inner_cone", -1)),
            "a.json: lights[0].inner_cone: must be at least 0 and less than outer_cone (45 degrees), got -1");
  EXPECT_EQ(spot({{"position", {0, 0, 3}}, {"outer_cone", 30}}),
            "a.json: lights[0].outer_cone: only a spot light (a \"position\" and a \"direction\") has a cone");
  EXPECT_EQ(spot({{"direction", {0, 0, -1}}, {"inner_cone", 10}}),
            "a.json: lights[0].inner_cone: only a spot light (a \"position\" and a \"direction\") has a cone");
  EXPECT_EQ(spot({{"position", "camera"}, {"direction", {0, 0, -1}}}),
            "a.json: lights[0].position: a spot light stands at a point, not at the camera");
  EXPECT_EQ(spot({{"position", {0, 0, 3}}, {"direction", {0, 0, 0}}}),
            "a.json: lights[0].direction: must have a non-zero finite length, got length 0");
}

TEST(SceneErrors, LightFalloff) {
  const auto light = [](ordered_json l) {
    return errorFor([&](ordered_json& s) { s["lights"] = ordered_json::array({l}); });
  };
  EXPECT_EQ(light({{"position", {0, 0, 3}}, {"falloff", "linear"}}),
            "a.json: lights[0].falloff: expected \"material\" or \"inverse_square\", got 'linear'");
  EXPECT_EQ(light({{"direction", {0, 0, -1}}, {"falloff", "inverse_square"}}),
            "a.json: lights[0].falloff: a directional light reaches every point alike: it has no fall-off");
  EXPECT_EQ(light({{"position", {0, 0, 3}}, {"range", 5}}),
            "a.json: lights[0].range: needs \"falloff\": \"inverse_square\" (the range windows that fall-off)");
  EXPECT_EQ(light({{"position", {0, 0, 3}}, {"falloff", "inverse_square"}, {"range", -1}}),
            "a.json: lights[0].range: must be 1e-06 to 1e+15 metres, or 0 for none, got -1");
  EXPECT_EQ(objectError(R"({"shape": "mesh", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "faces": [[0, 1, 2]],
                           "file_lights": false})"),
            "a.json: objects[0].file_lights: needs 'file' (the lights of a mesh file)");
  EXPECT_EQ(objectError(R"({"shape": "mesh", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "faces": [[0, 1, 2]],
                           "file_light_shadows": true})"),
            "a.json: objects[0].file_light_shadows: needs 'file' (the lights of a mesh file)");
}

TEST(SceneErrors, UnknownKeyNested) {
  EXPECT_EQ(errorFor([](ordered_json& s) { s["camera"]["zoom"] = 2; }),
            "a.json: camera.zoom: unknown key (allowed: position, direction, look_at, up, fov, "
            "aspect, resolution, width, height, near, far, fit, fx, fy, cx, cy, projection, ortho_height)");
  EXPECT_EQ(
      materialError(R"({"shininess": 3})"),
      "a.json: materials.m.shininess: unknown key (allowed: ka, kd, ks, n, attenuation, color, texture)");
  EXPECT_EQ(errorFor([](ordered_json& s) {
              s["lights"] = {{{"position", {0, 0, 0}}, {"power", 1}}};
            }),
            "a.json: lights[0].power: unknown key (allowed: position, direction, intensity, color, inner_cone, "
            "outer_cone, falloff, range, shadows)");
  EXPECT_EQ(objectError(R"({"shape": "sphere", "radiu": 1})"),
            "a.json: objects[0].radiu: unknown key (allowed: shape, material, subdivide, closed, "
            "scale, rotate, object_id, cast_shadows, center, radius, segments)");
}

TEST(SceneErrors, KeyOfAnotherShape) {
  EXPECT_EQ(objectError(R"({"shape": "cube", "radius": 1})"),
            "a.json: objects[0].radius: unknown key, not used by shape 'cube' (allowed: shape, "
            "material, subdivide, closed, scale, rotate, object_id, cast_shadows, center, size)");
}

TEST(SceneErrors, MissingRequiredField) {
  EXPECT_EQ(errorFor([](ordered_json& s) { s.erase("camera"); }),
            "a.json: top level: missing required field 'camera'");
  EXPECT_EQ(errorFor([](ordered_json& s) { s.erase("objects"); }),
            "a.json: top level: missing required field 'objects'");
  EXPECT_EQ(cameraError(R"({"direction": [1, 0, 0]})"),
            "a.json: camera: missing required field 'position'");
  EXPECT_EQ(cameraError(R"({"position": [0, 0, 0]})"),
            "a.json: camera: missing required field 'direction' (or 'look_at')");
  EXPECT_EQ(objectError(R"({"radius": 1})"), "a.json: objects[0]: missing required field 'shape'");
  EXPECT_EQ(objectError(R"({"shape": "polyhedron"})"),
            "a.json: objects[0]: missing required field 'points'");
  EXPECT_EQ(objectError(R"({"shape": "mesh"})"),
            "a.json: objects[0]: missing required field 'file'");
  EXPECT_EQ(errorFor([](ordered_json& s) {
              s["lights"] = {{{"intensity", 1}}};
            }),
            "a.json: lights[0]: missing required field 'position'");
}

TEST(SceneErrors, EmptyObjects) {
  EXPECT_EQ(errorFor([](ordered_json& s) { s["objects"] = ordered_json::array(); }),
            "a.json: objects: scene has no objects");
}

// ---- types ----

TEST(SceneErrors, WrongType) {
  EXPECT_EQ(errorFor([](ordered_json& s) { s["camera"]["fov"] = "60"; }),
            "a.json: camera.fov: must be a number, got string");
  EXPECT_EQ(errorFor([](ordered_json& s) { s["camera"]["fov"] = true; }),
            "a.json: camera.fov: must be a number, got boolean");
  EXPECT_EQ(errorFor([](ordered_json& s) {
              s["camera"] = {1, 2};
            }),
            "a.json: camera: must be an object, got array");
  EXPECT_EQ(errorFor([](ordered_json& s) { s["objects"][0]["closed"] = 1; }),
            "a.json: objects[0].closed: must be true or false, got number");
  EXPECT_EQ(
      errorFor([](ordered_json& s) { s["objects"][0]["material"] = 3; }),
      "a.json: objects[0].material: must be a material name or a material object, got number");
  EXPECT_EQ(errorFor([](ordered_json& s) { s["lights"] = ordered_json::object(); }),
            "a.json: lights: must be an array, got object");
}

TEST(SceneErrors, BadVector) {
  EXPECT_EQ(cameraError(R"({"position": [0, "1", 0], "direction": [1, 0, 0]})"),
            "a.json: camera.position[1]: must be a number, got string");
  EXPECT_EQ(cameraError(R"({"position": [0, 0], "direction": [1, 0, 0]})"),
            "a.json: camera.position: must be an array of 3 numbers, got 2 elements");
  EXPECT_EQ(cameraError(R"({"position": 0, "direction": [1, 0, 0]})"),
            "a.json: camera.position: must be an array of 3 numbers, got number");
}

TEST(SceneErrors, NonIntegerSegments) {
  EXPECT_EQ(objectError(R"({"shape": "sphere", "segments": 32.5})"),
            "a.json: objects[0].segments: must be an integer, got 32.5");
}

TEST(SceneErrors, UnknownShape) {
  EXPECT_EQ(objectError(R"({"shape": "torus"})"),
            "a.json: objects[0].shape: unknown shape 'torus' (allowed: sphere, cube, cylinder, "
            "cone, icosphere, polyhedron, mesh)");
}

TEST(SceneErrors, UnknownInterpolation) {
  EXPECT_EQ(errorFor([](ordered_json& s) { s["render"]["interpolation"] = "linear"; }),
            "a.json: render.interpolation: must be one of perspective, screen, got 'linear'");
}

TEST(SceneErrors, RenderModesOutOfTheirSets) {
  EXPECT_EQ(errorFor([](ordered_json& s) { s["render"]["shading"] = "smooth"; }),
            "a.json: render.shading: must be one of gouraud, flat, phong, got 'smooth'");
  EXPECT_EQ(errorFor([](ordered_json& s) { s["render"]["specular"] = "cook-torrance"; }),
            "a.json: render.specular: must be one of phong, blinn, got 'cook-torrance'");
  EXPECT_EQ(errorFor([](ordered_json& s) { s["render"]["shading"] = 1; }),
            "a.json: render.shading: must be a string, got number");
  EXPECT_EQ(errorFor([](ordered_json& s) { s["render"]["samples"] = 3; }),
            "a.json: render.samples: must be 1, 4, 9 or 16 (a regular grid of samples per pixel), got 3");
  EXPECT_EQ(errorFor([](ordered_json& s) { s["render"]["samples"] = 0; }),
            "a.json: render.samples: must be between 1 and 16, got 0");
  EXPECT_EQ(errorFor([](ordered_json& s) { s["render"]["samples"] = 2.5; }),
            "a.json: render.samples: must be an integer, got 2.5");
  EXPECT_EQ(errorFor([](ordered_json& s) { s["render"]["texture_filter"] = "trilinear"; }),
            "a.json: render.texture_filter: must be one of nearest, bilinear, got 'trilinear'");
  EXPECT_EQ(errorFor([](ordered_json& s) { s["render"]["sample"] = 4; }),
            "a.json: render.sample: unknown key (allowed: interpolation, shading, specular, samples, texture_filter, point_size, line_width)");
}

// ---- ranges ----

TEST(SceneErrors, OutOfRange) {
  EXPECT_EQ(materialError(R"({"ks": -1})"), "a.json: materials.m.ks: must be >= 0, got -1");
  EXPECT_EQ(objectError(R"({"shape": "sphere", "material": {"ks": -0.5}})"),
            "a.json: objects[0].material.ks: must be >= 0, got -0.5");
  EXPECT_EQ(objectError(R"({"shape": "sphere", "segments": 2})"),
            "a.json: objects[0].segments: must be between 3 and 4096, got 2");
  EXPECT_EQ(objectError(R"({"shape": "cone", "rings": 0})"),
            "a.json: objects[0].rings: must be between 1 and 4096, got 0");
  EXPECT_EQ(objectError(R"({"shape": "cube", "subdivide": 11})"),
            "a.json: objects[0].subdivide: must be between 0 and 10, got 11");
  EXPECT_EQ(objectError(R"({"shape": "cube", "size": 0})"),
            "a.json: objects[0].size: must be > 0, got 0");
  EXPECT_EQ(objectError(R"({"shape": "polyhedron", "points": [[0,0,0],[1,0,0],[0,1,0]]})"),
            "a.json: objects[0].points: needs at least 4 points, got 3");
  EXPECT_EQ(errorFor([](ordered_json& s) {
              s["background"] = {0, 1.5, 0};
            }),
            "a.json: background[1]: must be between 0 and 1, got 1.5");
  EXPECT_EQ(errorFor([](ordered_json& s) {
              s["ambient"] = {0, 0, -1};
            }),
            "a.json: ambient[2]: must be >= 0, got -1");
  EXPECT_EQ(errorFor([](ordered_json& s) {
              s["lights"] = {{{"position", {0, 0, 0}}, {"intensity", -2}}};
            }),
            "a.json: lights[0].intensity: must be >= 0, got -2");
}

// 1e300 is a finite double but inf as a float: inf * 0 would make NaN in the shading.
TEST(SceneErrors, TooLargeForAFloat) {
  EXPECT_EQ(materialError(R"({"ks": 1e300})"),
            "a.json: materials.m.ks: too large for a 32-bit float, got 1e+300");
}

TEST(SceneErrors, FovIsExclusive) {
  EXPECT_EQ(errorFor([](ordered_json& s) { s["camera"]["fov"] = 0; }),
            "a.json: camera.fov: must be > 0 and < 180, got 0");
  EXPECT_EQ(errorFor([](ordered_json& s) { s["camera"]["fov"] = 180; }),
            "a.json: camera.fov: must be > 0 and < 180, got 180");
}

TEST(SceneErrors, Intrinsics) {
  const std::string eye = R"("position": [0, -5, 0], "look_at": [0, 0, 0], )";
  const auto error = [&](const std::string& rest) { return cameraError(("{" + eye + rest + "}").c_str()); };
  EXPECT_EQ(error(R"("fy": 100, "width": 64, "height": 48)"),
            "a.json: camera: missing required field 'fx' (given 'fy', 'cx' or 'cy')");
  EXPECT_EQ(error(R"("fx": 100, "fov": 40, "width": 64, "height": 48)"),
            "a.json: camera.fov: cannot be given with 'fx': the intrinsics set the field of view");
  EXPECT_EQ(error(R"("fx": 100)"), "a.json: camera: 'fx' needs 'width' and 'height' (the image the intrinsics describe)");
  EXPECT_EQ(error(R"("fx": 0, "width": 64, "height": 48)"), "a.json: camera.fx: must be > 0 (a focal length in pixels), got 0");
  EXPECT_EQ(error(R"("fx": 100, "fy": -1, "width": 64, "height": 48)"),
            "a.json: camera.fy: must be between 0 and 1e+11, got -1");
  EXPECT_EQ(error(R"("fx": 100, "cx": 40000, "width": 64, "height": 48)"),
            "a.json: camera.cx: must be between -16384 and 32768, got 40000");
  EXPECT_EQ(error(R"("fx": 100, "cx": 31.5, "cy": 23.5, "fy": 90, "width": 64, "height": 48)"), "(no error)");
}

TEST(SceneErrors, Orthographic) {
  const std::string eye = R"("position": [0, -5, 0], "look_at": [0, 0, 0], )";
  const auto error = [&](const std::string& rest) { return cameraError(("{" + eye + rest + "}").c_str()); };
  const std::string ortho = R"("projection": "orthographic", )";
  EXPECT_EQ(error(R"("projection": "fisheye")"),
            "a.json: camera.projection: must be one of perspective, orthographic, got 'fisheye'");
  EXPECT_EQ(error(R"("ortho_height": 2)"), "a.json: camera.ortho_height: is only used with 'projection': 'orthographic'");
  EXPECT_EQ(error(ortho + R"("ortho_height": 2)"),
            "a.json: camera: an orthographic camera needs 'width' and 'height' (its image in pixels)");
  EXPECT_EQ(error(ortho + R"("width": 64, "height": 48)"),
            "a.json: camera: missing required field 'ortho_height' (the metres the image spans from top to bottom)");
  EXPECT_EQ(error(ortho + R"("ortho_height": 2, "fov": 40, "width": 64, "height": 48)"),
            "a.json: camera.fov: cannot be given with 'projection': 'orthographic' (ortho_height sets the view)");
  EXPECT_EQ(error(ortho + R"("ortho_height": 2, "fx": 40, "width": 64, "height": 48)"),
            "a.json: camera.fx: cannot be given with 'projection': 'orthographic' (ortho_height sets the view)");
  EXPECT_EQ(error(ortho + R"("ortho_height": 0, "width": 64, "height": 48)"),
            "a.json: camera.ortho_height: must be between 1e-06 and 1e+15, got 0");
  EXPECT_EQ(error(ortho + R"("ortho_height": "2", "width": 64, "height": 48)"),
            "a.json: camera.ortho_height: must be a number, got string");
  EXPECT_EQ(error(ortho + R"("ortho_height": 2.5, "width": 64, "height": 48)"), "(no error)");
}

TEST(SceneErrors, FarMustExceedNear) {
  EXPECT_EQ(errorFor([](ordered_json& s) { s["camera"]["far"] = 0.01; }),
            "a.json: camera.far: must be > near (0.05), got 0.01");
  EXPECT_EQ(errorFor([](ordered_json& s) { s["camera"]["near"] = 0; }),
            "a.json: camera.near: must be > 0, got 0");
}

TEST(SceneErrors, AttenuationNotPositive) {
  const std::string prefix =
      "a.json: materials.m.attenuation: a + b*d + c*d^2 must stay positive for all distances d > "
      "0, got ";
  EXPECT_EQ(materialError(R"({"attenuation": [0, 0, 0]})"), prefix + "[0, 0, 0]");
  // 1 - 3d + d^2 has roots at d = 0.38 and 2.62.
  EXPECT_EQ(materialError(R"({"attenuation": [1, -3, 1]})"), prefix + "[1, -3, 1]");
  // b^2 = 4ac exactly: zero at d = 1.
  EXPECT_EQ(materialError(R"({"attenuation": [1, -2, 1]})"), prefix + "[1, -2, 1]");
  // Negative far away / near the light.
  EXPECT_EQ(materialError(R"({"attenuation": [1, -0.1, 0]})"), prefix + "[1, -0.1, 0]");
  EXPECT_EQ(materialError(R"({"attenuation": [-1, 1, 1]})"), prefix + "[-1, 1, 1]");
}

// ---- camera geometry ----

TEST(SceneErrors, ZeroDirection) {
  EXPECT_EQ(cameraError(R"({"position": [0, 0, 0], "direction": [0, 0, 0]})"),
            "a.json: camera.direction: must have a non-zero finite length, got length 0");
}

TEST(SceneErrors, LookAtEqualsPosition) {
  EXPECT_EQ(cameraError(R"({"position": [1, 2, 3], "look_at": [1, 2, 3]})"),
            "a.json: camera.look_at: equals camera.position, so there is no view direction");
}

TEST(SceneErrors, DirectionAndLookAtTogether) {
  EXPECT_EQ(cameraError(R"({"position": [0, 0, 0], "direction": [1, 0, 0], "look_at": [1, 1, 1]})"),
            "a.json: camera.look_at: cannot be given together with 'direction'");
}

TEST(SceneErrors, UpParallelToDirection) {
  EXPECT_EQ(cameraError(R"({"position": [0, 0, 0], "direction": [1, 1, 0], "up": [-2, -2, 0]})"),
            "a.json: camera.up: parallel to the view direction");
  // The default up [0, 0, 1] with a camera looking straight down.
  EXPECT_EQ(cameraError(R"({"position": [0, 0, 5], "look_at": [0, 0, 0]})"),
            "a.json: camera.up: parallel to the view direction");
  EXPECT_EQ(cameraError(R"({"position": [0, 0, 0], "direction": [1, 0, 0], "up": [0, 0, 0]})"),
            "a.json: camera.up: must have a non-zero finite length, got length 0");
}

TEST(SceneErrors, WidthWithoutHeight) {
  EXPECT_EQ(errorFor([](ordered_json& s) { s["camera"]["width"] = 640; }),
            "a.json: camera.width: must be given together with 'height'");
  EXPECT_EQ(errorFor([](ordered_json& s) { s["camera"]["height"] = 480; }),
            "a.json: camera.height: must be given together with 'width'");
}

TEST(SceneErrors, WidthWithResolutionOrAspect) {
  EXPECT_EQ(cameraError(R"({"position": [0, 0, 0], "direction": [1, 0, 0], "resolution": 800,
                            "width": 640, "height": 480})"),
            "a.json: camera.resolution: cannot be given together with 'width' and 'height'");
  EXPECT_EQ(cameraError(R"({"position": [0, 0, 0], "direction": [1, 0, 0], "aspect": 2,
                            "width": 640, "height": 480})"),
            "a.json: camera.aspect: cannot be given together with 'width' and 'height'");
}

TEST(SceneErrors, ImageSizeOutOfBounds) {
  // H = floor(2 * 20000 * tan(30 deg)) = 23094, W = floor(23094.01 * 1.5) = 34641.
  EXPECT_EQ(errorFor([](ordered_json& s) { s["camera"]["resolution"] = 20000; }),
            "a.json: camera.resolution: image would be 34641x23094 pixels (resolution 20000, fov "
            "60, aspect 1.5); each side must be 1 to 16384");
  // H = floor(2 * 0.5 * tan(30 deg)) = 0.
  EXPECT_EQ(errorFor([](ordered_json& s) { s["camera"]["resolution"] = 0.5; }),
            "a.json: camera.resolution: image would be 0x0 pixels (resolution 0.5, fov 60, aspect "
            "1.5); each side must be 1 to 16384");
  EXPECT_EQ(errorFor([](ordered_json& s) {
              s["camera"]["width"] = 16385;
              s["camera"]["height"] = 100;
            }),
            "a.json: camera.width: must be between 1 and 16384, got 16385");
  // The largest size allowed loads.
  EXPECT_EQ(errorFor([](ordered_json& s) {
              s["camera"]["width"] = 16384;
              s["camera"]["height"] = 16384;
            }),
            "(no error)");
}

// ---- references ----

TEST(SceneErrors, UnknownMaterialName) {
  EXPECT_EQ(errorFor([](ordered_json& s) {
              s["materials"] = {{"red", ordered_json::object()}, {"blue", ordered_json::object()}};
              s["objects"][0]["material"] = "green";
            }),
            "a.json: objects[0].material: unknown material 'green' (known: red, blue)");
  EXPECT_EQ(
      errorFor([](ordered_json& s) { s["objects"][0]["material"] = "green"; }),
      "a.json: objects[0].material: unknown material 'green' (no named materials are defined)");
}

TEST(SceneErrors, MissingMeshFile) {
  std::string dir = test::makeTempDir();
  std::string scene = R"({"camera": {"position": [0, 0, 0], "direction": [1, 0, 0]},
                          "objects": [{"shape": "mesh", "file": "meshes/x.obj"}]})";
  try {
    parseSceneSpec(scene, "a.json", dir);
    FAIL() << "no error";
  } catch (const SceneError& error) {
    EXPECT_EQ(std::string(error.what()),
              "a.json: objects[0].file: cannot read 'meshes/x.obj': No such file or directory");
  }
  // A folder is not a mesh file either.
  test::writeFile(dir + "/meshes/x.obj/inside", "");
  try {
    parseSceneSpec(scene, "a.json", dir);
    FAIL() << "no error";
  } catch (const SceneError& error) {
    EXPECT_EQ(std::string(error.what()),
              "a.json: objects[0].file: cannot read 'meshes/x.obj': Is a directory");
  }
}

}  // namespace
}  // namespace phongvk
