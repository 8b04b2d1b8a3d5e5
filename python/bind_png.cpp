// bind_png.cpp — write_png, read_png and encode_png for Python (see bindings.h).
#include "bindings.h"

namespace phongvk::python {

void bindPng(py::module_& m) {
  m.def("write_png", [](const FsPath& path, const py::array& image, int level) {
    const PngImage pixels = pngImageFromArray(image, "image");
    const py::gil_scoped_release release;
    std::visit([&](const auto& any) { writePng(path.text, any, level); }, pixels);
  }, py::arg("path"), py::arg("image"), py::arg("level") = PNG_LEVEL_DEFAULT,
        "Writes an image array as a PNG, atomically (no partial file): (height, width, 3) uint8 as RGB, "
        "(height, width, 4) uint8 as RGBA, (height, width) uint16 as 16-bit grey (a depth in millimetres, ids), "
        "(height, width) uint8 as 8-bit grey and bool as 0 and 255 (a mask). path: str or os.PathLike. "
        "level: deflate level, 0 (stored) to 12 (smallest); the same pixels at every level. Raises OutputError, "
        "or ValueError for another array or a level out of range.");
  m.def("read_png", &pngArray, py::arg("path"), py::arg("mode") = "rgb",
        "Reads a PNG as mode says: \"rgb\" a (height, width, 3) uint8 array, \"rgba\" (height, width, 4) "
        "uint8 (alpha 255 where the file has none), \"grey16\" (height, width) uint16 (a depth PNG's "
        "millimetres, an ids PNG's index + 1; 8-bit samples scaled by 257).");
  m.def("encode_png", [](const py::array& image, int level) {
    const std::vector<uint8_t> png = encodedPng(pngImageFromArray(image, "image"), level, "image");
    return py::bytes(reinterpret_cast<const char*>(png.data()), png.size());
  }, py::arg("image"), py::arg("level") = PNG_LEVEL_DEFAULT,
        "An image array as PNG bytes, deflated at `level` (0 to 12): (height, width, 3) uint8 as RGB, "
        "(height, width, 4) uint8 as RGBA, (height, width) uint16 as 16-bit grey, (height, width) uint8 or bool (0 and 255) as 8-bit grey.");
  m.attr("PNG_LEVEL_DEFAULT") = PNG_LEVEL_DEFAULT;
}

}  // namespace phongvk::python
