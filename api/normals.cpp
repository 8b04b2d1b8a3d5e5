// normals.cpp — see normals.h. The surface is the one the reference shades a pixel with
// (render_reference.h pixelSurface, over the shared headers), in the same float operations.
#include "api/normals.h"

#include "reference/render_reference.h"
#include "shaders/phong.h"

namespace phongvk {

using namespace gpu;

namespace {

// A vertex's homogeneous pixel-space position in this frame, as the shade pass computes it.
ShadedVertex projected(const VertexIn& stored, const FrameInputs& in) {
  const ObjectData& object = in.objects[stored.object];
  const VertexIn v = posedVertex(stored, object);
  return {vec4(toHomogeneous(v.position, object.viewOffset, in.frame), 1.0f), vec4(0.0f)};
}

// A world-axes direction in the camera's axes: (right, up, forward).
vec3 toCameraAxes(vec3 n, const FrameData& frame) {
  return vec3(dot3(vec3(frame.right), n), dot3(vec3(frame.up), n), dot3(vec3(frame.forward), n));
}

}  // namespace

SurfacePoint sampleSurface(const SceneData& data, const FrameInputs& in, uint32_t triangle, int x, int y) {
  const auto corners = recordShaded(data, in.frame, triangle, [&](uint32_t v) { return projected(data.vertices[v], in); });
  return pixelSurface(data, in, triangle, corners, x, y);
}

glm::vec3 cameraNormal(const SceneData& data, const FrameInputs& in, uint32_t triangle, int x, int y) {
  return toCameraAxes(sampleSurface(data, in, triangle, x, y).N, in.frame);
}

std::vector<float> normalsOfSamples(const SceneData& data, const FrameInputs& in, const std::vector<uint64_t>& sampleKeys,
                                    const std::vector<size_t>& nearest) {
  std::vector<float> normals(nearest.size() * 3, 0.0f);
  const size_t sampleWidth = in.frame.width;
  for (size_t i = 0; i < nearest.size(); ++i) {
    if (nearest[i] == NO_SAMPLE) continue;
    const uint32_t triangle = uint32_t(sampleKeys[nearest[i]]) - data.triangleBase;
    const glm::vec3 n = cameraNormal(data, in, triangle, int(nearest[i] % sampleWidth), int(nearest[i] / sampleWidth));
    normals[3 * i] = n.x;
    normals[3 * i + 1] = n.y;
    normals[3 * i + 2] = n.z;
  }
  return normals;
}

}  // namespace phongvk
