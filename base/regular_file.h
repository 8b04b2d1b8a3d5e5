// regular_file.h — the one way phongvk opens a file it reads (a scene, a mesh, an OBJ material
// library, a glTF buffer): only a regular file, opened so that nothing can block or run forever.
// A FIFO would block the open or the read until a writer came; a character device (/dev/zero,
// /dev/urandom) would never end; a folder has no bytes.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace phongvk {

// A read-only descriptor of the regular file at `path`, closed with the object. Opened with
// O_NONBLOCK (a FIFO's open returns at once) and checked with fstat before a byte is read.
// `path` for a message: a NUL in it written \0 (a message is read up to its first NUL).
std::string printablePath(const std::string& path);

class RegularFile {
 public:
  // The file, or std::nullopt with `why` set: the system's reason ("No such file or directory",
  // "Is a directory"), or what else it is ("a FIFO (named pipe), not a regular file", "a character
  // device, not a regular file", ...).
  static std::optional<RegularFile> open(const std::string& path, std::string& why);
  ~RegularFile();
  RegularFile(RegularFile&& other) noexcept;
  RegularFile& operator=(RegularFile&&) = delete;
  RegularFile(const RegularFile&) = delete;

  int fd() const { return fd_; }
  uint64_t size() const { return size_; }
  // Up to `max` bytes from the start, or the whole file when max is 0.
  std::string read(uint64_t max = 0) const;

 private:
  RegularFile(int fd, uint64_t size) : fd_(fd), size_(size) {}
  int fd_ = -1;
  uint64_t size_ = 0;
};

// Why `path` cannot be read as a regular file, or std::nullopt when it can.
std::optional<std::string> unreadableReason(const std::string& path);

}  // namespace phongvk
