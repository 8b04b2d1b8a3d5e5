// normals.h — vertex normals for meshes that come without them (OBJ files).
#pragma once

#include "geometry/mesh.h"

namespace phongvk {

// Sets every vertex normal to the normalised sum of the unnormalised face normals
// cross(b - a, c - a) of its triangles: each face weighs by its area, so a sliver does not tilt a
// vertex the way a large face does. Vertices shared by index are smooth; split ones stay sharp.
// A vertex whose sum cancels (a two-sided sheet) takes the normal of its first triangle with area;
// one whose triangles all have zero area gets +z. A vertex no triangle uses (one only points and
// lines draw) gets (0, 0, 0): it is drawn unlit. Unit length for every vertex a triangle uses.
void computeVertexNormals(Mesh& mesh);

}  // namespace phongvk
