// bind_scene.cpp — phongvk.Scene, load_scene and scene_from_dict for Python (see bindings.h).
#include "bindings.h"

#include "tools/option_text.h"

namespace phongvk::python {

void bindScene(py::module_& m) {
  py::class_<Scene>(m, "Scene", R"(A validated scene: camera, lights, materials, objects.

Made by Scene(width, height) (an empty scene to build in code: the default Camera at that size,
one white light at the camera, no objects yet), load_scene(path) or scene_from_dict(d); meshes are
added as numpy arrays with add() or add_mesh(). A scene file with an "animate" block is frame 0 of
its sequence; frame(i) gives the others.)")
      .def(py::init<int, int>(), py::arg("width"), py::arg("height"),
           "An empty scene rendered at width x height pixels (1..16384 each); SceneError for a size out of range.")
      .def_property_readonly("path", &Scene::path, "The file the scene came from ('' for one made in code or from a dict).")
      .def_property_readonly("width", &Scene::width, "Width in pixels of the image the scene's camera renders.")
      .def_property_readonly("height", &Scene::height, "Height in pixels of the image the scene's camera renders.")
      .def_property_readonly("object_count", &Scene::objectCount, "How many objects the scene has.")
      .def_property_readonly("light_count", &Scene::lightCount, "How many lights the scene has.")
      .def_property_readonly("frame_count", &Scene::frameCount,
                             "Frames of the scene's animation (1 for a scene without an \"animate\" block).")
      .def("frame", &Scene::frame, py::arg("index"),
           "Frame `index` of the scene's animation, validated like a scene file (IndexError when out of range).")
      .def("with_render", &withRender, py::arg("settings") = py::none(),
           R"(The same scene rendered with other settings: a phongvk.RenderSettings, or the scene's own
with some replaced, by a dict or by keywords: with_render(shading="phong", samples=4). The keys are
RenderSettings' (shading, specular, interpolation, samples, background). Checked like a scene file's
"render"; a bad value raises SceneError naming render.KEY.)")
      .def_property("render_settings", &Scene::renderSettings, &Scene::setRenderSettings,
                    "The render settings (a phongvk.RenderSettings); assigning some checks them like a scene "
                    "file's \"render\" and \"background\".")
      .def("add_mesh", &addMesh, py::arg("vertices"), py::arg("faces") = py::none(), py::arg("normals") = py::none(),
           py::arg("material") = py::none(), py::arg("closed") = false, py::arg("uvs") = py::none(),
           py::arg("colors") = py::none(), py::arg("object_id") = py::none(),
           R"(Adds a triangle mesh object; it follows the scene into its other frames (frame(i)).

vertices: (N, 3) floating-point array of world positions (or rows of 3 numbers), or, with
    faces left out, a phongvk.Mesh (built once, shared by every object that adds it) or one mesh
    object with .vertices and .faces arrays (a trimesh.Trimesh works without phongvk importing
    trimesh).
faces: (M, 3) integer array of vertex indices (or rows of 3 integers), counter-clockwise seen
    from outside.
normals: optional (N, 3) floating-point array of vertex normals; computed from the faces
    (area-weighted) when not given.
material: None (the scene's default material: Material() in a Scene(width, height), the file's
    default in a scene from a file or dict), a phongvk.Material, a dict of its fields ({"ks": 0.2,
    "color": [1, 0, 0]}), or the name of one of the scene's materials; checked like a scene file's.
closed: True if the mesh is a closed surface whose back faces may be culled.
uvs: optional (N, 2) array of texture coordinates, (0, 0) the texture's top-left corner and
    (1, 1) its bottom-right: what the material's texture (Material(texture=...)) is sampled with.
colors: optional (N, 3) or (N, 4) vertex colours, integers 0..255 (uint8) or floats 0..1, that
    multiply the material's colour (alpha is kept, not drawn). A trimesh-like object brings its
    own: visual.vertex_colors where visual.kind is "vertex", visual.uv (v flipped: trimesh's v
    runs up) and, with no material given, visual.material's image as the texture.
object_id: the object's number in the object_id output (0..2^31-1, shared by several objects
    if wanted); by default the next of the scene's ids, kept for the scene's life.

A wrong shape or dtype, a non-finite value or an index out of range raises ValueError naming the
argument and the first bad row; a bad material raises SceneError.)")
      .def("add", &addObject, py::arg("mesh"), py::arg("faces") = py::none(), py::kw_only(),
           py::arg("pose") = py::none(), py::arg("material") = py::none(), py::arg("closed") = false,
           py::arg("normals") = py::none(), py::arg("uvs") = py::none(), py::arg("colors") = py::none(),
           py::arg("object_id") = py::none(),
           R"(Adds a mesh placed by a (4, 4) local-to-world pose (identity when None) and returns its
handle, for set_pose, set_mesh, object_id and remove. mesh: a phongvk.Mesh (built once: placing it
many times builds and holds it once), one object with .vertices and .faces arrays (a
trimesh.Trimesh works, with its vertex colours, uvs and texture), or vertices with faces;
material, closed, normals, uvs, colors and object_id as in add_mesh.)")
      .def(
          "set_pose", [](Scene& s, unsigned long long id, const py::object& pose) { s.setPose(ObjectId{id}, matrix4(pose, "pose")); },
          py::arg("object"), py::arg("pose"),
          "Moves an object added with add(). IndexError for a handle this scene does not hold: one removed, or "
          "one another scene gave (handles are unique to the scene that gave them).")
      .def(
          "set_mesh",
          [](Scene& s, unsigned long long id, const py::object& mesh, const py::object& faces, const py::object& normals,
             const py::object& uvs, const py::object& colors) {
            s.setMesh(ObjectId{id}, meshOf(mesh, faces, normals, uvs, colors));
          },
          py::arg("object"), py::arg("mesh"), py::arg("faces") = py::none(), py::kw_only(), py::arg("normals") = py::none(),
          py::arg("uvs") = py::none(), py::arg("colors") = py::none(),
          "Replaces an added object's geometry (what add() takes as mesh) in place: its handle, object_id, pose, "
          "material and closed stay.")
      .def(
          "object_id", [](const Scene& s, unsigned long long id) { return s.objectId(ObjectId{id}); }, py::arg("object"),
          "The number an object added with add() has in the object_id output: stable for the scene's life, "
          "whatever is removed or added after it.")
      .def(
          "set_object_id", [](Scene& s, unsigned long long id, int32_t value) { s.setObjectId(ObjectId{id}, value); },
          py::arg("object"), py::arg("object_id"),
          "Gives an added object your own number in the object_id output (0..2^31-1; objects may share one).")
      .def(
          "casts_shadows", [](const Scene& s, unsigned long long id) { return s.castsShadows(ObjectId{id}); },
          py::arg("object"), "Whether an added object's triangles block lights that cast shadows (True when added).")
      .def(
          "set_cast_shadows", [](Scene& s, unsigned long long id, bool casts) { s.setCastShadows(ObjectId{id}, casts); },
          py::arg("object"), py::arg("cast_shadows"),
          "Whether an added object's triangles block lights that cast shadows, as a scene file's \"cast_shadows\": "
          "False for a ground plane or a helper that should not.")
      .def(
          "add_light", [](Scene& s, const Light& light) { return s.addLight(light).value; }, py::arg("light"),
          "Adds a light (a phongvk.Light, checked like a scene file's) after the scene's lights and returns its "
          "handle, for light, set_light and remove. It follows the scene into its other frames.")
      .def(
          "light", [](const Scene& s, unsigned long long id) { return s.light(LightId{id}); }, py::arg("light"),
          "The light a handle from add_light names (IndexError for one this scene does not hold).")
      .def(
          "set_light", [](Scene& s, unsigned long long id, const Light& light) { s.setLight(LightId{id}, light); },
          py::arg("light"), py::arg("value"), "Replaces the light a handle from add_light names.")
      .def(
          "_set_light_at", [](Scene& s, size_t index, const Light& light) { s.setLightAt(index, light); },
          py::arg("index"), py::arg("value"), "The light at `index` of lights replaced, its handle kept.")
      .def(
          "remove",
          [](Scene& s, unsigned long long id) {
            if (isLightHandle(id)) return s.removeLight(LightId{id});
            s.remove(ObjectId{id});
          },
          py::arg("handle"),
          "Takes out an object added with add() or a light added with add_light() (IndexError for a handle this "
          "scene does not hold, as set_pose).")
      .def_property_readonly("bounds", &Scene::bounds,
                             "The world box around every object's vertices, as built: (min, max), each (x, y, z). "
                             "Builds the meshes to know; SceneError first for a scene beyond the memory limit, as rendering it.")
      .def(
          "triangles",
          [](const Scene& s) {
            SceneTriangles t = s.triangles();
            const py::ssize_t vertices = py::ssize_t(t.mesh.positions.size() / 3), faces = py::ssize_t(t.objects.size());
            py::dict out;
            out["vertices"] = ownedArray(std::move(t.mesh.positions), {vertices, 3});
            out["normals"] = ownedArray(std::move(t.mesh.normals), {vertices, 3});
            out["faces"] = ownedArray(std::move(t.mesh.triangles), {faces, 3});
            out["objects"] = ownedArray(std::move(t.objects), {faces});
            const py::ssize_t lines = py::ssize_t(t.lineObjects.size()), points = py::ssize_t(t.pointObjects.size());
            out["lines"] = ownedArray(std::move(t.mesh.lines), {lines, 2});
            out["line_objects"] = ownedArray(std::move(t.lineObjects), {lines});
            out["points"] = ownedArray(std::move(t.mesh.points), {points});
            out["point_objects"] = ownedArray(std::move(t.pointObjects), {points});
            return out;
          },
          "Every triangle, line and point as both renderers draw them (shapes tessellated, meshes subdivided, "
          "transforms and poses applied), in world coordinates: a dict of numpy arrays, vertices (N, 3) float32, "
          "normals (N, 3) float32 (unit; 0 for a point's or a line's vertex given none), faces (M, 3) int64 "
          "(vertex indices) and objects (M,) int32 (each triangle's object, its index in the scene's objects), "
          "lines (L, 2) int64 and line_objects (L,), points (P,) int64 and point_objects (P,). The "
          "triangle_ids output numbers them in that order: triangle t is t, line k is M + k, point k is "
          "M + L + k. For drawing the same geometry with another renderer, or exporting it. Builds the meshes, "
          "as bounds does; SceneError for a scene whose meshes, or the arrays of them, need more than the "
          "memory limit.")
      .def_property("camera", &Scene::camera, &Scene::setCamera,
                    "The camera (a phongvk.Camera); assigning one checks it like a scene file's \"camera\".")
      .def_property("lights", &Scene::lights, &Scene::setLights,
                    "The lights (phongvk.Light); assigning a list checks it like a scene file's \"lights\".")
      .def_property("ambient", &Scene::ambient, &Scene::setAmbient,
                    "The ambient light, RGB (default white); assigning one checks it like a scene file's "
                    "\"ambient\".")
      .def("to_json", &Scene::toJson,
           R"(The scene as scene file JSON text (str): scene_from_dict(json.loads(text)) or load_scene
of the text saved gives a scene that renders the same bytes, and whose to_json() is this text again.
Every value is written: the camera, lights, materials (named ones by name, every other inline),
each object's parameters, scale and rotation (as {"matrix": rows}), mesh files by absolute path,
meshes added with add() or add_mesh() inline as "vertices", "faces" and "normals" at their poses,
and the render settings. An animated scene writes this frame, without its "animate" block.)")
      .def(
          "to_dict", [](const Scene& s) { return py::module_::import("json").attr("loads")(s.toJson()); },
          R"(The scene as a dict with the scene file's schema (to_json() read by json.loads):
phongvk.scene_from_dict(scene.to_dict()) renders the same bytes.)")
      .def("__repr__", [](const Scene& s) {
        return "<phongvk.Scene " + (s.path().empty() ? std::string("(no file)") : s.path()) + ": " +
               std::to_string(s.objectCount()) + " objects, " + std::to_string(s.lightCount()) + " lights, " +
               std::to_string(s.width()) + "x" + std::to_string(s.height()) + ">";
      });

