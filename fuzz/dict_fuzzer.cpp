// dict_fuzzer.cpp — libFuzzer target for scene_from_dict's path (scripts/fuzz.sh runs it): a Python
// value built from the bytes, written as JSON by python/json_writer.h (the module's own code), read
// by parseScene as scene_from_dict does, in an interpreter embedded once per process.
//
// The bytes are a program for a small stack machine (Op below), so that every input builds some
// value: dicts, lists, tuples, str (with lone surrogates), int (up to 2^131072), float (nan, inf),
// bool, None, numpy arrays and scalars of many dtypes, values JSON has no form for, the same
// object in two places, deep nesting and containers that hold themselves. The value on top of the
// stack at the end is written. Operands past the end of the input read as 0. The machine bounds
// what it builds (kMaxStack, kMaxIntBits, kMaxArrayValues) so that a hang is the writer's or the
// loader's, not its own.
//
// Any program must either give a Scene or throw SceneError: no crash, no sanitizer report, no hang,
// no leak, no other exception. That includes Python's: scene_from_dict promises SceneError at the
// JSON path for any bad value, so a Python exception out of the writer (error_already_set, say from
// numpy's item() or tolist()) or a pybind11::cast_error is a finding, not an answer.
#include "python/json_writer.h"

#include <phongvk/phongvk.h>

#include <pybind11/embed.h>
#include <sanitizer/lsan_interface.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <string>
#include <vector>

namespace {

namespace py = pybind11;
using namespace phongvk;

// Debian's interpreter (PHONGVK_PYTHON, whose prefix has Debian's numpy), set up for fuzzing:
// - its allocator is malloc, not pymalloc: ASan then sees every object (an overflow, a use after
//   free), and LSan the memory objects point to, which pymalloc's arenas (mmap) would hide from it
//   and report as leaked;
// - isolated from the environment (PYTHONPATH, PYTHONHOME, the user's site-packages), so a run
//   reproduces anywhere;
// - no signal handlers: libFuzzer's (SIGINT, and SIGALRM for -timeout) stay in place;
// - warnings ignored: numpy's overflow warnings would fill the log.
class Python {
 public:
  Python() : interpreter_(configure(config_), 0, nullptr, false) {
    py::module_::import("warnings").attr("simplefilter")("ignore");
    py::module_::import("json");  // the writer's, imported at start-up (LLVMFuzzerInitialize says why)
    numpy = py::module_::import("numpy");
    builtins = py::module_::import("builtins");
    collections = py::module_::import("collections");
  }

  py::module_ numpy, builtins, collections;

 private:
  static PyConfig* configure(PyConfig& config) {
    PyPreConfig pre;
    PyPreConfig_InitIsolatedConfig(&pre);
    pre.allocator = PYMEM_ALLOCATOR_MALLOC;
    check(Py_PreInitialize(&pre));
    PyConfig_InitIsolatedConfig(&config);
    config.install_signal_handlers = 0;
    check(PyConfig_SetBytesString(&config, &config.program_name, PHONGVK_PYTHON));
    return &config;
  }
  static void check(PyStatus status) {
    if (PyStatus_Exception(status)) Py_ExitStatusException(status);
  }

  PyConfig config_;  // before the interpreter, which is made from it
  py::scoped_interpreter interpreter_;
};

// Started once and never finalized: the process's end frees it all, and pybind11 2.10's
// finalize_interpreter leaks 8 bytes (its local_internals) that LSan's check at exit would report.
Python& embeddedPython() {
  static Python* const instance = new Python;
  return *instance;
}

enum class Op : uint8_t {
  None,
  False,
  True,
  Int8,      // 1 byte, signed
  Int64,     // 8 bytes, signed little-endian
  BigInt,    // n (1 byte), then n bytes: a signed little-endian integer
  Shift,     // k (2 bytes): the int on top shifted left k bits, up to 2^17 bits (past 4300 digits)
  Float,     // 8 bytes: a double's bits (nan, inf, subnormals)
  Str,       // n (1 byte), then n bytes of UTF-8 (bytes that are not: lone surrogates)
  List,      // k (1 byte): the top k values (fewer if the stack has fewer) as a list, deepest first
  Tuple,     // k (1 byte): likewise as a tuple
  Dict,      // k (1 byte): the top 2k values as key, value pairs, deepest first
  Append,    // pops a value into the container below: a list appends it, a dict maps str(len) to it
  Recurse,   // the container on top holds itself: a list appends itself, a dict maps "self" to itself
  Pick,      // k (1 byte): the value k below the top (0: the top) once more: one object in two places
  Array,     // dtype (1 byte, kDtypes): numpy.asarray(top, dtype)
  Scalar,    // dtype (1 byte, kDtypes): the first element of that array, a numpy scalar
  Other,     // which (1 byte): bytes, complex, set, object(), an empty OrderedDict
  Count
};

// "" lets numpy choose. longdouble and clongdouble have no Python type for item() to give.
const char* const kDtypes[] = {"", "float64", "float32", "float16", "longdouble", "clongdouble", "int8",
                               "int64", "uint64", "bool", "complex128", "object", "U", "S", "datetime64[s]"};

constexpr size_t kMaxStack = 1024;
constexpr size_t kMaxArrayValues = 4096;
constexpr size_t kMaxIntBits = size_t(1) << 17;

class Machine {
 public:
  Machine(const uint8_t* data, size_t size) : data_(data), size_(size) {}

