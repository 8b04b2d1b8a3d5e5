// json_writer.h — Python values as JSON text, for the scene loader (scene_from_dict). Header-only,
// so that the Python-dict fuzz target (fuzz/dict_fuzzer.cpp) runs the very code the module runs.
#pragma once

#include <phongvk/phongvk.h>

#include <pybind11/pybind11.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace phongvk::python {

namespace py = pybind11;

// Dicts, lists and tuples, strings, numbers (numpy's too, and arrays), booleans, None. JSON has no
// NaN or infinity, so such a number is reported here, at its JSON path, in the words the scene
// loader uses for a non-finite number. Hostile input is refused at its path with SceneError, never
// followed into a crash: a container nested deeper than the scene loader's MAX_JSON_DEPTH, or one
// that contains itself (a cycle would recurse forever).
class JsonWriter {
 public:
  // The most values one call writes: a list used in two places is written twice, so 40 levels of
  // `x = [x, x]` (no cycle, well within the depth limit) would ask for 2^40. Four million numbers
  // are a 1.3M-point polyhedron; larger data goes in as a mesh file or numpy arrays (add_mesh).
  static constexpr size_t MAX_VALUES = size_t(1) << 22;

  explicit JsonWriter(std::string name)
      : name_(std::move(name)),
        numpyGeneric_(py::module_::import("numpy").attr("generic")),
        numpyArray_(py::module_::import("numpy").attr("ndarray")),
        dumps_(py::module_::import("json").attr("dumps")) {}

  std::string write(const py::handle& value) {
    value_(value, "");
    return out_;
  }

 private:
  // The containers from the top down to the one being written.
  class Enter {
   public:
    Enter(JsonWriter& w, const py::handle& container, const std::string& path) : w_(w) {
      if (w.open_.size() >= MAX_JSON_DEPTH)
        w.fail(path, "nested deeper than " + std::to_string(MAX_JSON_DEPTH) + " levels of dicts and lists");
      if (std::find(w.open_.begin(), w.open_.end(), container.ptr()) != w.open_.end())
        w.fail(path, "contains itself (a dict or list that holds itself cannot be written as JSON)");
      w.open_.push_back(container.ptr());
    }
    ~Enter() { w_.open_.pop_back(); }
    Enter(const Enter&) = delete;
    Enter& operator=(const Enter&) = delete;

   private:
    JsonWriter& w_;
  };

  void value_(const py::handle& v, const std::string& path) {
    if (++values_ > MAX_VALUES)
      fail(path, "the scene holds more than " + std::to_string(MAX_VALUES) +
                     " values (a list or dict used in several places is written at each); pass large data as a mesh file "
                     "or as numpy arrays to add_mesh");
    if (v.is_none()) {
      out_ += "null";
    } else if (py::isinstance<py::bool_>(v)) {
      out_ += v.cast<bool>() ? "true" : "false";
    } else if (py::isinstance<py::int_>(v) || py::isinstance<py::float_>(v)) {
      number(v, path);
    } else if (py::isinstance(v, numpyGeneric_)) {
      // A numpy scalar as the Python value it holds; a long double or a datetime holds itself.
      const py::object item = v.attr("item")();
      if (py::isinstance(item, numpyGeneric_)) notJson(v, path);
      value_(item, path);
    } else if (py::isinstance<py::str>(v)) {
      out_ += dumps_(v).cast<std::string>();
    } else if (py::isinstance<py::dict>(v)) {
      object(py::reinterpret_borrow<py::dict>(v), path);
    } else if (py::isinstance(v, numpyArray_)) {
      value_(v.attr("tolist")(), path);
    } else if (py::isinstance<py::list>(v) || py::isinstance<py::tuple>(v)) {
      array(py::reinterpret_borrow<py::sequence>(v), path);
    } else {
      notJson(v, path);
    }
  }

  [[noreturn]] void notJson(const py::handle& v, const std::string& path) const {
    fail(path, "must be a JSON value (dict, list, str, number, bool or None), got " + typeName(v));
  }

  // Named by type, not by value: the repr of an int of 5,000 digits raises, and one of a long
  // string is no help in a message.
  static std::string typeName(const py::handle& v) { return std::string(py::str(py::type::of(v).attr("__name__"))); }

  void number(const py::handle& v, const std::string& path) {
    if (py::isinstance<py::int_>(v) || py::isinstance<py::bool_>(v)) {
      // Python prints no int of over 4300 digits; no scene value needs more than 64 bits.
      const size_t bits = v.attr("bit_length")().cast<size_t>();
      if (bits > 64) fail(path, "must be a number a scene can hold, got an integer of " + std::to_string(bits) + " bits");
      out_ += std::string(py::str(v));
      return;
    }
    const double x = v.cast<double>();
    if (!std::isfinite(x)) fail(path, "must be finite, got " + std::string(std::isnan(x) ? "nan" : x > 0 ? "inf" : "-inf"));
    out_ += std::string(py::repr(py::float_(x)));  // the shortest text that reads back as x
  }

  void object(const py::dict& d, const std::string& path) {
    const Enter enter(*this, d, path);
    out_ += "{";
    bool first = true;
    for (const auto& [key, value] : d) {
      if (!py::isinstance<py::str>(key)) fail(path, "keys must be strings, got a key of type " + typeName(key));
      out_ += first ? "" : ", ";
      first = false;
      const std::string k = keyText(key, path);
      out_ += dumps_(key).cast<std::string>() + ": ";
      value_(value, path.empty() ? k : path + "." + k);
    }
    out_ += "}";
  }

  // A key as UTF-8; a lone surrogate ('\udcff', from a file name decoded with errors="surrogateescape")
  // has none.
  std::string keyText(const py::handle& key, const std::string& path) const {
    Py_ssize_t size = 0;
    const char* utf8 = PyUnicode_AsUTF8AndSize(key.ptr(), &size);
    if (!utf8) {
      PyErr_Clear();
      fail(path, "keys must be text that UTF-8 can hold, got " + std::string(py::repr(key)));
    }
    return std::string(utf8, size_t(size));
  }

  void array(const py::sequence& s, const std::string& path) {
    const Enter enter(*this, s, path);
    out_ += "[";
    for (size_t i = 0; i < s.size(); ++i) {
      out_ += i ? ", " : "";
      value_(s[i], path + "[" + std::to_string(i) + "]");
    }
    out_ += "]";
  }

  [[noreturn]] void fail(const std::string& path, const std::string& what) const {
    throw SceneError((name_.empty() ? "" : name_ + ": ") + (path.empty() ? "top level" : path) + ": " + what);
  }

  std::string name_;
  std::string out_;
  std::vector<PyObject*> open_;
  size_t values_ = 0;
  py::object numpyGeneric_, numpyArray_, dumps_;
};

}  // namespace phongvk::python
