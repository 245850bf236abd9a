#include "core/shapes/ply_reader.h"

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <vector>

#include "core/errors/interrupted.h"

namespace caustica {
namespace {
namespace CAUSTICA_UNITY_ID {

enum class Format { Ascii, LittleEndian, BigEndian };
enum class Type { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

struct Property {
  std::string name;
  Type type;
  std::optional<Type> count_type;  // set for a list; `type` is then its items' type
};

struct Element {
  std::string name;
  uint64_t count = 0;
  std::vector<Property> properties;
};

// Long enough for any real header; a file that has not ended its header by
// then is not a PLY file worth reading further.
constexpr size_t kMaxHeaderBytes = 1 << 20;
constexpr uint64_t kStopCheckInterval = 1 << 16;

std::optional<Type> parse_type(std::string_view name) {
  static const std::array<std::pair<std::string_view, Type>, 16> names{{{"char", Type::Int8},
                                                                        {"int8", Type::Int8},
                                                                        {"uchar", Type::UInt8},
                                                                        {"uint8", Type::UInt8},
                                                                        {"short", Type::Int16},
                                                                        {"int16", Type::Int16},
                                                                        {"ushort", Type::UInt16},
                                                                        {"uint16", Type::UInt16},
                                                                        {"int", Type::Int32},
                                                                        {"int32", Type::Int32},
                                                                        {"uint", Type::UInt32},
                                                                        {"uint32", Type::UInt32},
                                                                        {"float", Type::Float32},
                                                                        {"float32", Type::Float32},
                                                                        {"double", Type::Float64},
                                                                        {"float64", Type::Float64}}};
  for (const auto& [n, t] : names)
    if (n == name) return t;
  return std::nullopt;
}

size_t type_size(Type t) {
  switch (t) {
    case Type::Int8:
    case Type::UInt8:
      return 1;
    case Type::Int16:
    case Type::UInt16:
      return 2;
    case Type::Int32:
    case Type::UInt32:
    case Type::Float32:
      return 4;
    case Type::Float64:
      return 8;
  }
  return 0;
}

bool is_integer(Type t) { return t != Type::Float32 && t != Type::Float64; }

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

std::vector<std::string_view> words(std::string_view line) {
  std::vector<std::string_view> out;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    const size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

// Shows at most a short, printable excerpt of what the file holds.
std::string excerpt(std::string_view text) {
  std::string out;
  for (char c : text.substr(0, 40)) out += (c >= 32 && c < 127) ? c : '?';
  return text.size() > 40 ? out + "..." : out;
}

struct Header {
  Format format = Format::Ascii;
  std::vector<Element> elements;
  size_t body = 0;    // offset of the first byte after end_header
  int body_line = 0;  // line number of the body's first line
};

Header parse_header(std::string_view bytes) {
  Header header;
  size_t pos = 0;
  int line_number = 0;
  bool have_format = false;
  const auto fail = [&](const std::string& problem) -> PlyError {
    return PlyError("line " + std::to_string(line_number) + ": " + problem);
  };
  while (true) {
    const size_t end = bytes.find('\n', pos);
    if (end == std::string_view::npos || end > kMaxHeaderBytes) {
      ++line_number;
      throw fail(end == std::string_view::npos ? "the header has no end_header line"
                                               : "the header is longer than 1 MiB without an end_header line");
    }
    const std::string_view line = bytes.substr(pos, end - pos);
    pos = end + 1;
    ++line_number;
    const auto w = words(line);
    if (line_number == 1) {
      if (w.size() != 1 || w[0] != "ply") throw fail("not a PLY file (it does not start with 'ply')");
      continue;
    }
    if (w.empty() || w[0] == "comment" || w[0] == "obj_info") continue;
    if (w[0] == "format") {
      if (w.size() != 3 || w[2] != "1.0") throw fail("expected 'format <kind> 1.0', got '" + excerpt(line) + "'");
      if (w[1] == "ascii")
        header.format = Format::Ascii;
      else if (w[1] == "binary_little_endian")
        header.format = Format::LittleEndian;
      else if (w[1] == "binary_big_endian")
        header.format = Format::BigEndian;
      else
        throw fail("unknown format '" + excerpt(w[1]) + "'");
      have_format = true;
    } else if (w[0] == "element") {
      if (w.size() != 3) throw fail("expected 'element <name> <count>', got '" + excerpt(line) + "'");
      Element element{std::string(w[1]), 0, {}};
      const auto [ptr, ec] = std::from_chars(w[2].data(), w[2].data() + w[2].size(), element.count);
      if (ec != std::errc() || ptr != w[2].data() + w[2].size())
        throw fail("element '" + excerpt(w[1]) + "' has count '" + excerpt(w[2]) + "', not a non-negative integer");
      header.elements.push_back(std::move(element));
    } else if (w[0] == "property") {
      if (header.elements.empty()) throw fail("a property before any element");
      Property property;
      if (w.size() == 5 && w[1] == "list") {
        property.count_type = parse_type(w[2]);
        const auto item = parse_type(w[3]);
        if (!property.count_type || !item) throw fail("unknown type in '" + excerpt(line) + "'");
        if (!is_integer(*property.count_type)) throw fail("a list's count must have an integer type");
        property.type = *item;
        property.name = std::string(w[4]);
      } else if (w.size() == 3) {
        const auto type = parse_type(w[1]);
        if (!type) throw fail("unknown type '" + excerpt(w[1]) + "'");
        property.type = *type;
        property.name = std::string(w[2]);
      } else {
        throw fail("expected 'property <type> <name>' or 'property list <type> <type> <name>', got '" + excerpt(line) +
                   "'");
      }
      header.elements.back().properties.push_back(std::move(property));
    } else if (w[0] == "end_header") {
      break;
    } else {
      throw fail("unknown header keyword '" + excerpt(w[0]) + "'");
    }
  }
  if (!have_format) throw PlyError("line 2: the header names no format");
  header.body = pos;
  header.body_line = line_number + 1;
  return header;
}

// Reads the body's values one at a time, in either encoding, and knows
// where it is for messages.
class BodyReader {
 public:
  BodyReader(std::string_view bytes, const Header& header)
      : bytes_(bytes), pos_(header.body), format_(header.format), line_(header.body_line) {}

  size_t remaining() const { return bytes_.size() - pos_; }
  // How many values of type t the rest of the file can hold at most: in
  // ascii each takes a digit, and all but the last a separator.
  uint64_t capacity(Type t) const {
    return format_ == Format::Ascii ? (remaining() + 1) / 2 : remaining() / type_size(t);
  }

  double read(Type t) {
    if (format_ == Format::Ascii) return read_ascii(t);
    if (remaining() < type_size(t)) throw error("the file ends in the middle of the data");
    switch (t) {
      case Type::Int8:
        return take<int8_t>();
      case Type::UInt8:
        return take<uint8_t>();
      case Type::Int16:
        return take<int16_t>();
      case Type::UInt16:
        return take<uint16_t>();
      case Type::Int32:
        return take<int32_t>();
      case Type::UInt32:
        return take<uint32_t>();
      case Type::Float32:
        return take<float>();
      case Type::Float64:
        return take<double>();
    }
    return 0;
  }

  PlyError error(const std::string& problem) const {
    if (format_ == Format::Ascii) return PlyError("line " + std::to_string(line_) + ": " + problem);
    return PlyError("byte " + std::to_string(pos_) + ": " + problem);
  }

 private:
  // A fixed-size copy compiles to one load, where a copy of type_size(t)
  // bytes called memcpy for each value.
  template <class T>
  double take() {
    std::array<unsigned char, sizeof(T)> raw;
    std::memcpy(raw.data(), bytes_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    if ((format_ == Format::BigEndian) != (std::endian::native == std::endian::big))
      std::reverse(raw.begin(), raw.end());
    return double(std::bit_cast<T>(raw));
  }

  double read_ascii(Type t) {
    while (pos_ < bytes_.size() && is_space(bytes_[pos_])) {
      if (bytes_[pos_] == '\n') ++line_;
      ++pos_;
    }
    const size_t start = pos_;
    while (pos_ < bytes_.size() && !is_space(bytes_[pos_])) ++pos_;
    const std::string_view token = bytes_.substr(start, pos_ - start);
    if (token.empty()) throw error("the file ends in the middle of the data");
    const char* first = token.data();
    const char* last = first + token.size();
    if (*first == '+') ++first;
    double value = 0;
    std::from_chars_result result;
    if (is_integer(t)) {
      int64_t integer = 0;
      result = std::from_chars(first, last, integer);
      value = double(integer);
    } else {
      result = std::from_chars(first, last, value);
    }
    if (result.ec != std::errc() || result.ptr != last)
      throw error("'" + excerpt(token) + "' is not " + (is_integer(t) ? "an integer" : "a number"));
    return value;
  }

  std::string_view bytes_;
  size_t pos_;
  Format format_;
  int line_;
};

// Where the vertex element keeps what the mesh needs; -1 where it has none.
struct VertexLayout {
  std::array<int, 3> position{-1, -1, -1};
  std::array<int, 3> normal{-1, -1, -1};
  std::array<int, 2> uv{-1, -1};
};

VertexLayout vertex_layout(const Element& vertex) {
  VertexLayout layout;
  const auto find = [&](std::initializer_list<std::string_view> names) {
    for (std::string_view name : names)
      for (size_t i = 0; i < vertex.properties.size(); ++i)
        if (vertex.properties[i].name == name && !vertex.properties[i].count_type) return int(i);
    return -1;
  };
  layout.position = {find({"x"}), find({"y"}), find({"z"})};
  layout.normal = {find({"nx"}), find({"ny"}), find({"nz"})};
  layout.uv = {find({"u", "s", "texture_u", "texture_s"}), find({"v", "t", "texture_v", "texture_t"})};
  if (layout.position[0] < 0 || layout.position[1] < 0 || layout.position[2] < 0)
    throw PlyError("the vertex element has no x, y and z properties");
  return layout;
}

bool complete(const auto& indices) {
  for (int i : indices)
    if (i < 0) return false;
  return true;
}

}  // namespace CAUSTICA_UNITY_ID
using namespace CAUSTICA_UNITY_ID;
}  // namespace

MeshData read_ply(std::string_view bytes) {
  const Header header = parse_header(bytes);
  BodyReader body(bytes, header);
  MeshData mesh;
  std::optional<uint64_t> vertex_count;
  for (const Element& element : header.elements)
    if (element.name == "vertex") {
      if (vertex_count) throw PlyError("the file has two vertex elements");
      vertex_count = element.count;
    }
  if (!vertex_count) throw PlyError("the file has no vertex element");
  if (*vertex_count > std::numeric_limits<uint32_t>::max())
    throw PlyError("the file declares " + std::to_string(*vertex_count) + " vertices, more than 2^32 - 1");

  for (const Element& element : header.elements) {
    const bool is_vertex = element.name == "vertex";
    const bool is_face = element.name == "face";
    if (element.properties.empty() && !is_vertex) continue;
    const VertexLayout layout = is_vertex ? vertex_layout(element) : VertexLayout{};
    // Each item holds at least one value per property; the smallest type
    // bounds how many values fit.
    Type smallest = Type::Float64;
    for (const Property& p : element.properties)
      if (type_size(p.count_type.value_or(p.type)) < type_size(smallest)) smallest = p.count_type.value_or(p.type);
    const uint64_t values_per_item = element.properties.size();
    if (element.count > body.capacity(smallest) / values_per_item)
      throw body.error("element '" + excerpt(element.name) + "' declares " + std::to_string(element.count) +
                       " items, more than the " + std::to_string(body.remaining()) + " bytes left can hold");

    int face_list = -1;
    if (is_vertex) {
      mesh.positions.reserve(element.count);
      if (complete(layout.normal)) mesh.normals.reserve(element.count);
      if (complete(layout.uv)) mesh.uvs.reserve(element.count);
    }
    if (is_face) {
      // At least a triangle a face; the count was checked against the bytes
      // left above, so a lying header cannot reserve much.
      mesh.indices.reserve(mesh.indices.size() + 3 * element.count);
      for (size_t i = 0; i < element.properties.size(); ++i)
        if ((element.properties[i].name == "vertex_indices" || element.properties[i].name == "vertex_index") &&
            element.properties[i].count_type) {
          if (!is_integer(element.properties[i].type)) throw PlyError("face vertex indices must be integers");
          face_list = int(i);
        }
    }

    std::vector<double> values(element.properties.size());
    std::vector<uint32_t> polygon;
    for (uint64_t item = 0; item < element.count; ++item) {
      if (item % kStopCheckInterval == 0 && stop_request().load()) throw Interrupted("interrupted");
      for (size_t p = 0; p < element.properties.size(); ++p) {
        const Property& property = element.properties[p];
        if (!property.count_type) {
          values[p] = body.read(property.type);
          continue;
        }
        const double count = body.read(*property.count_type);
        if (count < 0 || count > double(body.capacity(property.type)))
          throw body.error("a list of " + std::to_string(int64_t(count)) + " items in " + excerpt(element.name) + " " +
                           std::to_string(item) + " does not fit in the rest of the file");
        if (int(p) != face_list) {
          for (int64_t k = 0; k < int64_t(count); ++k) body.read(property.type);
          continue;
        }
        polygon.clear();
        for (int64_t k = 0; k < int64_t(count); ++k) {
          const double index = body.read(property.type);
          if (index < 0 || index >= double(*vertex_count))
            throw body.error("face " + std::to_string(item) + " refers to vertex " + std::to_string(int64_t(index)) +
                             ", but the mesh has " + std::to_string(*vertex_count) + " vertices");
          polygon.push_back(uint32_t(index));
        }
        for (size_t k = 2; k < polygon.size(); ++k)
          mesh.indices.insert(mesh.indices.end(), {polygon[0], polygon[k - 1], polygon[k]});
      }
      if (!is_vertex) continue;
      const auto at = [&](int index) {
        const double v = values[size_t(index)];
        if (!(std::abs(v) <= std::numeric_limits<float>::max()))
          throw body.error("vertex " + std::to_string(item) + " has a value that is not finite in float");
        return float(v);
      };
      mesh.positions.emplace_back(at(layout.position[0]), at(layout.position[1]), at(layout.position[2]));
      if (complete(layout.normal))
        mesh.normals.emplace_back(at(layout.normal[0]), at(layout.normal[1]), at(layout.normal[2]));
      if (complete(layout.uv)) mesh.uvs.emplace_back(at(layout.uv[0]), at(layout.uv[1]));
    }
  }
  return mesh;
}

}  // namespace caustica
