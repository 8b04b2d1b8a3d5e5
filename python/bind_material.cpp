// bind_material.cpp — phongvk.Material for Python (see bindings.h).
#include "bindings.h"

namespace phongvk::python {

void bindMaterial(py::module_& m) {
  const Material material;
  py::class_<Material>(m, "Material", R"(A material, as a scene file's material object: ka, kd, ks (the
ambient, diffuse and specular coefficients), n (the specular exponent, the shininess), attenuation
(a, b, c of the fall-off 1 / (a + b d + c d^2)) and color (RGB). The defaults are the scene file's
but the fall-off: 0.15, 1.0, 0.8, 10, (1, 0, 0), grey 0.8; no fall-off, as a model file rendered
alone has, so a scene built in code is well exposed at any distance (a scene file's default
attenuation is the paper's (1, 0.2, 0.2)). Given to Scene.add or add_mesh, it is checked like a
scene file's material (SceneError naming objects[N].material.KEY). texture: a base-colour texture
that multiplies color where the object's mesh has texture coordinates (uvs): a PNG or JPEG file's
path, a phongvk.Texture, or an image array ((height, width, 3 or 4) uint8, row 0 at the top), held
as a phongvk.Texture of its pixels (a scene's to_json() writes it as a data URI of its PNG); None
for none.)")
      .def(py::init([](double ka, double kd, double ks, double n, Vec3 attenuation, Vec3 color, const py::object& texture) {
             Material material{ka, kd, ks, n, attenuation, color};
             setTexture(material, texture);
             return material;
           }),
           py::kw_only(), py::arg("ka") = material.ka, py::arg("kd") = material.kd, py::arg("ks") = material.ks,
           py::arg("n") = material.n, py::arg("attenuation") = material.attenuation, py::arg("color") = material.color,
           py::arg("texture") = py::none())
      .def_readwrite("ka", &Material::ka, "Ambient coefficient (>= 0).")
      .def_readwrite("kd", &Material::kd, "Diffuse coefficient (>= 0).")
      .def_readwrite("ks", &Material::ks, "Specular coefficient (>= 0).")
      .def_readwrite("n", &Material::n, "Specular exponent, the shininess (>= 0).")
      .def_readwrite("attenuation", &Material::attenuation,
                     "(a, b, c) of the fall-off 1 / (a + b d + c d^2), positive at every distance d > 0.")
      .def_readwrite("color", &Material::color, "RGB (>= 0).")
      .def_property(
          "texture",
          [](const Material& x) {
            if (x.textureImage) return py::cast(*x.textureImage);
            return x.texture.empty() ? py::object(py::none()) : py::object(py::str(x.texture));
          },
          setTexture, "The texture's file (or data URI), or the phongvk.Texture an array became; None for none.")
      .def("__eq__", [](const Material& a, const Material& b) { return a == b; }, py::is_operator())
      .def("__repr__", [](const Material& x) {
        return "phongvk.Material(ka=" + floatText(x.ka) + ", kd=" + floatText(x.kd) + ", ks=" + floatText(x.ks) +
               ", n=" + floatText(x.n) + ", attenuation=" + vec3Text(x.attenuation) + ", color=" + vec3Text(x.color) +
               (x.textureImage                        ? ", texture=" + textureRepr(*x.textureImage)
                : x.texture.empty()                   ? std::string()
                : x.texture.rfind("data:", 0) == 0    ? ", texture=<PNG data URI, " + std::to_string(x.texture.size()) + " characters>"
                                                      : ", texture='" + x.texture + "'") +
               ")";
      });
}

}  // namespace phongvk::python
