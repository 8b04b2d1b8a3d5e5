// app.h — what the phongvk subcommands do; main.cpp only parses arguments and calls these.
#pragma once

#include <string>

namespace phongvk {

// Exit codes, documented in the README.
enum ExitCode : int {
  EXIT_OK = 0,
  EXIT_DIFF_ABOVE_TOLERANCE = 1,
  EXIT_BAD_INPUT = 2,   // scene errors, bad options, unwritable output
  EXIT_NO_DEVICE = 3,   // no usable Vulkan device
  EXIT_FAILURE_OTHER = 4,
};

struct ViewOptions {
  std::string scene;
  int width = 0;        // with height: overrides the scene camera's image size
  int height = 0;
  int device = -1;      // Vulkan device index, -1 = best
  bool validate = false;
};

struct RenderOptions : ViewOptions {
  std::string output;
  std::string backend = "gpu";  // gpu (compute) | cpu (reference) | raster (graphics pipeline)
  int repeat = 0;               // > 0: time this many frames after a warm-up
};

struct DiffOptions : ViewOptions {
  std::string heatmap;          // optional PNG
  double tolerance = 1;         // max allowed channel difference, in 8-bit units
};

int runRender(const RenderOptions& options);
int runDiff(const DiffOptions& options);
int runDevices();

}  // namespace phongvk
