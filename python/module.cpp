// module.cpp — phongvk's Python extension (_phongvk), on the public C++ API (include/phongvk) alone:
// numpy arrays in and out, the GIL released while rendering, C++ errors as Python exceptions. What
// users import is the package around it (python/phongvk/__init__.py); the docstrings here are what
// help() shows.
#include "bindings.h"

PYBIND11_MODULE(_phongvk, m) {
  using namespace phongvk;
  using namespace phongvk::python;
  m.doc() = "phongvk's compiled core; import phongvk, not this module.";

  // C++ failures as Python exceptions, all under phongvk.Error: a bad scene is also a ValueError,
  // a bad argument a ValueError (an index past the end an IndexError), an unwritable file an
  // OSError, a missing Vulkan device or a device limit a RuntimeError. Subclasses are registered
  // after their bases: pybind11 tries the last registered translator first.
  const py::object error = py::register_exception<Error>(m, "Error", PyExc_RuntimeError);
  const auto under = [&](PyObject* python) { return py::make_tuple(error, py::handle(python)); };
  py::register_exception<SceneError>(m, "SceneError", under(PyExc_ValueError));
  const py::object argument = py::register_exception<ArgumentError>(m, "ArgumentError", under(PyExc_ValueError));
  py::register_exception<RangeError>(m, "RangeError", py::make_tuple(argument, py::handle(PyExc_IndexError)));
  py::register_exception<OutputError>(m, "OutputError", under(PyExc_OSError));
  py::register_exception<NoDeviceError>(m, "NoDeviceError", under(PyExc_RuntimeError));
  py::register_exception<DeviceError>(m, "DeviceError", under(PyExc_RuntimeError));

  m.attr("__version__") = version();
  m.attr("__revision__") = revision();

  bindCamera(m);
  bindLight(m);
  bindTexture(m);
  bindMaterial(m);
  bindRenderSettings(m);
  bindMesh(m);
  bindScene(m);
  bindRenderer(m);
  bindPng(m);
  m.attr("NO_TRIANGLE") = NO_TRIANGLE;
}
