// huge_pages.h — large arrays on 2 MiB pages where the kernel offers them (Linux transparent huge
// pages, asked for per range with madvise). A mesh of millions of triangles fills hundreds of MiB
// of fresh memory, and a one-frame 4K render ~150 MiB of fresh buffers and images; on 4 KiB pages
// the kernel's page faults were a large part of both (docs/DECISIONS.md, "Huge pages for large
// meshes, images and a CPU device's buffers"). Only where a range spans whole 2 MiB pages;
// elsewhere it does nothing.
#pragma once

#include <cstddef>
#include <vector>

namespace phongvk {

// Asks for 2 MiB pages for the whole 2 MiB pages inside [data, data + bytes), before it is touched.
void adviseHugePages(const void* data, size_t bytes);

// v with room for n elements, on huge pages where possible (v's memory is untouched until then).
template <typename T>
void reserveLarge(std::vector<T>& v, size_t n) {
  if (n <= v.capacity()) return;
  std::vector<T> grown;
  grown.reserve(n);
  adviseHugePages(grown.data(), n * sizeof(T));
  grown.insert(grown.end(), v.begin(), v.end());
  v.swap(grown);
}

}  // namespace phongvk
