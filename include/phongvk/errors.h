// errors.h — the failures phongvk reports as exceptions, one type per exit code of the CLI
// (README "Exit codes"). Anything else thrown is a std::runtime_error with a message that names
// the cause (a device limit, a Vulkan call that failed).
#pragma once

#include "phongvk/export.h"

#include <cstddef>
#include <stdexcept>

namespace phongvk {

// Objects and arrays nest at most this deep in a scene (a scene file needs 5; Python dicts given to
// scene_from_dict likewise); deeper is a SceneError before anything is built (a 200 KB file of
// 100,000 brackets would otherwise cost gigabytes, a deep dict the interpreter's stack).
inline constexpr size_t MAX_JSON_DEPTH = 64;

// A scene that cannot be loaded or built. what() names the file, the JSON path and, for a mesh,
// the inner file and line: "scenes/a.json: objects[2].material.ks: must be >= 0, got -1".
class PHONGVK_API SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// An output file that cannot be written (missing folder, permissions, a FIFO in the way). Nothing
// partial is left behind.
class PHONGVK_API OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Writing an output file failed on the way (a full disk, a file-size limit, /dev/full); the
// message has the system's reason. Nothing partial is left behind.
class PHONGVK_API OutputWriteError : public OutputError {
 public:
  using OutputError::OutputError;
};

// No usable Vulkan driver or device (or not the one asked for); what() lists every device and
// what it lacks.
class PHONGVK_API NoDeviceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace phongvk
