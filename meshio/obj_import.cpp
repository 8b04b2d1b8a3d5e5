// obj_import.cpp — see obj_import.h. tinyobjloader parses and triangulates; everything it lets
// through unchecked (indices out of range, numbers it reads as 0, NaN) is checked here.
#include "meshio/obj_import.h"

#include "phongvk/errors.h"

#include "base/mapped_file.h"
#include "base/number_text.h"
#include "base/regular_file.h"
#include "base/text_words.h"
#include "geometry/normals.h"
#include "geometry/polygon.h"
#include "image/texture_decode.h"
#include "meshio/mesh_import.h"

#include <tiny_obj_loader.h>

#include <cassert>
#include <algorithm>
#include <cctype>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <istream>
#include <map>
#include <sstream>
#include <unordered_map>

namespace phongvk {
namespace {

struct ObjData {
  std::vector<float> positions;           // xyz per position
  std::vector<float> normals;             // xyz per normal
  std::vector<float> texcoords;           // uv per 'vt' line
  std::vector<tinyobj::index_t> corners;  // the faces' corners, in order
  std::vector<uint32_t> faceSizes;        // corners per face, in file order
  std::vector<tinyobj::index_t> pointCorners;  // the 'p' lines' vertices, in order (a point cloud: every 'v')
  std::vector<tinyobj::index_t> lineCorners;   // the 'l' lines' vertices, in order
  std::vector<uint32_t> lineSizes;             // vertices per 'l' line, in file order
  std::vector<int> faceMaterials;         // each face's material (usemtl), -1 for none
  std::vector<std::string> diffuseMaps;   // each material's map_Kd, as its library names it
  std::vector<std::string> ignoredMaps;   // the other maps the materials name (map_Ks, bump, ...), once each
};

[[noreturn]] void fail(const std::string& where, const std::string& path, const std::string& why) {
  throw SceneError(where + ": " + path + ": " + why);
}

std::string firstLine(const std::string& text) {
  std::string line = text.substr(0, text.find('\n'));
  return line.empty() ? "unknown error" : line;
}

// A decimal number as tinyobjloader reads one: [+-] digits [. digits] [(e|E) [+-] digits], at
// least one digit before the exponent. It reads anything else ("nan", "inf", "0x1p3", "abc") as 0
// without a word, so such a token is an error here, not a silent vertex at the origin.
bool isPlainNumber(std::string_view token) {
  size_t i = 0, digits = 0;
  auto skipDigits = [&] {
    size_t start = i;
    while (i < token.size() && std::isdigit(static_cast<unsigned char>(token[i]))) ++i;
    return i - start;
  };
  if (i < token.size() && (token[i] == '+' || token[i] == '-')) ++i;
  digits += skipDigits();
  if (i < token.size() && token[i] == '.') {
    ++i;
    digits += skipDigits();
  }
  if (digits == 0) return false;
  if (i < token.size() && (token[i] == 'e' || token[i] == 'E')) {
    ++i;
    if (i < token.size() && (token[i] == '+' || token[i] == '-')) ++i;
    if (skipDigits() == 0) return false;
  }
  return i == token.size();
}

// The words of one line, up to a '#' comment, into `words` (emptied first: one vector serves every
// line of a file).
void wordsOf(std::string_view line, std::vector<std::string_view>& words) {
  words.clear();
  appendWords(line.substr(0, line.find('#')), words);
}

// A face corner "v", "v/vt", "v//vn" or "v/vt/vn": each index an integer, not 0, within 32 bits
// (tinyobjloader wraps 4294967299 to 3 without a word).
bool isCorner(std::string_view corner) {
  size_t parts = 0;
  while (true) {
    const size_t slash = corner.find('/');
    const std::string_view part = corner.substr(0, slash);
    if (!part.empty() || parts == 0) {
      int64_t index = 0;
      const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), index);
      if (error != std::errc() || end != part.data() + part.size() || index == 0 || index > INT32_MAX || index < -INT32_MAX)
        return false;
    }
    if (slash == std::string_view::npos) return parts < 3;
    corner.remove_prefix(slash + 1);
    ++parts;
  }
}

