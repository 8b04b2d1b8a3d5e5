// ply_file.cpp — see ply_file.h.
#include "meshio/ply_file.h"

#include "base/huge_pages.h"
#include "base/number_text.h"
#include "base/text_words.h"
#include "geometry/polygon.h"
#include "image/texture_decode.h"
#include "meshio/mesh_import.h"
#include "phongvk/errors.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cctype>
#include <charconv>
#include <cstring>
#include <sstream>
#include <type_traits>
#include <vector>

namespace phongvk {
namespace {

enum class Type { None, Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

struct Property {
  std::string name;
  Type type = Type::None;       // a scalar's type, or a list's item type
  Type countType = Type::None;  // lists: the length's type; None for scalars
};

struct Element {
  std::string name;
  uint64_t count = 0;
  std::vector<Property> properties;
};

struct Header {
  std::string format;
  size_t end = 0;  // offset of the first byte after "end_header\n"
  std::vector<Element> elements;
  std::string textureFile;  // the first "comment TextureFile <name>" (MeshLab's, Blender's)
};

[[noreturn]] void fail(const std::string& where, const std::string& path, const std::string& why) {
  throw SceneError(where + ": " + path + ": " + why);
}

Type typeOf(const std::string& name) {
  if (name == "char" || name == "int8") return Type::Int8;
  if (name == "uchar" || name == "uint8") return Type::UInt8;
  if (name == "short" || name == "int16") return Type::Int16;
  if (name == "ushort" || name == "uint16") return Type::UInt16;
  if (name == "int" || name == "int32") return Type::Int32;
  if (name == "uint" || name == "uint32") return Type::UInt32;
  if (name == "float" || name == "float32") return Type::Float32;
  if (name == "double" || name == "float64") return Type::Float64;
  return Type::None;
}

int sizeOf(Type t) {
  switch (t) {
    case Type::Int8: case Type::UInt8: return 1;
    case Type::Int16: case Type::UInt16: return 2;
    case Type::Int32: case Type::UInt32: case Type::Float32: return 4;
    case Type::Float64: return 8;
    case Type::None: return 0;
  }
  return 0;
}

bool isInteger(Type t) { return t != Type::None && t != Type::Float32 && t != Type::Float64; }

Header parseHeader(std::string_view bytes, const std::string& path, const std::string& where) {
  Header header;
  const size_t limit = std::min<size_t>(bytes.size(), 1 << 16);
  size_t at = 0;
  for (int lineNumber = 1; at < limit; ++lineNumber) {
    const size_t newline = bytes.find('\n', at);
    if (newline == std::string_view::npos || newline >= limit) break;
    std::string line(bytes.substr(at, newline - at));
    at = newline + 1;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    const auto bad = [&](const std::string& why) { fail(where, path, "header line " + std::to_string(lineNumber) + ": " + why); };
    if (keyword == "end_header") {
      if (line.find_last_not_of(" \t") + 1 != std::string("end_header").size() || line.rfind("end_header", 0) != 0)
        bad("'end_header' must be alone on its line");
      header.end = at;  // the first byte after the line's newline
      if (header.format.empty()) bad("no 'format' line");
      return header;
    }
    if (keyword == "format") {
      words >> header.format;
      if (header.format != "ascii" && header.format != "binary_little_endian" && header.format != "binary_big_endian")
        bad("unknown format '" + header.format + "'");
    } else if (keyword == "element") {
      Element element;
      std::string count;
      words >> element.name >> count;
      const auto [end, error] = std::from_chars(count.data(), count.data() + count.size(), element.count);
      if (element.name.empty() || count.empty() || error != std::errc() || end != count.data() + count.size())
        bad("an element needs a name and a count (a whole number), got '" + line + "'");
      header.elements.push_back(element);
    } else if (keyword == "comment") {
      std::string word;
      words >> word;
      if (word == "TextureFile" && header.textureFile.empty()) {
        std::getline(words >> std::ws, header.textureFile);
        header.textureFile.erase(header.textureFile.find_last_not_of(" \t") + 1);
      }
    } else if (keyword == "property") {
      if (header.elements.empty()) bad("a property before any element");
      std::string type;
      words >> type;
      Property property;
      if (type == "list") {
        std::string countType, itemType;
        words >> countType >> itemType;
        property.countType = typeOf(countType);
        property.type = typeOf(itemType);
        if (!isInteger(property.countType) || sizeOf(property.countType) == 8 || property.type == Type::None)
          bad("unknown list types '" + countType + " " + itemType + "' (a list's length is an integer)");
      } else {
        property.type = typeOf(type);
        if (property.type == Type::None) bad("unknown type '" + type + "'");
      }
      words >> property.name;
      header.elements.back().properties.push_back(property);
    }
  }
  fail(where, path, "no 'end_header' line in the first 64 KB");
}

// Reads binary values of either byte order, at increasing offsets; the layout check has made sure
// every read stays inside the file.
class Cursor {
 public:
  Cursor(std::string_view bytes, size_t at, bool bigEndian) : bytes_(bytes), at_(at), bigEndian_(bigEndian) {}

