// memory_text.h — the one message for memory a limit does not allow, whoever checks it (the scene's
// estimate, prepare/memory_estimate.h; a sequence's contact sheet, tools/output_memory.h).
#pragma once

#include <cstdint>
#include <string>

namespace phongvk {

// "<path>: <what> needs about N GiB (<detail>), more than the M GiB limit (by default the
// machine's memory; PHONGVK_MAX_MEMORY_GB or --max-memory-gb sets it); <remedy>", the two
// amounts with as many decimals as it takes to tell them apart. No "<path>: " for an empty path.
std::string memoryMessage(const std::string& path, const std::string& what, uint64_t bytes, uint64_t limit,
                          const std::string& detail, const std::string& remedy);

}  // namespace phongvk
