// scene_write.cpp — see scene_write.h. One writer per section of the scene file, each the
// counterpart of its reader (scene_camera.cpp, scene_lighting.cpp, scene_objects.cpp, scene.cpp).
#include "scene/scene_write.h"

#include "image/texture_uri.h"
#include "scene/object_pose.h"

#include <filesystem>

namespace phongvk {
namespace {

using scenejson::Json;

// Doubles are stored as they are and dumped as the shortest text that reads back the same; a
// float widens to its exact double, which the reader narrows back to the same float.
Json vec3Json(const glm::dvec3& v) { return Json::array({v.x, v.y, v.z}); }
Json vec3Json(const glm::vec3& v) { return Json::array({double(v.x), double(v.y), double(v.z)}); }

Json cameraJson(const CameraSpec& c) {
  Json json = Json::object();
  if (c.fit) {
    json["fit"] = true;
  } else {
    json["position"] = vec3Json(c.position);
  }
  json["direction"] = vec3Json(c.direction);
  json["up"] = vec3Json(c.up);
  if (c.width > 0 && c.height > 0) {
    json["width"] = c.width;
    json["height"] = c.height;
  } else {
    // The image and focal length come from these (camera.h makeView); width and height would
    // set another focal length.
    json["aspect"] = c.aspect;
    json["resolution"] = c.resolution;
  }
  if (c.orthographic) {
    json["projection"] = "orthographic";
    if (!c.fit) json["ortho_height"] = c.orthoHeight;
  } else if (c.intrinsics) {
    json["fx"] = c.fx;
    json["fy"] = c.fy;
    json["cx"] = c.cx;
    json["cy"] = c.cy;
  } else {
    json["fov"] = c.fov;
  }
  if (!c.fit) {
    json["near"] = c.nearPlane;
    json["far"] = c.farPlane;
  }
  return json;
}

Json lightJson(const LightSpec& light) {
  Json json = Json::object();
  if (light.directional || light.spot) json["direction"] = vec3Json(light.direction);
  if (!light.directional) json["position"] = light.atCamera ? Json("camera") : vec3Json(light.position);
  if (light.spot) {
    json["inner_cone"] = light.innerCone;
    json["outer_cone"] = light.outerCone;
  }
  if (light.inverseSquare) json["falloff"] = "inverse_square";
  if (light.range != 0) json["range"] = light.range;
  if (light.shadows) json["shadows"] = true;
  json["intensity"] = double(light.intensity);
  json["color"] = vec3Json(light.color);
  return json;
}

Json lightsJson(const std::vector<LightSpec>& lights) {
  Json json = Json::array();
  for (const LightSpec& light : lights) json.push_back(lightJson(light));
  return json;
}

// `withColor` false: a glTF mesh's material whose colour its base colours replace.
Json materialJson(const MaterialSpec& m, bool withColor = true) {
  Json json = {{"ka", double(m.ka)},
               {"kd", double(m.kd)},
               {"ks", double(m.ks)},
               {"n", double(m.n)},
               {"attenuation", vec3Json(m.attenuation)}};
  if (withColor) json["color"] = vec3Json(m.color);
  if (!m.texture.empty()) json["texture"] = m.texture;
  else if (m.textureImage) json["texture"] = textureDataUri(*m.textureImage);  // held in memory
  return json;
}

Json namedMaterialsJson(const SceneSpec& scene) {
  Json json = Json::object();
  for (size_t i = 0; i < scene.materialNames.size(); ++i) json[scene.materialNames[i]] = materialJson(scene.materials[i]);
  return json;
}

// A name for a named material; every other inline, with its values (the default one too).
Json objectMaterialJson(const SceneSpec& scene, const Object& object) {
  if (size_t(object.material) < scene.materialNames.size()) return scene.materialNames[size_t(object.material)];
  return materialJson(scene.materials[size_t(object.material)], !object.baseColors);
}

// Row-major, as the file's {"matrix": rows} reads it (glm keeps columns: m[column][row]).
Json rotationJson(const glm::dmat3& m) {
  Json rows = Json::array();
  for (int r = 0; r < 3; ++r) rows.push_back(Json::array({m[0][r], m[1][r], m[2][r]}));
  return {{"matrix", std::move(rows)}};
}

Json pointsJson(const std::vector<glm::dvec3>& points) {
  Json json = Json::array();
  for (const glm::dvec3& p : points) json.push_back(vec3Json(p));
  return json;
}

// A mesh's own textures (a model file's), each as a PNG data URI with its wrap modes, and which
// one each vertex samples (-1: none).
void writeMeshTextures(const Mesh& mesh, Json& json) {
  Json textures = Json::array(), ids = Json::array();
  for (const auto& texture : mesh.textures) {
    textures.push_back({{"image", textureDataUri(*texture)},
                        {"wrap", Json::array({TEXTURE_WRAP_NAMES[texture->wrapU], TEXTURE_WRAP_NAMES[texture->wrapV]})}});
  }
  for (uint32_t id : mesh.textureIds) ids.push_back(id == gpu::TEXTURE_NONE ? int64_t(-1) : int64_t(id));
  json["textures"] = std::move(textures);
  json["texture_ids"] = std::move(ids);
}

// A mesh given as arrays, inline: its rows as built (mesh_arrays.h reads them back unchanged).
void writeArrays(const Mesh& mesh, Json& json) {
  Json vertices = Json::array(), faces = Json::array(), normals = Json::array(), colors = Json::array();
  for (const glm::vec3& p : mesh.positions) vertices.push_back(vec3Json(p));
  for (const glm::uvec3& t : mesh.triangles) faces.push_back(Json::array({t.x, t.y, t.z}));
  for (const glm::vec3& n : mesh.normals) normals.push_back(vec3Json(n));
  for (uint32_t c : mesh.colors) colors.push_back(Json::array({c & 0xFF, (c >> 8) & 0xFF, (c >> 16) & 0xFF, c >> 24}));
  json["vertices"] = std::move(vertices);
  if (!mesh.triangles.empty()) json["faces"] = std::move(faces);
  Json lines = Json::array(), points = Json::array();
  for (const glm::uvec2& l : mesh.lines) lines.push_back(Json::array({l.x, l.y}));
  for (uint32_t p : mesh.points) points.push_back(p);
  if (!mesh.lines.empty()) json["lines"] = std::move(lines);
  if (!mesh.points.empty()) json["point_indices"] = std::move(points);
  json["normals"] = std::move(normals);
  if (!mesh.colors.empty()) json["colors"] = std::move(colors);
  Json uvs = Json::array();
  for (const glm::vec2& uv : mesh.uvs) uvs.push_back(Json::array({double(uv.x), double(uv.y)}));
  if (!mesh.uvs.empty()) json["uvs"] = std::move(uvs);
  if (!mesh.textures.empty()) writeMeshTextures(mesh, json);
}

// The keys of the object's shape (scene_objects.cpp kShapes), each with its value.
void writeGeometry(const Object& object, Json& json) {
  const Shape s = object.shape;
  if (s != Shape::Polyhedron && s != Shape::Mesh) json["center"] = vec3Json(object.center);
  if (s == Shape::Sphere || s == Shape::Cylinder || s == Shape::Cone || s == Shape::Icosphere) json["radius"] = object.radius;
  if (s == Shape::Cube) json["size"] = object.size;
  if (s == Shape::Cylinder || s == Shape::Cone) json["height"] = object.height;
  if (s == Shape::Sphere || s == Shape::Cylinder || s == Shape::Cone) json["segments"] = object.segments;
  if (s == Shape::Cone) json["rings"] = object.rings;
  if (s == Shape::Polyhedron) json["points"] = pointsJson(object.points);
  if (s != Shape::Mesh) return;
  if (object.arrays) {
    writeArrays(*object.arrays, json);
  } else {
    json["file"] = std::filesystem::absolute(object.file).lexically_normal().string();
    if (!object.fileLights) json["file_lights"] = false;
    if (object.fileLightShadows) json["file_light_shadows"] = true;
  }
  json["translate"] = vec3Json(object.translate);
  json["up"] = object.up == UpAxis::Y ? "y" : "z";
  if (object.pointSize) json["point_size"] = *object.pointSize;
  if (object.lineWidth) json["line_width"] = *object.lineWidth;
}

Json objectJson(const SceneSpec& scene, const Object& object) {
  Json json = {{"shape", std::string(shapeName(object.shape))}};
  writeGeometry(object, json);
  json["scale"] = vec3Json(object.scale);
  json["rotate"] = rotationJson(object.rotation);
  json["subdivide"] = object.subdivide;
  json["closed"] = object.closed;
  if (!object.castShadows) json["cast_shadows"] = false;
  json["material"] = objectMaterialJson(scene, object);
  if (object.label) json["object_id"] = *object.label;
  if (object.poseLinear) {  // placed by a pose: the pose, for the object to read back posed
    for (const char* key : {"translate", "scale", "rotate"}) json.erase(key);
    const Matrix4 m = objectPose(object);
    Json rows = Json::array();
    for (int r = 0; r < 4; ++r) rows.push_back(Json::array({m[4 * r], m[4 * r + 1], m[4 * r + 2], m[4 * r + 3]}));
    json["pose"] = std::move(rows);
  }
  return json;
}

Json objectsJson(const SceneSpec& scene) {
  Json json = Json::array();
  for (const Object& object : scene.objects) json.push_back(objectJson(scene, object));
  return json;
}

Json renderJson(const SceneSpec& scene) {
  return {{"interpolation", INTERPOLATION_NAMES[size_t(scene.interpolation)]},
          {"shading", SHADING_NAMES[size_t(scene.shading)]},
          {"specular", SPECULAR_NAMES[size_t(scene.specular)]},
          {"samples", scene.samples},
          {"texture_filter", TEXTURE_FILTER_NAMES[size_t(scene.textureFilter)]},
          {"point_size", scene.pointSize},
          {"line_width", scene.lineWidth}};
}

}  // namespace

Json sceneJson(const SceneSpec& scene) {
  return {{"camera", cameraJson(scene.camera)},
          {"background", vec3Json(scene.background)},
          {"ambient", vec3Json(scene.ambient)},
          {"lights", lightsJson(scene.lights)},
          {"materials", namedMaterialsJson(scene)},
          {"objects", objectsJson(scene)},
          {"render", renderJson(scene)}};
}

}  // namespace phongvk
