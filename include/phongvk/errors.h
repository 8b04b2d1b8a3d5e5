// errors.h — the failures phongvk reports as exceptions. Every one derives from phongvk::Error, so
// one `catch (const phongvk::Error&)` serves a user; the kinds below map to the CLI's exit codes
// (docs/CLI.md "Exit codes") and to Python's exceptions. Only std::bad_alloc (memory ran out past the
// estimate) comes from elsewhere.
#pragma once

#include "phongvk/export.h"

#include <cstddef>
#include <stdexcept>

namespace phongvk {

// Objects and arrays nest at most this deep in a scene (a scene file needs 5; Python dicts given to
// scene_from_dict likewise); deeper is a SceneError before anything is built (a 200 KB file of
// 100,000 brackets would otherwise cost gigabytes, a deep dict the interpreter's stack).
inline constexpr size_t MAX_JSON_DEPTH = 64;

// The base of every phongvk failure; what() says what failed and why.
class PHONGVK_API Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A scene that cannot be loaded or built. what() names the file, the JSON path and, for a mesh,
// the inner file and line: "scenes/a.json: objects[2].material.ks: must be >= 0, got -1".
class PHONGVK_API SceneError : public Error {
 public:
  using Error::Error;
};

// A call made with an argument it cannot take: arrays of the wrong shape, an unknown backend, a
// PNG level out of range, keys asked of the graphics backend. Python: ValueError.
class PHONGVK_API ArgumentError : public Error {
 public:
  using Error::Error;
};

// An index past the end: a frame of a sequence that has fewer. Python: IndexError.
class PHONGVK_API RangeError : public ArgumentError {
 public:
  using ArgumentError::ArgumentError;
};

// The device cannot render what was asked (a buffer or loop limit a scene exceeds, a format it
// lacks), or a Vulkan call failed (vulkan/vk_check.h VulkanError, which names the call and result).
class PHONGVK_API DeviceError : public Error {
 public:
  using Error::Error;
};

// An output file that cannot be written (missing folder, permissions, a FIFO in the way). Nothing
// partial is left behind.
class PHONGVK_API OutputError : public Error {
 public:
  using Error::Error;
};

// Writing an output file failed on the way (a full disk, a file-size limit, /dev/full); the
// message has the system's reason. Nothing partial is left behind.
class PHONGVK_API OutputWriteError : public OutputError {
 public:
  using OutputError::OutputError;
};

// No usable Vulkan driver or device (or not the one asked for); what() lists every device and
// what it lacks.
class PHONGVK_API NoDeviceError : public Error {
 public:
  using Error::Error;
};

}  // namespace phongvk
