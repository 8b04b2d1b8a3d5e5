// The compute passes' embedded SPIR-V keeps every floating-point operation NoContraction after
// spirv-opt (cmake/shaders.cmake, shaders/no_contraction.cpp): the renderers' bit-for-bit
// agreement rests on no optimizer rewriting one, and glslang's `precise` alone leaves the
// operations inside helper functions undecorated.
#include "shaders/spirv_words.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <span>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace phongvk::spirv;

// The words of a glslang-style C array header (`const uint32_t name[] = {0x07230203, ...};`).
std::vector<uint32_t> embeddedWords(const std::filesystem::path& header) {
  std::ifstream in(header);
  std::stringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  const std::string body = s.substr(s.find('{'));
  std::vector<uint32_t> words;
  const std::regex word("0x([0-9a-fA-F]{8})");
  for (auto it = std::sregex_iterator(body.begin(), body.end(), word); it != std::sregex_iterator(); ++it) {
    words.push_back(uint32_t(std::stoul((*it)[1].str(), nullptr, 16)));
  }
  return words;
}

// The compute modules' headers: every x.spv.h but the graphics baseline's stages (x_vert, x_frag).
std::vector<std::filesystem::path> computeModules() {
  std::vector<std::filesystem::path> found;
  for (const auto& entry : std::filesystem::directory_iterator(PHONGVK_SPIRV_DIR)) {
    const std::string name = entry.path().filename().string();
    if (name.size() < 6 || name.substr(name.size() - 6) != ".spv.h") continue;
    if (name.find("_vert.") != std::string::npos || name.find("_frag.") != std::string::npos) continue;
    found.push_back(entry.path());
  }
  return found;
}

TEST(SpirvModules, EveryFloatOperationOfEveryComputePassIsNoContraction) {
  const std::vector<std::filesystem::path> modules = computeModules();
  ASSERT_GE(modules.size(), 20u) << "the compute passes and their _exact builds, in " << PHONGVK_SPIRV_DIR;
  size_t operations = 0;
  for (const auto& module : modules) {
    SCOPED_TRACE(module.filename().string());
    const std::vector<uint32_t> words = embeddedWords(module);
    Contraction found;
    ASSERT_EQ(findContraction(words, found), "");
    operations += found.wanted.size();
    size_t undecorated = 0;
    for (uint32_t id : found.wanted) undecorated += found.decorated.count(id) == 0;
    EXPECT_EQ(undecorated, 0u) << "of " << found.wanted.size() << " float operations";
  }
  EXPECT_GT(operations, 1000u);  // the passes' shading, depth and clipping maths, all found
}

TEST(SpirvModules, TheWalkerRejectsWhatIsNotAWholeModule) {
  const std::vector<uint32_t> words = embeddedWords(computeModules().at(0));
  Contraction found;
  ASSERT_EQ(findContraction(words, found), "");
  std::vector<uint32_t> cut = words;
  cut.push_back((5u << 16) | OP_DECORATE);  // an instruction of five words, one there
  EXPECT_NE(findContraction(cut, found), "");
  std::vector<uint32_t> swapped = words;
  swapped[0] = 0x03022307u;  // the magic number of a big-endian module
  EXPECT_NE(findContraction(swapped, found), "");
}

// The 32-bit key path's builds (`_k32`, cmake/shaders.cmake) declare no capability a device
// without 64-bit integers or 8-bit storage lacks, and use no 64-bit or 8-bit integer type: they
// are what SwiftShader and such GPUs run (docs/DESIGN.md "Visibility").
TEST(SpirvModules, TheKeys32BuildsUseNo64BitOr8BitIntegers) {
  constexpr uint32_t OP_TYPE_INT = 21, OP_CAPABILITY = 17;
  // Int64, Int64Atomics, Int8, StorageBuffer8BitAccess, UniformAndStorageBuffer8BitAccess.
  const std::set<uint32_t> forbidden = {11, 12, 39, 4448, 4449};
  size_t builds = 0;
  for (const auto& module : computeModules()) {
    if (module.filename().string().find("_k32") == std::string::npos) continue;
    SCOPED_TRACE(module.filename().string());
    ++builds;
    const std::vector<uint32_t> words = embeddedWords(module);
    std::vector<std::string> found;
    ASSERT_EQ(forEachInstruction(words, [&](size_t, uint32_t opcode, std::span<const uint32_t> op) {
                if (opcode == OP_CAPABILITY && forbidden.count(op[1])) found.push_back("capability " + std::to_string(op[1]));
                if (opcode == OP_TYPE_INT && op[2] != 32) found.push_back("a " + std::to_string(op[2]) + "-bit integer type");
              }),
              "");
    EXPECT_TRUE(found.empty()) << found.front();
  }
  EXPECT_EQ(builds, 40u) << "every pass's _k32, _k32_exact, _k32s and _k32s_exact build, in " << PHONGVK_SPIRV_DIR;
}

}  // namespace
