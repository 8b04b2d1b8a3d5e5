// scene_lighting.cpp — the scene file's "lights" and materials (docs/DESIGN.md "Phong, per vertex"):
// colours, intensities, Phong coefficients and an attenuation that stays positive at every distance.
#include "scene/scene_sections.h"

#include "scene/scene_textures.h"

namespace phongvk::scenejson {
namespace {

const Keys kLightKeys = {"position", "direction", "intensity", "color", "inner_cone", "outer_cone", "falloff", "range", "shadows"};
const Keys kMaterialKeys = {"ka", "kd", "ks", "n", "attenuation", "color", "texture"};

// The file's light as a value, its keys and types checked (the values are lightSpec's).
Light lightValues(const Node& node) {
  requireObject(node);
  checkKeys(node, kLightKeys);
  Light light;
  const auto array = [](const Node& n) {
    const glm::dvec3 v = vec3(n);
    return Vec3{v.x, v.y, v.z};
  };
  const std::optional<Node> direction = node.find("direction");
  const std::optional<Node> position = node.find("position");
  if (direction) {
    light.spot = position.has_value();  // a position and a direction: a spot light
    light.directional = !light.spot;
    light.direction = array(*direction);
  }
  for (auto [key, field] : {std::pair{"inner_cone", &light.innerCone}, {"outer_cone", &light.outerCone}}) {
    if (auto cone = node.find(key)) {
      if (!light.spot) cone->fail("only a spot light (a \"position\" and a \"direction\") has a cone");
      *field = number(*cone);
    }
  }
  if (auto intensity = node.find("intensity")) light.intensity = number(*intensity);
  if (auto lightColor = node.find("color")) light.color = array(*lightColor);
  if (auto falloff = node.find("falloff")) {
    const std::string name = string(*falloff);
    if (name != "material" && name != "inverse_square")
      falloff->fail("expected \"material\" or \"inverse_square\", got '" + name + "'");
    light.inverseSquare = name == "inverse_square";
  }
  if (auto range = node.find("range")) light.range = number(*range);
  if (auto shadows = node.find("shadows")) light.shadows = boolean(*shadows);
  if (light.directional) return light;
  if (!position) node.require("position");  // fails: a light needs one
  if (position->json().is_string()) {
    if (string(*position) != "camera") position->fail("must be a point or \"camera\", got '" + string(*position) + "'");
    light.atCamera = true;
  } else {
    light.position = array(*position);
  }
  return light;
}

// A spot light's cones: 0 <= inner < outer <= 90 degrees (glTF's rule, in degrees).
void checkCones(const Light& light, const Where& at) {
  const auto finite = [&](double value, const char* key) {
    if (!std::isfinite(value)) at.at(key).fail("must be a number of degrees, got " + formatNumber(value));
  };
  finite(light.innerCone, "inner_cone");
  finite(light.outerCone, "outer_cone");
  if (light.outerCone <= 0 || light.outerCone > 90)
    at.at("outer_cone").fail("must be more than 0 and at most 90 degrees, got " + formatNumber(light.outerCone));
  if (light.innerCone < 0 || light.innerCone >= light.outerCone)
    at.at("inner_cone").fail("must be at least 0 and less than outer_cone (" + formatNumber(light.outerCone) +
                             " degrees), got " + formatNumber(light.innerCone));
}

// The inverse square is a point or spot light's; a range needs it: more than 0, at most 1e15 m.
void checkFalloff(const Light& light, const Where& at) {
  if (light.inverseSquare && light.directional)
    at.at("falloff").fail("a directional light reaches every point alike: it has no fall-off");
  if (light.range == 0) return;
  if (!light.inverseSquare) at.at("range").fail("needs \"falloff\": \"inverse_square\" (the range windows that fall-off)");
  if (!(light.range >= 1e-6 && light.range <= MAX_COORDINATE))
    at.at("range").fail("must be 1e-06 to 1e+15 metres, or 0 for none, got " + formatNumber(light.range));
}

}  // namespace

LightSpec lightSpec(const Light& light, const Where& at) {
  LightSpec spec;
  if (light.directional && light.spot) at.fail("a light is directional or a spot light, not both");
  if (light.spot && light.atCamera) at.at("position").fail("a spot light stands at a point, not at the camera");
  if (light.directional || light.spot) {
    spec.directional = light.directional;
    spec.spot = light.spot;
    spec.direction = usableDirection(toVec(light.direction), at.at("direction"));
  }
  if (light.spot) {
    checkCones(light, at);
    spec.innerCone = light.innerCone;
    spec.outerCone = light.outerCone;
  }
  checkFalloff(light, at);
  spec.inverseSquare = light.inverseSquare;
  spec.range = light.range;
  spec.shadows = light.shadows;
  spec.intensity = nonNegativeFloat(light.intensity, at.at("intensity"));
  spec.color = color(toVec(light.color), at.at("color"));
  if (light.directional) return spec;
  spec.atCamera = light.atCamera;
  if (!light.atCamera) spec.position = point(toVec(light.position), at.at("position"));
  return spec;
}

// At most MAX_LIGHTS, checked before any light is read.
void checkLightCount(size_t count, const Where& at) {
  if (count > MAX_LIGHTS)
    at.fail("a scene has at most " + std::to_string(MAX_LIGHTS) + " lights, this one " + std::to_string(count));
}

std::vector<LightSpec> lightSpecs(const std::vector<Light>& lights, const Where& at) {
  checkLightCount(lights.size(), at);
  std::vector<LightSpec> specs;
  for (size_t i = 0; i < lights.size(); ++i) specs.push_back(lightSpec(lights[i], at.element(i)));
  return specs;
}

std::vector<LightSpec> readLights(const Node& node) {
  requireArray(node);
  checkLightCount(node.json().size(), node.where());
  std::vector<LightSpec> lights;
  for (size_t i = 0; i < node.json().size(); ++i) lights.push_back(lightSpec(lightValues(node.element(i)), node.element(i).where()));
  return lights;
}

namespace {

// 1 / (a + b d + c d^2) needs a + b d + c d^2 > 0 for every distance d > 0: a and c may not be
// negative (small and large d), not all zero, and a negative b needs the quadratic to have no
// real root (b^2 < 4ac). Checked on the floats the renderers will use.
glm::vec3 attenuation(const glm::dvec3& value, const Where& at) {
  const glm::vec3 abc = glm::vec3(checked3(value, floatComponent, at));
  double a = abc.x, b = abc.y, c = abc.z;
  bool allZero = a == 0 && b == 0 && c == 0;
  if (a < 0 || c < 0 || allZero || !(b >= 0 || b * b < 4 * a * c)) {
    at.fail("a + b*d + c*d^2 must stay positive for all distances d > 0, got [" + formatNumber(abc.x) + ", " +
            formatNumber(abc.y) + ", " + formatNumber(abc.z) + "]");
  }
  return abc;
}

// The file's material as values, its keys and types checked (the values are materialSpec's).
MaterialValues materialValues(const Node& node) {
  requireObject(node);
  checkKeys(node, kMaterialKeys);
  MaterialValues m;
  for (auto [key, field] : {std::pair{"ka", &m.ka}, {"kd", &m.kd}, {"ks", &m.ks}, {"n", &m.n}}) {
    if (auto value = node.find(key)) *field = number(*value);
  }
  if (auto value = node.find("attenuation")) m.attenuation = vec3(*value);
  if (auto value = node.find("color")) m.color = vec3(*value);
  if (auto texture = node.find("texture")) m.texture = string(*texture);
  return m;
}

}  // namespace

MaterialSpec materialSpec(const MaterialValues& m, const std::string& baseDir, const Where& at) {
  MaterialSpec material;
  material.ka = nonNegativeFloat(m.ka, at.at("ka"));
  material.kd = nonNegativeFloat(m.kd, at.at("kd"));
  material.ks = nonNegativeFloat(m.ks, at.at("ks"));
  material.n = nonNegativeFloat(m.n, at.at("n"));
  material.attenuation = attenuation(m.attenuation, at.at("attenuation"));
  material.color = color(m.color, at.at("color"));
  material.textureImage = m.textureImage;
  if (m.texture) {
    const std::string& source = *m.texture;
    if (source.empty()) at.at("texture").fail("must name a PNG or JPEG file or be a data URI of one, got ''");
    try {
      material.textureImage = sceneTexture(source, baseDir);
    } catch (const SceneError& error) {
      at.at("texture").fail(error.what());
    }
    material.texture = textureSourceOf(source, baseDir);
  }
  return material;
}

MaterialSpec readMaterial(const Node& node, const std::string& baseDir) {
  return materialSpec(materialValues(node), baseDir, node.where());
}

}  // namespace phongvk::scenejson
