// model_scene.h — a mesh file rendered with no scene file (`phongvk render model.ply -o out.png`,
// phongvk.load_scene("model.glb")): the model upright, in full view, lit from the camera.
#pragma once

#include "scene/scene_json.h"

#include <optional>
#include <string>

namespace phongvk {

// True when `path` names a mesh file by its extension (.obj .ply .stl .gltf .glb, any case)
// rather than a scene file.
bool isModelFile(const std::string& path);

// How a model alone is shown where its user says: its up axis (none: as its format usually has
// it, mesh_file.h usuallyYUp) and an orthographic camera instead of the perspective one.
struct ModelView {
  std::optional<UpAxis> up;
  std::optional<bool> orthographic;  // given: whether the fitted camera is orthographic (else perspective)
  bool fileLights = true;            // false: a glTF file's own lights left out
  bool fileLightShadows = false;     // true: those lights cast shadows
};

// The scene for a model alone: the mesh (standing up along view.up; back faces drawn), a camera
// fitted from the front, left and above (960x720, 40° field of view, or orthographic), one white
// light at the camera without fall-off (in place of which a glTF file's own lights light it, where
// it places some: prepare/scene_data.h), a dark grey background. A glTF model keeps its base
// colours. Throws SceneError for a file that is not a mesh.
scenejson::Json modelScene(const std::string& path, const ModelView& view = {});

}  // namespace phongvk