  double read(Type t) {
    switch (t) {
      case Type::Int8: return double(get<int8_t>());
      case Type::UInt8: return double(get<uint8_t>());
      case Type::Int16: return double(get<int16_t>());
      case Type::UInt16: return double(get<uint16_t>());
      case Type::Int32: return double(get<int32_t>());
      case Type::UInt32: return double(get<uint32_t>());
      case Type::Float32: return double(get<float>());
      case Type::Float64: return get<double>();
      case Type::None: return 0;
    }
    return 0;
  }
  void skip(size_t n) { at_ += n; }
  size_t at() const { return at_; }
  void beginRow(const Element&, uint64_t) {}
  // A list's length (the layout check has bounded it by the file) and then its items are read.
  double listLength(const Property& p) { return read(p.countType); }
  void skipList(const Property& p, double length) { skip(size_t(length) * size_t(sizeOf(p.type))); }

 private:
  template <typename T>
  T get() {
    unsigned char raw[sizeof(T)];
    std::memcpy(raw, bytes_.data() + at_, sizeof(T));
    if (bigEndian_) std::reverse(raw, raw + sizeof(T));
    at_ += sizeof(T);
    T value;
    std::memcpy(&value, raw, sizeof(T));
    return value;
  }

  std::string_view bytes_;
  size_t at_;
  bool bigEndian_;
};

// Reads an ASCII file's element rows, one line each, value by value; every value must be a
// number, every list's length a whole number within the line. Messages name the line.
class TextCursor {
 public:
  TextCursor(std::string_view bytes, size_t at, const std::string& path, const std::string& where)
      : bytes_(bytes), at_(at), path_(path), where_(where) {
    for (size_t i = 0; i < at && i < bytes.size(); ++i) line_ += bytes[i] == '\n';
  }

  void beginRow(const Element& element, uint64_t index) {
    element_ = &element;
    index_ = index;
    tokens_.clear();
    next_ = 0;
    while (tokens_.empty()) {
      if (at_ >= bytes_.size()) bad("the file ends early");
      const size_t end = std::min(bytes_.find('\n', at_), bytes_.size());
      ++line_;
      appendWords(bytes_.substr(at_, end - at_), tokens_);
      at_ = end + 1;
    }
  }

  double read(Type) {
    if (next_ >= tokens_.size()) bad("fewer values than the header's properties");
    const std::string_view token = tokens_[next_++];
    double value = 0;
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (error != std::errc() || end != token.data() + token.size()) {
      std::string why(1, '\'');  // appended piece by piece: GCC 12 warns (-Wrestrict) on "'" + ...
      bad(why.append(token).append("' is not a number"));
    }
    return value;
  }

  double listLength(const Property& p) {
    const double length = read(p.countType);
    if (!(length >= 0 && length <= double(tokens_.size() - next_) && length == std::floor(length)))
      bad("a list length of " + formatNumber(length) + " where " + std::to_string(tokens_.size() - next_) + " values follow");
    return length;
  }

  void skipList(const Property&, double length) { next_ += size_t(length); }

 private:
  [[noreturn]] void bad(const std::string& why) const {
    fail(where_, path_, "line " + std::to_string(line_) + " (element '" + element_->name + "' " + std::to_string(index_) + "): " + why);
  }

