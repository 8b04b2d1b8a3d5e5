// obj_import.h — triangle meshes from Wavefront OBJ files (through tinyobjloader).
#pragma once

#include "scene/mesh.h"

#include <string>

namespace phongvk {

// Reads `path`: polygons triangulated, positions multiplied by `scale` (> 0). Normals come from the
// file when every face vertex has one (vertices are then the file's distinct position/normal
// pairs); otherwise vertices are the file's positions (welded by index, so the surface is smooth)
// with area-weighted normals. Zero-area triangles are dropped; unused positions are not kept.
// Throws SceneError "<where>: <path>: <why>" (where is e.g. "objects[6].file") when the file
// cannot be read or parsed, has no triangles, has an index out of range or a non-finite number,
// or has only degenerate triangles.
Mesh importObj(const std::string& path, double scale, const std::string& where);

}  // namespace phongvk
