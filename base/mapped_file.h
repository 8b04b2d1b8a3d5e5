// mapped_file.h — a file's bytes, mapped read-only: a 190 MB scan is read where it lies, not
// copied into fresh memory the kernel must zero first (which took most of a load's time).
#pragma once

#include <string>
#include <string_view>

namespace phongvk {

class MappedFile {
 public:
  // Throws SceneError "<where>: <path>: <why>" when the file cannot be opened or mapped.
  MappedFile(const std::string& path, const std::string& where);
  ~MappedFile();
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;

  std::string_view bytes() const { return {static_cast<const char*>(data_), size_}; }

 private:
  void* data_ = nullptr;
  size_t size_ = 0;
};

}  // namespace phongvk
