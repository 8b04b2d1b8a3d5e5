// phongvk — headless Phong/Gouraud renderer. main parses arguments and calls cli/commands.h.
#include "cli/commands.h"
#include "phongvk/phongvk.h"
#include "tools/option_text.h"

#include <CLI/CLI.hpp>

#include <cmath>
#include <csignal>
#include <cstdio>
#include <string>

namespace {

using namespace phongvk::cli;

void addViewOptions(CLI::App* command, ViewOptions& options) {
  command->add_option("scene", options.scene, "Scene file (JSON), or a mesh file (.obj .ply .stl .gltf .glb) to view alone")->required();
  auto* width = command->add_option("--width", options.width, "Image width in pixels (with --height)")
                    ->check(CLI::Range(1, 16384));
  auto* height = command->add_option("--height", options.height, "Image height in pixels (with --width)")
                     ->check(CLI::Range(1, 16384));
  width->needs(height);
  height->needs(width);
  command->add_option("--device", options.device, "Vulkan device index (see 'phongvk devices')")
      ->check(CLI::Validator(
          [](const std::string& text) {
            int index = -1;
            return CLI::detail::lexical_cast(text, index) && index >= 0
                       ? std::string()
                       : "must be a device index, 0 or more (see 'phongvk devices'), got " + text;
          },
          "INDEX"));
  command->add_flag("--validate", options.validate, "Enable the Vulkan validation layers");
  command->add_option("--max-memory-gb", options.maxMemoryGb,
                      "Memory a scene may take, in GiB (default: the machine's memory, or PHONGVK_MAX_MEMORY_GB)")
      ->check(CLI::Validator(
          [](const std::string& text) {
            try {
              phongvk::memoryLimitBytes(text, "value");
              return std::string();
            } catch (const phongvk::SceneError& e) {
              return std::string(e.what());
            }
          },
          "GIB"));
  command->add_option("--shading", options.shading, "gouraud, flat or phong: overrides the scene's render.shading")
      ->check(CLI::IsMember({"gouraud", "flat", "phong"}));
  command->add_option("--specular", options.specular, "phong or blinn: overrides the scene's render.specular")
      ->check(CLI::IsMember({"phong", "blinn"}));
  command->add_option("--samples", options.samples, "1, 4, 9 or 16 samples per pixel: overrides render.samples")
      ->check(CLI::IsMember({1, 4, 9, 16}));
  command->add_option("--up", options.up,
                      "y or z: the up axis of a model file rendered alone, for one whose exporter used the other "
                      "convention (default: its format's usual one, y for glTF and OBJ, z for PLY and STL)")
      ->check(CLI::IsMember({"y", "z"}));
  command->add_option("--projection", options.projection,
                      "perspective or orthographic: the fitted camera of a model file rendered alone (default "
                      "perspective); a scene file's camera says its own")
      ->check(CLI::IsMember({"perspective", "orthographic"}));
  command->add_flag("--no-file-lights", options.noFileLights,
                    "Light a glTF model file rendered alone from the camera, leaving out the lights it places "
                    "(KHR_lights_punctual); a scene file says it per object (\"file_lights\")");
  command->add_flag("--file-light-shadows", options.fileLightShadows,
                    "The lights a glTF model file rendered alone places cast shadows (as a light's \"shadows\"); "
                    "a scene file says it per object (\"file_light_shadows\")");
  command->add_option("--png-level", options.pngLevel,
                      "PNG deflate level: 0 (stored, largest) to 12 (smallest, slowest); the same pixels at every "
                      "level (default " + std::to_string(phongvk::PNG_LEVEL_DEFAULT) + ", the fastest)")
      ->check(CLI::Range(phongvk::PNG_LEVEL_MIN, phongvk::PNG_LEVEL_MAX));
}

// A file or folder to write: an empty name would write nothing, or fail only after rendering.
const CLI::Validator OUTPUT_NAME(
    [](const std::string& text) { return text.empty() ? std::string("must name a file, got an empty name") : std::string(); },
    "FILE");

// `render` also offers the graphics-pipeline baseline ("graphics", or by its older name
// "raster"); sequences use the other two.
void addBackendOption(CLI::App* command, std::string& backend, bool withGraphics = false) {
  std::vector<std::string> choices = {"gpu", "cpu"};
  std::string help = "gpu (Vulkan compute, default) or cpu (the reference)";
  if (withGraphics) {
    choices.insert(choices.end(), {"graphics", "raster"});
    help = "gpu (Vulkan compute, default), cpu (the reference) or graphics (Vulkan graphics pipeline; also 'raster')";
  }
  command->add_option("--backend", backend, help)->check(CLI::IsMember(choices));
}

// CLI11 reports an unknown first word as a missing subcommand; name it and the commands instead.
int rejectUnknownCommand(CLI::App& app, int argc, char** argv) {
  if (argc < 2 || argv[1][0] == '-') return 0;
  std::string known;
  for (const CLI::App* command : app.get_subcommands([](CLI::App*) { return true; })) {
    if (command->get_name() == argv[1]) return 0;
    known += (known.empty() ? "" : ", ") + command->get_name();
  }
  std::fprintf(stderr, "error: unknown command '%s' (commands: %s; see phongvk --help)\n", argv[1], known.c_str());
  return EXIT_BAD_INPUT;
}

}  // namespace

