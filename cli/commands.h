// commands.h — the phongvk subcommands; main.cpp parses the arguments and calls these. Each runs
// on the public API (include/phongvk) only.
#pragma once

#include "phongvk/phongvk.h"

#include <string>
#include <vector>

namespace phongvk::cli {

// Exit codes, documented in docs/CLI.md "Exit codes".
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
  std::string maxMemoryGb;  // --max-memory-gb: the scene memory limit in GiB (empty: the default, setMemoryLimit)
  bool validate = false;
  int pngLevel = PNG_LEVEL_DEFAULT;  // deflate level of every PNG the command writes
  std::string shading;  // --shading, --specular, --samples: override the scene's "render" ("", 0: its own)
  std::string specular;
  int samples = 0;
  std::string up;       // --up y|z: a model file alone stood up along this axis ("": its format's usual one)
  std::string projection;  // --projection perspective|orthographic: a model file alone's fitted camera ("": perspective)
  bool noFileLights = false;  // --no-file-lights: a glTF file alone lit from the camera, not by its own lights
  bool fileLightShadows = false;  // --file-light-shadows: a glTF file alone: its own lights cast shadows
};

// --up and --projection as the library takes them.
LoadOptions loadOptions(const ViewOptions& options);  // and sets --max-memory-gb, before any file is read

struct RenderOptions : ViewOptions {
  std::string output;
  std::string backend = "gpu";  // gpu (compute) | cpu (reference) | graphics (graphics pipeline; also "raster")
  int repeat = 0;               // > 0: time this many frames after a warm-up
  bool mpi = false;             // --mpi: this process renders its share of the scene (render_mpi.cpp)
  bool rgba = false;            // --rgba: -o is RGBA, alpha from coverage (render_outputs.h)
  std::string depth;            // --depth FILE (.png or .npy; "": none)
  std::string ids;              // --ids FILE: object ids (.png or .npy; "": none)
  std::string normals;          // --normals FILE: camera-space normals (.png or .npy; "": none)
  std::string lights;           // --lights FILE: how many lights reach each pixel (.png or .npy; "": none)
};

struct DiffOptions : ViewOptions {
  std::string heatmap;          // optional PNG
  double tolerance = 1;         // max allowed channel difference, in 8-bit units
  std::vector<int> devices;     // --devices: these devices each against the reference (empty: --device's)
};

struct SequenceOptions : ViewOptions {
  std::string outputDir;
  std::string frames = ":";  // START:END[:STEP], half-open like a Python slice; ":" is every frame
  std::string sheet;         // contact sheet PNG, optional
  int thumbnailWidth = 160;  // on the sheet; frames are box-filtered down to it, never enlarged
  bool skipExisting = false; // --skip-existing: keep frames an earlier run wrote whole (pngIsComplete)
  std::string backend = "gpu";
};

int runRender(const RenderOptions& options);     // render.cpp
int runRenderMpi(const RenderOptions& options);  // render_mpi.cpp: under mpirun, one process of several
int runDiff(const DiffOptions& options);         // diff.cpp
int runSequence(const SequenceOptions& options); // sequence.cpp
int runDevices();                                // devices.cpp

}  // namespace phongvk::cli