  std::string_view bytes_;
  size_t at_;
  const std::string& path_;
  const std::string& where_;
  uint64_t line_ = 0;
  const Element* element_ = nullptr;
  uint64_t index_ = 0;
  std::vector<std::string_view> tokens_;
  size_t next_ = 0;
};

void walkBinary(const Header& header, std::string_view bytes, const std::string& path, const std::string& where) {
  const bool bigEndian = header.format == "binary_big_endian";
  uint64_t at = header.end;
  for (const Element& element : header.elements) {
    bool lists = false;
    uint64_t rowSize = 0;
    for (const Property& p : element.properties) {
      lists = lists || p.countType != Type::None;
      rowSize += uint64_t(sizeOf(p.type));
    }
    const auto truncated = [&](uint64_t index) {
      fail(where, path, "element '" + element.name + "' " + std::to_string(index) + " of " + std::to_string(element.count) +
                            " runs past the end of the file (" + std::to_string(bytes.size()) + " bytes)");
    };
    if (!lists) {
      if (rowSize != 0 && element.count > (bytes.size() - at) / rowSize) truncated((bytes.size() - at) / rowSize);
      at += element.count * rowSize;
      continue;
    }
    for (uint64_t i = 0; i < element.count; ++i) {
      for (const Property& p : element.properties) {
        const uint64_t size = uint64_t(sizeOf(p.type));
        if (p.countType == Type::None) {
          if (size > bytes.size() - at) truncated(i);
          at += size;
          continue;
        }
        const uint64_t countSize = uint64_t(sizeOf(p.countType));
        if (countSize > bytes.size() - at) truncated(i);
        const double length = Cursor(bytes, size_t(at), bigEndian).read(p.countType);
        at += countSize;
        if (length < 0 || length > double(bytes.size() - at) / double(size)) truncated(i);
        at += uint64_t(length) * size;
      }
    }
  }
}

// Where in a vertex row each wanted property is (-1: absent).
struct VertexLayout {
  int position[3] = {-1, -1, -1};
  int normal[3] = {-1, -1, -1};
  int color[3] = {-1, -1, -1};
  int uv[2] = {-1, -1};
};

// The vertex's scalar property called `name` (the last, if the header names it twice), or -1.
int propertyIndex(const Element& vertex, const char* name) {
  int index = -1;
  for (size_t p = 0; p < vertex.properties.size(); ++p) {
    if (vertex.properties[p].countType == Type::None && vertex.properties[p].name == name) index = int(p);
  }
  return index;
}

VertexLayout vertexLayout(const Element& vertex) {
  static const char* kNames[9] = {"x", "y", "z", "nx", "ny", "nz", "red", "green", "blue"};
  VertexLayout layout;
  int* slots[9] = {&layout.position[0], &layout.position[1], &layout.position[2], &layout.normal[0], &layout.normal[1],
                   &layout.normal[2],   &layout.color[0],    &layout.color[1],    &layout.color[2]};
  for (int k = 0; k < 9; ++k) *slots[k] = propertyIndex(vertex, kNames[k]);
  // Colours by the other names scanners write (diffuse_red, ...), where red, green, blue are not all there.
  static const char* kDiffuseNames[3] = {"diffuse_red", "diffuse_green", "diffuse_blue"};
  if (layout.color[0] < 0 || layout.color[1] < 0 || layout.color[2] < 0) {
    for (int k = 0; k < 3; ++k) layout.color[k] = propertyIndex(vertex, kDiffuseNames[k]);
  }
  // Texture coordinates, by the names exporters use: the first pair present.
  static const char* kUvNames[4][2] = {{"u", "v"}, {"s", "t"}, {"texture_u", "texture_v"}, {"texture_s", "texture_t"}};
  for (const auto& names : kUvNames) {
    if (layout.uv[0] >= 0) break;
    if (propertyIndex(vertex, names[0]) >= 0 && propertyIndex(vertex, names[1]) >= 0)
      layout.uv[0] = propertyIndex(vertex, names[0]), layout.uv[1] = propertyIndex(vertex, names[1]);
  }
  return layout;
}

uint32_t colorChannel(double value, Type type) {
  const double unit = type == Type::Float32 || type == Type::Float64 ? value : value / 255.0;
  return uint32_t(std::lround(std::fmin(std::fmax(std::isnan(unit) ? 0.0 : unit, 0.0), 1.0) * 255.0));
}

// Reads the elements through `Cursor` (binary) or `TextCursor` (ASCII).
template <typename Rows>
class Reader {
 public:
  // `maxRows`: at most this many rows fit in the file (each at least a byte).
  Reader(const Header& header, uint64_t maxRows, const std::string& path, const std::string& where)
      : header_(header), maxRows_(maxRows), path_(path), where_(where) {}