  m.def(
      "load_scene",
      [](const FsPath& path, std::optional<std::string> up, std::optional<std::string> projection, bool fileLights,
         bool fileLightShadows) {
        return loadScene(path.text, LoadOptions{up ? parseModelUp(*up) : ModelUp::Usual,
                                                projection ? std::optional<bool>(parseOrthographic(*projection)) : std::nullopt,
                                                fileLights, fileLightShadows});
      },
      py::arg("path"), py::arg("up") = py::none(), py::arg("projection") = py::none(), py::arg("file_lights") = true,
      py::arg("file_light_shadows") = false,
      R"(Reads and validates a scene file (the CLI's schema), or a model file (.obj .ply .stl .gltf
.glb) as a scene of its own: the model in full view, lit from the camera. Raises SceneError naming
the file and the JSON path.

up: None, "y" or "z": the up axis of a model file loaded alone, for one whose exporter used the
    other convention (None: its format's usual one, y for glTF and OBJ, z for PLY and STL).
projection: None, "perspective" or "orthographic": the fitted camera of a model file loaded alone
    (None: perspective); a scene file's camera says its own, and either given with one is an
    error.
file_lights: False lights a glTF model file loaded alone from the camera, leaving out the lights it
    places (KHR_lights_punctual); a scene file says it per object ("file_lights").
file_light_shadows: True makes the lights a glTF model file loaded alone places cast shadows (as a
    light's "shadows"); a scene file says it per object ("file_light_shadows").)");
  m.def("scene_from_dict", &sceneFromDict, py::arg("d"), py::arg("base_dir") = py::none(),
        R"(A scene from a dict with the scene file's schema, validated the same way.

Relative mesh paths resolve against base_dir (the working directory when None). The dict may have
no objects yet ("objects": []) and get them from add() or add_mesh(); rendering a scene without
objects raises SceneError. A scene built in code needs no dict: Scene(width, height).)");
}

}  // namespace phongvk::python
