// output_memory.h — outputs the CLI makes beside a scene (a sequence's contact sheet) checked against
// the library's memory limit (phongvk.h memoryLimit), with the message the scene's own check gives.
#pragma once

#include <cstdint>
#include <string>

namespace phongvk {

// Throws SceneError "<path>: <what> needs about N GiB (<detail>), more than the M GiB limit (...);
// <remedy>" when `bytes` exceed memoryLimit().
void checkOutputMemory(const std::string& path, const std::string& what, uint64_t bytes, const std::string& detail,
                       const std::string& remedy);

}  // namespace phongvk
