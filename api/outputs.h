// outputs.h — a frame's outputs besides its colours (alpha, depth, object and triangle ids), read
// from its visibility keys: the same keys on both renderers make the same outputs.
#pragma once

#include "phongvk/phongvk.h"
#include "prepare/scene_data.h"

namespace phongvk {

// Whether any output asked for is read from the keys (all but the colour).
bool needsKeys(const Outputs& outputs);

// `out` rendered with keys at `side` x `side` samples per pixel (its image already filtered down),
// as the outputs asked for: per pixel, the nearest sample (the smallest key) gives the depth and
// ids, the covered samples the alpha (their share of 255, rounded as the colours are).
RenderedFrame outputsFromKeys(RenderOutput&& out, int side, const SceneData& data, const Outputs& outputs);

}  // namespace phongvk
