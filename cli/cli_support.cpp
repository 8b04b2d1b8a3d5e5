#include "cli/cli_support.h"

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
  } catch (const std::exception& e) {
    return report(e, EXIT_FAILURE_OTHER);
  }
}

Scene sizedAsAsked(const Scene& scene, const ViewOptions& options) {
  std::string render;
  auto add = [&](const char* key, const std::string& value) {
    render += std::string(render.empty() ? "{" : ", ") + "\"" + key + "\": " + value;
  };
  if (!options.shading.empty()) add("shading", "\"" + options.shading + "\"");
  if (!options.specular.empty()) add("specular", "\"" + options.specular + "\"");
  if (options.samples > 0) add("samples", std::to_string(options.samples));
  const Scene rendered = render.empty() ? scene : scene.withRender(render + "}");
  if (options.width <= 0 && options.height <= 0) return rendered;
  return rendered.withImageSize(options.width, options.height);
}

Scene loadEveryFrameValidated(const ViewOptions& options) {
  const Scene scene = loadScene(options.scene);
  for (int i = 1; i < scene.frameCount(); ++i) {
    try {
      sizedAsAsked(scene.frame(i), options);
    } catch (const SceneError& error) {
      throw SceneError(scene.path() + ": frame " + std::to_string(i) + ": " + error.what());
    }
  }
  return sizedAsAsked(scene, options);
}

RendererOptions rendererOptions(const ViewOptions& options, const std::string& backend) {
  // The scene memory limit goes with the renderer, which checks every scene against it.
  if (options.maxMemoryGb > 0) setMemoryLimit(uint64_t(options.maxMemoryGb * double(uint64_t(1) << 30)));
  const Backend chosen = parseBackend(backend);
  if (chosen == Backend::Cpu && options.device >= 0)
    throw UsageError("--device " + std::to_string(options.device) + " selects a Vulkan device, and --backend cpu uses none");
  return {chosen, options.device, options.validate};
}

}  // namespace phongvk::cli
