// obj_import.cpp — see obj_import.h. tinyobjloader parses and triangulates; everything it lets
// through unchecked (indices out of range, numbers it reads as 0, NaN) is checked here.
#include "scene/obj_import.h"

#include "scene/normals.h"
#include "scene/scene_json.h"

#include <tiny_obj_loader.h>

#include <cassert>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <unordered_map>

namespace phongvk {
namespace {

struct ObjData {
  std::vector<float> positions;           // xyz per position
  std::vector<float> normals;             // xyz per normal
  std::vector<tinyobj::index_t> corners;  // three per triangle
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
bool isPlainNumber(const std::string& token) {
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

// Every number on the file's v, vn and vt lines is a plain decimal number (up to a '#' comment).
void checkNumbers(const std::string& path, const std::string& where) {
  std::ifstream in(path);
  std::string line;
  for (size_t lineNumber = 1; std::getline(in, line); ++lineNumber) {
    std::istringstream words(line.substr(0, line.find('#')));
    std::string keyword, token;
    words >> keyword;
    if (keyword != "v" && keyword != "vn" && keyword != "vt") continue;
    while (words >> token) {
      if (!isPlainNumber(token))
        fail(where, path, "line " + std::to_string(lineNumber) + ": '" + token + "' in a '" + keyword +
                              "' line is not a number");
    }
  }
}

ObjData parse(const std::string& path, const std::string& where) {
  if (!std::ifstream(path)) fail(where, path, "cannot open the file");
  checkNumbers(path, where);
  tinyobj::ObjReaderConfig config;
  config.triangulate = true;
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  if (!reader.ParseFromFile(path, config))
    fail(where, path, "not a valid OBJ file: " + firstLine(reader.Error()));
  // tinyobjloader skips a quad with a bad index, with only this warning.
  if (reader.Warning().find("invalid vertex index") != std::string::npos)
    fail(where, path, "a face's vertex index is out of range");
  ObjData data{reader.GetAttrib().vertices, reader.GetAttrib().normals, {}};
  for (const tinyobj::shape_t& shape : reader.GetShapes())
    data.corners.insert(data.corners.end(), shape.mesh.indices.begin(), shape.mesh.indices.end());
  if (data.corners.empty()) fail(where, path, "no triangles (no 'f' lines)");
  assert(data.corners.size() % 3 == 0);
  return data;
}

void checkIndices(const ObjData& data, const std::string& path, const std::string& where) {
  const size_t positionCount = data.positions.size() / 3, normalCount = data.normals.size() / 3;
  for (const tinyobj::index_t& c : data.corners) {
    if (c.vertex_index < 0 || size_t(c.vertex_index) >= positionCount)
      fail(where, path,
           "a face's vertex index is out of range (the file has " + std::to_string(positionCount) +
               " vertices)");
    if (c.normal_index >= 0 && size_t(c.normal_index) >= normalCount)
      fail(where, path,
           "a face's normal index is out of range (the file has " + std::to_string(normalCount) +
               " normals)");
  }
}

// Finite, and within the scene's coordinate range: a float position that overflowed to inf would
// make NaN vertices.
void checkPositions(const ObjData& data, const std::string& path, const std::string& where) {
  for (float x : data.positions) {
    if (!std::isfinite(x)) fail(where, path, "a vertex position is not a finite number");
    if (std::abs(double(x)) > MAX_COORDINATE)
      fail(where, path,
           "a vertex coordinate is " + scenejson::formatNumber(double(x)) + ", beyond the " +
               scenejson::formatNumber(MAX_COORDINATE) + " m a scene may use");
  }
}

glm::dvec3 at(const std::vector<float>& xyz, int index) {
  return {xyz[3 * size_t(index)], xyz[3 * size_t(index) + 1], xyz[3 * size_t(index) + 2]};
}

// Usable file normals: every corner has one, finite and not zero.
bool hasFileNormals(const ObjData& data) {
  for (const tinyobj::index_t& c : data.corners) {
    if (c.normal_index < 0) return false;
    glm::dvec3 n = at(data.normals, c.normal_index);
    if (!std::isfinite(glm::length(n)) || glm::length(n) == 0.0) return false;
  }
  return true;
}

// Vertices are the distinct (position, normal) index pairs the faces use, in the order of first use.
Mesh buildMesh(const ObjData& data, bool fileNormals) {
  Mesh mesh;
  std::unordered_map<uint64_t, uint32_t> vertexOf;  // (position, normal) index pair -> vertex; lookups only
  auto vertex = [&](const tinyobj::index_t& c) {
    const int normal = fileNormals ? c.normal_index : 0;
    const uint64_t key = (uint64_t(uint32_t(c.vertex_index)) << 32) | uint32_t(normal);
    auto [it, inserted] = vertexOf.try_emplace(key, uint32_t(mesh.positions.size()));
    if (inserted) {
      mesh.positions.push_back(glm::vec3(at(data.positions, c.vertex_index)));
      if (fileNormals) mesh.normals.push_back(glm::vec3(at(data.normals, normal)));
    }
    return it->second;
  };
  for (size_t k = 0; k < data.corners.size(); k += 3) {
    mesh.triangles.push_back({vertex(data.corners[k]), vertex(data.corners[k + 1]), vertex(data.corners[k + 2])});
  }
  return mesh;
}

}  // namespace

Mesh importObj(const std::string& path, const std::string& where) {
  ObjData data = parse(path, where);
  checkIndices(data, path, where);
  checkPositions(data, path, where);
  return buildMesh(data, hasFileNormals(data));
}

}  // namespace phongvk