// A vertex of a 'p' or an 'l' line: its position index as the file writes it, that index resolved
// (0-based; out of range when the file's 'v' lines do not reach it) and the line it is on.
struct ElementVertex {
  int64_t written = 0, resolved = 0;
  size_t lineNumber = 0;
};

// What the file's lines say beyond tinyobjloader's reading: the faces' corner counts (tinyobjloader
// keeps only their low 8 bits), and the points and polylines of its 'p' and 'l' lines, read here
// (tinyobjloader 2.0.0rc10 repeats a shape's lines and points at each change of material).
struct ObjLines {
  std::vector<uint32_t> faceSizes;
  std::vector<ElementVertex> pointVertices, lineVertices;
  std::vector<uint32_t> lineSizes;
  size_t vertexLines = 0;  // 'v' lines
};

// Calls visit(lineNumber, words) for each line of `text` that has words, lines numbered from 1.
template <typename Visit>
void forEachLine(std::string_view text, Visit&& visit) {
  size_t lineNumber = 0;
  std::vector<std::string_view> words;
  for (size_t start = 0; start < text.size();) {
    const size_t end = std::min(text.find('\n', start), text.size());
    ++lineNumber;
    wordsOf(text.substr(start, end - start), words);
    start = end + 1;
    if (!words.empty()) visit(lineNumber, words);
  }
}

// The position index of the 'p' or 'l' vertex `word` (checked by isCorner), resolved as a face
// corner's is: positive from the first 'v' line, negative back from the last before it.
ElementVertex elementVertex(std::string_view word, size_t vertexLines, size_t lineNumber) {
  int64_t index = 0;
  std::from_chars(word.data(), word.data() + std::min(word.find('/'), word.size()), index);
  return {index, index > 0 ? index - 1 : int64_t(vertexLines) + index, lineNumber};
}

// A 'p' line's vertices, or an 'l' line's (two or more), added to `lines`.
void readElement(const std::vector<std::string_view>& words, size_t lineNumber, ObjLines& lines, const std::string& path,
                 const std::string& where) {
  const bool line = words[0] == "l";
  if (words.size() < (line ? 3u : 2u))
    fail(where, path, "line " + std::to_string(lineNumber) + ": " +
                          (line ? "an 'l' line needs 2 vertices or more, got " + std::to_string(words.size() - 1)
                                : std::string("a 'p' line needs a vertex or more")));
  for (size_t w = 1; w < words.size(); ++w) {
    if (!isCorner(words[w]))
      fail(where, path, "line " + std::to_string(lineNumber) + ": '" + std::string(words[w]).substr(0, 40) + "' is not a" +
                            (line ? "n 'l'" : " 'p'") + " vertex (v or v/vt, indices 32-bit and not 0)");
    (line ? lines.lineVertices : lines.pointVertices).push_back(elementVertex(words[w], lines.vertexLines, lineNumber));
  }
  if (line) lines.lineSizes.push_back(uint32_t(words.size() - 1));
}

