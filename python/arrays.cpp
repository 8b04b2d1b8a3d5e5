// arrays.cpp — numpy arrays in and out, checked, and PNGs of them (see bindings.h).
#include "bindings.h"

namespace phongvk::python {

py::array_t<uint8_t> imageArray(Image&& image) {
  const py::ssize_t h = image.height, w = image.width;
  return ownedArray(std::move(image.rgb), {h, w, 3});
}

py::array pngArray(const FsPath& file, const std::string& mode) {
  const std::string& path = file.text;
  if (mode == "rgb") return imageArray(readPng(path));
  if (mode == "rgba") {
    ImageRGBA image = readPngRGBA(path);
    return ownedArray(std::move(image.rgba), {image.height, image.width, 4});
  }
  if (mode == "grey16") {
    ImageGrey16 image = readPngGrey16(path);
    return ownedArray(std::move(image.grey), {image.height, image.width});
  }
  throw ArgumentError("mode: expected 'rgb', 'rgba' or 'grey16', got '" + mode + "'");
}

[[noreturn]] void raiseMemoryError(const std::string& message) {
  PyErr_SetString(PyExc_MemoryError, message.c_str());
  throw py::error_already_set();
}

std::string shapeText(const py::array& a) {
  std::string text = "(";
  for (py::ssize_t i = 0; i < a.ndim(); ++i) text += (i ? ", " : "") + std::to_string(a.shape(i));
  return text + (a.ndim() == 1 ? ",)" : ")");
}

std::string typeName(const py::handle& value) { return py::str(py::type::of(value).attr("__name__")); }

py::array numberArray(const py::handle& value, const char* name, const std::string& expected) {
  py::array a;
  if (py::isinstance<py::array>(value)) {
    a = py::reinterpret_borrow<py::array>(value);
  } else {
    try {
      a = py::module_::import("numpy").attr("asarray")(value);
    } catch (py::error_already_set& e) {
      if (e.matches(PyExc_MemoryError)) throw;
      throw py::value_error(std::string(name) + ": expected " + expected + ", got " + typeName(value) + " (" +
                            e.what() + ")");
    }
  }
  const char kind = a.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u') {
    throw py::value_error(std::string(name) + ": expected " + expected + ", got " + typeName(value) + " of dtype " +
                          std::string(py::str(a.dtype())));
  }
  return a;
}

std::optional<ImageGrey8> grey8FromArray(const py::array& array, const char* name) {
  const bool bools = array.dtype().kind() == 'b';
  if (array.ndim() != 2 || !(bools || py::isinstance<py::array_t<uint8_t>>(array))) return std::nullopt;
  if (array.shape(0) == 0 || array.shape(1) == 0)
    throw py::value_error(std::string(name) + ": expected a non-empty array, got shape " + shapeText(array));
  ImageGrey8 image{int(array.shape(1)), int(array.shape(0)), valuesOf<uint8_t>(array, name)};
  if (bools) {
    for (uint8_t& v : image.grey) v = v ? 255 : 0;
  }
  return image;
}

void checkPngArray(const py::array& array, const char* name, const char* expected) {
  const std::string shape = shapeText(array);
  const bool bytes = py::isinstance<py::array_t<uint8_t>>(array), words = py::isinstance<py::array_t<uint16_t>>(array);
  const py::ssize_t channels = array.ndim() == 3 ? array.shape(2) : 0;
  if (!(bytes && (channels == 3 || channels == 4)) && !(words && array.ndim() == 2)) {
    throw py::value_error(std::string(name) + ": expected " + expected + ", got " +
                          std::string(py::str(array.dtype())) + " of shape " + shape);
  }
  if (array.shape(0) == 0 || array.shape(1) == 0) {
    throw py::value_error(std::string(name) + ": expected a non-empty array, got shape " + shape);
  }
}

PngImage pngImageFromArray(const py::array& array, const char* name) {
  if (std::optional<ImageGrey8> grey = grey8FromArray(array, name)) return std::move(*grey);
  checkPngArray(array, name, PNG_WRITE_ARRAYS);
  const int w = int(array.shape(1)), h = int(array.shape(0));
  if (array.ndim() == 2) return ImageGrey16{w, h, valuesOf<uint16_t>(array, name)};
  if (array.shape(2) == 4) return ImageRGBA{w, h, valuesOf<uint8_t>(array, name)};
  Image image;
  image.width = w;
  image.height = h;
  image.rgb = valuesOf<uint8_t>(array, name);
  return image;
}

std::vector<uint8_t> encodedPng(const PngImage& pixels, int level, const char* name) {
  std::vector<uint8_t> png;
  bool noMemory = false;
  {
    const py::gil_scoped_release release;
    try {
      png = std::visit([&](const auto& any) { return encodePng(any, level); }, pixels);
    } catch (const std::bad_alloc&) {
      noMemory = true;
    }
  }
  if (noMemory) {
    const auto [w, h] = std::visit([](const auto& any) { return std::pair(any.width, any.height); }, pixels);
    raiseMemoryError(std::string(name) + ": no memory to encode its " + std::to_string(w) + " x " + std::to_string(h) + " PNG");
  }
  return png;
}

}  // namespace phongvk::python
