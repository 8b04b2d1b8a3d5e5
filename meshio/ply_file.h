// ply_file.h — PLY files, ASCII and binary, read by phongvk (docs/DECISIONS.md "Mesh files").
#pragma once

#include "geometry/mesh.h"

#include <string>
#include <string_view>

namespace phongvk {

// The PLY file `bytes` as a loaded mesh (mesh_import.h), ASCII or binary of either byte order:
// the vertex element's x, y, z (and nx, ny, nz where every vertex has a finite normal: zero ones
// are (0, 0, 0) in a file without triangles, and none are used otherwise; red, green, blue, or
// diffuse_red, diffuse_green, diffuse_blue, as 8 bits), the face element's vertex_indices, polygons
// cut into triangles (polygon.h; faces of one or two vertices are a point and a line) and the edge
// element's vertex1 and vertex2 as lines. A file with none of these (no face or edge element, or
// none of their rows) is a point cloud: every vertex a point. The file is checked against its
// header as it is read (binary: first every list's length within the file; ASCII: every row a
// line of numbers, every list within its line). Throws SceneError "<where>: <path>: <why>" for a
// file that ends early, a non-finite position, an index out of range or a face without vertices,
// naming the element and its index (and the line, for ASCII).
Mesh readPly(std::string_view bytes, const std::string& path, const std::string& where);

}  // namespace phongvk
