// model_scene.cpp — see model_scene.h.
#include "scene/model_scene.h"

#include "meshio/mesh_file.h"

#include <filesystem>

namespace phongvk {

bool isModelFile(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
  return extension == ".obj" || extension == ".ply" || extension == ".stl" || extension == ".gltf" || extension == ".glb";
}

scenejson::Json modelScene(const std::string& path, const ModelView& view) {
  const DetectedFormat detected = detectMeshFormat(path);
  if (!detected.format) throw SceneError(detected.problem);  // "<path>: <why>": the user's file alone
  const MeshFormat format = *detected.format;
  const std::string file = std::filesystem::absolute(path).string();
  const glm::vec3 noFallOff = noFallOffMaterial().attenuation;
  scenejson::Json camera = {{"fit", true}, {"width", 960}, {"height", 720}};
  if (view.orthographic.value_or(false)) {
    camera["projection"] = "orthographic";
  } else {
    camera["fov"] = 40;
  }
  scenejson::Json object = {
      {"shape", "mesh"},
      {"file", file},
      {"up", view.up ? (*view.up == UpAxis::Y ? "y" : "z") : usuallyYUp(format) ? "y" : "z"},
      {"material", {{"attenuation", {noFallOff.x, noFallOff.y, noFallOff.z}}}}};
  if (!view.fileLights) object["file_lights"] = false;
  if (view.fileLightShadows) object["file_light_shadows"] = true;
  return scenejson::Json{
      {"camera", camera},
      {"background", {0.12, 0.12, 0.14}},
      {"ambient", {1, 1, 1}},
      {"lights", {{{"position", "camera"}}}},
      {"objects", {object}},
  };
}

}  // namespace phongvk
