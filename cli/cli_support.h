// cli_support.h — what the phongvk subcommands share: failures mapped to exit codes, output
// checks before any work, loading the scene the options name, and timing.
#pragma once

#include "cli/commands.h"
#include "phongvk/phongvk.h"

#include <chrono>
#include <functional>
#include <stdexcept>
#include <string>

namespace phongvk::cli {

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

// `scene` at the size the options ask for (--width/--height) and with the render options they set
// (--shading, --specular, --samples), or as it is.
Scene sizedAsAsked(const Scene& scene, const ViewOptions& options);

// Frame `index` of `sequence` at the asked size, validated and checked against the memory limit
// (a frame that grows past it fails before frame 0 is written). Throws SceneError
// "<file>: frame N: ..." for a bad frame, naming the file and the frame once.
Scene frameAsAsked(const Scene& sequence, int index, const ViewOptions& options);

// The scene the options name, at the asked size, every frame of an animated scene validated first
// (a radius that turns negative at frame 25 fails a one-frame render as it fails the sequence).
// Throws SceneError "<file>: frame N: ..." for a bad frame.
Scene loadEveryFrameValidated(const ViewOptions& options);

// The renderer the options ask for: `backend` on options.device, validating if asked. Throws
// UsageError for --device with the reference, which uses no device.
RendererOptions rendererOptions(const ViewOptions& options, const std::string& backend);

}  // namespace phongvk::cli
