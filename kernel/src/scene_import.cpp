// load_mesh: reads the file, hands it to the format's reader (scene_readers.hpp), then skips the
// degenerate faces and counts the non-manifold ones (definitions in hlr/kernel/scene.hpp).
#include <hlr/kernel/scene.hpp>

#include "scene_readers.hpp"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <locale.h>
#include <memory>

namespace hlr {
namespace scene_detail {

void fail(const std::string& problem) { throw FormatError(problem); }

namespace {
locale_t c_locale() {
  static locale_t loc = newlocale(LC_ALL_MASK, "C", locale_t(0));
  return loc;
}
}  // namespace

bool parse_double(std::string_view token, double& value) {
  // strtod needs a terminated string, and must not read past the token.
  char buffer[128];
  if (token.empty() || token.size() >= sizeof buffer) return false;
  std::memcpy(buffer, token.data(), token.size());
  buffer[token.size()] = '\0';
  char* end = nullptr;
  value = strtod_l(buffer, &end, c_locale());  // overflow gives ±inf, caught by check_coordinate
  return end == buffer + token.size();
}

bool parse_int(std::string_view token, std::int64_t& value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  if (token.empty() || token.front() == '+') return false;
  auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  return ec == std::errc() && end == token.data() + token.size();
}

std::string number_text(double v) {
  char text[64];
  auto end = std::to_chars(text, text + sizeof text, v).ptr;
  return std::string(text, end);
}

std::string quoted(std::string_view token) {
  constexpr std::size_t kMax = 40;
  const bool shortened = token.size() > kMax;
  std::string out;  // appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "'" + string
  out.reserve(kMax + 5);
  out.push_back('\'');
  out.append(shortened ? token.substr(0, kMax) : token);
  if (shortened) out.append("...");
  out.push_back('\'');
  return out;
}

void coordinate_failure(double v, int axis, std::string_view text, const std::string& where) {
  static const char* const kAxis[] = {"x", "y", "z"};
  std::string spelled = text.empty() ? number_text(v) : std::string(text);
  std::string head = where + ": " + kAxis[axis] + " coordinate " + spelled;
  bool overflowed = std::isinf(v) && !text.empty() &&
                    text.find_first_of("iI") == std::string_view::npos;  // "1e400", not "inf"
  if (std::isfinite(v) || overflowed)
    fail(head + " is out of range (at most 1e100 in magnitude)");
  fail(head + " is not a finite number");
}

void split_tokens(std::string_view line, std::vector<std::string_view>& out, bool comments) {
  out.clear();
  std::size_t i = 0, n = line.size();
  auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; };
  while (i < n) {
    while (i < n && blank(line[i])) ++i;
    if (i >= n || (comments && line[i] == '#')) return;
    std::size_t start = i;
    while (i < n && !blank(line[i]) && !(comments && line[i] == '#')) ++i;
    out.push_back(line.substr(start, i - start));
  }
}

bool LineReader::next(std::string_view& line) {
  if (pos_ >= text_.size()) return false;
  std::size_t end = text_.find('\n', pos_);
  if (end == std::string_view::npos) end = text_.size();
  line = text_.substr(pos_, end - pos_);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  pos_ = end < text_.size() ? end + 1 : end;
  ++line_;
  return true;
}

bool TokenReader::next(std::string_view& token) {
  auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; };
  while (pos_ < text_.size() && (blank(text_[pos_]) || text_[pos_] == '\n')) {
    if (text_[pos_] == '\n') ++line_;
    ++pos_;
  }
  if (pos_ >= text_.size()) return false;
  std::size_t start = pos_;
  while (pos_ < text_.size() && !blank(text_[pos_]) && text_[pos_] != '\n') ++pos_;
  token = text_.substr(start, pos_ - start);
  return true;
}

void TokenReader::skip_line() {
  std::size_t end = text_.find('\n', pos_);
  pos_ = end == std::string_view::npos ? text_.size() : end;  // the '\n' is counted by next()
}

