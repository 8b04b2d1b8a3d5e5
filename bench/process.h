// process.h — the benchmark's commands run as processes: a shell command line timed and its
// output read, the numbers a command prints, and a scratch folder for what they write.
#pragma once

#include <filesystem>
#include <string>

namespace phongvk::bench {

struct Process {
  int status = -1;
  std::string out;  // stdout
  double seconds = 0;
};

// Runs a shell command line, its stderr discarded, and times it.
Process run(const std::string& command);

// `text` in single quotes, for a shell command line (paths without quotes of their own).
std::string quoted(const std::string& text);

// Environment assignments (each followed by a space) that put every cache a `phongvk` process
// keeps in folder `dir`: phongvk's float probe and pipeline cache and Mesa's (XDG_CACHE_HOME), and
// NVIDIA's shader cache. An empty `dir` is a new machine's first run.
std::string cachesIn(const std::string& dir);

// The number after `label` in `text`; NaN when it is not there.
double after(const std::string& text, const std::string& label);

// The number before `label` (" frames/s after the first").
double before(const std::string& text, const std::string& label);

// A new folder under the system's temporary one, removed with everything in it when it goes.
struct Scratch {
  std::filesystem::path dir;
  Scratch();
  ~Scratch();
  Scratch(const Scratch&) = delete;
  Scratch& operator=(const Scratch&) = delete;
};

}  // namespace phongvk::bench
