// output_memory.cpp — see output_memory.h.
#include "tools/output_memory.h"

#include "base/memory_text.h"
#include "phongvk/phongvk.h"

namespace phongvk {

void checkOutputMemory(const std::string& path, const std::string& what, uint64_t bytes, const std::string& detail,
                       const std::string& remedy) {
  const uint64_t limit = memoryLimit();
  if (bytes > limit) throw SceneError(memoryMessage(path, what, bytes, limit, detail, remedy));
}

}  // namespace phongvk