  Mesh read(Rows& cursor) {
    const Element* vertex = nullptr;
    for (const Element& element : header_.elements) {
      // Binary rows of no properties take no bytes: nothing to read, however many the header says.
      if (element.properties.empty() && std::is_same_v<Rows, Cursor>) continue;
      if (element.name == "vertex" && !vertex) {
        vertex = &element;
        readVertices(element, cursor);
      } else if (element.name == "face") {
        readFaces(element, cursor);
      } else if (element.name == "edge") {
        readEdges(element, cursor);
      } else {
        skipElement(element, cursor);
      }
    }
    if (!vertex) fail(where_, path_, "no 'vertex' element");
    if (part_.triangles.empty() && part_.points.empty() && part_.lines.empty()) {  // a point cloud
      part_.points.resize(part_.positions.size());
      for (size_t v = 0; v < part_.points.size(); ++v) part_.points[v] = uint32_t(v);
    }
    std::vector<MeshPart> parts(1);
    parts[0] = std::move(part_);
    // A zero normal is unusable where a triangle may use it, and (0, 0, 0), unlit, on points and lines alone.
    if (badNormal_ || (zeroNormal_ && !parts[0].triangles.empty())) parts[0].normals.clear();
    Mesh mesh = joinParts(parts, false, where_ + ": " + path_);
    if (faceTexcoords_)
      mesh.notice = path_ + ": its per-face texture coordinates (texcoord lists) are not read (phongvk reads u and v per vertex)";
    return mesh;
  }

 private:
  void readVertices(const Element& element, Rows& cursor) {
    const VertexLayout layout = vertexLayout(element);
    for (int k = 0; k < 3; ++k)
      if (layout.position[k] < 0) fail(where_, path_, "the vertex element has no x, y and z");
    const bool normals = layout.normal[0] >= 0 && layout.normal[1] >= 0 && layout.normal[2] >= 0;
    const bool colors = layout.color[0] >= 0 && layout.color[1] >= 0 && layout.color[2] >= 0;
    // Texture coordinates count where the header names a texture; v runs up the image there, as
    // in OBJ, and down in phongvk (texture_image.h).
    const bool uvs = layout.uv[0] >= 0 && !header_.textureFile.empty();
    if (uvs) part_.texture = std::make_shared<const TextureImage>(readTextureFile(
                 texturePathBeside(header_.textureFile, path_), where_ + ": " + path_ + ": TextureFile '" + header_.textureFile + "'"));
    std::vector<double> row(element.properties.size());
    const size_t rows = size_t(std::min<uint64_t>(element.count, maxRows_));  // a header may promise more than is there
    reserveLarge(part_.positions, rows);
    if (layout.normal[0] >= 0) reserveLarge(part_.normals, rows);
    for (uint64_t v = 0; v < element.count; ++v) {
      cursor.beginRow(element, v);
      for (size_t p = 0; p < element.properties.size(); ++p) row[p] = readProperty(element.properties[p], cursor);
      const glm::dvec3 position(row[size_t(layout.position[0])], row[size_t(layout.position[1])], row[size_t(layout.position[2])]);
      for (int k = 0; k < 3; ++k) {
        if (!(std::abs(position[k]) <= MAX_COORDINATE))
          fail(where_, path_, "vertex " + std::to_string(v) + " is not finite or beyond the " +
                                  formatNumber(MAX_COORDINATE) + " m a scene may use");
      }
      part_.positions.push_back(glm::vec3(position));
      if (normals) addNormal(glm::dvec3(row[size_t(layout.normal[0])], row[size_t(layout.normal[1])], row[size_t(layout.normal[2])]));
      if (colors) {
        uint32_t c = 0xFF000000u;
        for (int k = 0; k < 3; ++k)
          c |= colorChannel(row[size_t(layout.color[k])], element.properties[size_t(layout.color[k])].type) << (8 * k);
        part_.colors.push_back(c);
      }
      if (uvs) part_.uvs.push_back(glm::vec2(float(row[size_t(layout.uv[0])]), float(1.0 - row[size_t(layout.uv[1])])));
    }
    badNormal_ = badNormal_ || !normals;
  }

  void addNormal(const glm::dvec3& n) {
    const double length = glm::length(n);
    badNormal_ = badNormal_ || !std::isfinite(length);
    zeroNormal_ = zeroNormal_ || length == 0.0;
    part_.normals.push_back(length == 0.0 ? glm::vec3(0.0f) : glm::vec3(n));
  }

  double readProperty(const Property& p, Rows& cursor) {
    if (p.countType == Type::None) return cursor.read(p.type);
    cursor.skipList(p, cursor.listLength(p));
    return 0;
  }