// What tinyobjloader lets through without a word, checked line by line: every number on the v, vn
// and vt lines is a plain decimal number, a v line has x, y and z, a face has three corners or
// more and every corner index is one (in 32 bits), a 'p' line a vertex or more and an 'l' line two;
// and the file is text.
ObjLines checkLines(std::string_view text, const std::string& path, const std::string& where) {
  ObjLines lines;
  std::vector<uint32_t>& faceSizes = lines.faceSizes;
  if (text.find('\0') != std::string_view::npos)
    fail(where, path, "not a text file (it holds NUL bytes: binary, or UTF-16 text, which OBJ is not)");
  forEachLine(text, [&](size_t lineNumber, const std::vector<std::string_view>& words) {
    const auto at = [&] { return "line " + std::to_string(lineNumber) + ": "; };  // built only for a message
    const std::string_view keyword = words[0];
    if (keyword == "v" || keyword == "vn" || keyword == "vt") {
      for (size_t w = 1; w < words.size(); ++w) {
        if (!isPlainNumber(words[w]))
          fail(where, path, at() + "'" + std::string(words[w]).substr(0, 40) + "' in a '" + std::string(keyword) + "' line is not a number");
      }
      if (keyword == "v" && words.size() < 4)
        fail(where, path, at() + "a 'v' line needs x, y and z, got " + std::to_string(words.size() - 1) + " numbers");
      if (keyword == "v") ++lines.vertexLines;
    } else if (keyword == "p" || keyword == "l") {
      readElement(words, lineNumber, lines, path, where);
    } else if (keyword == "f") {
      if (words.size() < 4) fail(where, path, at() + "a face needs 3 corners or more, got " + std::to_string(words.size() - 1));
      faceSizes.push_back(uint32_t(words.size() - 1));
      for (size_t w = 1; w < words.size(); ++w) {
        if (!isCorner(words[w]))
          fail(where, path, at() + "'" + std::string(words[w]).substr(0, 40) + "' is not a face corner (v, v/vt, v//vn or v/vt/vn, indices 32-bit and not 0)");
      }
    }
  });
  return lines;
}

// The points' or the lines' vertices as corners of the file's positions (no normal, no texture
// coordinate). Throws for an index outside the file's 'v' lines, naming the line.
std::vector<tinyobj::index_t> elementCorners(const std::vector<ElementVertex>& vertices, size_t positions, const char* keyword,
                                             const std::string& path, const std::string& where) {
  std::vector<tinyobj::index_t> corners;
  corners.reserve(vertices.size());
  for (const ElementVertex& v : vertices) {
    if (v.resolved < 0 || uint64_t(v.resolved) >= positions)
      fail(where, path, "line " + std::to_string(v.lineNumber) + ": '" + keyword + "' vertex index " + std::to_string(v.written) +
                            " is out of range (the file has " + std::to_string(positions) + " vertices)");
    corners.push_back({int(v.resolved), -1, -1});
  }
  return corners;
}

glm::dvec3 at(const std::vector<float>& xyz, int index) {
  return {xyz[3 * size_t(index)], xyz[3 * size_t(index) + 1], xyz[3 * size_t(index) + 2]};
}

// A normal index of the file's 'vn' lines whose normal is finite and not zero.
bool usableNormal(const std::vector<float>& normals, int index) {
  if (index < 0) return false;
  const double length = glm::length(at(normals, index));
  return std::isfinite(length) && length != 0.0;
}

// A file of 'v' lines alone is a point cloud: every vertex a point, with the normal of the 'vn'
// line of the same rank (where usable) when there are as many as 'v' lines (MeshLab writes them so).
std::vector<tinyobj::index_t> pointCloud(const std::vector<float>& positions, const std::vector<float>& normals) {
  std::vector<tinyobj::index_t> corners(positions.size() / 3);
  const bool paired = normals.size() == positions.size();
  for (size_t v = 0; v < corners.size(); ++v) corners[v] = {int(v), paired && usableNormal(normals, int(v)) ? int(v) : -1, -1};
  return corners;
}

// The points and lines of the file's 'p' and 'l' lines; in a file without them and without faces,
// every vertex a point.
void addPointsAndLines(ObjData& data, const ObjLines& lines, const std::string& path, const std::string& where) {
  const size_t positions = data.positions.size() / 3;
  data.pointCorners = elementCorners(lines.pointVertices, positions, "p", path, where);
  data.lineCorners = elementCorners(lines.lineVertices, positions, "l", path, where);
  data.lineSizes = lines.lineSizes;
  if (data.corners.empty() && data.pointCorners.empty() && data.lineCorners.empty()) {
    if (positions == 0) fail(where, path, "nothing to draw (no 'f', 'l', 'p' or 'v' lines)");
    data.pointCorners = pointCloud(data.positions, data.normals);
  }
}

