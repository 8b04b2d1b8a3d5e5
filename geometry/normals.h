// normals.h — vertex normals for meshes that come without them (OBJ files).
#pragma once

#include "geometry/mesh.h"

namespace phongvk {

// Sets every vertex normal to the normalised sum of the unnormalised face normals
// cross(b - a, c - a) of its triangles: each face weighs by its area, so a sliver does not tilt a
// vertex the way a large face does. Vertices shared by index are smooth; split ones stay sharp.
// A vertex whose sum cancels (a two-sided sheet) takes the normal of its first triangle with area;
// one with no such triangle gets +z. Unit length always.
void computeVertexNormals(Mesh& mesh);

}  // namespace phongvk