std::int32_t GroupTable::id(const std::string& key, const std::string& name) {
  auto [it, inserted] = ids_.try_emplace(key, static_cast<std::int32_t>(names_.size()));
  if (inserted) names_.push_back(name);
  return it->second;
}

}  // namespace scene_detail

namespace {

using scene_detail::RawMesh;

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// The extension of the last path component, with its dot, or "".
std::string extension_of(const std::string& path) {
  std::size_t slash = path.find_last_of('/');
  std::size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  return path.substr(dot);
}

std::string read_file(const std::string& path) {
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!file) throw ImportError(path + ": cannot open (" + std::strerror(errno) + ")");
  std::string bytes;
  char buffer[1 << 16];
  for (;;) {
    std::size_t got = std::fread(buffer, 1, sizeof buffer, file.get());
    bytes.append(buffer, got);
    if (got < sizeof buffer) break;
  }
  if (std::ferror(file.get())) throw ImportError(path + ": cannot read (" + std::strerror(errno) + ")");
  return bytes;
}

// Repeated vertex index anywhere in the face.
bool has_repeated_index(const std::vector<std::uint32_t>& f) {
  if (f.size() <= 16) {
    for (std::size_t i = 0; i < f.size(); ++i)
      for (std::size_t j = i + 1; j < f.size(); ++j)
        if (f[i] == f[j]) return true;
    return false;
  }
  std::vector<std::uint32_t> sorted(f);
  std::sort(sorted.begin(), sorted.end());
  return std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end();
}

// All vertices on one line (coincident points included), decided exactly. The coordinates are
// doubles, so CGAL's filtered predicate on Epeck points decides exactly without constructing
// anything.
using Point3 = CGAL::Exact_predicates_exact_constructions_kernel::Point_3;
bool all_collinear(const std::vector<std::uint32_t>& f, const std::vector<Point3>& p) {
  const Point3& a = p[f[0]];
  std::size_t j = 1;
  while (j < f.size() && p[f[j]] == a) ++j;
  if (j == f.size()) return true;  // all coincide
  const Point3& b = p[f[j]];
  for (std::size_t k = j + 1; k < f.size(); ++k)
    if (!CGAL::collinear(a, b, p[f[k]])) return false;
  return true;
}

// Faces with an edge of more than two faces, or of two faces running the same way along it.
std::size_t count_nonmanifold(const std::vector<std::vector<std::uint32_t>>& faces) {
  struct Use {
    std::uint32_t lo, hi, face;
    bool forward;  // the face runs lo -> hi
  };
  std::vector<Use> uses;
  std::size_t total = 0;
  for (const auto& f : faces) total += f.size();
  uses.reserve(total);
  for (std::size_t k = 0; k < faces.size(); ++k) {
    const auto& f = faces[k];
    for (std::size_t i = 0; i < f.size(); ++i) {
      std::uint32_t u = f[i], v = f[(i + 1) % f.size()];
      uses.push_back({std::min(u, v), std::max(u, v), static_cast<std::uint32_t>(k), u < v});
    }
  }
  std::sort(uses.begin(), uses.end(), [](const Use& x, const Use& y) {
    return x.lo != y.lo ? x.lo < y.lo : x.hi < y.hi;
  });
  std::vector<char> bad(faces.size(), 0);
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i;
    while (j < uses.size() && uses[j].lo == uses[i].lo && uses[j].hi == uses[i].hi) ++j;
    bool clash = j - i > 2 || (j - i == 2 && uses[i].forward == uses[i + 1].forward);
    if (clash)
      for (std::size_t k = i; k < j; ++k) bad[uses[k].face] = 1;
    i = j;
  }
  return static_cast<std::size_t>(std::count(bad.begin(), bad.end(), 1));
}

