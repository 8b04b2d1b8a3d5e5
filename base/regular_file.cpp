// regular_file.cpp — see regular_file.h.
#include "base/regular_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace phongvk {
namespace {

std::string kindOf(mode_t mode) {
  if (S_ISDIR(mode)) return std::strerror(EISDIR);
  if (S_ISFIFO(mode)) return "a FIFO (named pipe), not a regular file";
  if (S_ISCHR(mode)) return "a character device, not a regular file";
  if (S_ISBLK(mode)) return "a block device, not a regular file";
  if (S_ISSOCK(mode)) return "a socket, not a regular file";
  return "not a regular file";
}

}  // namespace

std::string printablePath(const std::string& path) {
  std::string text;
  for (char c : path) text += c == '\0' ? std::string("\\0") : std::string(1, c);
  return text;
}

std::optional<RegularFile> RegularFile::open(const std::string& path, std::string& why) {
  if (path.find('\0') != std::string::npos) {  // the system would open the path up to it: another file
    why = "the path contains a NUL character";
    return std::nullopt;
  }
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);
  if (fd < 0) {
    why = std::strerror(errno);
    return std::nullopt;
  }
  struct stat info;
  if (::fstat(fd, &info) != 0 || !S_ISREG(info.st_mode)) {
    why = S_ISREG(info.st_mode) ? std::strerror(errno) : kindOf(info.st_mode);
    ::close(fd);
    return std::nullopt;
  }
  // Regular files never block; blocking reads again, as every reader expects.
  ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
  return RegularFile(fd, uint64_t(info.st_size));
}

RegularFile::~RegularFile() {
  if (fd_ >= 0) ::close(fd_);
}

RegularFile::RegularFile(RegularFile&& other) noexcept : fd_(other.fd_), size_(other.size_) { other.fd_ = -1; }

std::string RegularFile::read(uint64_t max) const {
  const uint64_t want = max == 0 || max > size_ ? size_ : max;
  std::string bytes(size_t(want), '\0');
  size_t got = 0;
  while (got < bytes.size()) {
    const ssize_t n = ::pread(fd_, bytes.data() + got, bytes.size() - got, off_t(got));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;  // the file shrank meanwhile: what is there
    got += size_t(n);
  }
  bytes.resize(got);
  return bytes;
}

std::optional<std::string> unreadableReason(const std::string& path) {
  std::string why;
  if (RegularFile::open(path, why)) return std::nullopt;
  return why;
}

}  // namespace phongvk
