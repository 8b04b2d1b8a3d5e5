// cli_support.h — what the phongvk subcommands share: failures mapped to exit codes, output
// checks before any work, timing, and the GPU backend's context + renderer.
#pragma once

#include "host/app.h"
#include "host/context.h"
#include "host/gpu_renderer.h"

#include <chrono>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>

namespace phongvk {

// A command-line value that is well formed for the parser but wrong for this input, e.g.
// --frames 0:200 for a sequence of 120 frames. Exits with EXIT_BAD_INPUT.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start);

// Runs a command, turning each kind of failure into its message on stderr and its exit code.
int guarded(const std::function<int()>& command);

// Fails before any rendering when the output cannot be written, so no time is wasted and no
// partial file appears.
void checkWritable(const std::string& path);

// The GPU backend: a context and a renderer holding the uploaded scene.
struct GpuSession {
  VulkanContext context;
  std::optional<GpuRenderer> renderer;

  explicit GpuSession(const ViewOptions& options);  // the context only; load() adds a renderer
  GpuSession(const ViewOptions& options, const SceneData& data);
  ~GpuSession();

  // Replaces the renderer with one holding `data` (new geometry is a new upload).
  void load(const SceneData& data);

  GpuSession(const GpuSession&) = delete;
  GpuSession& operator=(const GpuSession&) = delete;
};

}  // namespace phongvk
