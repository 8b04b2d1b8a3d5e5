// bind_light.cpp — phongvk.Light for Python (see bindings.h).
#include "bindings.h"

namespace phongvk::python {

void bindLight(py::module_& m) {
  py::class_<Light>(m, "Light", R"(A light: a point light at position (or at_camera=True: at the eye,
wherever the camera is), or a directional light (direction=(x, y, z): its light travels that way
and reaches every point alike, without fall-off, as the sun's); intensity, color. Assigned to
Scene.lights, checked like a scene file's "lights".)")
      .def(py::init([](Vec3 position, std::optional<Vec3> direction, double intensity, Vec3 color, bool atCamera) {
             Light light{position, intensity, color, atCamera};
             if (direction) {
               light.directional = true;
               light.direction = *direction;
             }
             return light;
           }),
           py::kw_only(), py::arg("position") = Vec3{0, 0, 0}, py::arg("direction") = py::none(),
           py::arg("intensity") = 1.0, py::arg("color") = Vec3{1, 1, 1}, py::arg("at_camera") = false)
      .def_readwrite("position", &Light::position)
      .def_property(
          "direction",
          [](const Light& l) { return l.directional ? std::optional<Vec3>(l.direction) : std::nullopt; },
          [](Light& l, std::optional<Vec3> direction) {
            l.directional = direction.has_value();
            if (direction) l.direction = *direction;
          },
          "The direction a directional light's light travels, or None for a point light.")
      .def_readwrite("intensity", &Light::intensity)
      .def_readwrite("color", &Light::color)
      .def_readwrite("at_camera", &Light::atCamera)
      .def("__repr__", [](const Light& l) {
        const std::string where = l.directional ? "direction=" + vec3Text(l.direction)
                                  : l.atCamera  ? std::string("at_camera=True")
                                                : "position=" + vec3Text(l.position);
        return "phongvk.Light(" + where + ", intensity=" + std::string(py::str(py::float_(l.intensity))) +
               ", color=" + vec3Text(l.color) + ")";
      });
}

}  // namespace phongvk::python