// The file's bytes as a stream, read where they lie (no copy).
class BytesStream : private std::streambuf, public std::istream {
 public:
  explicit BytesStream(std::string_view bytes) : std::istream(this) {
    char* begin = const_cast<char*>(bytes.data());  // only read: std::streambuf's get area is char*
    setg(begin, begin, begin + bytes.size());
  }
};

// The material libraries an OBJ names (mtllib), resolved against its folder as tinyobjloader
// resolves them, and read only if they are regular files (regular_file.h): a FIFO or a device
// named there would block or never end. A library that is missing is passed over, as every OBJ
// reader does (materials do not change how phongvk renders an OBJ); one that is not a regular file
// is an error.
class MaterialLibraries : public tinyobj::MaterialReader {
 public:
  MaterialLibraries(std::string folder, const std::string& path, const std::string& where)
      : folder_(std::move(folder)), path_(path), where_(where) {}

  bool operator()(const std::string& name, std::vector<tinyobj::material_t>* materials,
                  std::map<std::string, int>* byName, std::string* warning, std::string* error) override {
    const std::string library = name.empty() || name[0] == '/' || folder_.empty() ? name : folder_ + "/" + name;
    std::error_code missing;
    if (!std::filesystem::exists(library, missing)) return false;
    std::string why;
    const std::optional<RegularFile> file = RegularFile::open(library, why);
    if (!file) fail(where_, path_, "mtllib '" + name + "': " + why);
    const std::string text = file->read();
    BytesStream in(text);
    tinyobj::LoadMtl(byName, materials, &in, warning, error);
    return true;
  }

 private:
  std::string folder_;
  const std::string& path_;
  const std::string& where_;
};

// The number of each kind of index a face corner has: position, texture coordinate, normal.
struct IndexCounts {
  size_t positions = 0, texcoords = 0, normals = 0;
};

// The face corner with an index outside the file's positions, texture coordinates or normals,
// named by its line: the first whose index, resolved as tinyobjloader resolves it (positive:
// 1-based; negative: back from the last 'v', 'vt' or 'vn' line before it), is not one of the
// file's; empty when every index is. Run only once an index looks bad, so the common case pays
// nothing for the line numbers.
std::string badIndexAt(std::string_view text, const IndexCounts& count) {
  IndexCounts before;
  std::string found;
  const auto bad = [](int64_t index, size_t lines, size_t total) {
    const int64_t resolved = index > 0 ? index - 1 : int64_t(lines) + index;
    return resolved < 0 || uint64_t(resolved) >= total;
  };
  forEachLine(text, [&](size_t lineNumber, const std::vector<std::string_view>& words) {
    if (!found.empty()) return;
    if (words[0] == "v") ++before.positions;
    if (words[0] == "vt") ++before.texcoords;
    if (words[0] == "vn") ++before.normals;
    if (words[0] != "f") return;
    for (size_t w = 1; w < words.size() && found.empty(); ++w) {
      const std::string_view corner = words[w];
      const size_t slash = corner.find('/'), second = slash == std::string_view::npos ? slash : corner.find('/', slash + 1);
      const size_t texEnd = std::min(second, corner.size());
      int64_t v = 0, vt = 0, vn = 0;
      std::from_chars(corner.data(), corner.data() + std::min(slash, corner.size()), v);
      const bool hasTexcoord = slash != std::string_view::npos && slash + 1 < texEnd;
      if (hasTexcoord) std::from_chars(corner.data() + slash + 1, corner.data() + texEnd, vt);
      const bool hasNormal = second != std::string_view::npos && second + 1 < corner.size();
      if (hasNormal) std::from_chars(corner.data() + second + 1, corner.data() + corner.size(), vn);
      const std::string at = "line " + std::to_string(lineNumber) + ": face corner '" + std::string(corner.substr(0, 40)) + "': ";
      if (bad(v, before.positions, count.positions))
        found = at + "vertex index " + std::to_string(v) + " is out of range (the file has " + std::to_string(count.positions) + " vertices)";
      else if (hasTexcoord && bad(vt, before.texcoords, count.texcoords))
        found = at + "texture coordinate index " + std::to_string(vt) + " is out of range (the file has " +
                std::to_string(count.texcoords) + " 'vt' lines)";
      else if (hasNormal && bad(vn, before.normals, count.normals))
        found = at + "normal index " + std::to_string(vn) + " is out of range (the file has " + std::to_string(count.normals) + " normals)";
    }
  });
  return found;
}

