#include "app.h"

#include "host/context.h"
#include "host/gpu_renderer.h"
#include "reference/camera.h"
#include "reference/compare.h"
#include "reference/render_reference.h"
#include "reference/scene_data.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <optional>
#include <unistd.h>

namespace phongvk {

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// Runs a command, turning each kind of failure into its message on stderr and its exit code.
int guarded(const std::function<int()>& command) {
  try {
    return command();
  } catch (const SceneError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return EXIT_BAD_INPUT;
  } catch (const OutputError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return EXIT_BAD_INPUT;
  } catch (const NoDeviceError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return EXIT_NO_DEVICE;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return EXIT_FAILURE_OTHER;
  }
}

// Fails before any rendering when the output cannot be written, so no time is wasted and no
// partial file appears.
void checkWritable(const std::string& path) {
  if (path.empty()) return;
  std::filesystem::path folder = std::filesystem::path(path).parent_path();
  if (folder.empty()) folder = ".";
  if (!std::filesystem::is_directory(folder)) {
    throw OutputError("cannot write '" + path + "': folder '" + folder.string() + "' does not exist");
  }
  if (access(folder.c_str(), W_OK) != 0) {
    throw OutputError("cannot write '" + path + "': folder '" + folder.string() + "' is not writable");
  }
  if (std::filesystem::is_directory(path)) throw OutputError("cannot write '" + path + "': it is a folder");
}

// A scene loaded and flattened, with the view the options ask for.
struct Prepared {
  Scene scene;
  SceneData data;
  View view;
  FrameInputs frame;
  double loadMs = 0;
};

Prepared prepare(const ViewOptions& options) {
  const auto start = Clock::now();
  Prepared p;
  p.scene = loadScene(options.scene);
  CameraSpec camera = p.scene.camera;
  if (options.width > 0 || options.height > 0) camera = withImageSize(camera, options.width, options.height);
  p.view = makeView(camera);
  p.data = buildSceneData(p.scene);
  p.frame = makeFrame(p.data, p.view);
  p.loadMs = msSince(start);
  return p;
}

// The GPU backend: a context and a renderer holding the uploaded scene.
struct GpuSession {
  VulkanContext context;
  std::optional<GpuRenderer> renderer;

  GpuSession(const ViewOptions& options, const SceneData& data) {
    context = createContext({options.device, options.validate});
    try {
      renderer.emplace(context, data);
    } catch (...) {
      destroyContext(context);
      throw;
    }
  }
  ~GpuSession() {
    renderer.reset();
    destroyContext(context);
  }
};

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

// --repeat: N timed frames after one warm-up, wall clock per frame and device time.
void printRepeatTiming(int repeat, const std::function<double()>& frame) {
  frame();  // warm-up: first-use costs (pipeline caches, page faults) are not a frame's
  std::vector<double> wall, device;
  for (int i = 0; i < repeat; ++i) {
    const auto start = Clock::now();
    const double deviceMs = frame();
    wall.push_back(msSince(start));
    device.push_back(deviceMs);
  }
  std::printf("frame ms: median %.3f (device %.3f, min %.3f, max %.3f)\n", median(wall), median(device),
              *std::min_element(wall.begin(), wall.end()), *std::max_element(wall.begin(), wall.end()));
}

void printSummary(const RenderOptions& options, const Prepared& p, const std::string& backend, double renderMs) {
  std::printf("rendered %s: %dx%d, %zu objects, %zu triangles, %zu lights, %s backend: scene %.1f ms, render %.1f ms -> %s\n",
              options.scene.c_str(), p.view.width, p.view.height, p.scene.objects.size(), p.data.triangles.size(),
              p.scene.lights.size(), backend.c_str(), p.loadMs, renderMs, options.output.c_str());
}

}  // namespace

int runRender(const RenderOptions& options) {
  return guarded([&] {
    checkWritable(options.output);
    const Prepared p = prepare(options);
    RenderOutput out;
    const auto start = Clock::now();
    std::string backend = "cpu (reference)";
    if (options.backend == "cpu") {
      out = renderReference(p.data, p.frame);
      if (options.repeat > 0) {
        printRepeatTiming(options.repeat, [&] {
          const auto t = Clock::now();
          renderReference(p.data, p.frame);
          return msSince(t);
        });
      }
    } else {
      GpuSession gpu(options, p.data);
      out = gpu.renderer->render(p.frame);
      backend = "gpu (" + gpu.context.report.name + ")";
      if (options.repeat > 0) {
        printRepeatTiming(options.repeat, [&] {
          gpu.renderer->render(p.frame);
          return gpu.renderer->lastPassTimes().total;
        });
      }
    }
    const double renderMs = msSince(start);
    writePng(options.output, out.image);
    printSummary(options, p, backend, renderMs);
    return int(EXIT_OK);
  });
}

int runDiff(const DiffOptions& options) {
  return guarded([&] {
    checkWritable(options.heatmap);
    const Prepared p = prepare(options);
    const RenderOutput reference = renderReference(p.data, p.frame);
    GpuSession gpu(options, p.data);
    const RenderOutput port = gpu.renderer->render(p.frame, true);
    const DiffStats stats = compareImages(reference.image, port.image, reference.keys, port.keys);
    std::printf("scene:               %s\ndevice:              %s\n%s", options.scene.c_str(),
                gpu.context.report.name.c_str(), formatDiff(stats).c_str());
    if (!options.heatmap.empty()) {
      writePng(options.heatmap, diffHeatmap(reference.image, port.image, reference.keys, port.keys));
      std::printf("heatmap:             %s\n", options.heatmap.c_str());
    }
    const bool pass = stats.maxChannelDiff() <= options.tolerance;
    std::printf("result:              %s (tolerance %g of 255 per channel)\n", pass ? "PASS" : "FAIL", options.tolerance);
    return int(pass ? EXIT_OK : EXIT_DIFF_ABOVE_TOLERANCE);
  });
}

int runDevices() {
  return guarded([] {
    std::printf("%s", formatDeviceList(listDevices()).c_str());
    return int(EXIT_OK);
  });
}

}  // namespace phongvk
