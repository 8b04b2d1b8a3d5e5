// scene_lighting.cpp — the scene file's "lights" and materials (docs/DESIGN.md "Phong, per vertex"):
// colours, intensities, Phong coefficients and an attenuation that stays positive at every distance.
#include "scene/scene_sections.h"

#include "scene/scene_textures.h"

namespace phongvk::scenejson {
namespace {

const Keys kLightKeys = {"position", "direction", "intensity", "color"};
const Keys kMaterialKeys = {"ka", "kd", "ks", "n", "attenuation", "color", "texture"};

LightSpec readLight(const Node& node) {
  requireObject(node);
  checkKeys(node, kLightKeys);
  LightSpec light;
  const std::optional<Node> direction = node.find("direction");
  if (direction) {
    if (node.find("position")) node.failAt("direction", "a light has a position or a direction, not both");
    light.directional = true;
    light.direction = usableDirection(*direction, vec3(*direction));
  }
  if (auto intensity = node.find("intensity")) light.intensity = nonNegativeFloat(*intensity);
  if (auto lightColor = node.find("color")) light.color = color(*lightColor);
  if (direction) return light;
  const Node position = node.require("position");
  if (position.json().is_string()) {
    if (string(position) != "camera") position.fail("must be a point or \"camera\", got '" + string(position) + "'");
    light.atCamera = true;
  } else {
    light.position = point(position);
  }
  if (auto intensity = node.find("intensity")) light.intensity = nonNegativeFloat(*intensity);
  if (auto lightColor = node.find("color")) light.color = color(*lightColor);
  return light;
}

}  // namespace

std::vector<LightSpec> readLights(const Node& node) {
  requireArray(node);
  if (node.json().size() > MAX_LIGHTS)
    node.fail("a scene has at most " + std::to_string(MAX_LIGHTS) + " lights, this one " + std::to_string(node.json().size()));
  std::vector<LightSpec> lights;
  for (size_t i = 0; i < node.json().size(); ++i) lights.push_back(readLight(node.element(i)));
  return lights;
}

namespace {

// 1 / (a + b d + c d^2) needs a + b d + c d^2 > 0 for every distance d > 0: a and c may not be
// negative (small and large d), not all zero, and a negative b needs the quadratic to have no
// real root (b^2 < 4ac). Checked on the floats the renderers will use.
glm::vec3 readAttenuation(const Node& node) {
  glm::vec3 abc = glm::vec3(vec3(node, floatComponent));
  double a = abc.x, b = abc.y, c = abc.z;
  bool allZero = a == 0 && b == 0 && c == 0;
  if (a < 0 || c < 0 || allZero || !(b >= 0 || b * b < 4 * a * c)) {
    node.fail("a + b*d + c*d^2 must stay positive for all distances d > 0, got [" +
              formatNumber(abc.x) + ", " + formatNumber(abc.y) + ", " + formatNumber(abc.z) + "]");
  }
  return abc;
}

}  // namespace

MaterialSpec readMaterial(const Node& node, const std::string& baseDir) {
  requireObject(node);
  checkKeys(node, kMaterialKeys);
  MaterialSpec material;
  if (auto ka = node.find("ka")) material.ka = nonNegativeFloat(*ka);
  if (auto kd = node.find("kd")) material.kd = nonNegativeFloat(*kd);
  if (auto ks = node.find("ks")) material.ks = nonNegativeFloat(*ks);
  if (auto n = node.find("n")) material.n = nonNegativeFloat(*n);
  if (auto attenuation = node.find("attenuation")) {
    material.attenuation = readAttenuation(*attenuation);
  }
  if (auto materialColor = node.find("color")) material.color = color(*materialColor);
  if (auto texture = node.find("texture")) {
    const std::string source = string(*texture);
    if (source.empty()) texture->fail("must name a PNG or JPEG file or be a data URI of one, got ''");
    try {
      material.textureImage = sceneTexture(source, baseDir);
    } catch (const SceneError& error) {
      texture->fail(error.what());
    }
    material.texture = textureSourceOf(source, baseDir);
  }
  return material;
}

}  // namespace phongvk::scenejson
