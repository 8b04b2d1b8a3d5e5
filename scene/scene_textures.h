// scene_textures.h — the textures a scene's materials name ("texture": a file or a data URI),
// decoded once per process while some scene holds them: a sequence reads its scene file again for
// every frame, and a frame with the same texture must not decode it again.
#pragma once

#include "geometry/texture_image.h"

#include <memory>
#include <string>

namespace phongvk {

// The texture `source` names: a data URI, or a file (resolved against `baseDir` unless absolute;
// decoded again when the file changed). Throws SceneError "<what>: <why>", <what> "the data URI" or
// the file as `source` names it ('textures/wood.png').
std::shared_ptr<const TextureImage> sceneTexture(const std::string& source, const std::string& baseDir);

// `source` as a scene file written elsewhere reads it: a file as an absolute path, a data URI as it is.
std::string textureSourceOf(const std::string& source, const std::string& baseDir);

}  // namespace phongvk
