// option_text.cpp — the options' text forms (option_text.h).
#include "tools/option_text.h"

#include "base/memory_limit.h"

namespace phongvk {

ModelUp parseModelUp(const std::string& name) {
  if (name == "y") return ModelUp::Y;
  if (name == "z") return ModelUp::Z;
  throw ArgumentError("up: expected 'y' or 'z', got '" + name + "'");
}

bool parseOrthographic(const std::string& projection) {
  if (projection == "perspective") return false;
  if (projection == "orthographic") return true;
  throw ArgumentError("projection: expected 'perspective' or 'orthographic', got '" + projection + "'");
}

uint64_t memoryLimitBytes(const std::string& gib, const std::string& what) { return parseMemoryLimit(gib, what); }

}  // namespace phongvk
