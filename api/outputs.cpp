// outputs.cpp — see outputs.h.
#include "api/outputs.h"

#include "api/lights_reached.h"
#include "api/normals.h"
#include "shaders/depth.h"

#include <algorithm>
#include <cstdint>

namespace phongvk {

bool needsKeys(const Outputs& outputs) {
  return outputs.alpha || outputs.depth || outputs.objectIds || outputs.triangleIds || outputs.normals || outputs.lights;
}

RenderedFrame outputsFromKeys(RenderOutput&& out, int side, const SceneData& data, const FrameInputs& in,
                             const Outputs& outputs, const std::vector<int32_t>& objectIds) {
  const int width = out.image.width, height = out.image.height, samples = side * side, sampleWidth = width * side;
  const size_t pixels = size_t(width) * size_t(height);
  // Per pixel, the nearest of its samples (the smallest key), where it lies, and how many of them a
  // triangle covers.
  std::vector<uint64_t> keys(pixels, gpu::KEY_CLEAR);
  const bool surfaces = outputs.normals || outputs.lights;  // outputs taken at the nearest sample's point
  std::vector<size_t> nearest(surfaces ? pixels : 0, NO_SAMPLE);
  std::vector<uint8_t> alpha(outputs.alpha ? pixels : 0);
  for (size_t i = 0; i < pixels; ++i) {
    const size_t x = i % size_t(width), y = i / size_t(width);
    int covered = 0;
    for (int j = 0; j < side; ++j) {
      for (int k = 0; k < side; ++k) {
        const size_t sample = (y * side + j) * size_t(sampleWidth) + x * side + k;
        const uint64_t key = out.keys[sample];
        covered += key != gpu::KEY_CLEAR;
        if (key >= keys[i]) continue;  // the first of equal keys: ties go to the earlier sample
        keys[i] = key;
        if (surfaces) nearest[i] = sample;
      }
    }
    if (outputs.alpha) alpha[i] = uint8_t((255 * covered + samples / 2) / samples);  // rounded as the colours are
  }
  std::vector<float> normals = outputs.normals ? normalsOfSamples(data, in, out.keys, nearest) : std::vector<float>();
  std::vector<int32_t> lights = outputs.lights ? lightsReached(data, in, out.keys, nearest) : std::vector<int32_t>();
  // The keys read as the visibility buffer reads them (image.h visibilityOf).
  RenderOutput perPixel{std::move(out.image), std::move(keys)};
  Visibility visibility = visibilityOf(perPixel);
  RenderedFrame frame{std::move(perPixel.image), std::move(alpha)};
  if (outputs.depth) frame.depth = std::move(visibility.depth);
  frame.normals = std::move(normals);
  frame.lights = std::move(lights);
  if (outputs.triangleIds) {
    frame.triangleIds.resize(pixels);  // a record as the primitive it draws; NO_TRIANGLE reads as -1
    for (size_t i = 0; i < pixels; ++i) {
      const uint32_t record = visibility.triangle[i];
      frame.triangleIds[i] = record == NO_TRIANGLE ? -1 : int32_t(primitiveOf(data, record));
    }
  }
  if (outputs.objectIds) {
    frame.objectIds.resize(pixels);
    for (size_t i = 0; i < pixels; ++i) {
      const uint32_t triangle = visibility.triangle[i];  // the whole scene's index (a share's keys are offset)
      frame.objectIds[i] = triangle == NO_TRIANGLE ? -1 : objectIds[data.triangles[triangle - data.triangleBase].w];
    }
  }
  return frame;
}

std::vector<int32_t> objectIdsOf(const SceneSpec& scene) {
  std::vector<int32_t> ids;
  for (size_t i = 0; i < scene.objects.size(); ++i) ids.push_back(scene.objects[i].label.value_or(int32_t(i)));
  return ids;
}

}  // namespace phongvk
