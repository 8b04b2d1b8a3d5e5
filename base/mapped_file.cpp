// mapped_file.cpp — see mapped_file.h.
#include "base/mapped_file.h"

#include "base/regular_file.h"
#include "phongvk/errors.h"

#include <sys/mman.h>

#include <cerrno>
#include <cstring>

namespace phongvk {

MappedFile::MappedFile(const std::string& path, const std::string& where) {
  std::string why;
  const std::optional<RegularFile> file = RegularFile::open(path, why);
  if (!file) throw SceneError(where + ": " + path + ": cannot open the file: " + why);
  size_ = size_t(file->size());
  if (size_ > 0) {
    data_ = ::mmap(nullptr, size_, PROT_READ, MAP_PRIVATE, file->fd(), 0);
    if (data_ == MAP_FAILED) {
      data_ = nullptr;
      throw SceneError(where + ": " + path + ": cannot read the file: " + std::strerror(errno));
    }
    ::madvise(data_, size_, MADV_SEQUENTIAL);
  }
}

MappedFile::~MappedFile() {
  if (data_) ::munmap(data_, size_);
}

}  // namespace phongvk
