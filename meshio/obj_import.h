// obj_import.h — meshes from Wavefront OBJ files (through tinyobjloader): faces, points and lines.
#pragma once

#include "geometry/mesh.h"

#include <string>

namespace phongvk {

// Reads `path` as a loaded mesh (mesh_import.h): polygons triangulated, each 'p' line's vertices
// points, each 'l' line a polyline (its consecutive pairs of vertices lines); a file of 'v' lines
// alone is a point cloud, every vertex a point. Normals come from the file when every face vertex
// has a usable one (vertices are then the file's distinct position/normal pairs; points and lines
// have none, (0, 0, 0), but in a point cloud with a 'vn' line for each 'v' line); otherwise
// vertices are the file's positions (welded by index, so the surface is smooth) and get no
// normals. Throws SceneError "<where>: <path>: <why>" (where is e.g. "objects[6].file") when the
// file cannot be read or parsed, has nothing to draw, has an index out of range or a number that
// is not a plain finite decimal, with the line where there is one.
Mesh importObj(const std::string& path, const std::string& where);

}  // namespace phongvk
