// spirv_words.h — walking a SPIR-V module's words (SPIR-V spec 2.3–2.4), for the build tool that
// decorates float operations (no_contraction.cpp) and the test that checks every embedded module
// kept those decorations (tests/spirv_modules_test.cpp). Header-only, no dependencies.
#pragma once

#include <cstddef>
#include <cstdint>
#include <set>
#include <span>
#include <string>

namespace phongvk::spirv {

inline constexpr uint32_t MAGIC = 0x07230203u;
inline constexpr size_t HEADER_WORDS = 5;
inline constexpr uint32_t OP_DECORATE = 71;
inline constexpr uint32_t DECORATION_NO_CONTRACTION = 42;

// The arithmetic instructions whose results are floating point (spec 3.52.13): OpFNegate, OpFAdd,
// OpFSub, OpFMul, OpFDiv, OpFRem, OpFMod, and the vector and matrix products with OpDot. Their
// result id is word 2.
inline bool isFloatArithmetic(uint32_t opcode) {
  switch (opcode) {
    case 127: case 129: case 131: case 133: case 136: case 140: case 141:
    case 142: case 143: case 144: case 145: case 146: case 147: case 148:
      return true;
    default:
      return false;
  }
}

// Calls visit(offset, opcode, instruction words) for every instruction after the header; an error
// message for a module that is not whole (bad magic number, an instruction past the end), or empty.
template <typename Visit>
std::string forEachInstruction(std::span<const uint32_t> words, Visit visit) {
  if (words.size() < HEADER_WORDS || words[0] != MAGIC) return "not SPIR-V (bad magic number, or not little-endian)";
  for (size_t i = HEADER_WORDS; i < words.size();) {
    const uint32_t count = words[i] >> 16;
    if (count == 0 || i + count > words.size()) return "instruction at word " + std::to_string(i) + " runs past the end";
    visit(i, words[i] & 0xffffu, words.subspan(i, count));
    i += count;
  }
  return "";
}

// The float arithmetic results of a module (`wanted`) and the ids decorated NoContraction.
struct Contraction {
  std::set<uint32_t> wanted;
  std::set<uint32_t> decorated;
};

inline std::string findContraction(std::span<const uint32_t> words, Contraction& found) {
  return forEachInstruction(words, [&](size_t, uint32_t opcode, std::span<const uint32_t> inst) {
    if (opcode == OP_DECORATE && inst.size() >= 3 && inst[2] == DECORATION_NO_CONTRACTION) found.decorated.insert(inst[1]);
    if (isFloatArithmetic(opcode) && inst.size() >= 3) found.wanted.insert(inst[2]);
  });
}

}  // namespace phongvk::spirv
