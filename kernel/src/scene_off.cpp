// OFF (Geomview's Object File Format), ASCII:
//
//   [ST][C][N]OFF [V F E]     header keyword (optional), counts on the same line or the next
//   V F E                     vertex, face and edge counts (E is ignored, and may be missing)
//   x y z ...                 V lines: the first three numbers are the coordinates; the rest of
//                             the line (normal, color, texture coordinates) is ignored
//   n i0 ... i(n-1) [color]   F lines: a face of n vertex indices (from 0), optionally a color
//
// '#' starts a comment; blank lines are skipped. A vertex or a face is one line; the lines after
// the counts are read in pieces of a megabyte side by side (read_body), as reading them in order
// would. Binary OFF and the 4OFF / nOFF variants are rejected. A file that ends before the
// promised vertices and faces is truncated; content after the last face is ignored with a warning.
// Faces that carry a color are grouped by it (see scene.hpp); the color's numbers are compared as
// numbers ("1 0 0" and "1.0 0 0" are the same group).
#include "scene_readers.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cctype>
#include <limits>
#include <optional>
#include <string_view>

namespace hlr::scene_detail {

namespace {

// The body of the file (after the counts) in pieces of about kPieceBytes, each ending after a line
// break: read side by side, they give what reading the lines in order gives, errors included (the
// first in the file is the one reported). A smaller file is one piece, read on the calling thread.
constexpr std::size_t kPieceBytes = std::size_t(1) << 20;

// Whether the line holds a token: a character that is neither blank nor in a comment.
bool has_content(std::string_view line) {
  for (char c : line) {
    if (c == '#') return false;
    if (!is_blank(c)) return true;
  }
  return false;
}

struct Piece {
  std::string_view text;
  std::size_t lines = 0, contents = 0;         // counted first
  std::size_t first_line = 0, first_content = 0;  // then placed
  std::optional<std::string> error;            // the first problem in the piece
  std::optional<std::size_t> after_last_face;  // the line of the first content after the faces
  std::vector<std::pair<std::size_t, std::pair<std::string, std::string>>> colors;  // face, (key, name)
};

void read_piece(Piece& piece, std::size_t nv, std::size_t nf, RawMesh& mesh) {
  LineReader lines(piece.text);
  std::vector<std::string_view> tok;
  std::string_view line;
  std::size_t content = piece.first_content;
  auto line_number = [&] { return piece.first_line + lines.line_number() - 1; };  // in the file
  auto at = [&] { return "line " + std::to_string(line_number()) + ": "; };
  try {
    while (lines.next(line)) {
      split_tokens(line, tok, true);
      if (tok.empty()) continue;
      const std::size_t i = content++;
      if (i < nv) {
        if (tok.size() < 3)
          fail(at() + "vertex " + std::to_string(i) + " has " + std::to_string(tok.size()) +
               (tok.size() == 1 ? " number" : " numbers") + ", expected 3 coordinates");
        std::array<double, 3>& p = mesh.vertices[i];
        for (int a = 0; a < 3; ++a) {
          if (!parse_double(tok[a], p[a]))
            fail(at() + "vertex " + std::to_string(i) + ": expected a number, found " + quoted(tok[a]));
          check_coordinate(p[a], a, tok[a], [&] { return at() + "vertex " + std::to_string(i); });
        }
        continue;
      }
      const std::size_t k = i - nv;
      if (k >= nf) {
        piece.after_last_face = line_number();
        return;
      }
      auto face = [&] { return at() + "face " + std::to_string(k) + ": "; };
      std::int64_t n;
      if (!parse_int(tok[0], n) || n < 0) fail(face() + "expected the vertex count, found " + quoted(tok[0]));
      if (static_cast<std::uint64_t>(n) > tok.size() - 1)
        fail(face() + "the count promises " + std::to_string(n) + " vertex indices, the line has " +
             std::to_string(tok.size() - 1));
      std::vector<std::uint32_t>& f = mesh.faces[k];
      f.resize(static_cast<std::size_t>(n));
      for (std::size_t j = 0; j < f.size(); ++j) {
        std::int64_t v;
        if (!parse_int(tok[1 + j], v)) fail(face() + "expected a vertex index, found " + quoted(tok[1 + j]));
        if (v < 0 || static_cast<std::uint64_t>(v) >= nv)
          fail(face() + "vertex index " + std::to_string(v) + " is out of range (" + std::to_string(nv) +
               " vertices)");
        f[j] = static_cast<std::uint32_t>(v);
      }
      // The color, if any: the numbers after the indices.
      if (tok.size() > 1 + f.size()) {
        auto& [key, name] = piece.colors.emplace_back(k, std::pair<std::string, std::string>()).second;
        for (std::size_t j = 1 + f.size(); j < tok.size(); ++j) {
          double c;
          if (!parse_double(tok[j], c)) fail(face() + "unexpected " + quoted(tok[j]) + " after the vertex indices");
          key += number_text(c) + ' ';
          if (!name.empty()) name += ' ';
          name += tok[j];
        }
      }
    }
  } catch (const FormatError& e) {
    piece.error = e.what();
  }
}

// The vertex and face lines after the counts; `first_line` is the number of the body's first line.
void read_body(std::string_view body, std::size_t first_line, std::size_t nv, std::size_t nf, RawMesh& mesh) {
  std::vector<Piece> pieces;
  for (std::size_t begin = 0; begin < body.size();) {
    std::size_t end = begin + kPieceBytes;
    end = end >= body.size() ? body.size() : std::min(body.size(), body.find('\n', end) + 1);
    if (end == 0) end = body.size();  // no line break after the cut (npos + 1)
    pieces.emplace_back().text = body.substr(begin, end - begin);
    begin = end;
  }
  auto each_piece = [&](auto&& work) {
    if (pieces.size() <= 1) {
      for (Piece& piece : pieces) work(piece);
    } else {
      tbb::parallel_for(std::size_t(0), pieces.size(), [&](std::size_t k) { work(pieces[k]); });
    }
  };
  each_piece([](Piece& piece) {
    LineReader lines(piece.text);
    std::string_view line;
    while (lines.next(line)) piece.contents += has_content(line);
    piece.lines = lines.line_number();
  });
  std::size_t contents = 0, line = first_line;
  for (Piece& piece : pieces) {
    piece.first_content = contents;
    piece.first_line = line;
    contents += piece.contents;
    line += piece.lines;
  }
  // Room for what the file holds, not for what its header promises.
  mesh.vertices.resize(std::min(nv, contents));
  mesh.faces.resize(std::min(nf, contents - mesh.vertices.size()));
  each_piece([&](Piece& piece) { read_piece(piece, nv, nf, mesh); });
  for (const Piece& piece : pieces)
    if (piece.error) fail(*piece.error);
  if (contents < nv)
    fail("truncated: the header promises " + std::to_string(nv) + " vertices, the file ends after " +
         std::to_string(contents));
  if (contents < nv + nf)
    fail("truncated: the header promises " + std::to_string(nf) + " faces, the file ends after " +
         std::to_string(contents - nv));
  // Faces that carry a color are grouped by it, the others in a group of their own, numbered in
  // the order of the faces.
  bool any_color = false;
  for (const Piece& piece : pieces) any_color |= !piece.colors.empty();
  if (any_color) {
    GroupTable groups;
    mesh.face_group.resize(nf);
    std::size_t k = 0;
    for (const Piece& piece : pieces)
      for (const auto& [face, color] : piece.colors) {
        for (; k < face; ++k) mesh.face_group[k] = groups.id("", "(no color)");
        mesh.face_group[k++] = groups.id(color.first, "color " + color.second);
      }
    for (; k < nf; ++k) mesh.face_group[k] = groups.id("", "(no color)");
    mesh.group_names = groups.names();
  }
  for (const Piece& piece : pieces)
    if (piece.after_last_face) {
      mesh.warnings.push_back("content after the last face ignored (from line " +
                              std::to_string(*piece.after_last_face) + ")");
      break;
    }
}

}  // namespace

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

  read_body(std::string_view(bytes).substr(lines.offset()), lines.line_number() + 1, nv, nf, mesh);
  return mesh;
}

}  // namespace hlr::scene_detail
