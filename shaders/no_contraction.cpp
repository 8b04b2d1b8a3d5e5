// no_contraction.cpp — a build tool: decorates every floating-point arithmetic instruction of a
// SPIR-V module NoContraction, as GLSL's `precise` does for the expressions it reaches.
//
//   phongvk_no_contraction in.spv out.spv
//
// The reference computes every float operation as written, one IEEE rounding each (C++ without
// contraction), and the GPU passes must give the same bits. `precise` marks the operations that
// feed a precise variable, but glslang stops at function boundaries: the plain `a / b` inside a
// helper such as exact_float.h's `divide` stays undecorated, and once spirv-opt has inlined it,
// its folding rules are free to rewrite it (x / 255.0 became x * 0.00392156886, one ulp off).
// Decorated, no optimizer may fuse, reassociate or rewrite any of them: spirv-opt checks
// NoContraction before every floating-point folding rule, and drivers map it to exact operations
// (NIR's `exact`). The result is the module the shaders' own words promise: IEEE operations as
// written.
#include "shaders/spirv_words.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace {

using namespace phongvk::spirv;

// The instructions that come before the module's types (capabilities, extensions, imports, the
// memory model, entry points, execution modes, debug names and annotations): decorations go
// after the last of them.
bool isBeforeTypes(uint32_t opcode) {
  switch (opcode) {
    case 2: case 3: case 4: case 5: case 6: case 7:            // debug: source, names, strings
    case 10: case 11: case 14: case 15: case 16: case 17:      // extension ... capability
    case 71: case 72: case 73: case 74: case 75:               // annotations
    case 330: case 331: case 332: case 5632: case 5633:        // processed, mode id, id and string decorations
      return true;
    default:
      return false;
  }
}

struct Module {
  std::vector<uint32_t> words;
  std::string error;
};

Module read(const char* path) {
  Module m;
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    m.error = "cannot open";
    return m;
  }
  std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.size() % 4 != 0) {
    m.error = "not a whole SPIR-V module";
    return m;
  }
  m.words.resize(bytes.size() / 4);
  std::copy(bytes.begin(), bytes.end(), reinterpret_cast<char*>(m.words.data()));
  return m;
}

// Adds the decorations; an error message, or empty.
std::string decorate(std::vector<uint32_t>& words) {
  Contraction found;
  std::string error = findContraction(words, found);
  size_t insertAt = 0;
  if (error.empty()) {
    error = forEachInstruction(words, [&](size_t at, uint32_t opcode, std::span<const uint32_t>) {
      if (insertAt == 0 && !isBeforeTypes(opcode)) insertAt = at;
    });
  }
  if (!error.empty()) return error;
  if (insertAt == 0) return "no types or functions";
  std::vector<uint32_t> added;
  for (uint32_t id : found.wanted) {
    if (found.decorated.count(id) == 0) added.insert(added.end(), {(3u << 16) | OP_DECORATE, id, DECORATION_NO_CONTRACTION});
  }
  words.insert(words.begin() + static_cast<std::ptrdiff_t>(insertAt), added.begin(), added.end());
  return "";
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s in.spv out.spv\n", argv[0]);
    return 2;
  }
  Module m = read(argv[1]);
  if (m.error.empty()) m.error = decorate(m.words);
  if (!m.error.empty()) {
    std::fprintf(stderr, "%s: %s\n", argv[1], m.error.c_str());
    return 1;
  }
  std::ofstream out(argv[2], std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(m.words.data()), static_cast<std::streamsize>(m.words.size() * 4));
  out.close();
  if (!out) {
    std::fprintf(stderr, "%s: cannot write\n", argv[2]);
    return 1;
  }
  return 0;
}
