// stl_file.h — STL files, binary and ASCII, read by phongvk (docs/DECISIONS.md "Mesh files").
#pragma once

#include "geometry/mesh.h"

#include <string>
#include <string_view>

namespace phongvk {

// The STL file `bytes` as a loaded mesh (mesh_import.h): each facet's three vertices its own, no
// normals (computed flat from the winding: files often leave the facet normals zero). A binary
// file is an 80-byte header, a triangle count and 50 bytes a triangle; an ASCII file is
// `solid ... facet normal n n n / outer loop / vertex x y z (three times) / endloop / endfacet ...
// endsolid`, one or more solids. Throws SceneError "<where>: <path>: <why>" for a file whose size
// disagrees with its count, a facet without three vertices, a value that is not a number or a
// position that is not finite, naming the facet (and the line, for ASCII).
Mesh readStl(std::string_view bytes, const std::string& path, const std::string& where);

}  // namespace phongvk
