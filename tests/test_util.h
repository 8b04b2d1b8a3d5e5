// test_util.h — small helpers shared by the test suites.
#pragma once

#include "phongvk/phongvk.h"
#include "prepare/scene_data.h"
#include "scene/scene_checks.h"
#include "scene/scene_json.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace phongvk::test {

// The message of the exception `call` throws as E, or a failure if it throws nothing.
template <typename E, typename F>
std::string thrownMessage(F&& call) {
  try {
    call();
  } catch (const E& error) {
    return error.what();
  }
  ADD_FAILURE() << "nothing was thrown";
  return "";
}


// Sets an environment variable for one scope and puts the old value back.
class ScopedEnv {
 public:
  ScopedEnv(const std::string& name, const std::string& value) : name_(name) {
    if (const char* old = std::getenv(name.c_str())) old_ = old;
    setenv(name.c_str(), value.c_str(), 1);
  }
  ~ScopedEnv() { old_ ? setenv(name_.c_str(), old_->c_str(), 1) : unsetenv(name_.c_str()); }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;

 private:
  std::string name_;
  std::optional<std::string> old_;
};

// Absolute path of a file in the source tree, e.g. sourcePath("scenes/basic.json").
std::string sourcePath(const std::string& relative);

// A fresh empty directory under the system temp dir, unique per call; removed with its contents
// when the test process exits.
std::string makeTempDir();

// This process's executable memory mappings (Linux /proc/self/maps); -1 where it cannot say. A
// driver that compiles code per frame (lavapipe inlining uniforms) makes it grow frame by frame.
int executableMappings();

// Renders `in` and a relit copy (another ambient) alternately through `render`, four frames and
// then twenty more; the executable mappings the twenty added to the process (0: nothing compiled).
int mappingsAddedByRelitFrames(const FrameInputs& in, const std::function<void(const FrameInputs&)>& render);

// Writes `text` to `path` (creating it), for tests that need a scene file on disk.
void writeFile(const std::string& path, const std::string& text);

// Every scene file under scenes/, relative to the source tree ("scenes/paper/fig1_cube.json"), sorted.
std::vector<std::string> allScenes();

// Fails unless a renderer on `deviceName` (Renderer::deviceName) is where the test's environment
// says it must run: PHONGVK_TEST_DEVICE (a part of the device's name, e.g. SwiftShader) and
// PHONGVK_KEY_PATH=32 (the 32-bit key path), where set (tests/CMakeLists.txt's swiftshader and
// keys32 entries).
void expectTestDevice(const std::string& deviceName);

// A test name for a parameter that is a path: every character but letters and digits becomes '_'.
std::string pathTestName(const ::testing::TestParamInfo<std::string>& info);

// A file's bytes (a failed check, and "", where it cannot be read).
std::string readBytes(const std::string& path);


struct CommandResult {
  int exitCode = -1;
  std::string output;  // stdout and stderr together
};

// Runs the phongvk CLI with `args` (a shell-quoted argument string) and captures its output.
CommandResult runCli(const std::string& args);

// The same with environment assignments before the command, e.g. "LP_NUM_THREADS=1".
CommandResult runCliWithEnvironment(const std::string& assignments, const std::string& args);

// The same, but as an unprivileged user when the tests run as root (CI containers do), so file
// permissions apply: through `setpriv` (util-linux) as uid/gid 65534 (nobody).
CommandResult runCliUnprivileged(const std::string& args);

// `scene` with the render options of `json`, an object of a scene file's "render" keys
// ({"shading": "phong", "samples": 4}), in place of its own; the options it does not name keep the
// scene's. The tests' render modes are written as a scene file writes them.
inline RenderSettings withRenderOptions(RenderSettings settings, const std::string& json) {
  const scenejson::Json options = scenejson::Json::parse(json);
  for (const auto& [key, value] : options.items()) {
    if (key == "shading") settings.shading = parseShading(value.get<std::string>());
    else if (key == "specular") settings.specular = parseSpecular(value.get<std::string>());
    else if (key == "interpolation") settings.interpolation = parseInterpolation(value.get<std::string>());
    else if (key == "samples") settings.samples = value.get<int>();
    else if (key == "texture_filter") settings.textureFilter = value.get<std::string>() == "nearest" ? TextureFilter::Nearest : TextureFilter::Bilinear;
    else ADD_FAILURE() << "no render option '" << key << "'";
  }
  return settings;
}

inline Scene withRenderOptions(const Scene& scene, const std::string& json) {
  return scene.withRender(withRenderOptions(scene.renderSettings(), json));
}

// The same for a scene model (the renderers' own input), checked as a scene file's "render".
inline SceneSpec withRenderOptions(SceneSpec spec, const std::string& json) {
  scenejson::setRenderSettings(spec, withRenderOptions(scenejson::renderSettingsOf(spec), json), scenejson::Where("render"));
  return spec;
}

}  // namespace phongvk::test