Mesh finish(const std::string& path, RawMesh raw, ImportReport& report) {
  auto fail = [&](const std::string& problem) -> void { throw ImportError(path + ": " + problem); };
  constexpr std::size_t kMaxCount = std::numeric_limits<std::uint32_t>::max();
  if (raw.vertices.size() > kMaxCount) fail("too many vertices (at most 2^32 - 1)");
  if (raw.faces.size() > kMaxCount) fail("too many faces (at most 2^32 - 1)");
  if (raw.faces.empty())
    fail("no faces (the file has " + std::to_string(raw.vertices.size()) + " vertices and no face)");
  // Readers check every coordinate and index as they read; checked again here, where it is cheap,
  // so that no reader can let one through.
  for (std::size_t i = 0; i < raw.vertices.size(); ++i)
    for (int a = 0; a < 3; ++a)
      scene_detail::check_coordinate(raw.vertices[i][a], a, "", [&] { return "vertex " + std::to_string(i); });
  for (std::size_t k = 0; k < raw.faces.size(); ++k)
    for (std::uint32_t v : raw.faces[k])
      if (v >= raw.vertices.size())
        fail("face " + std::to_string(k) + ": vertex index " + std::to_string(v) + " is out of range (" +
             std::to_string(raw.vertices.size()) + " vertices)");

  Mesh mesh;
  mesh.file = path;
  std::vector<Point3> points;
  points.reserve(raw.vertices.size());
  for (const auto& v : raw.vertices) points.emplace_back(v[0], v[1], v[2]);

  const bool groups = !raw.face_group.empty();
  std::size_t degenerate = 0;
  mesh.faces.reserve(raw.faces.size());
  mesh.face_index.reserve(raw.faces.size());
  for (std::size_t k = 0; k < raw.faces.size(); ++k) {
    auto& f = raw.faces[k];
    if (f.size() < 3 || has_repeated_index(f) || all_collinear(f, points)) {
      ++degenerate;
      continue;
    }
    mesh.faces.push_back(std::move(f));
    mesh.face_index.push_back(static_cast<std::uint32_t>(k));
    if (groups) mesh.face_group.push_back(raw.face_group[k]);
  }
  if (mesh.faces.empty())
    fail("no faces left: all " + std::to_string(raw.faces.size()) + " faces are degenerate");
  mesh.vertices = std::move(raw.vertices);
  if (groups) mesh.group_names = std::move(raw.group_names);

  std::size_t nonmanifold = count_nonmanifold(mesh.faces);
  for (const auto& w : raw.warnings) report.warnings.push_back(path + ": " + w);
  if (degenerate > 0)
    report.warnings.push_back(path + ": " + std::to_string(degenerate) +
                              (degenerate == 1 ? " degenerate face skipped" : " degenerate faces skipped"));
  if (nonmanifold > 0)
    report.warnings.push_back(path + ": " + std::to_string(nonmanifold) +
                              (nonmanifold == 1 ? " face is non-manifold (kept)" : " faces are non-manifold (kept)"));
  report.degenerate_faces += degenerate;
  report.nonmanifold_faces += nonmanifold;
  return mesh;
}

}  // namespace

Mesh load_mesh(const std::string& path, ImportReport& report) {
  const std::string ext = lower(extension_of(path));
  RawMesh (*reader)(const std::string&) = nullptr;
  if (ext == ".off") reader = &scene_detail::read_off;
  else if (ext == ".obj") reader = &scene_detail::read_obj;
  else if (ext == ".stl") reader = &scene_detail::read_stl;
  else if (ext == ".ply") reader = &scene_detail::read_ply;
  else if (ext.empty()) throw ImportError(path + ": no file extension (expected .off, .obj, .stl or .ply)");
  else throw ImportError(path + ": unknown extension '" + extension_of(path) + "' (expected .off, .obj, .stl or .ply)");

  std::string bytes = read_file(path);
  if (bytes.empty()) throw ImportError(path + ": empty file");
  RawMesh raw;
  try {
    raw = reader(bytes);
  } catch (const scene_detail::FormatError& e) {
    throw ImportError(path + ": " + e.what());
  } catch (const std::bad_alloc&) {
    throw ImportError(path + ": out of memory while reading");
  }
  bytes = std::string();
  return finish(path, std::move(raw), report);
}

}  // namespace hlr
