#include "test_util.h"

#include <cstdlib>
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <stdexcept>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace phongvk::test {

std::string sourcePath(const std::string& relative) {
  return std::string(PHONGVK_SOURCE_DIR) + "/" + relative;
}

int executableMappings() {
  std::ifstream maps("/proc/self/maps");
  if (!maps) return -1;
  int count = 0;
  for (std::string line; std::getline(maps, line);) count += line.find(" r-xp ") != std::string::npos;
  return count;
}

int mappingsAddedByRelitFrames(const FrameInputs& in, const std::function<void(const FrameInputs&)>& render) {
  FrameInputs relit = in;
  relit.frame.ambient = glm::vec3(0.5f, 0.4f, 0.3f);
  for (int i = 0; i < 4; ++i) render(i % 2 ? relit : in);
  const int settled = executableMappings();
  for (int i = 0; i < 20; ++i) render(i % 2 ? relit : in);
  return executableMappings() - settled;
}

namespace {

// Every directory makeTempDir made, removed with its contents when the test process exits.
struct TempDirs {
  std::vector<std::filesystem::path> made;
  ~TempDirs() {
    for (const auto& dir : made) {
      std::error_code ignored;
      std::filesystem::remove_all(dir, ignored);
    }
  }
};

}  // namespace

std::string makeTempDir() {
  static std::mt19937_64 rng{std::random_device{}()};
  static TempDirs dirs;
  auto dir = std::filesystem::temp_directory_path() / ("phongvk-test-" + std::to_string(rng()));
  std::filesystem::create_directories(dir);
  dirs.made.push_back(dir);
  return dir.string();
}

void writeFile(const std::string& path, const std::string& text) {
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + path);
}

std::vector<std::string> allScenes() {
  std::vector<std::string> scenes;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(sourcePath("scenes"))) {
    if (entry.path().extension() == ".json") {
      scenes.push_back(std::filesystem::relative(entry.path(), sourcePath("")).string());
    }
  }
  std::sort(scenes.begin(), scenes.end());
  return scenes;
}

void expectTestDevice(const std::string& deviceName) {
  if (const char* expected = std::getenv("PHONGVK_TEST_DEVICE")) {
    EXPECT_NE(deviceName.find(expected), std::string::npos) << "ran on " << deviceName << ", not " << expected;
  }
  const char* path = std::getenv("PHONGVK_KEY_PATH");
  if (path && std::string(path) == "32") {
    EXPECT_NE(deviceName.find("keys: 32-bit"), std::string::npos) << "ran on " << deviceName;
  }
}

std::string pathTestName(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = info.param;
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return name;
}

std::string readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  EXPECT_TRUE(in.is_open()) << path;
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

namespace {

CommandResult run(const std::string& prefix, const std::string& args) {
  std::string command = prefix + std::string(PHONGVK_CLI) + " " + args + " 2>&1";
  CommandResult result;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) throw std::runtime_error("popen failed: " + command);
  char buffer[4096];
  size_t n;
  while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) result.output.append(buffer, n);
  int status = pclose(pipe);
  result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

}  // namespace

CommandResult runCli(const std::string& args) { return run("", args); }

CommandResult runCliWithEnvironment(const std::string& assignments, const std::string& args) {
  return run(assignments + " ", args);
}

CommandResult runCliUnprivileged(const std::string& args) {
  return run(geteuid() == 0 ? "setpriv --reuid=65534 --regid=65534 --clear-groups " : "", args);
}

}  // namespace phongvk::test
