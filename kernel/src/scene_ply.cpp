// PLY (Stanford polygon format), ASCII and binary (little and big endian).
//
// The header declares elements and their properties; the data follows in that order. Read here:
// the "vertex" element's x, y, z (any numeric type) and the "face" element's index list
// ("vertex_indices" or "vertex_index", integer type), plus the face's red / green / blue / alpha
// as its group (scene.hpp). Every other element and property is read past and ignored.
// ASCII numbers are parsed as doubles whatever type the header declares (the text is the input);
// binary values of every type convert to double without rounding. The data must hold every
// element the header promises (else: truncated); data after the last element is ignored with a
// warning.
#include "scene_readers.hpp"

#include <algorithm>
#include <bit>
#include <cstring>
#include <limits>
#include <optional>

namespace hlr::scene_detail {

namespace {

enum class Type { i8, u8, i16, u16, i32, u32, f32, f64 };

std::optional<Type> type_named(std::string_view s) {
  if (s == "char" || s == "int8") return Type::i8;
  if (s == "uchar" || s == "uint8") return Type::u8;
  if (s == "short" || s == "int16") return Type::i16;
  if (s == "ushort" || s == "uint16") return Type::u16;
  if (s == "int" || s == "int32") return Type::i32;
  if (s == "uint" || s == "uint32") return Type::u32;
  if (s == "float" || s == "float32") return Type::f32;
  if (s == "double" || s == "float64") return Type::f64;
  return std::nullopt;
}
bool is_integer(Type t) { return t != Type::f32 && t != Type::f64; }
std::size_t size_of(Type t) {
  switch (t) {
    case Type::i8: case Type::u8: return 1;
    case Type::i16: case Type::u16: return 2;
    case Type::i32: case Type::u32: case Type::f32: return 4;
    case Type::f64: return 8;
  }
  return 0;
}

// What a property is to us.
enum class Role { none, x, y, z, indices, red, green, blue, alpha };

struct Property {
  std::string name;
  bool list = false;
  Type count_type = Type::u8;
  Type type = Type::f32;
  Role role = Role::none;
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> properties;
};

enum class Format { ascii, binary_le, binary_be };

// One value source: ASCII tokens or binary bytes.
class Source {
 public:
  Source(std::string_view data, std::size_t first_line, Format format)
      : format_(format), tokens_(data, first_line), data_(data) {}

  // A value of type t: as a double (exact for every binary type), `text` the token if ASCII.
  // Returns false at the end of the data.
  bool value(Type t, double& v, std::string_view& text, bool& well_formed) {
    well_formed = true;
    if (format_ == Format::ascii) {
      if (!tokens_.next(text)) return false;
      if (is_integer(t)) {
        std::int64_t i;
        well_formed = parse_int(text, i);
        v = static_cast<double>(i);
      } else {
        well_formed = parse_double(text, v);
      }
      return true;
    }
    text = {};
    std::size_t n = size_of(t);
    if (data_.size() - pos_ < n) return false;
    unsigned char b[8];
    std::memcpy(b, data_.data() + pos_, n);
    pos_ += n;
    bool big = format_ == Format::binary_be;
    if ((std::endian::native == std::endian::big) != big)
      for (std::size_t i = 0; i < n / 2; ++i) std::swap(b[i], b[n - 1 - i]);
    switch (t) {
      case Type::i8: { std::int8_t x; std::memcpy(&x, b, 1); v = x; break; }
      case Type::u8: { std::uint8_t x; std::memcpy(&x, b, 1); v = x; break; }
      case Type::i16: { std::int16_t x; std::memcpy(&x, b, 2); v = x; break; }
      case Type::u16: { std::uint16_t x; std::memcpy(&x, b, 2); v = x; break; }
      case Type::i32: { std::int32_t x; std::memcpy(&x, b, 4); v = x; break; }
      case Type::u32: { std::uint32_t x; std::memcpy(&x, b, 4); v = x; break; }
      case Type::f32: { float x; std::memcpy(&x, b, 4); v = x; break; }
      case Type::f64: { std::memcpy(&v, b, 8); break; }
    }
    return true;
  }

