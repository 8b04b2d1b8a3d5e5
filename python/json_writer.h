// json_writer.h — Python values as JSON text, for the scene loader (scene_from_dict). Header-only,
// so that the Python-dict fuzz target (fuzz/dict_fuzzer.cpp) runs the very code the module runs.
#pragma once

#include <phongvk/phongvk.h>

#include <pybind11/pybind11.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <variant>
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
  // What a value costs on its way into a scene, at most: its text here and its node in the scene
  // loader's tree (a float's 20 characters and a node of 16 bytes, and the arrays' spare room).
  static constexpr uint64_t BYTES_PER_VALUE = 128;

  // The most values one call writes: what fits in the memory limit (phongvk::memoryLimit()) at
  // BYTES_PER_VALUE, so any scene whose text fits is written (a mesh to_dict wrote, of any size
  // the scene held), and a list used in two places, written twice, cannot ask for 2^40 values
  // from 40 levels of `x = [x, x]` (no cycle, well within the depth limit).
  static uint64_t maxValues() { return memoryLimit() / BYTES_PER_VALUE; }

  explicit JsonWriter(std::string name)
      : name_(std::move(name)),
        maxValues_(maxValues()),
        numpyGeneric_(py::module_::import("numpy").attr("generic")),
        numpyArray_(py::module_::import("numpy").attr("ndarray")),
        dumps_(py::module_::import("json").attr("dumps")) {}

  std::string write(const py::handle& value) {
    value_(value);
    return out_;
  }

 private:
  // The containers from the top down to the one being written.
  class Enter {
   public:
    Enter(JsonWriter& w, const py::handle& container) : w_(w) {
      if (w.open_.size() >= MAX_JSON_DEPTH)
        w.fail("nested deeper than " + std::to_string(MAX_JSON_DEPTH) + " levels of dicts and lists");
      if (std::find(w.open_.begin(), w.open_.end(), container.ptr()) != w.open_.end())
        w.fail("contains itself (a dict or list that holds itself cannot be written as JSON)");
      w.open_.push_back(container.ptr());
    }
    ~Enter() { w_.open_.pop_back(); }
    Enter(const Enter&) = delete;
    Enter& operator=(const Enter&) = delete;

   private:
    JsonWriter& w_;
  };

  void value_(const py::handle& v) {
    if (++values_ > maxValues_)
      fail("the scene holds more than " + std::to_string(maxValues_) +
                     " values, the most the memory limit allows at " + std::to_string(BYTES_PER_VALUE) +
                     " bytes each (a list or dict used in several places is written at each); pass large data as a "
                     "mesh file or as numpy arrays to add_mesh");
    if (v.is_none()) {
      out_ += "null";
    } else if (py::isinstance<py::bool_>(v)) {
      out_ += v.cast<bool>() ? "true" : "false";
    } else if (py::isinstance<py::int_>(v) || py::isinstance<py::float_>(v)) {
      number(v);
    } else if (py::isinstance(v, numpyGeneric_)) {
      // A numpy scalar as the Python value it holds; a long double or a datetime holds itself.
      const py::object item = v.attr("item")();
      if (py::isinstance(item, numpyGeneric_)) notJson(v);
      value_(item);
    } else if (py::isinstance<py::str>(v)) {
      out_ += dumps_(v).cast<std::string>();
    } else if (py::isinstance<py::dict>(v)) {
      object(py::reinterpret_borrow<py::dict>(v));
    } else if (py::isinstance(v, numpyArray_)) {
      value_(v.attr("tolist")());
    } else if (py::isinstance<py::list>(v) || py::isinstance<py::tuple>(v)) {
      array(py::reinterpret_borrow<py::sequence>(v));
    } else {
      notJson(v);
    }
  }

  [[noreturn]] void notJson(const py::handle& v) const {
    fail("must be a JSON value (dict, list, str, number, bool or None), got " + typeName(v));
  }

  // Named by type, not by value: the repr of an int of 5,000 digits raises, and one of a long
  // string is no help in a message.
  static std::string typeName(const py::handle& v) { return std::string(py::str(py::type::of(v).attr("__name__"))); }

  void number(const py::handle& v) {
    if (py::isinstance<py::int_>(v) || py::isinstance<py::bool_>(v)) {
      // Python prints no int of over 4300 digits; no scene value needs more than 64 bits.
      const size_t bits = v.attr("bit_length")().cast<size_t>();
      if (bits > 64) fail("must be a number a scene can hold, got an integer of " + std::to_string(bits) + " bits");
      out_ += std::string(py::str(v));
      return;
    }
    const double x = v.cast<double>();
    if (!std::isfinite(x)) fail("must be finite, got " + std::string(std::isnan(x) ? "nan" : x > 0 ? "inf" : "-inf"));
    out_ += std::string(py::repr(py::float_(x)));  // the shortest text that reads back as x
  }

  void object(const py::dict& d) {
    const Enter enter(*this, d);
    out_ += "{";
    bool first = true;
    for (const auto& [key, value] : d) {
      if (!py::isinstance<py::str>(key)) fail("keys must be strings, got a key of type " + typeName(key));
      out_ += first ? "" : ", ";
      first = false;
      const Step step(*this, keyText(key));
      out_ += dumps_(key).cast<std::string>() + ": ";
      value_(value);
    }
    out_ += "}";
  }

  // A key as UTF-8; a lone surrogate ('\udcff', from a file name decoded with errors="surrogateescape")
  // has none.
  std::string keyText(const py::handle& key) const {
    Py_ssize_t size = 0;
    const char* utf8 = PyUnicode_AsUTF8AndSize(key.ptr(), &size);
    if (!utf8) {
      PyErr_Clear();
      fail("keys must be text that UTF-8 can hold, got " + std::string(py::repr(key)));
    }
    return std::string(utf8, size_t(size));
  }

  void array(const py::sequence& s) {
    const Enter enter(*this, s);
    out_ += "[";
    for (size_t i = 0; i < s.size(); ++i) {
      out_ += i ? ", " : "";
      const Step step(*this, i);
      value_(s[i]);
    }
    out_ += "]";
  }

  // A key or an index on the way down to the value being written; the JSON path is made of them only
  // for a message (made for every value, it took most of a large mesh's time).
  class Step {
   public:
    template <typename KeyOrIndex>
    Step(JsonWriter& w, KeyOrIndex step) : w_(w) {
      w.steps_.emplace_back(std::move(step));
    }
    ~Step() { w_.steps_.pop_back(); }
    Step(const Step&) = delete;
    Step& operator=(const Step&) = delete;

   private:
    JsonWriter& w_;
  };

  // "objects[0].material.ks", or "top level".
  std::string path() const {
    std::string text;
    for (const auto& step : steps_) {
      // Appended piece by piece: GCC 12 warns (-Wrestrict, a known false positive) on "[" + a + "]".
      if (const size_t* index = std::get_if<size_t>(&step)) text.append("[").append(std::to_string(*index)).append("]");
      else text.append(text.empty() ? "" : ".").append(std::get<std::string>(step));
    }
    return text.empty() ? "top level" : text;
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw SceneError((name_.empty() ? "" : name_ + ": ") + path() + ": " + what);
  }

  std::string name_;
  std::string out_;
  std::vector<PyObject*> open_;
  std::vector<std::variant<std::string, size_t>> steps_;
  uint64_t maxValues_;
  uint64_t values_ = 0;
  py::object numpyGeneric_, numpyArray_, dumps_;
};

}  // namespace phongvk::python
