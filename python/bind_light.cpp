// bind_light.cpp — phongvk.Light for Python (see bindings.h).
#include "bindings.h"

namespace phongvk::python {

namespace {

bool falloffIsInverseSquare(const std::string& falloff) {
  if (falloff != "material" && falloff != "inverse_square")
    throw ArgumentError("falloff: expected 'material' or 'inverse_square', got '" + falloff + "'");
  return falloff == "inverse_square";
}

}  // namespace

void bindLight(py::module_& m) {
  py::class_<Light>(m, "Light", R"(A light: a point light at position (or at_camera=True: at the eye,
wherever the camera is), or a directional light (direction=(x, y, z): its light travels that way
and reaches every point alike, without fall-off, as the sun's), or a spot light at position
(spot=(x, y, z): the way it points; full within inner_cone degrees of that axis, dark beyond
outer_cone, glTF's smooth fall-off between); intensity, color; falloff="inverse_square" (with an
optional range) for a point or spot light that falls off as 1/d^2 rather than as each material's
attenuation says; shadows=True for a light that objects shadow (exact rays, the same on every
device). Assigned to Scene.lights, checked
like a scene file's "lights".)")
      .def(py::init([](Vec3 position, std::optional<Vec3> direction, std::optional<Vec3> spot, double innerCone,
                       double outerCone, const std::string& falloff, double range, double intensity, Vec3 color,
                       bool atCamera, bool shadows) {
             if (direction && spot) throw ArgumentError("Light: direction= (a directional light) or spot= (a spot light), not both");
             Light light{position, intensity, color, atCamera};
             light.directional = direction.has_value();
             light.spot = spot.has_value();
             if (direction || spot) light.direction = direction ? *direction : *spot;
             light.innerCone = innerCone;
             light.outerCone = outerCone;
             light.inverseSquare = falloffIsInverseSquare(falloff);
             light.range = range;
             light.shadows = shadows;
             return light;
           }),
           py::kw_only(), py::arg("position") = Vec3{0, 0, 0}, py::arg("direction") = py::none(),
           py::arg("spot") = py::none(), py::arg("inner_cone") = 0.0, py::arg("outer_cone") = 45.0,
           py::arg("falloff") = "material", py::arg("range") = 0.0,
           py::arg("intensity") = 1.0, py::arg("color") = Vec3{1, 1, 1}, py::arg("at_camera") = false,
           py::arg("shadows") = false)
      .def_readwrite("position", &Light::position)
      .def_property(
          "direction",
          [](const Light& l) { return l.directional ? std::optional<Vec3>(l.direction) : std::nullopt; },
          [](Light& l, std::optional<Vec3> direction) {
            l.directional = direction.has_value();
            if (direction) l.direction = *direction;
            if (direction) l.spot = false;
          },
          "The direction a directional light's light travels, or None for a point or spot light.")
      .def_property(
          "spot", [](const Light& l) { return l.spot ? std::optional<Vec3>(l.direction) : std::nullopt; },
          [](Light& l, std::optional<Vec3> axis) {
            l.spot = axis.has_value();
            if (axis) l.direction = *axis;
            if (axis) l.directional = false;
          },
          "The direction a spot light points, or None for another light.")
      .def_readwrite("inner_cone", &Light::innerCone, "A spot light's full-intensity half-angle, degrees.")
      .def_readwrite("outer_cone", &Light::outerCone, "A spot light's half-angle beyond which it is dark, degrees.")
      .def_property(
          "falloff", [](const Light& l) { return l.inverseSquare ? "inverse_square" : "material"; },
          [](Light& l, const std::string& falloff) { l.inverseSquare = falloffIsInverseSquare(falloff); },
          "\"material\" (each material's attenuation) or \"inverse_square\" (1/d^2, glTF's).")
      .def_readwrite("range", &Light::range, "With the inverse square: where it is windowed to 0, metres (0: none).")
      .def_readwrite("shadows", &Light::shadows,
                     "Whether it lights only what its shadow rays reach (objects with cast_shadows false never block them).")
      .def_readwrite("intensity", &Light::intensity)
      .def_readwrite("color", &Light::color)
      .def_readwrite("at_camera", &Light::atCamera)
      .def("__repr__", [](const Light& l) {
        const std::string where =
            l.directional ? "direction=" + vec3Text(l.direction)
            : l.spot      ? "position=" + vec3Text(l.position) + ", spot=" + vec3Text(l.direction) + ", inner_cone=" +
                           std::string(py::str(py::float_(l.innerCone))) +
                           ", outer_cone=" + std::string(py::str(py::float_(l.outerCone)))
            : l.atCamera  ? std::string("at_camera=True")
                          : "position=" + vec3Text(l.position);
        return "phongvk.Light(" + where + ", intensity=" + std::string(py::str(py::float_(l.intensity))) +
               ", color=" + vec3Text(l.color) + ")";
      });
}

}  // namespace phongvk::python
