// facing.cpp — see facing.h.
#include "prepare/facing.h"

#include "shaders/phong.h"

namespace phongvk {

bool seenOnlyFromBehind(const SceneData& data, const glm::dvec3& eye) {
  size_t back = 0;
  for (uint32_t id = 0; id < data.quadBase; ++id) {  // points and lines face every way
    const glm::uvec4& t = data.triangles[id];
    const glm::dvec3 origin = data.objectOrigins[t.w];
    const gpu::ObjectData& object = data.objects[t.w];  // a posed object's vertices as the renderers turn them
    const glm::dvec3 p0 = origin + glm::dvec3(gpu::posedVertex(data.vertices[t.x], object).position);
    const glm::dvec3 p1 = origin + glm::dvec3(gpu::posedVertex(data.vertices[t.y], object).position);
    const glm::dvec3 p2 = origin + glm::dvec3(gpu::posedVertex(data.vertices[t.z], object).position);
    const double side = glm::dot(glm::cross(p1 - p0, p2 - p0), eye - p0);
    if (side > 0) return false;  // a front face is in sight
    back += side < 0;
  }
  return back > 0;
}

}  // namespace phongvk