// Every index of every face corner is one of the file's lines. tinyobjloader leaves an index it
// cannot resolve below 0, where -1 also means "none": a corner with -1 where the file has lines
// of that kind is checked against the text, as is every index out of range.
void checkIndices(const ObjData& data, std::string_view text, const std::string& path, const std::string& where) {
  const IndexCounts count{data.positions.size() / 3, data.texcoords.size() / 2, data.normals.size() / 3};
  const auto outside = [](int index, size_t total) { return index < -1 || (index >= 0 && size_t(index) >= total); };
  bool surely = false, maybe = false;
  for (const tinyobj::index_t& c : data.corners) {
    surely = surely || c.vertex_index < 0 || size_t(c.vertex_index) >= count.positions ||
             outside(c.texcoord_index, count.texcoords) || outside(c.normal_index, count.normals);
    maybe = maybe || (c.texcoord_index == -1 && count.texcoords > 0) || (c.normal_index == -1 && count.normals > 0);
  }
  if (!surely && !maybe) return;
  const std::string at = badIndexAt(text, count);
  if (!at.empty()) fail(where, path, at);
  if (surely)
    fail(where, path, "a face's index is out of range (the file has " + std::to_string(count.positions) + " vertices, " +
                          std::to_string(count.texcoords) + " 'vt' lines and " + std::to_string(count.normals) + " normals)");
}

