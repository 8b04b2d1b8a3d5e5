#include "cli/cli_support.h"

#include "tools/option_text.h"

#include <cstdio>

namespace phongvk::cli {

double msSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

namespace {

int report(const std::exception& error, int exitCode) {
  std::fprintf(stderr, "error: %s\n", error.what());
  return exitCode;
}

}  // namespace

int guarded(const std::function<int()>& command) {
  try {
    return command();
  } catch (const SceneError& e) {
    return report(e, EXIT_BAD_INPUT);
  } catch (const OutputWriteError& e) {
    return report(e, EXIT_FAILURE_OTHER);
  } catch (const OutputError& e) {
    return report(e, EXIT_BAD_INPUT);
  } catch (const UsageError& e) {
    return report(e, EXIT_BAD_INPUT);
  } catch (const NoDeviceError& e) {
    return report(e, EXIT_NO_DEVICE);
  } catch (const ArgumentError& e) {
    return report(e, EXIT_BAD_INPUT);
  } catch (const std::exception& e) {
    return report(e, EXIT_FAILURE_OTHER);
  }
}

Scene sizedAsAsked(const Scene& scene, const ViewOptions& options) {
  RenderSettings settings = scene.renderSettings();
  if (!options.shading.empty()) settings.shading = parseShading(options.shading);
  if (!options.specular.empty()) settings.specular = parseSpecular(options.specular);
  if (options.samples > 0) settings.samples = options.samples;
  const Scene rendered = scene.withRender(settings);
  if (options.width <= 0 && options.height <= 0) return rendered;
  return rendered.withImageSize(options.width, options.height);
}

Scene frameAsAsked(const Scene& sequence, int index, const ViewOptions& options) {
  const std::string prefix = sequence.path() + ": frame " + std::to_string(index) + ": ";
  try {
    const Scene frame = sizedAsAsked(sequence.frame(index), options);
    checkSceneMemory(frame);
    return frame;
  } catch (const SceneError& error) {
    // The frame's own checks name the file and the frame already; the size, render options and
    // memory checks name the file alone.
    const std::string what = error.what(), file = sequence.path() + ": ";
    if (sequence.frameCount() == 1 || what.rfind(prefix, 0) == 0) throw;
    throw SceneError(prefix + (what.rfind(file, 0) == 0 ? what.substr(file.size()) : what));
  }
}

LoadOptions loadOptions(const ViewOptions& options) {
  // The memory limit holds from the first file read: a scene's textures are decoded as it loads.
  if (!options.maxMemoryGb.empty()) setMemoryLimit(memoryLimitBytes(options.maxMemoryGb, "--max-memory-gb"));
  return {options.up.empty() ? ModelUp::Usual : parseModelUp(options.up),
          options.projection.empty() ? std::nullopt : std::optional<bool>(parseOrthographic(options.projection)),
          !options.noFileLights, options.fileLightShadows};
}

Scene loadEveryFrameValidated(const ViewOptions& options) {
  const Scene scene = loadScene(options.scene, loadOptions(options));
  for (int i = 1; i < scene.frameCount(); ++i) frameAsAsked(scene, i, options);
  return frameAsAsked(scene, 0, options);
}

RendererOptions rendererOptions(const ViewOptions& options, const std::string& backend) {
  const Backend chosen = parseBackend(backend);
  if (chosen == Backend::Cpu && options.device >= 0)
    throw UsageError("--device " + std::to_string(options.device) + " selects a Vulkan device, and --backend cpu uses none");
  return {chosen, options.device, options.validate};
}

}  // namespace phongvk::cli
