// scene_sections.h — the readers of the scene file's sections, each in a file of its own
// (scene_camera.cpp, scene_lighting.cpp, scene_objects.cpp), the value readers they share
// (scene_values.cpp), and the material table objects and the file's "materials" fill together.
// scene.cpp reads the whole file with them. Every reader throws SceneError at the failing node.
#pragma once

#include "base/regular_file.h"
#include "scene/scene.h"
#include "scene/scene_checks.h"
#include "scene/scene_json.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace phongvk::scenejson {

// ---- values shared by several sections (scene_values.cpp) ----
float nonNegativeFloat(const Node& node);
// Vector elements are read as doubles; these hold values a float represents exactly.
double floatComponent(const Node& node);
double nonNegativeComponent(const Node& node);
double unitComponent(const Node& node);
glm::vec3 color(const Node& node);      // components >= 0
glm::vec3 unitColor(const Node& node);  // components in [0, 1]
// Positions and sizes stay within MAX_COORDINATE metres, so that every offset, distance and
// squared distance the renderers take in float stays finite (a 1e300 m centre would become an
// infinite eye offset and NaN vertices).
double coordinate(const Node& node);
glm::dvec3 point(const Node& node);
double length(const Node& node);  // > 0 and <= MAX_COORDINATE
// A direction the camera basis can normalize: length neither zero nor overflowing.
glm::dvec3 usableDirection(const Node& node, glm::dvec3 direction);
// The same checks of values wherever they came from (scene_checks.h), failing at `at`.
float nonNegativeFloat(double value, const Where& at);
double nonNegativeComponent(double value, const Where& at);
double unitComponent(double value, const Where& at);
double floatComponent(double value, const Where& at);
double coordinate(double value, const Where& at);
glm::dvec3 point(const glm::dvec3& value, const Where& at);
glm::dvec3 usableDirection(const glm::dvec3& direction, const Where& at);
// ---- sections ----
CameraSpec readCamera(const Node& camera);       // scene_camera.cpp
std::vector<LightSpec> readLights(const Node& node);  // scene_lighting.cpp
// A material object; a "texture" file is resolved against baseDir (scene_lighting.cpp).
MaterialSpec readMaterial(const Node& node, const std::string& baseDir);
// A mesh object's arrays given inline ("vertices", "faces", "normals", "colors", "uvs", and its own
// "textures" with "texture_ids"), built as Scene::addMesh builds arrays (mesh_arrays.cpp), with its
// messages under the object's path; texture files resolve against baseDir.
std::shared_ptr<const Mesh> readMeshArrays(const Node& object, const std::string& baseDir);

// A scene's materials as objects take them (SceneSpec::materials, materialNames, defaultMaterial):
// the named materials first, in file order, then one entry per inline material, and one shared
// default for objects that name none. Works on the scene it is given, so objects added later
// (arrays) resolve their materials the same way.
class MaterialTable {
 public:
  // `baseDir`: where the scene's texture files are (its file's folder; "" for the working directory).
  MaterialTable(SceneSpec& scene, std::string baseDir) : scene_(scene), baseDir_(std::move(baseDir)) {}
  const std::string& baseDir() const { return baseDir_; }

  void readNamed(const Node& node) {
    requireObject(node);
    for (const auto& [name, value] : node.json().items()) {
      scene_.materials.push_back(readMaterial(node.child(name), baseDir_));
      scene_.materialNames.push_back(name);
    }
  }

  // The index for an object's "material": absent, a name, or an inline material object.
  int add(const MaterialSpec& material) {
    scene_.materials.push_back(material);
    return int(scene_.materials.size()) - 1;
  }

  int forObject(const std::optional<Node>& node) {
    if (!node) return defaultIndex();
    if (node->json().is_string()) return named(string(*node), node->where());
    if (!node->json().is_object()) {
      node->fail(std::string("must be a material name or a material object, got ") +
                 node->json().type_name());
    }
    return add(readMaterial(*node, baseDir_));
  }

  // The same for a material given in code: the default, a name, or values checked at `at`.
  int forObject(const MaterialChoice& choice, const Where& at) {
    if (const auto* name = std::get_if<std::string>(&choice)) return named(*name, at);
    if (const auto* values = std::get_if<MaterialValues>(&choice)) return add(materialSpec(*values, baseDir_, at));
    return defaultIndex();
  }

 private:
  int defaultIndex() {
    if (!scene_.defaultMaterial) scene_.defaultMaterial = add(MaterialSpec{});
    return *scene_.defaultMaterial;
  }

  int named(const std::string& name, const Where& at) const {
    const std::vector<std::string>& names = scene_.materialNames;
    for (size_t i = 0; i < names.size(); ++i) {
      if (names[i] == name) return int(i);
    }
    at.fail("unknown material '" + name + "' (" + describeNames() + ")");
  }

  std::string describeNames() const {
    const std::vector<std::string>& names = scene_.materialNames;
    if (names.empty()) return "no named materials are defined";
    std::string text = "known: ";
    for (size_t i = 0; i < names.size(); ++i) text += (i ? ", " : "") + names[i];
    return text;
  }

  SceneSpec& scene_;
  std::string baseDir_;
};

// The whole scene file without its "animate" block (scene.cpp). `root` names the file (or the frame
// of a sequence) in messages, `path` is SceneSpec::path and relative files resolve against baseDir.
SceneSpec readScene(const Node& root, const std::string& path, const std::string& baseDir, bool objectsLater);

// The "objects" array (scene_objects.cpp); each object's material goes through `materials`. Empty
// is an error unless `mayBeEmpty` (objects come later, as arrays).
std::vector<Object> readObjects(const Node& node, const std::string& baseDir, MaterialTable& materials,
                                bool mayBeEmpty);

}  // namespace phongvk::scenejson
