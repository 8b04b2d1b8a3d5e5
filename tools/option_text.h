// option_text.h — the text forms of the API's options, as the CLI's flags and the Python
// package's keyword arguments take them: --up / up=, --projection / projection=, --max-memory-gb.
// A C++ caller passes the enums and numbers themselves (phongvk.h LoadOptions, setMemoryLimit).
#pragma once

#include <phongvk/phongvk.h>

#include <cstdint>
#include <string>

namespace phongvk {

// "y" or "z"; ArgumentError "up: expected 'y' or 'z', got '...'" for anything else.
ModelUp parseModelUp(const std::string& name);

// "perspective" or "orthographic": whether it is orthographic (LoadOptions::orthographic);
// ArgumentError "projection: expected 'perspective' or 'orthographic', got '...'" for anything else.
bool parseOrthographic(const std::string& projection);

// A limit in GiB as text ("4", "0.5"), as PHONGVK_MAX_MEMORY_GB and --max-memory-gb take it, in
// bytes (a value past 64 bits is no limit). Throws SceneError "<what> is '<text>': expected a number
// of GiB, at least 0.001 ..." for anything else (empty, not a number, NaN, too small).
uint64_t memoryLimitBytes(const std::string& gib, const std::string& what);

}  // namespace phongvk