int main(int argc, char** argv) {
  // A file-size limit (ulimit -f) then fails the write with EFBIG, which the writer reports and
  // cleans up after, instead of killing the process and leaving a temporary file behind.
  std::signal(SIGXFSZ, SIG_IGN);
  CLI::App app{"phongvk: Phong illumination per vertex, Gouraud interpolation, on Vulkan compute or the CPU reference"};
  app.require_subcommand(1);
  // Usage errors read as every other error of the command: "error: ..." (a validator's message too).
  app.failure_message([](const CLI::App* failed, const CLI::Error& e) { return "error: " + CLI::FailureMessage::simple(failed, e); });
  app.set_version_flag("--version", std::string("phongvk ") + phongvk::version() + " (" + phongvk::revision() + ")");

  RenderOptions render;
  CLI::App* renderCmd = app.add_subcommand("render", "Render a scene to PNG");
  addViewOptions(renderCmd, render);
  renderCmd->add_option("-o,--output", render.output, "Output PNG ('-': standard output, the summary then goes to standard error)")
      ->required()
      ->check(OUTPUT_NAME);
  addBackendOption(renderCmd, render.backend, true);
  renderCmd->add_option("--repeat", render.repeat, "Time N frames after a warm-up and print the median")
      ->check(CLI::Range(1, 100000));
  renderCmd->add_flag("--mpi", render.mpi,
                      "Under mpirun: each process renders a share of the triangles, the keys are composited by "
                      "MPI_Allreduce (MPI_MIN) and rank 0 writes the PNG (and --rgba, --depth, --ids, --normals)");
  renderCmd->add_flag("--rgba", render.rgba,
                      "Write -o as RGBA: alpha 255 where triangles cover every sample of the pixel, 0 where none");
  renderCmd->add_option("--depth", render.depth,
                        "Also write the depth along the camera axis: FILE.png, 16-bit grey in millimetres (rounded, "
                        "0 where empty, at most 65535: the TUM/NYU RGB-D datasets' convention), or FILE.npy, float32 "
                        "metres, +inf where empty")
      ->check(OUTPUT_NAME);
  renderCmd->add_option("--ids", render.ids,
                        "Also write each pixel's object: FILE.png, 16-bit grey, object index + 1 (0 where empty; at "
                        "most 65534 objects), or FILE.npy, int32 index, -1 where empty")
      ->check(OUTPUT_NAME);
  renderCmd->add_option("--normals", render.normals,
                        "Also write each pixel's shading normal in camera space (x right, y up, z forward): "
                        "FILE.png, 8-bit RGB normal map, (n + 1) / 2 * 255 rounded (0, 0, 0 where empty), or "
                        "FILE.npy, float32 (height, width, 3), 0, 0, 0 where empty")
      ->check(OUTPUT_NAME);
  renderCmd->add_option("--lights", render.lights,
                        "Also write how many lights reach each pixel's surface (shadowed lights whose ray is "
                        "blocked do not): FILE.png, 16-bit grey, count + 1 (0 where empty), or FILE.npy, int32, -1 "
                        "where empty")
      ->check(OUTPUT_NAME);

  DiffOptions diff;
  CLI::App* diffCmd = app.add_subcommand("diff", "Render with both backends and compare pixel by pixel");
  addViewOptions(diffCmd, diff);
  diffCmd->add_option("--heatmap", diff.heatmap, "Write a PNG showing where the images differ")
      ->check(OUTPUT_NAME);
  diffCmd->add_option("--devices", diff.devices,
                      "Comma-separated Vulkan device indices (see 'phongvk devices'): render on each of them and the "
                      "reference, and compare each device with the reference")
      ->delimiter(',')
      ->check(CLI::NonNegativeNumber)
      ->excludes("--device")
      ->excludes("--heatmap");
  diffCmd->add_option("--tolerance", diff.tolerance, "Largest allowed channel difference, in 8-bit units (default 1)")
      ->check(CLI::Validator(
          [](const std::string& text) {
            double value = 0;
            const bool parsed = CLI::detail::lexical_cast(text, value);
            return parsed && value >= 0 && value <= 255 ? std::string() : "must be a number from 0 to 255, got " + text;
          },
          "0..255"));

  SequenceOptions sequence;
  CLI::App* sequenceCmd = app.add_subcommand("sequence", "Render the frames of an animated scene to numbered PNGs");
  addViewOptions(sequenceCmd, sequence);
  sequenceCmd->add_option("-o,--output", sequence.outputDir, "Folder for frame_0000.png, frame_0001.png, ...")
      ->required()
      ->check(OUTPUT_NAME);
  sequenceCmd->add_option("--frames", sequence.frames,
                          "START:END[:STEP], END excluded like a Python slice (default: every frame)");
  sequenceCmd->add_option("--sheet", sequence.sheet, "Also write a contact sheet of the frames (PNG)")
      ->check(OUTPUT_NAME);
  sequenceCmd->add_flag("--skip-existing", sequence.skipExisting,
                        "Keep the frames an earlier run already wrote whole, and render only the others "
                        "(a restarted or requeued job wastes no work)");
  sequenceCmd->add_option("--thumb-width", sequence.thumbnailWidth, "Widest thumbnail on the sheet (default 160)")
      ->check(CLI::Range(8, 4096));
  addBackendOption(sequenceCmd, sequence.backend);

  app.add_subcommand("devices", "List Vulkan devices and whether phongvk can use them");

  if (const int code = rejectUnknownCommand(app, argc, argv)) return code;
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // CLI11 prints help (exit 0) or the usage error; a usage error is bad input (exit 2).
    const int code = app.exit(e);
    return code == 0 ? 0 : EXIT_BAD_INPUT;
  }
  if (renderCmd->parsed()) return runRender(render);
  if (diffCmd->parsed()) return runDiff(diff);
  if (sequenceCmd->parsed()) return runSequence(sequence);
  return runDevices();
}
