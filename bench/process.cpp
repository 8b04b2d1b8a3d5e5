// process.cpp — commands run as processes, and what they print (process.h).
#include "process.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <stdexcept>

namespace phongvk::bench {

namespace fs = std::filesystem;

Process run(const std::string& command) {
  Process p;
  const auto start = std::chrono::steady_clock::now();
  FILE* pipe = popen((command + " 2>/dev/null").c_str(), "r");
  if (pipe == nullptr) throw std::runtime_error("cannot run: " + command);
  char buffer[4096];
  for (size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) p.out.append(buffer, n);
  p.status = pclose(pipe);
  p.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return p;
}

std::string quoted(const std::string& text) { return "'" + text + "'"; }

std::string cachesIn(const std::string& dir) {
  return "XDG_CACHE_HOME=" + quoted(dir) + " __GL_SHADER_DISK_CACHE_PATH=" + quoted(dir) + " ";
}

double after(const std::string& text, const std::string& label) {
  const size_t at = text.find(label);
  double value = std::numeric_limits<double>::quiet_NaN();
  if (at == std::string::npos || std::sscanf(text.c_str() + at + label.size(), "%lf", &value) != 1) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  return value;
}

double before(const std::string& text, const std::string& label) {
  const size_t at = text.find(label);
  if (at == std::string::npos) return std::numeric_limits<double>::quiet_NaN();
  const size_t start = text.find_last_of(' ', at - 1);
  return std::strtod(text.c_str() + (start == std::string::npos ? 0 : start + 1), nullptr);
}

Scratch::Scratch() {
  std::string pattern = (fs::temp_directory_path() / "phongvk-bench-XXXXXX").string();
  if (mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("cannot make a temporary folder");
  dir = pattern;
}

Scratch::~Scratch() {
  std::error_code ignored;
  fs::remove_all(dir, ignored);
}

}  // namespace phongvk::bench
