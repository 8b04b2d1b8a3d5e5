// outputs.h — a frame's outputs besides its colours (alpha, depth, object and triangle ids,
// normals), read from its visibility keys: the same keys on both renderers make the same outputs.
#pragma once

#include "phongvk/phongvk.h"
#include "prepare/scene_data.h"

namespace phongvk {

// Whether any output asked for is read from the keys (all but the colour).
bool needsKeys(const Outputs& outputs);

// `out` rendered with keys at `side` x `side` samples per pixel (its image already filtered down)
// from the frame `in` (in the samples' view), as the outputs asked for: per pixel, the nearest
// sample (the smallest key; of equal keys the first in row order) gives the depth, the ids and the
// normal (normals.h, at that sample's position), the covered samples the alpha (their share of 255,
// rounded as the colours are). The object id is `objectIds[object]` (objectIdsOf).
RenderedFrame outputsFromKeys(RenderOutput&& out, int side, const SceneData& data, const FrameInputs& in,
                             const Outputs& outputs, const std::vector<int32_t>& objectIds);

// What the object_id output says for each of the scene's objects: its label (Object::label, the
// file's "object_id" or the one Scene::add gave it), else its index.
std::vector<int32_t> objectIdsOf(const SceneSpec& scene);

}  // namespace phongvk
