// Internal to hlr_scene: the format readers and what they share.
//
// Why hlr reads the formats itself rather than through OpenMesh::IO (OpenMesh 9.0, measured with
// a BaseImporter that records every call; kernel/tests/openmesh_probe_test.cpp keeps the
// evidence):
//   - every reader hands coordinates over as float: the OFF, OBJ and STL readers call
//     add_vertex(Vec3f), the PLY reader add_vertex() + set_point(Vec3f), even for `property
//     double`; BaseImporter has no set_point(Vec3d). "0.1" arrives as 0.100000001490116.
//   - truncated OFF and PLY files read "successfully", with invented faces; a truncated ASCII
//     STL reads as the facets before the cut, a truncated binary STL as an empty mesh.
//   - the STL reader drops triangles whose corners coincide, so the faces after them are
//     renumbered and the drop is not reported;
//   - the OBJ reader passes no `g` groups to the importer, and `usemtl` only as the material's
//     diffuse color, only when the .mtl file is found (else it prints a warning to stderr).
// Each reader here is small, exact (text numbers go through strtod in the C locale, binary
// values convert to double without rounding) and checks counts and sizes.
#pragma once

#include <array>
#include <bit>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include <hlr/kernel/scene.hpp>

namespace hlr::scene_detail {

// A problem in the file, without the file name; load_mesh prefixes it.
struct FormatError : std::runtime_error {
  using std::runtime_error::runtime_error;
};
[[noreturn]] void fail(const std::string& problem);

// What a reader produces: the file's vertices and all of its faces, in file order.
struct RawMesh {
  std::vector<std::array<double, 3>> vertices;
  std::vector<std::vector<std::uint32_t>> faces;  // every index < vertices.size() (readers check)
  std::vector<std::int32_t> face_group;           // empty, or one id per face
  std::vector<std::string> group_names;
  std::vector<std::string> warnings;  // problems without the file name
};

// `bytes` is the whole file, non-empty.
RawMesh read_off(const std::string& bytes);
RawMesh read_obj(const std::string& bytes);
RawMesh read_stl(const std::string& bytes);
RawMesh read_ply(const std::string& bytes);

// --- shared parsing helpers -----------------------------------------------------------------

// Parses the whole token as a double (strtod in the C locale: correctly rounded, independent of
// the user's locale; accepts a sign, exponents, hex floats, inf and nan). False when the token
// is not entirely a number.
bool parse_double(std::string_view token, double& value);
// Parses the whole token as a decimal integer with optional sign. False otherwise or on overflow.
bool parse_int(std::string_view token, std::int64_t& value);

// Checks one coordinate: finite and within kMaxImportCoordinate. `where` is called only to build
// the message, e.g. "line 12: vertex 3"; `text` is the token as written ("" for binary input).
template <class Where>
void check_coordinate(double v, int axis, std::string_view text, Where&& where);
void coordinate_failure(double v, int axis, std::string_view text, const std::string& where);

// The blanks that separate tokens: space, tab, \r, \v, \f.
inline bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// Splits on blanks (is_blank); a '#' starts a comment when `comments` is set.
void split_tokens(std::string_view line, std::vector<std::string_view>& out, bool comments);

// Reads `text` line by line: '\n' ends a line, a '\r' before it is dropped. Counts lines from 1.
class LineReader {
 public:
  explicit LineReader(std::string_view text) : text_(text) {}
  bool next(std::string_view& line);
  std::size_t line_number() const { return line_; }  // of the line last returned
  std::size_t offset() const { return pos_; }        // just past the line last returned
 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t line_ = 0;
};

// Reads `text` token by token (blank-separated, across lines) and counts lines from 1.
class TokenReader {
 public:
  explicit TokenReader(std::string_view text, std::size_t first_line = 1) : text_(text), line_(first_line) {}
  bool next(std::string_view& token);
  void skip_line();                                  // drops the rest of the current line
  std::size_t line_number() const { return line_; }  // of the token last returned
 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t line_;
};

std::string quoted(std::string_view token);  // 'token', shortened when long
std::string number_text(double v);           // shortest round-trip spelling

// Coordinates as a key for "equal as doubles": -0 becomes +0 (NaN never gets this far).
inline std::array<double, 3> coordinate_key(std::array<double, 3> p) {
  for (double& v : p)
    if (v == 0) v = 0.0;
  return p;
}
struct CoordinateHash {
  std::size_t operator()(const std::array<double, 3>& p) const {
    std::uint64_t h = 0x9e3779b97f4a7c15ull;
    for (double v : p) h ^= std::bit_cast<std::uint64_t>(v) + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
    return static_cast<std::size_t>(h);
  }
};

// Assigns group ids in order of first appearance.
class GroupTable {
 public:
  std::int32_t id(const std::string& key, const std::string& name);
  const std::vector<std::string>& names() const { return names_; }
 private:
  std::unordered_map<std::string, std::int32_t> ids_;
  std::vector<std::string> names_;
};

template <class Where>
void check_coordinate(double v, int axis, std::string_view text, Where&& where) {
  if (!(v >= -kMaxImportCoordinate && v <= kMaxImportCoordinate)) coordinate_failure(v, axis, text, where());
}

}  // namespace hlr::scene_detail
