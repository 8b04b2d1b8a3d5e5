// output_file.cpp — see output_file.h.
#include "image/output_file.h"

#include "phongvk/errors.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

namespace phongvk {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void refuse(const std::string& path, const std::string& why) {
  throw OutputError("cannot write '" + path + "': " + why);
}

[[noreturn]] void writeFailed(const std::string& path, int error) {
  throw OutputWriteError("cannot write '" + path + "': " + std::strerror(error));
}

// The file `path` names, through any symbolic links (a dangling link names the file it would
// create). Refuses a loop of links.
// Refuses a name too long for the system with its reason.
fs::path resolved(const std::string& path) {
  fs::path target(path);
  std::error_code error;
  for (int hops = 0;; ++hops) {
    const fs::file_status status = fs::symlink_status(target, error);
    if (error == std::errc::filename_too_long) refuse(path, error.message());  // the rest: the checks below say it better
    if (!fs::is_symlink(status)) break;
    if (hops == 40) refuse(path, "too many levels of symbolic links");
    const fs::path link = fs::read_symlink(target, error);
    if (error) refuse(path, error.message());
    target = link.is_absolute() ? link : target.parent_path() / link;
  }
  return target;
}

// What kind of thing is at `target`, for a message; empty for a regular file, a character device
// (written straight into) or nothing.
std::string unwritableKind(const fs::path& target) {
  struct stat info;
  if (::stat(target.c_str(), &info) != 0) return "";
  if (S_ISDIR(info.st_mode)) return "it is a folder";
  if (S_ISFIFO(info.st_mode)) return "it is a FIFO (named pipe), not a regular file; use -o - to write to standard output";
  if (S_ISSOCK(info.st_mode)) return "it is a socket, not a regular file; use -o - to write to standard output";
  if (S_ISBLK(info.st_mode)) return "it is a block device, not a regular file";
  return "";
}

bool isCharacterDevice(const fs::path& target) {
  struct stat info;
  return ::stat(target.c_str(), &info) == 0 && S_ISCHR(info.st_mode);
}

// Writes all of `bytes` to `fd`; the errno of the first failure, or 0.
int writeAll(int fd, const std::vector<uint8_t>& bytes) {
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    done += size_t(n);
  }
  return 0;
}

void writeToStdout(const std::vector<uint8_t>& bytes) {
  std::fflush(stdout);  // what was printed before goes first
  if (const int error = writeAll(STDOUT_FILENO, bytes)) writeFailed("-", error);
}

void writeToDevice(const std::string& path, const fs::path& target, const std::vector<uint8_t>& bytes) {
  const int fd = ::open(target.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) writeFailed(path, errno);
  const int error = writeAll(fd, bytes);
  const int closed = ::close(fd) == 0 ? 0 : errno;
  if (error || closed) writeFailed(path, error ? error : closed);
}

// A temporary file in the target's folder: a short name, so that a target name of up to NAME_MAX
// characters still has one; unique per process and call.
fs::path temporaryBeside(const fs::path& target) {
  static std::atomic<unsigned> counter{0};
  return target.parent_path() / (".phongvk-" + std::to_string(::getpid()) + "-" + std::to_string(counter++) + ".tmp");
}

void writeAtomically(const std::string& path, const fs::path& target, const std::vector<uint8_t>& bytes) {
  const fs::path temp = temporaryBeside(target);
  const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) writeFailed(path, errno);
  int error = writeAll(fd, bytes);
  if (::close(fd) != 0 && !error) error = errno;
  if (!error && ::rename(temp.c_str(), target.c_str()) != 0) error = errno;
  if (error) {
    ::unlink(temp.c_str());
    writeFailed(path, error);
  }
}

}  // namespace

void checkOutputPath(const std::string& path) {
  if (path.empty() || path == "-") return;
  const fs::path target = resolved(path);
  fs::path folder = target.parent_path();
  if (folder.empty()) folder = ".";
  if (fs::exists(folder) && !fs::is_directory(folder)) refuse(path, "'" + folder.string() + "' is a file, not a folder");
  if (!fs::is_directory(folder)) refuse(path, "folder '" + folder.string() + "' does not exist");
  const std::string kind = unwritableKind(target);
  if (!kind.empty()) refuse(path, kind);
  if (isCharacterDevice(target)) return;  // written in place: its folder need not be writable
  if (::access(folder.c_str(), W_OK) != 0) refuse(path, "folder '" + folder.string() + "' is not writable");
}

void writeOutputFile(const std::string& path, const std::vector<uint8_t>& bytes) {
  if (path == "-") return writeToStdout(bytes);
  checkOutputPath(path);
  const fs::path target = resolved(path);
  if (isCharacterDevice(target)) return writeToDevice(path, target, bytes);
  writeAtomically(path, target, bytes);
}

}  // namespace phongvk
