// memory_limit.h — the memory a scene may take: one limit for the whole process, read by every
// check that refuses work before it allocates (the scene's estimate, prepare/memory_estimate.h; a
// texture's pixels before they are decoded, image/texture_decode.h).
#pragma once

#include <cstdint>
#include <string>

namespace phongvk {

// The machine's physical memory, or PHONGVK_MAX_MEMORY_GB (a number of GiB, to raise or lower it),
// or what setSceneMemoryLimit set (0: back to those).
// Throws SceneError for a PHONGVK_MAX_MEMORY_GB that parseMemoryLimit refuses.
uint64_t sceneMemoryLimit();
void setSceneMemoryLimit(uint64_t bytes);

// The smallest limit that can be set, in GiB (about 1 MiB): below it no scene fits.
inline constexpr double MIN_MEMORY_GIB = 0.001;

// A limit in GiB as text ("4", "0.5", "1e3") in bytes; a finite value too large for 64 bits
// (1e11 GiB) is no limit. Throws SceneError "<what> is '<text>': expected a number of GiB, at
// least 0.001 ..." for anything else: empty, not a number, NaN, infinite (inf, 1e400), below
// MIN_MEMORY_GIB.
uint64_t parseMemoryLimit(const std::string& text, const std::string& what);

}  // namespace phongvk