  void readFaces(const Element& element, Rows& cursor) {
    reserveLarge(part_.triangles, size_t(std::min<uint64_t>(element.count, maxRows_)));
    const size_t vertices = part_.positions.size();
    for (uint64_t f = 0; f < element.count; ++f) {
      cursor.beginRow(element, f);
      for (const Property& p : element.properties) {
        faceTexcoords_ = faceTexcoords_ || p.name == "texcoord";
        if (p.countType == Type::None || (p.name != "vertex_indices" && p.name != "vertex_index")) {
          readProperty(p, cursor);
          continue;
        }
        if (!isInteger(p.type)) fail(where_, path_, "the face element's " + p.name + " are not integers");
        const double length = cursor.listLength(p);
        if (length == 0) fail(where_, path_, "face " + std::to_string(f) + " has no vertices");
        corners_.clear();
        for (uint64_t k = 0; k < uint64_t(length); ++k) {
          const double index = cursor.read(p.type);
          if (!(index >= 0 && index < double(vertices)))
            fail(where_, path_, "face " + std::to_string(f) + " has vertex index " + formatNumber(index) +
                                    ", but there are " + std::to_string(vertices) + " vertices");
          corners_.push_back(uint32_t(index));
        }
        if (corners_.size() >= 3) triangulatePolygon(part_.positions, corners_, part_.triangles);
        if (corners_.size() == 2) part_.lines.push_back({corners_[0], corners_[1]});
        if (corners_.size() == 1) part_.points.push_back(corners_[0]);
      }
    }
  }

  // The edge element's rows as lines: vertex1 to vertex2 (other properties read and passed over).
  void readEdges(const Element& element, Rows& cursor) {
    const int ends[2] = {propertyIndex(element, "vertex1"), propertyIndex(element, "vertex2")};
    if (ends[0] < 0 || ends[1] < 0) fail(where_, path_, "the edge element has no vertex1 and vertex2");
    for (int end : ends) {
      if (!isInteger(element.properties[size_t(end)].type))
        fail(where_, path_, "the edge element's " + element.properties[size_t(end)].name + " is not an integer");
    }
    reserveLarge(part_.lines, part_.lines.size() + size_t(std::min<uint64_t>(element.count, maxRows_)));
    std::vector<double> row(element.properties.size());
    const size_t vertices = part_.positions.size();
    for (uint64_t e = 0; e < element.count; ++e) {
      cursor.beginRow(element, e);
      for (size_t p = 0; p < element.properties.size(); ++p) row[p] = readProperty(element.properties[p], cursor);
      glm::uvec2 line;
      for (int k = 0; k < 2; ++k) {
        const double index = row[size_t(ends[k])];
        if (!(index >= 0 && index < double(vertices)))
          fail(where_, path_, "edge " + std::to_string(e) + " has vertex index " + formatNumber(index) + ", but there are " +
                                  std::to_string(vertices) + " vertices");
        line[k] = uint32_t(index);
      }
      part_.lines.push_back(line);
    }
  }

  void skipElement(const Element& element, Rows& cursor) {
    if constexpr (std::is_same_v<Rows, Cursor>) {  // rows of fixed size (the layout check bounded them): one step
      bool lists = false;
      size_t rowSize = 0;
      for (const Property& p : element.properties) {
        lists = lists || p.countType != Type::None;
        rowSize += size_t(sizeOf(p.type));
      }
      if (!lists) {
        cursor.skip(size_t(element.count) * rowSize);
        return;
      }
    }
    for (uint64_t i = 0; i < element.count; ++i) {
      cursor.beginRow(element, i);
      for (const Property& p : element.properties) readProperty(p, cursor);
    }
  }

  const Header& header_;
  uint64_t maxRows_;
  const std::string& path_;
  const std::string& where_;
  MeshPart part_;
  std::vector<uint32_t> corners_;  // the face being read
  bool badNormal_ = false;   // a normal that is not finite, or no nx, ny, nz: none are used
  bool zeroNormal_ = false;  // a normal of zero length
  bool faceTexcoords_ = false;  // MeshLab's per-face "texcoord" lists, which are not read
};

}  // namespace

Mesh readPly(std::string_view bytes, const std::string& path, const std::string& where) {
  const Header header = parseHeader(bytes, path, where);
  if (header.format == "ascii") {
    TextCursor rows(bytes, header.end, path, where);
    return Reader<TextCursor>(header, bytes.size() - header.end, path, where).read(rows);
  }
  walkBinary(header, bytes, path, where);
  Cursor rows(bytes, header.end, header.format == "binary_big_endian");
  return Reader<Cursor>(header, bytes.size() - header.end, path, where).read(rows);
}

}  // namespace phongvk
