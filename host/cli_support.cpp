#include "cli_support.h"

#include <cstdio>
#include <filesystem>
#include <unistd.h>

namespace phongvk {

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

void checkWritable(const std::string& path) {
  if (path.empty()) return;
  std::filesystem::path folder = std::filesystem::path(path).parent_path();
  if (folder.empty()) folder = ".";
  if (std::filesystem::exists(folder) && !std::filesystem::is_directory(folder)) {
    throw OutputError("cannot write '" + path + "': '" + folder.string() + "' is a file, not a folder");
  }
  if (!std::filesystem::is_directory(folder)) {
    throw OutputError("cannot write '" + path + "': folder '" + folder.string() + "' does not exist");
  }
  if (access(folder.c_str(), W_OK) != 0) {
    throw OutputError("cannot write '" + path + "': folder '" + folder.string() + "' is not writable");
  }
  if (std::filesystem::is_directory(path)) throw OutputError("cannot write '" + path + "': it is a folder");
}

GpuSession::GpuSession(const ViewOptions& options) : context(createContext({options.device, options.validate})) {}

GpuSession::GpuSession(const ViewOptions& options, const SceneData& data) : GpuSession(options) {
  load(data);  // the delegating constructor has finished: a throw here runs ~GpuSession
}

void GpuSession::load(const SceneData& data) {
  renderer.reset();  // the old buffers go before the new ones are allocated
  renderer.emplace(context, data);
}

GpuSession::~GpuSession() {
  renderer.reset();
  destroyContext(context);
}

}  // namespace phongvk
