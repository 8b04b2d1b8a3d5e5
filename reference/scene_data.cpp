#include "scene_data.h"

#include "mesh.h"

#include <limits>

namespace phongvk {

namespace {

gpu::MaterialData toGpu(const Material& m) {
  gpu::MaterialData g{};
  g.color = m.color;
  g.ka = m.ka;
  g.attenuation = m.attenuation;
  g.kd = m.kd;
  g.ks = m.ks;
  g.n = m.n;
  return g;
}

void appendObject(SceneData& data, const Object& object, uint32_t objectIndex) {
  const ObjectMesh built = buildObjectMesh(object);
  const Mesh& mesh = built.mesh;
  const uint64_t base = data.vertices.size();
  if (base + mesh.positions.size() > std::numeric_limits<uint32_t>::max()) {
    throw SceneError(object.jsonPath + ": the scene has more than 2^32 vertices");
  }
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    data.vertices.push_back({mesh.positions[i], objectIndex, mesh.normals[i], 0});
  }
  for (const glm::uvec3& t : mesh.triangles) {
    data.triangles.push_back(glm::uvec4(glm::uvec3(static_cast<uint32_t>(base)) + t, objectIndex));
  }
  data.objectOrigins.push_back(built.origin);
  gpu::ObjectData o{};
  o.material = static_cast<uint32_t>(object.material);
  o.flags = built.closed ? gpu::OBJECT_CULL_BACK : 0u;
  data.objects.push_back(o);
}

glm::vec3 inBasis(const View& view, const glm::dvec3& v) {
  return glm::vec3(glm::dot(view.right, v), glm::dot(view.up, v), glm::dot(view.forward, v));
}

}  // namespace

SceneData buildSceneData(const Scene& scene) {
  SceneData data;
  for (size_t i = 0; i < scene.objects.size(); ++i) appendObject(data, scene.objects[i], static_cast<uint32_t>(i));
  for (const Material& m : scene.materials) data.materials.push_back(toGpu(m));
  if (data.materials.empty()) data.materials.push_back(toGpu(Material{}));
  for (const Light& l : scene.lights) {
    data.lightPositions.push_back(l.position);
    gpu::LightData g{};
    g.intensity = l.intensity;
    g.color = l.color;
    data.lights.push_back(g);
  }
  data.background = scene.background;
  data.ambient = scene.ambient;
  data.interpolation = scene.interpolation == Interpolation::Screen ? gpu::INTERP_SCREEN : gpu::INTERP_PERSPECTIVE;
  return data;
}

FrameInputs makeFrame(const SceneData& data, const View& view) {
  FrameInputs in;
  gpu::FrameData& f = in.frame;
  f.right = glm::vec4(glm::vec3(view.right), 0.0f);
  f.up = glm::vec4(glm::vec3(view.up), 0.0f);
  f.forward = glm::vec4(glm::vec3(view.forward), 0.0f);
  f.ambient = data.ambient;
  f.focal = static_cast<float>(view.focal);
  f.background = data.background;
  f.nearPlane = static_cast<float>(view.nearPlane);
  f.principal = glm::vec2(view.width * 0.5f, view.height * 0.5f);
  f.farPlane = static_cast<float>(view.farPlane);
  f.lightCount = static_cast<uint32_t>(data.lights.size());
  f.width = static_cast<uint32_t>(view.width);
  f.height = static_cast<uint32_t>(view.height);
  f.interpolation = data.interpolation;
  f.triangleCount = static_cast<uint32_t>(data.triangles.size());
  f.vertexCount = static_cast<uint32_t>(data.vertices.size());

  in.objects = data.objects;
  for (size_t i = 0; i < in.objects.size(); ++i) {
    const glm::dvec3 offset = data.objectOrigins[i] - view.eye;
    in.objects[i].viewOffset = inBasis(view, offset);
    in.objects[i].worldOffset = glm::vec3(offset);
  }
  in.lights = data.lights;
  for (size_t i = 0; i < in.lights.size(); ++i) {
    in.lights[i].position = glm::vec3(data.lightPositions[i] - view.eye);
  }
  return in;
}

}  // namespace phongvk