  // The value the program builds, or none for a program that leaves nothing.
  py::object run() {
    while (at_ < size_) {
      const Op op = Op(next() % uint8_t(Op::Count));
      try {
        step(op);
      } catch (const py::error_already_set&) {
        // Python refused the operation (an unhashable key, a ragged array): it is skipped.
      }
      if (stack_.size() > kMaxStack) stack_.erase(stack_.begin(), stack_.end() - kMaxStack);
    }
    return stack_.empty() ? py::object() : stack_.back();
  }

 private:
  uint8_t next() { return at_ < size_ ? data_[at_++] : 0; }

  // The next n bytes (fewer at the end of the input).
  std::string bytes(size_t n) {
    n = std::min(n, size_ - at_);
    std::string s(reinterpret_cast<const char*>(data_ + at_), n);
    at_ += n;
    return s;
  }

  template <typename T>
  T number() {
    std::string s = bytes(sizeof(T));
    s.resize(sizeof(T), '\0');
    T value;
    std::memcpy(&value, s.data(), sizeof value);
    return value;
  }

  // Whether `v` holds at most `budget` values, counting each time a list or tuple is met: numpy's
  // asarray walks them all, and a list that holds one list twice, 30 deep, has 2^30 (the harness's
  // hang, not a finding). A list that holds itself runs out of budget.
  bool fewValues(const py::handle& v, size_t& budget) const {
    if (budget == 0) return false;
    --budget;
    if (py::isinstance(v, embeddedPython().numpy.attr("ndarray"))) {
      const size_t size = v.attr("size").cast<size_t>();
      if (size > budget) return false;
      budget -= size;
    }
    if (py::isinstance<py::list>(v) || py::isinstance<py::tuple>(v)) {
      for (const py::handle item : py::reinterpret_borrow<py::sequence>(v))
        if (!fewValues(item, budget)) return false;
    }
    return true;
  }

  // Whether `v` is, or its lists and tuples hold, an array of byte strings (dtype kind 'S'). Debian
  // 12's numpy 1.24 raises its parse error for such an array cast to datetime64 with the GIL
  // released, and crashes the interpreter (`np.array([b'x']).astype('datetime64[s]')` does, in
  // plain python3): numpy's bug, not the writer's, so the machine does not ask for that cast. Only
  // called on values fewValues accepted, which are finite.
  bool holdsByteStrings(const py::handle& v) const {
    if (py::isinstance(v, embeddedPython().numpy.attr("ndarray")))
      return v.attr("dtype").attr("kind").cast<std::string>() == "S";
    if (py::isinstance<py::list>(v) || py::isinstance<py::tuple>(v)) {
      for (const py::handle item : py::reinterpret_borrow<py::sequence>(v))
        if (holdsByteStrings(item)) return true;
    }
    return false;
  }

  // The top n values, removed from the stack, deepest first.
  std::vector<py::object> take(size_t n) {
    n = std::min(n, stack_.size());
    std::vector<py::object> top(stack_.end() - std::ptrdiff_t(n), stack_.end());
    stack_.resize(stack_.size() - n);
    return top;
  }

