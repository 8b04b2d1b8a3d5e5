// version.cpp — the library's version (CMakeLists.txt project()) and the git revision it was built
// from (cmake/revision.cmake, regenerated at every build).
#include "phongvk/phongvk.h"

#include "phongvk_revision.h"

namespace phongvk {

const char* version() { return PHONGVK_VERSION_STRING; }
const char* revision() { return PHONGVK_REVISION_STRING; }

}  // namespace phongvk
