// scene_write.h — a validated scene written back as scene file JSON (docs/DESIGN.md "Scene file"):
// what Scene::toJson gives.
#pragma once

#include "scene/scene.h"
#include "scene/scene_json.h"

#include <string>

namespace phongvk {

// `scene` as a scene file that the loader reads back into a scene rendering the same bytes, and
// whose own text is this one again. Every value is written, none left to a default; numbers as
// the shortest text that reads back as the same double (a float field's value as its exact double);
// the camera's image as width and height, or as the resolution and aspect that set it; each
// object's rotation as a matrix; mesh files by absolute path and meshes given as arrays inline.
// Materials: the named ones by name, every other (the default included) inline. A glTF mesh
// whose base colours apply keeps its inline material without "color", as the file said it.
scenejson::Json sceneJson(const SceneSpec& scene);

}  // namespace phongvk