  std::size_t line_number() const { return tokens_.line_number(); }
  // After the last element: how much is left (tokens or bytes).
  std::string leftover() {
    if (format_ == Format::ascii) {
      std::string_view t;
      return tokens_.next(t) ? "content after the last element ignored (from line " +
                                   std::to_string(tokens_.line_number()) + ")"
                             : "";
    }
    std::size_t n = data_.size() - pos_;
    return n ? std::to_string(n) + (n == 1 ? " byte" : " bytes") + " after the last element ignored" : "";
  }

 private:
  Format format_;
  TokenReader tokens_;
  std::string_view data_;
  std::size_t pos_ = 0;
};

}  // namespace

RawMesh read_ply(const std::string& bytes) {
  // --- header -----------------------------------------------------------------------------
  LineReader lines(bytes);
  std::string_view line;
  std::vector<std::string_view> tok;
  auto at = [&] { return "line " + std::to_string(lines.line_number()) + ": "; };
  if (!lines.next(line) || (split_tokens(line, tok, false), tok.size() != 1 || tok[0] != "ply"))
    fail("not a PLY file: the first line is not 'ply'");
  std::optional<Format> format;
  std::vector<Element> elements;
  bool ended = false;
  while (lines.next(line)) {
    split_tokens(line, tok, false);
    if (tok.empty()) continue;
    if (tok[0] == "end_header") {
      ended = true;
      break;
    }
    if (tok[0] == "comment" || tok[0] == "obj_info") continue;
    if (tok[0] == "format") {
      if (tok.size() < 2) fail(at() + "'format' without a format");
      if (tok[1] == "ascii") format = Format::ascii;
      else if (tok[1] == "binary_little_endian") format = Format::binary_le;
      else if (tok[1] == "binary_big_endian") format = Format::binary_be;
      else fail(at() + "unknown format " + quoted(tok[1]));
    } else if (tok[0] == "element") {
      std::int64_t count;
      if (tok.size() != 3 || !parse_int(tok[2], count) || count < 0)
        fail(at() + "expected 'element NAME COUNT'");
      elements.push_back({std::string(tok[1]), static_cast<std::uint64_t>(count), {}});
    } else if (tok[0] == "property") {
      if (elements.empty()) fail(at() + "property before any element");
      Property p;
      if (tok.size() == 5 && tok[1] == "list") {
        auto ct = type_named(tok[2]), t = type_named(tok[3]);
        if (!ct || !t) fail(at() + "unknown property type in " + quoted(line));
        if (!is_integer(*ct)) fail(at() + "a list count must have an integer type");
        p.list = true;
        p.count_type = *ct;
        p.type = *t;
        p.name = tok[4];
      } else if (tok.size() == 3) {
        auto t = type_named(tok[1]);
        if (!t) fail(at() + "unknown property type " + quoted(tok[1]));
        p.type = *t;
        p.name = tok[2];
      } else {
        fail(at() + "expected 'property TYPE NAME' or 'property list COUNT_TYPE TYPE NAME'");
      }
      elements.back().properties.push_back(std::move(p));
    } else {
      fail(at() + "unknown header line " + quoted(line));
    }
  }
  if (!ended) fail("truncated: the header has no 'end_header'");
  if (!format) fail("the header has no 'format' line");

  // --- roles --------------------------------------------------------------------------------
  const Element* vertex = nullptr;
  const Element* face = nullptr;
  bool face_color = false;
  for (auto& e : elements) {
    if (e.name == "vertex" && !vertex) {
      vertex = &e;
      for (auto& p : e.properties)
        if (!p.list) {
          if (p.name == "x") p.role = Role::x;
          else if (p.name == "y") p.role = Role::y;
          else if (p.name == "z") p.role = Role::z;
        }
      for (Role r : {Role::x, Role::y, Role::z}) {
        bool has = false;
        for (auto& p : e.properties) has = has || p.role == r;
        if (!has)
          fail(std::string("the vertex element has no ") + (r == Role::x ? "x" : r == Role::y ? "y" : "z") +
               " property");
      }
    } else if (e.name == "face" && !face) {
      face = &e;
      bool has_indices = false;
      for (auto& p : e.properties) {
        if (p.list && !has_indices && (p.name == "vertex_indices" || p.name == "vertex_index")) {
          if (!is_integer(p.type)) fail("the face element's " + p.name + " must have an integer type");
          p.role = Role::indices;
          has_indices = true;
        } else if (!p.list) {
          if (p.name == "red") p.role = Role::red;
          else if (p.name == "green") p.role = Role::green;
          else if (p.name == "blue") p.role = Role::blue;
          else if (p.name == "alpha") p.role = Role::alpha;
          face_color = face_color || p.role != Role::none;
        }
      }
      if (!has_indices) fail("the face element has no vertex_indices list");
    }
  }
  if (!vertex) fail("no vertex element");
  constexpr std::uint64_t kMax = std::numeric_limits<std::uint32_t>::max();
  if (vertex->count > kMax || (face && face->count > kMax)) fail("counts beyond 2^32 - 1 are not supported");

  // --- data ---------------------------------------------------------------------------------
  RawMesh mesh;
  Source src(std::string_view(bytes).substr(lines.offset()), lines.line_number() + 1, *format);
  GroupTable groups;
  std::string key, name;
  for (const Element& e : elements) {
    const bool is_vertex = &e == vertex, is_face = &e == face;
    if (e.properties.empty()) continue;  // its items hold nothing to read
    // Reserve no more items than the data can hold: the count is not trusted yet.
    std::size_t min_item = 0;
    for (const Property& p : e.properties)
      min_item += *format == Format::ascii ? 2 : size_of(p.list ? p.count_type : p.type);
    const std::size_t cap = std::min<std::uint64_t>(e.count, bytes.size() / std::max<std::size_t>(min_item, 1));
    if (is_vertex) mesh.vertices.reserve(cap);
    if (is_face) mesh.faces.reserve(cap);
    for (std::uint64_t k = 0; k < e.count; ++k) {
      auto where = [&] {
        std::string s = *format == Format::ascii ? "line " + std::to_string(src.line_number()) + ": " : "";
        return s + e.name + " " + std::to_string(k);
      };
      auto get = [&](Type t, const Property& p, double& v, std::string_view& text) {
        bool ok;
        if (!src.value(t, v, text, ok))
          fail("truncated: the file ends in " + e.name + " " + std::to_string(k) + " of " + std::to_string(e.count));
        if (!ok)
          fail(where() + ": property " + p.name + ": expected " + (is_integer(t) ? "an integer" : "a number") +
               ", found " + quoted(text));
      };
      std::array<double, 3> point{};
      std::vector<std::uint32_t> f;
      key.clear();
      name.clear();
      for (const Property& p : e.properties) {
        double v;
        std::string_view text;
        if (!p.list) {
          get(p.type, p, v, text);
          if (p.role == Role::x || p.role == Role::y || p.role == Role::z) {
            int a = p.role == Role::x ? 0 : p.role == Role::y ? 1 : 2;
            check_coordinate(v, a, text, where);
            point[a] = v;
          } else if (p.role != Role::none) {  // a face color component
            key += p.name + '=' + number_text(v) + ' ';
            if (!name.empty()) name += ' ';
            name += number_text(v);
          }
          continue;
        }
        get(p.count_type, p, v, text);
        if (v < 0) fail(where() + ": property " + p.name + ": negative list length");
        const auto n = static_cast<std::uint64_t>(v);
        if (p.role == Role::indices) f.reserve(std::min<std::uint64_t>(n, 64));  // n is not trusted yet
        for (std::uint64_t j = 0; j < n; ++j) {
          get(p.type, p, v, text);
          if (p.role == Role::indices) {
            if (v < 0 || v >= static_cast<double>(kMax))
              fail(where() + ": vertex index " + number_text(v) + " is out of range");
            f.push_back(static_cast<std::uint32_t>(v));
          }
        }
      }
      if (is_vertex) mesh.vertices.push_back(point);
      if (is_face) {
        mesh.faces.push_back(std::move(f));
        if (face_color) mesh.face_group.push_back(groups.id(key, "color " + name));
      }
    }
  }
  std::string leftover = src.leftover();
  if (!leftover.empty()) mesh.warnings.push_back(leftover);

  for (std::size_t k = 0; k < mesh.faces.size(); ++k)
    for (std::uint32_t v : mesh.faces[k])
      if (v >= mesh.vertices.size())
        fail("face " + std::to_string(k) + ": vertex index " + std::to_string(v) + " is out of range (" +
             std::to_string(mesh.vertices.size()) + " vertices)");
  mesh.group_names = groups.names();
  return mesh;
}

}  // namespace hlr::scene_detail