// The maps of material m other than map_Kd, by their keywords, added to `names` once each.
void noteIgnoredMaps(const tinyobj::material_t& m, std::vector<std::string>& names) {
  const std::pair<const std::string*, const char*> maps[] = {
      {&m.ambient_texname, "map_Ka"},  {&m.specular_texname, "map_Ks"},  {&m.specular_highlight_texname, "map_Ns"},
      {&m.bump_texname, "bump"},       {&m.displacement_texname, "disp"}, {&m.alpha_texname, "map_d"},
      {&m.reflection_texname, "refl"}, {&m.roughness_texname, "map_Pr"}, {&m.metallic_texname, "map_Pm"},
      {&m.sheen_texname, "map_Ps"},    {&m.emissive_texname, "map_Ke"},  {&m.normal_texname, "norm"}};
  for (const auto& [texture, name] : maps) {
    if (!texture->empty() && std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  }
}

ObjData parse(const std::string& path, const std::string& where) {
  const MappedFile file(path, where);
  const ObjLines lines = checkLines(file.bytes(), path, where);
  const std::vector<uint32_t>& faceSizes = lines.faceSizes;
  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> materials;
  std::string warning, error;
  BytesStream in(file.bytes());
  MaterialLibraries libraries(std::filesystem::path(path).parent_path().string(), path, where);
  // Polygons are cut by ear clipping (polygon.h), not fanned: no triangulation here.
  if (!tinyobj::LoadObj(&attrib, &shapes, &materials, &warning, &error, &in, &libraries, false, false))
    fail(where, path, "not a valid OBJ file: " + firstLine(error));
  // tinyobjloader skips a quad with a bad index, with only this warning.
  if (warning.find("invalid vertex index") != std::string::npos) {
    const std::string at = badIndexAt(file.bytes(), {attrib.vertices.size() / 3, attrib.texcoords.size() / 2, attrib.normals.size() / 3});
    fail(where, path, at.empty() ? "a face has an invalid vertex index" : at);
  }
  ObjData data{attrib.vertices, attrib.normals, attrib.texcoords, {}, faceSizes, {}, {}, {}, {}, {}, {}};
  for (const tinyobj::material_t& m : materials) {
    data.diffuseMaps.push_back(m.diffuse_texname);
    noteIgnoredMaps(m, data.ignoredMaps);
  }
  size_t faces = 0;
  for (const tinyobj::shape_t& shape : shapes) {
    data.corners.insert(data.corners.end(), shape.mesh.indices.begin(), shape.mesh.indices.end());
    data.faceMaterials.insert(data.faceMaterials.end(), shape.mesh.material_ids.begin(), shape.mesh.material_ids.end());
    for (size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f, ++faces) {
      // tinyobjloader's count is the low 8 bits of ours (a face of 300 corners: 44): ours is kept.
      if (faces >= faceSizes.size() || uint8_t(faceSizes[faces]) != uint8_t(shape.mesh.num_face_vertices[f]))
        fail(where, path, "tinyobjloader read the faces differently from the file's 'f' lines");
    }
  }
  size_t corners = 0;
  for (uint32_t size : faceSizes) corners += size;
  if (faces != faceSizes.size() || corners != data.corners.size())
    fail(where, path, "tinyobjloader read the faces differently from the file's 'f' lines");
  checkIndices(data, file.bytes(), path, where);
  addPointsAndLines(data, lines, path, where);
  return data;
}

// Finite, and within the scene's coordinate range: a float position that overflowed to inf would
// make NaN vertices.
void checkPositions(const ObjData& data, const std::string& path, const std::string& where) {
  for (float x : data.positions) {
    if (!std::isfinite(x)) fail(where, path, "a vertex position is not a finite number");
    if (std::abs(double(x)) > MAX_COORDINATE)
      fail(where, path,
           "a vertex coordinate is " + formatNumber(double(x)) + ", beyond the " +
               formatNumber(MAX_COORDINATE) + " m a scene may use");
  }
}

// Usable file normals: every face corner has one, finite and not zero. (Points and lines have
// their own: none, or in a point cloud the usable ones of its 'vn' lines.)
bool hasFileNormals(const ObjData& data) {
  for (const tinyobj::index_t& c : data.corners) {
    if (!usableNormal(data.normals, c.normal_index)) return false;
  }
  return true;
}

// The materials' diffuse maps, each decoded once (file by file), as the mesh's textures; and each
// material's index among them (gpu::TEXTURE_NONE for a material without one).
std::vector<uint32_t> loadDiffuseMaps(const ObjData& data, Mesh& mesh, const std::string& path, const std::string& where) {
  std::vector<uint32_t> textureOf(data.diffuseMaps.size(), gpu::TEXTURE_NONE);
  std::map<std::string, uint32_t> byFile;
  for (size_t m = 0; m < data.diffuseMaps.size(); ++m) {
    if (data.diffuseMaps[m].empty()) continue;
    const std::string file = texturePathBeside(data.diffuseMaps[m], path);
    const auto [it, added] = byFile.emplace(file, uint32_t(mesh.textures.size()));
    if (added) {
      mesh.textures.push_back(std::make_shared<const TextureImage>(
          readTextureFile(file, where + ": " + path + ": map_Kd '" + data.diffuseMaps[m] + "'")));
    }
    textureOf[m] = it->second;
  }
  return textureOf;
}

// A vertex of the mesh: the position, normal and texture coordinate indices of a corner and the
// texture its face samples (gpu::TEXTURE_NONE, and no coordinate, where none).
struct CornerKey {
  uint32_t position, normal, texcoord, texture;
  bool operator==(const CornerKey&) const = default;
};

struct CornerHash {
  size_t operator()(const CornerKey& k) const {
    return std::hash<uint64_t>()((uint64_t(k.position) << 32 | k.normal) ^ (uint64_t(k.texcoord) << 32 | k.texture) * 0x9E3779B97F4A7C15ull);
  }
};

// Whether every corner of the face starting at corners[k] has a texture coordinate.
bool faceHasTexcoords(const ObjData& data, size_t k, uint32_t size) {
  for (uint32_t c = 0; c < size; ++c) {
    if (data.corners[k + c].texcoord_index < 0) return false;
  }
  return true;
}

// Vertices are the distinct corners (position, normal, and where the face samples a texture its
// texture coordinate and texture) the faces, points and lines use, in the order of first use; with
// file normals, a point's or a line's vertex without one has (0, 0, 0). OBJ's v runs up the image,
// phongvk's down (texture_image.h): v becomes 1 - v.
Mesh buildMesh(const ObjData& data, bool fileNormals, const std::string& path, const std::string& where) {
  Mesh mesh;
  const std::vector<uint32_t> textureOf = loadDiffuseMaps(data, mesh, path, where);
  const bool textured = !mesh.textures.empty();
  std::unordered_map<CornerKey, uint32_t, CornerHash> vertexOf;  // lookups only
  auto vertex = [&](const tinyobj::index_t& c, uint32_t texture) {
    const int normal = fileNormals ? c.normal_index : 0;
    const uint32_t texcoord = texture == gpu::TEXTURE_NONE ? 0u : uint32_t(c.texcoord_index);
    auto [it, inserted] = vertexOf.try_emplace({uint32_t(c.vertex_index), uint32_t(normal), texcoord, texture},
                                               uint32_t(mesh.positions.size()));
    if (inserted) {
      mesh.positions.push_back(glm::vec3(at(data.positions, c.vertex_index)));
      if (fileNormals) mesh.normals.push_back(normal < 0 ? glm::vec3(0.0f) : glm::vec3(at(data.normals, normal)));
      if (textured) {
        const bool has = texture != gpu::TEXTURE_NONE;
        const double u = has ? data.texcoords[2 * size_t(texcoord)] : 0.0, v = has ? data.texcoords[2 * size_t(texcoord) + 1] : 1.0;
        mesh.uvs.push_back(glm::vec2(float(u), float(1.0 - v)));
        mesh.textureIds.push_back(texture);
      }
    }
    return it->second;
  };
  std::vector<uint32_t> face;
  size_t k = 0;
  for (size_t f = 0; f < data.faceSizes.size(); ++f) {
    const uint32_t size = data.faceSizes[f];
    const int material = f < data.faceMaterials.size() ? data.faceMaterials[f] : -1;
    uint32_t texture = material >= 0 && size_t(material) < textureOf.size() ? textureOf[size_t(material)] : gpu::TEXTURE_NONE;
    if (!faceHasTexcoords(data, k, size)) texture = gpu::TEXTURE_NONE;
    face.clear();
    for (unsigned int c = 0; c < size; ++c) face.push_back(vertex(data.corners[k + c], texture));
    k += size;
    triangulatePolygon(mesh.positions, face, mesh.triangles);
  }
  const auto untextured = [&](const tinyobj::index_t& c) { return vertex(c, gpu::TEXTURE_NONE); };
  for (const tinyobj::index_t& c : data.pointCorners) mesh.points.push_back(untextured(c));
  size_t first = 0;  // each polyline: its consecutive pairs
  for (uint32_t size : data.lineSizes) {
    for (uint32_t i = 0; i + 1 < size; ++i) mesh.lines.push_back({untextured(data.lineCorners[first + i]), untextured(data.lineCorners[first + i + 1])});
    first += size;
  }
  return mesh;
}

}  // namespace

Mesh importObj(const std::string& path, const std::string& where) {
  ObjData data = parse(path, where);
  checkPositions(data, path, where);
  Mesh mesh = buildMesh(data, hasFileNormals(data), path, where);
  mesh.notice = ignoredMapsNotice(path, data.ignoredMaps);
  return mesh;
}

}  // namespace phongvk
