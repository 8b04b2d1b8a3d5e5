// bind_texture.cpp — phongvk.Texture for Python (see bindings.h).
#include "bindings.h"

namespace phongvk::python {

void bindTexture(py::module_& m) {
  py::class_<Texture>(m, "Texture", R"(A texture held in memory, made once from an image array ((height, width, 3 or
4) uint8 RGB or RGBA, or (height, width) uint16 grey; row 0 at the top) and shared by every material
that takes it: Material(texture=...) makes one of an array, or takes one made before. Its texels are
written from the array directly, whatever its strides: no copy of the array, no PNG. A scene's
to_json() writes it as a data URI of its PNG.)")
      .def(py::init([](const py::object& image) { return textureOfArray(numberArray(image, "image", PNG_ARRAYS), "image"); }),
           py::arg("image"))
      .def_property_readonly("width", &Texture::width)
      .def_property_readonly("height", &Texture::height)
      .def("__eq__", [](const Texture& a, const Texture& b) { return a == b; }, py::is_operator())
      .def("__repr__", textureRepr);
}

}  // namespace phongvk::python
