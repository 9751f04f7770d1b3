// OFF (Geomview's Object File Format), ASCII:
//
//   [ST][C][N]OFF [V F E]     header keyword (optional), counts on the same line or the next
//   V F E                     vertex, face and edge counts (E is ignored, and may be missing)
//   x y z ...                 V lines: the first three numbers are the coordinates; the rest of
//                             the line (normal, color, texture coordinates) is ignored
//   n i0 ... i(n-1) [color]   F lines: a face of n vertex indices (from 0), optionally a color
//
// '#' starts a comment; blank lines are skipped. The file is read line by line: a vertex or a face
// is one line. Binary OFF and the 4OFF / nOFF variants are rejected. A file that ends before the
// promised vertices and faces is truncated; content after the last face is ignored with a warning.
// Faces that carry a color are grouped by it (see scene.hpp); the color's numbers are compared as
// numbers ("1 0 0" and "1.0 0 0" are the same group).
#include "scene_readers.hpp"

#include <algorithm>
#include <cctype>
#include <limits>

namespace hlr::scene_detail {

RawMesh read_off(const std::string& bytes) {
  RawMesh mesh;
  LineReader lines(bytes);
  std::vector<std::string_view> tok;
  std::string_view line;
  auto next_content = [&] {
    while (lines.next(line)) {
      split_tokens(line, tok, true);
      if (!tok.empty()) return true;
    }
    return false;
  };
  auto at = [&] { return "line " + std::to_string(lines.line_number()) + ": "; };

  if (!next_content()) fail("no OFF header (only blanks and comments)");
  std::size_t counts_from = 0;  // where the counts start in tok
  std::int64_t probe;
  if (!parse_int(tok[0], probe)) {
    std::string_view keyword = tok[0];
    auto upper = [](char c) { return static_cast<char>(std::toupper(static_cast<unsigned char>(c))); };
    std::size_t m = keyword.size();
    if (m < 3 || upper(keyword[m - 3]) != 'O' || upper(keyword[m - 2]) != 'F' || upper(keyword[m - 1]) != 'F')
      fail("not an OFF file: it starts with " + quoted(keyword) + ", expected 'OFF'");
    std::string_view prefix = keyword.substr(0, m - 3);  // ST, C, N: extra numbers per vertex line
    while (!prefix.empty()) {
      if (prefix.substr(0, 2) == "ST") prefix.remove_prefix(2);
      else if (prefix.front() == 'C' || prefix.front() == 'N') prefix.remove_prefix(1);
      else if (prefix.front() == '4' || prefix.front() == 'n')
        fail(quoted(keyword) + " (homogeneous or n-dimensional vertices) is not supported");
      else fail("unknown OFF header keyword " + quoted(keyword));
    }
    if (tok.size() > 1 && (tok[1] == "BINARY" || tok[1] == "binary"))
      fail("binary OFF is not supported; write ASCII OFF, or PLY");
    counts_from = 1;
    if (tok.size() == 1) {  // counts on the next line
      if (!next_content()) fail("truncated: the file ends after the header keyword, before the counts");
      counts_from = 0;
    }
  }
  std::size_t n_counts = tok.size() - counts_from;
  if (n_counts < 2 || n_counts > 3)
    fail(at() + "expected the counts 'V F E', found " + std::to_string(n_counts) + " numbers");
  std::int64_t counts[3] = {0, 0, 0};
  for (std::size_t i = 0; i < n_counts; ++i)
    if (!parse_int(tok[counts_from + i], counts[i]) || counts[i] < 0)
      fail(at() + "expected a count, found " + quoted(tok[counts_from + i]));
  constexpr std::int64_t kMax = std::numeric_limits<std::uint32_t>::max();
  if (counts[0] > kMax || counts[1] > kMax) fail(at() + "counts beyond 2^32 - 1 are not supported");
  const std::size_t nv = static_cast<std::size_t>(counts[0]), nf = static_cast<std::size_t>(counts[1]);

  // A vertex line holds at least 6 bytes ("0 0 0\n"), a face line at least 2: reserving by the
  // counts alone would trust the header.
  mesh.vertices.reserve(std::min(nv, bytes.size() / 6));
  for (std::size_t i = 0; i < nv; ++i) {
    if (!next_content())
      fail("truncated: the header promises " + std::to_string(nv) + " vertices, the file ends after " +
           std::to_string(i));
    if (tok.size() < 3)
      fail(at() + "vertex " + std::to_string(i) + " has " + std::to_string(tok.size()) +
           (tok.size() == 1 ? " number" : " numbers") + ", expected 3 coordinates");
    std::array<double, 3> p;
    for (int a = 0; a < 3; ++a) {
      if (!parse_double(tok[a], p[a]))
        fail(at() + "vertex " + std::to_string(i) + ": expected a number, found " + quoted(tok[a]));
      check_coordinate(p[a], a, tok[a], [&] { return at() + "vertex " + std::to_string(i); });
    }
    mesh.vertices.push_back(p);
  }

  GroupTable groups;
  bool any_color = false;
  std::string key, name;
  mesh.faces.reserve(std::min(nf, bytes.size() / 2));
  mesh.face_group.reserve(std::min(nf, bytes.size() / 2));
  for (std::size_t k = 0; k < nf; ++k) {
    if (!next_content())
      fail("truncated: the header promises " + std::to_string(nf) + " faces, the file ends after " +
           std::to_string(k));
    auto face = [&] { return at() + "face " + std::to_string(k) + ": "; };
    std::int64_t n;
    if (!parse_int(tok[0], n) || n < 0) fail(face() + "expected the vertex count, found " + quoted(tok[0]));
    if (static_cast<std::uint64_t>(n) > tok.size() - 1)
      fail(face() + "the count promises " + std::to_string(n) + " vertex indices, the line has " +
           std::to_string(tok.size() - 1));
    std::vector<std::uint32_t> f(static_cast<std::size_t>(n));
    for (std::size_t j = 0; j < f.size(); ++j) {
      std::int64_t v;
      if (!parse_int(tok[1 + j], v)) fail(face() + "expected a vertex index, found " + quoted(tok[1 + j]));
      if (v < 0 || static_cast<std::uint64_t>(v) >= nv)
        fail(face() + "vertex index " + std::to_string(v) + " is out of range (" + std::to_string(nv) +
             " vertices)");
      f[j] = static_cast<std::uint32_t>(v);
    }
    // The color, if any: the numbers after the indices.
    key.clear();
    name.clear();
    for (std::size_t j = 1 + f.size(); j < tok.size(); ++j) {
      double c;
      if (!parse_double(tok[j], c))
        fail(face() + "unexpected " + quoted(tok[j]) + " after the vertex indices");
      key += number_text(c) + ' ';
      if (!name.empty()) name += ' ';
      name += tok[j];
    }
    if (!key.empty()) any_color = true;
    mesh.face_group.push_back(groups.id(key, key.empty() ? "(no color)" : "color " + name));
    mesh.faces.push_back(std::move(f));
  }
  if (any_color) mesh.group_names = groups.names();
  else mesh.face_group.clear();

  if (next_content())
    mesh.warnings.push_back("content after the last face ignored (from line " +
                            std::to_string(lines.line_number()) + ")");
  return mesh;
}

}  // namespace hlr::scene_detail
