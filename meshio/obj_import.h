// obj_import.h — triangle meshes from Wavefront OBJ files (through tinyobjloader).
#pragma once

#include "geometry/mesh.h"

#include <string>

namespace phongvk {

// Reads `path` as a loaded mesh (mesh_import.h): polygons triangulated. Normals come from the file
// when every face vertex has a usable one (vertices are then the file's distinct position/normal
// pairs); otherwise vertices are the file's positions (welded by index, so the surface is smooth)
// and get no normals. Throws SceneError "<where>: <path>: <why>" (where is e.g. "objects[6].file")
// when the file cannot be read or parsed, has no triangles, has an index out of range or a number
// that is not a plain finite decimal, with the line where there is one.
Mesh importObj(const std::string& path, const std::string& where);

}  // namespace phongvk
