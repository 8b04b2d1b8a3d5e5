// bind_mesh.cpp — phongvk.Mesh for Python (see bindings.h).
#include "bindings.h"

namespace phongvk::python {

void bindMesh(py::module_& m) {
  py::class_<TriangleMesh>(m, "Mesh", R"(A mesh built once, which Scene.add and add_mesh place as many
times as asked without building or holding it again: Mesh(vertices, faces, normals=None, uvs=None,
colors=None, lines=None, points=None) from arrays (or one object with .vertices and .faces, a
trimesh.Trimesh, whose visual's vertex colours and uvs come with it), checked as add_mesh checks
them, or Mesh.from_file(path, up=None) from an OBJ, PLY, STL, glTF or GLB file. Beside its triangles
(faces) it may draw line segments (lines: (L, 2) vertex indices) and points (points: (P,) vertex
indices); vertices alone are a point cloud (phongvk.Points, phongvk.Lines). A point's or a line's
vertex without a normal is drawn unlit, in its colour.)")
      .def(py::init([](const py::object& vertices, const py::object& faces, const py::object& normals, const py::object& uvs,
                       const py::object& colors, const py::object& lines, const py::object& points) {
             return TriangleMesh(meshArrays(vertices, faces, normals, uvs, colors, lines, points));
           }),
           py::arg("vertices"), py::arg("faces") = py::none(), py::arg("normals") = py::none(), py::arg("uvs") = py::none(),
           py::arg("colors") = py::none(), py::arg("lines") = py::none(), py::arg("points") = py::none())
      .def_static("from_file", &meshFromFile, py::arg("path"), py::arg("up") = py::none(),
                  R"(A mesh file read as a model rendered alone reads it: stood up by up ("y" or "z"; None: the
format's usual axis, y for glTF and OBJ, z for PLY and STL), a glTF's base colours as vertex colours,
in the file's coordinates (the pose it is added with places it). SceneError naming the file and its
line for a bad file.)")
      .def_property_readonly("vertex_count", &TriangleMesh::vertexCount)
      .def_property_readonly("triangle_count", &TriangleMesh::triangleCount)
      .def_property_readonly("line_count", &TriangleMesh::lineCount)
      .def_property_readonly("point_count", &TriangleMesh::pointCount)
      .def("__repr__", [](const TriangleMesh& mesh) {
        std::string text = "<phongvk.Mesh: " + std::to_string(mesh.vertexCount()) + " vertices, " +
                           std::to_string(mesh.triangleCount()) + " triangles";
        if (mesh.lineCount() != 0) text += ", " + std::to_string(mesh.lineCount()) + " lines";
        if (mesh.pointCount() != 0) text += ", " + std::to_string(mesh.pointCount()) + " points";
        return text + ">";
      });
}

}  // namespace phongvk::python