  void step(Op op) {
    Python& p = embeddedPython();
    switch (op) {
      case Op::None: return push(py::none());
      case Op::False: return push(py::bool_(false));
      case Op::True: return push(py::bool_(true));
      case Op::Int8: return push(py::int_(int8_t(next())));
      case Op::Int64: return push(py::int_(number<int64_t>()));
      case Op::BigInt: {
        const py::bytes b(bytes(next()));
        return push(p.builtins.attr("int").attr("from_bytes")(b, "little", py::arg("signed") = true));
      }
      case Op::Shift: {
        const size_t k = number<uint16_t>();
        if (stack_.empty() || !PyLong_CheckExact(stack_.back().ptr())) return;
        if (stack_.back().attr("bit_length")().cast<size_t>() + k > kMaxIntBits) return;
        stack_.back() = stack_.back().attr("__lshift__")(k);
        return;
      }
      case Op::Float: return push(py::float_(number<double>()));
      case Op::Str: {
        const std::string s = bytes(next());
        PyObject* str = PyUnicode_DecodeUTF8(s.data(), Py_ssize_t(s.size()), "surrogateescape");
        if (!str) throw py::error_already_set();
        return push(py::reinterpret_steal<py::object>(str));
      }
      case Op::List: {
        py::list list;
        for (py::object& v : take(next())) list.append(v);
        return push(list);
      }
      case Op::Tuple: {
        const std::vector<py::object> items = take(next());
        py::tuple tuple(items.size());
        for (size_t i = 0; i < items.size(); ++i) tuple[i] = items[i];
        return push(tuple);
      }
      case Op::Dict: {
        const size_t pairs = std::min(size_t(next()), stack_.size() / 2);
        py::dict dict;
        for (size_t i = stack_.size() - 2 * pairs; i < stack_.size(); i += 2) dict[stack_[i]] = stack_[i + 1];
        take(2 * pairs);  // only once every key was hashable
        return push(dict);
      }
      case Op::Append: {
        if (stack_.size() < 2) return;
        const py::object container = stack_[stack_.size() - 2];
        if (py::isinstance<py::list>(container)) {
          py::reinterpret_borrow<py::list>(container).append(stack_.back());
        } else if (py::isinstance<py::dict>(container)) {
          const py::dict dict = py::reinterpret_borrow<py::dict>(container);
          dict[py::str(std::to_string(dict.size()))] = stack_.back();
        } else {
          return;
        }
        stack_.pop_back();
        return;
      }
      case Op::Recurse: {
        if (stack_.empty()) return;
        const py::object& top = stack_.back();
        if (py::isinstance<py::list>(top)) py::reinterpret_borrow<py::list>(top).append(top);
        if (py::isinstance<py::dict>(top)) py::reinterpret_borrow<py::dict>(top)["self"] = top;
        return;
      }
      case Op::Pick: {
        const size_t k = next();
        if (k < stack_.size()) push(stack_[stack_.size() - 1 - k]);
        return;
      }
      case Op::Array:
      case Op::Scalar: {
        const char* dtype = kDtypes[next() % std::size(kDtypes)];
        size_t budget = kMaxArrayValues;
        if (stack_.empty() || !fewValues(stack_.back(), budget)) return;
        if (std::strncmp(dtype, "datetime64", 10) == 0 && holdsByteStrings(stack_.back())) return;
        const py::object type = *dtype ? py::object(py::str(dtype)) : py::object(py::none());
        py::object array = p.numpy.attr("asarray")(stack_.back(), type);
        if (op == Op::Scalar) array = array.attr("ravel")()[py::int_(0)];  // IndexError when empty
        stack_.back() = array;
        return;
      }
      case Op::Other: {
        switch (next() % 5) {
          case 0: return push(py::bytes("bytes"));
          case 1: return push(p.builtins.attr("complex")(1.0, -2.0));
          case 2: return push(py::set());
          case 3: return push(p.builtins.attr("object")());
          default: return push(p.collections.attr("OrderedDict")());
        }
      }
      case Op::Count: return;
    }
  }

  void push(py::object value) { stack_.push_back(std::move(value)); }

  const uint8_t* data_;
  size_t size_;
  size_t at_ = 0;
  std::vector<py::object> stack_;
};

}  // namespace

// CPython's start-up and numpy's import leave objects nothing points to (Cython's code objects among
// them), once per process. LSan is told to ignore what they allocate, and only that: unlike
// ASAN_OPTIONS=detect_leaks=0 or a suppression of libpython's frames, a leak made while fuzzing (an
// object the writer never releases) is still reported, by LSan's check at exit (scripts/fuzz.sh
// says why libFuzzer's check after each input is off for this target).
extern "C" int LLVMFuzzerInitialize(int*, char***) {
  const __lsan::ScopedDisabler startUp;
  embeddedPython();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const py::object value = Machine(data, size).run();
  if (!value) return 0;
  try {
    parseScene(python::JsonWriter("").write(value), "", ".", true);
  } catch (const SceneError&) {
    // rejected at its JSON path: the expected outcome for most programs
  }
  return 0;
}
