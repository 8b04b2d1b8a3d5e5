// lights_reached.cpp — see lights_reached.h.
#include "api/lights_reached.h"

#include "api/normals.h"
#include "reference/render_reference.h"
#include "shaders/shadow_rays.h"

namespace phongvk {

std::vector<int32_t> lightsReached(const SceneData& data, const FrameInputs& in, const std::vector<uint64_t>& sampleKeys,
                                   const std::vector<size_t>& nearest) {
  std::vector<int32_t> counts(nearest.size(), -1);
  const size_t sampleWidth = in.frame.width;
  for (size_t i = 0; i < nearest.size(); ++i) {
    if (nearest[i] == NO_SAMPLE) continue;
    const uint32_t triangle = uint32_t(sampleKeys[nearest[i]]) - data.triangleBase;
    const gpu::SurfacePoint s =
        sampleSurface(data, in, triangle, int(nearest[i] % sampleWidth), int(nearest[i] / sampleWidth));
    const glm::uvec3 owners = cornerVertices(data, triangle);
    int32_t count = 0;
    for (const gpu::LightData& light : in.lights) {
      count += (light.flags & gpu::LIGHT_SHADOWS) == 0u || gpu::lightReaches(*in.shadows, light, s.P, owners);
    }
    counts[i] = count;
  }
  return counts;
}

}  // namespace phongvk
