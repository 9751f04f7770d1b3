// Wavefront OBJ, polygonal part:
//
//   v x y z [w | r g b]     a vertex; the numbers after x y z are ignored
//   f a b c ...             a face; each corner is i, i/t, i//n or i/t/n with i counting from 1,
//   fo ...                  or from the end when negative (-1 = the latest vertex)
//   g name ...              current group names ("g" alone: "default")
//   usemtl name             current material
//
// '#' starts a comment, a '\' at the end of a line continues it on the next. vt, vn, vp, o, s,
// mtllib and the other statements are ignored; polylines (l), points (p) and free-form geometry
// (curv, curv2, surf) are ignored with one warning per kind. Vertex indices may refer forward
// (checked once the whole file is read). OBJ has no counts, so a cut file cannot be told from a
// short one: a cut "v" line is an error, a cut "f" line a degenerate face.
// Groups (scene.hpp): faces are grouped by the pair (g names, usemtl material) in force.
#include "scene_readers.hpp"

#include <limits>
#include <map>

namespace hlr::scene_detail {

namespace {
std::string joined(const std::vector<std::string_view>& tok, std::size_t from) {
  std::string s;
  for (std::size_t i = from; i < tok.size(); ++i) {
    if (!s.empty()) s += ' ';
    s += tok[i];
  }
  return s;
}
}  // namespace

RawMesh read_obj(const std::string& bytes) {
  RawMesh mesh;
  LineReader lines(bytes);
  std::vector<std::string_view> tok;
  std::string_view line;
  std::string joined_line;  // a line continued with '\'
  std::size_t line_no = 0;  // of the statement's first line
  auto at = [&] { return "line " + std::to_string(line_no) + ": "; };

  std::vector<std::size_t> face_line;  // for the deferred range check of forward indices
  std::map<std::string, std::size_t> ignored;
  GroupTable groups;
  bool any_group = false;
  std::string group_name, material;
  std::int32_t group_id = -1;  // of (group_name, material); -1: not looked up yet
  constexpr std::int64_t kMaxIndex = std::numeric_limits<std::uint32_t>::max();

  while (lines.next(line)) {
    line_no = lines.line_number();
    if (!line.empty() && line.back() == '\\') {
      joined_line.assign(line.substr(0, line.size() - 1));
      std::string_view more;
      while (lines.next(more)) {
        joined_line += ' ';
        if (!more.empty() && more.back() == '\\') {
          joined_line.append(more.substr(0, more.size() - 1));
        } else {
          joined_line.append(more);
          break;
        }
      }
      line = joined_line;
    }
    split_tokens(line, tok, true);
    if (tok.empty()) continue;
    const std::string_view kw = tok[0];
    if (kw == "v") {
      if (tok.size() < 4)
        fail(at() + "vertex " + std::to_string(mesh.vertices.size() + 1) + " has " +
             std::to_string(tok.size() - 1) + " numbers, expected 3 coordinates");
      std::array<double, 3> p;
      for (int a = 0; a < 3; ++a) {
        if (!parse_double(tok[1 + a], p[a]))
          fail(at() + "vertex " + std::to_string(mesh.vertices.size() + 1) + ": expected a number, found " +
               quoted(tok[1 + a]));
        check_coordinate(p[a], a, tok[1 + a],
                         [&] { return at() + "vertex " + std::to_string(mesh.vertices.size() + 1); });
      }
      mesh.vertices.push_back(p);
    } else if (kw == "f" || kw == "fo") {
      std::vector<std::uint32_t> f;
      f.reserve(tok.size() - 1);
      for (std::size_t j = 1; j < tok.size(); ++j) {
        std::string_view corner = tok[j];
        std::string_view index = corner.substr(0, corner.find('/'));
        std::int64_t i;
        if (!parse_int(index, i)) fail(at() + "expected a vertex index, found " + quoted(corner));
        if (i == 0) fail(at() + "vertex index 0 is invalid (OBJ counts from 1)");
        std::int64_t resolved = i > 0 ? i - 1 : static_cast<std::int64_t>(mesh.vertices.size()) + i;
        if (resolved < 0)
          fail(at() + "relative vertex index " + std::to_string(i) + " reaches before the first vertex (" +
               std::to_string(mesh.vertices.size()) + " vertices so far)");
        if (resolved >= kMaxIndex) fail(at() + "vertex index " + std::to_string(i) + " is out of range");
        f.push_back(static_cast<std::uint32_t>(resolved));
      }
      if (group_id < 0) {
        std::string name;
        if (!group_name.empty()) name = "g " + group_name;
        if (!material.empty()) name += (name.empty() ? "usemtl " : ", usemtl ") + material;
        group_id = groups.id(group_name + '\n' + material, name.empty() ? "(none)" : name);
      }
      mesh.face_group.push_back(group_id);
      mesh.faces.push_back(std::move(f));
      face_line.push_back(line_no);
    } else if (kw == "g") {
      group_name = tok.size() > 1 ? joined(tok, 1) : "default";
      any_group = true;
      group_id = -1;
    } else if (kw == "usemtl") {
      material = joined(tok, 1);
      any_group = true;
      group_id = -1;
    } else if (kw == "l" || kw == "p" || kw == "curv" || kw == "curv2" || kw == "surf") {
      ++ignored[std::string(kw)];
    }
  }

  for (std::size_t k = 0; k < mesh.faces.size(); ++k)
    for (std::uint32_t v : mesh.faces[k])
      if (v >= mesh.vertices.size())
        fail("line " + std::to_string(face_line[k]) + ": vertex index " + std::to_string(std::uint64_t(v) + 1) +
             " is out of range (" + std::to_string(mesh.vertices.size()) + " vertices)");
  for (const auto& [kw, n] : ignored) {
    const char* what = kw == "l" ? " (polyline)" : kw == "p" ? " (points)" : " (free-form geometry)";
    mesh.warnings.push_back(std::to_string(n) + " '" + kw + "' " + (n == 1 ? "statement" : "statements") + what +
                            " ignored");
  }
  if (any_group) mesh.group_names = groups.names();
  else mesh.face_group.clear();
  return mesh;
}

}  // namespace hlr::scene_detail
