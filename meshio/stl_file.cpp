// stl_file.cpp — see stl_file.h.
#include "meshio/stl_file.h"

#include "base/huge_pages.h"
#include "meshio/mesh_import.h"
#include "phongvk/errors.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace phongvk {
namespace {

[[noreturn]] void fail(const std::string& where, const std::string& path, const std::string& why) {
  throw SceneError(where + ": " + path + ": " + why);
}

glm::vec3 checked(glm::vec3 p, uint64_t facet, const std::string& path, const std::string& where) {
  for (int axis = 0; axis < 3; ++axis) {
    if (!(std::abs(double(p[axis])) <= MAX_COORDINATE))
      fail(where, path, "facet " + std::to_string(facet) + " has a vertex that is not finite or beyond the coordinates a scene may use");
  }
  return p;
}

bool isBinary(std::string_view bytes) {
  if (bytes.size() < 84) return false;
  uint32_t count;
  std::memcpy(&count, bytes.data() + 80, 4);
  return bytes.size() == 84 + 50 * uint64_t(count);
}

MeshPart readBinary(std::string_view bytes, const std::string& path, const std::string& where) {
  uint32_t count;
  std::memcpy(&count, bytes.data() + 80, 4);
  MeshPart part;
  reserveLarge(part.positions, 3 * size_t(count));
  reserveLarge(part.triangles, count);
  for (uint32_t f = 0; f < count; ++f) {
    const char* facet = bytes.data() + 84 + 50 * size_t(f) + 12;  // past the facet normal
    for (int k = 0; k < 3; ++k) {
      float xyz[3];
      std::memcpy(xyz, facet + 12 * k, 12);
      part.positions.push_back(checked(glm::vec3(xyz[0], xyz[1], xyz[2]), f, path, where));
    }
    part.triangles.push_back(glm::uvec3(3 * f, 3 * f + 1, 3 * f + 2));
  }
  return part;
}

// Words of an ASCII file, with their line numbers.
class Words {
 public:
  explicit Words(std::string_view text) : text_(text) {}

  bool next(std::string_view& word) {
    while (at_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[at_]))) line_ += text_[at_++] == '\n';
    if (at_ >= text_.size()) return false;
    const size_t start = at_;
    while (at_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[at_]))) ++at_;
    word = text_.substr(start, at_ - start);
    return true;
  }
  void skipLine() {
    while (at_ < text_.size() && text_[at_] != '\n') ++at_;
  }
  uint64_t line() const { return line_; }

 private:
  std::string_view text_;
  size_t at_ = 0;
  uint64_t line_ = 1;
};

MeshPart readAscii(std::string_view bytes, const std::string& path, const std::string& where) {
  Words words(bytes);
  MeshPart part;
  uint64_t facet = 0;
  int corners = 0;          // vertices of the current facet so far
  bool inFacet = false;     // between "facet" and "endfacet"
  bool inSolid = false;     // between "solid" and "endsolid"
  const auto bad = [&](const std::string& why) {
    fail(where, path, "line " + std::to_string(words.line()) + " (facet " + std::to_string(facet) + "): " + why);
  };
  std::string_view word;
  while (words.next(word)) {
    if (word == "solid") {
      inSolid = true;
      words.skipLine();  // the solid's name
    } else if (word == "endsolid") {
      if (inFacet) bad("'endsolid' inside a facet");
      inSolid = false;
      words.skipLine();
    } else if (word == "facet") {
      if (inFacet) bad("a facet inside a facet (an 'endfacet' is missing)");
      inFacet = true;
    } else if (word == "vertex") {
      if (!inFacet) bad("a vertex outside a facet");
      if (corners == 3) bad("a facet with more than three vertices");
      float xyz[3];
      for (float& c : xyz) {
        std::string_view number;
        if (!words.next(number)) bad("the file ends inside a vertex");
        const auto [end, error] = std::from_chars(number.data(), number.data() + number.size(), c);
        if (error != std::errc() || end != number.data() + number.size()) {
          std::string why(1, '\'');  // appended piece by piece: GCC 12 warns (-Wrestrict) on "'" + ...
          bad(why.append(number).append("' is not a number"));
        }
      }
      part.positions.push_back(checked(glm::vec3(xyz[0], xyz[1], xyz[2]), facet, path, where));
      ++corners;
    } else if (word == "endfacet") {
      if (!inFacet) bad("'endfacet' without its 'facet'");
      if (corners != 3) bad("a facet with " + std::to_string(corners) + " vertices");
      inFacet = false;
      const uint32_t first = uint32_t(part.positions.size() - 3);
      part.triangles.push_back(glm::uvec3(first, first + 1, first + 2));
      corners = 0;
      ++facet;
    }
    // "normal n n n", "outer loop", "endloop": nothing to keep (the normal's numbers are words of
    // their own, skipped here).
  }
  // A file cut short (a copy or download that stopped) is an error, not the facets before the cut.
  if (inFacet) bad("the file ends inside a facet (is it cut short?)");
  if (inSolid) bad("the file ends before 'endsolid' (is it cut short?)");
  return part;
}

}  // namespace

Mesh readStl(std::string_view bytes, const std::string& path, const std::string& where) {
  std::vector<MeshPart> parts;
  parts.push_back(isBinary(bytes) ? readBinary(bytes, path, where) : readAscii(bytes, path, where));
  return joinParts(parts, true, where + ": " + path);
}

}  // namespace phongvk
