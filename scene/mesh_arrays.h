// mesh_arrays.h — mesh objects given as arrays (include/phongvk/mesh.h) instead of a file: checked
// row by row, built once, and added to a scene as a `mesh` object of its own.
#pragma once

#include "geometry/mesh.h"
#include "phongvk/mesh.h"
#include "scene/scene.h"
#include "scene/scene_checks.h"
#include "scene/scene_json.h"

#include <memory>
#include <string>

namespace phongvk {

// The mesh the arrays describe, as an OBJ file with the same vertices and faces would give it:
// zero-area triangles dropped, given normals normalised, missing ones area-weighted. Throws
// ArgumentError naming the array and its first bad row: a non-finite or out-of-range
// position, an index outside the vertices, a normal without direction, a wrong count.
Mesh meshFromArrays(const MeshArrays& arrays);

// Appends a mesh built from arrays (meshFromArrays, once: a scene's added meshes follow it into its
// other frames) as a mesh object ("objects[N]") to `scene`, with `material`: the scene's default,
// one of its materials by name, or values checked as a scene file's material object (messages name
// "objects[N].material"). Throws SceneError for a bad material; `scene` is unchanged then.
void addMeshObject(SceneSpec& scene, std::shared_ptr<const Mesh> mesh, const scenejson::MaterialChoice& material,
                   bool closed);

}  // namespace phongvk
