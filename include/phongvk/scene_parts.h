// scene_parts.h — a scene's camera, lights, materials, render settings and poses as values, for a
// program that drives a scene from code (Scene::setCamera, setLights, add, setPose,
// setRenderSettings) instead of a scene file. Each is checked like the scene file's section it
// stands for, with the same messages ("camera.fov: ...", "objects[2].material.ks: ...").
#pragma once

#include "phongvk/export.h"

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace phongvk {

using Vec3 = std::array<double, 3>;

// A 4x4 matrix, row-major (m[row * 4 + column]), as numpy holds one. A pose maps an object's (or
// the camera's) own coordinates to world coordinates: its upper 3x3 block is the linear part
// (rotation, and scale if any), its last column the translation, its last row 0 0 0 1.
using Matrix4 = std::array<double, 16>;
inline constexpr Matrix4 IDENTITY_POSE = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

// Pinhole intrinsics as datasets give them, in pixels and OpenCV's convention (pixel centres at
// integer coordinates, so the centre of a W x H image is ((W - 1) / 2, (H - 1) / 2)): focal lengths
// fx (across) and fy (down), principal point (cx, cy). fx and fy may differ (non-square pixels)
// and the principal point may lie off centre, or outside the image within one largest image side
// (16384 pixels) of it. A scene file's camera says them as "fx", "fy", "cx", "cy".
struct Intrinsics {
  double fx = 0;
  double fy = 0;
  double cx = 0;
  double cy = 0;
  bool operator==(const Intrinsics&) const = default;
};

// A pinhole camera: where it is, what it looks at, which way is up (world coordinates, z up by
// default), the vertical field of view in degrees, and the image size (0 x 0: the scene's own).
// With intrinsics (and then a width and height) the intrinsics set the field of view and fov is
// not used.
struct Camera {
  Vec3 position = {0, -5, 2};
  Vec3 lookAt = {0, 0, 0};
  Vec3 up = {0, 0, 1};
  double fov = 60;
  int width = 0;
  int height = 0;
  double nearPlane = 0.05;
  double farPlane = 1000;
  std::optional<Intrinsics> intrinsics;
  // Set: an orthographic camera, whose image spans this many metres from top to bottom (and
  // orthoHeight * width / height across); every pixel looks along the view direction, and fov
  // is not used. It needs a width and height, and no intrinsics. A scene file says it as
  // "projection": "orthographic", "ortho_height": h.
  std::optional<double> orthoHeight;
  bool operator==(const Camera&) const = default;
};

// The axes of a camera pose, as the tools that make poses use them:
// OpenGL (and Blender, three.js, NeRF's transforms.json): the camera looks down its -z, y up, x right.
// OpenCV (and COLMAP, most datasets with intrinsics): the camera looks down its +z, y down, x right.
enum class PoseConvention { OpenGL, OpenCV };

// The camera a camera-to-world pose describes. Throws ArgumentError naming "pose" for a matrix
// that is not a rigid pose (non-finite values, a last row other than 0 0 0 1, a rotation block
// that is not orthonormal within 1e-6).
PHONGVK_API Camera cameraFromPose(const Matrix4& cameraToWorld, PoseConvention convention, double fov, int width,
                                  int height);

// The camera of pinhole intrinsics as datasets give them (Intrinsics: fx, fy, cx, cy in pixels),
// the image size, and a camera-to-world pose. Throws ArgumentError naming the value for a focal
// length that is not positive and finite or an image smaller than 1 x 1; the rest is checked when
// the camera is assigned to a scene (SceneError "camera.cx: ...", as a scene file's camera).
PHONGVK_API Camera cameraFromIntrinsics(double fx, double fy, double cx, double cy, int width, int height,
                                        const Matrix4& cameraToWorld,
                                        PoseConvention convention = PoseConvention::OpenGL);

// A light (docs/DESIGN.md "Lights"): a point light at `position`, or one that moves with the camera
// (atCamera), or a directional light (directional: its light travels along `direction` and reaches
// every point alike, without fall-off, as the sun's), or a spot light (spot: at `position`, pointing
// along `direction`, full within `innerCone` degrees of its axis, dark beyond `outerCone`, with
// glTF's smooth fall-off between them).
struct Light {
  Vec3 position = {0, 0, 0};
  double intensity = 1;
  Vec3 color = {1, 1, 1};
  bool atCamera = false;
  bool directional = false;
  Vec3 direction = {0, 0, -1};
  bool spot = false;
  double innerCone = 0;   // degrees from the axis, 0 <= innerCone < outerCone
  double outerCone = 45;  // degrees from the axis, at most 90
  // A point or spot light that falls off as 1/d^2 (glTF's, windowed to 0 at `range` metres when
  // range > 0) instead of as each material's attenuation says.
  bool inverseSquare = false;
  double range = 0;
  // Lights only the points from which nothing stands between it and them (docs/DESIGN.md "Shadows").
  bool shadows = false;
  bool operator==(const Light&) const = default;
};

struct ImageRGBA;     // phongvk/image.h
struct TextureImage;  // the texels as the renderers hold them

// A texture held in memory: its pixels given by the program, not read from a file, decoded once and
// shared by every material that takes it (Material::textureImage; copies share the texels). A
// scene written out (Scene::toJson) holds it as a data URI of its PNG.
class PHONGVK_API Texture {
 public:
  // `width` x `height` texels that `fillRow(y, rgba)` writes: row y (0 at the top) as `width` RGBA8
  // texels, 4 bytes each. Checked before anything is allocated: SceneError "<what>: ..." for a side
  // outside 1..16384, or texels (4 bytes each) that would pass the memory limit beside the textures
  // the process holds already.
  static Texture fromRows(int width, int height, const std::function<void(int y, uint8_t* rgba)>& fillRow,
                          const std::string& what = "texture");
  // An RGBA image's pixels, likewise.
  static Texture fromImage(const ImageRGBA& image, const std::string& what = "texture");

  int width() const;
  int height() const;
  // The same texels (a copy of this texture, or this texture itself).
  bool operator==(const Texture&) const = default;

 private:
  explicit Texture(std::shared_ptr<const TextureImage> image);
  std::shared_ptr<const TextureImage> image_;
  friend struct TextureAccess;
};

// A material (docs/DESIGN.md "Phong, per vertex"), as a scene file's material object: the ambient,
// diffuse and specular coefficients, the specular exponent n (the shininess), the attenuation
// a, b, c of the fall-off 1 / (a + b d + c d^2) and the colour (RGB >= 0). The defaults are the
// scene file's (the paper's) but the attenuation: [1, 0, 0], no fall-off, as a model file rendered
// alone has, so that a scene built in code is well exposed at any distance without tuning (a scene
// file's default is [1, 0.2, 0.2]; docs/DECISIONS.md, "Defaults of a scene built in code").
struct Material {
  double ka = 0.15;
  double kd = 1.0;
  double ks = 0.8;
  double n = 10;
  Vec3 attenuation = {1, 0, 0};
  Vec3 color = {0.8, 0.8, 0.8};
  // A base-colour texture that multiplies `color` where the object's mesh has texture coordinates
  // (docs/DESIGN.md "Textures"): a PNG or JPEG file, or a data URI of one
  // ("data:image/png;base64,..."); empty for none.
  std::string texture;
  // Or a texture held in memory, in place of `texture` (at most one of the two is set).
  std::optional<Texture> textureImage;
  bool operator==(const Material&) const = default;
};

// The choices of a scene file's "render" section (docs/DESIGN.md "Shading", "Gouraud"): where the
// Phong equation is evaluated, the highlight's base, and how barycentrics are interpolated.
enum class Shading { Gouraud, Flat, Phong };
enum class Specular { Phong, Blinn };
enum class Interpolation { Perspective, Screen };
// How a texture is sampled between its texels (docs/DESIGN.md "Textures").
enum class TextureFilter { Nearest, Bilinear };

// How a scene is rendered: its "render" section (shading, specular, interpolation, samples per
// pixel: 1, 4, 9 or 16, texture filter) and its background colour (RGB in [0, 1]; a scene gives it back as the
// renderers hold it, in 32-bit floats). The defaults are the scene file's. Where nothing is drawn,
// a frame's alpha output (Outputs::alpha) says so.
struct RenderSettings {
  Shading shading = Shading::Gouraud;
  Specular specular = Specular::Phong;
  Interpolation interpolation = Interpolation::Perspective;
  int samples = 1;
  Vec3 background = {0, 0, 0};
  TextureFilter textureFilter = TextureFilter::Bilinear;
  // Points' side and lines' width in pixels of the image (docs/DESIGN.md "Points and lines"):
  // above 0, at most 64; a mesh object's "point_size" and "line_width" may say otherwise for it.
  double pointSize = 1;
  double lineWidth = 1;
  bool operator==(const RenderSettings&) const = default;
};

// The scene file's names of the choices ("gouraud", "blinn", "screen", "nearest"), and the choice a name
// stands for: SceneError as a scene file's ("render.shading: must be one of gouraud, flat, phong,
// got 'smooth'") for any other name.
PHONGVK_API const char* shadingName(Shading shading);
PHONGVK_API const char* specularName(Specular specular);
PHONGVK_API const char* interpolationName(Interpolation interpolation);
PHONGVK_API Shading parseShading(const std::string& name);
PHONGVK_API Specular parseSpecular(const std::string& name);
PHONGVK_API Interpolation parseInterpolation(const std::string& name);
PHONGVK_API const char* textureFilterName(TextureFilter filter);
PHONGVK_API TextureFilter parseTextureFilter(const std::string& name);

// An object added in code: its handle for setPose and remove (Scene::add), unique to the scene
// that gave it.
struct ObjectId {
  unsigned long long value = 0;
  bool operator==(const ObjectId&) const = default;
};

// A light added in code (Scene::addLight): its handle for setLight and removeLight, unique to the
// scene that gave it, and never equal to an object's handle of that scene.
struct LightId {
  unsigned long long value = 0;
  bool operator==(const LightId&) const = default;
};

}  // namespace phongvk
