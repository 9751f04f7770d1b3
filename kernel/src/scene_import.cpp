// load_mesh: reads the file, hands it to the format's reader (scene_readers.hpp), welds vertices
// and prepares the faces (scene_faces.hpp), then counts the non-manifold faces (definitions in
// hlr/kernel/scene.hpp); add_mesh_file (hlr/kernel/scene_import.hpp).
#include <hlr/kernel/mesh_edges.hpp>
#include <hlr/kernel/scene.hpp>
#include <hlr/kernel/scene_import.hpp>

#include "scene_faces.hpp"
#include "scene_readers.hpp"

#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <limits>
#include <locale.h>
#include <memory>
#include <optional>
#include <sys/stat.h>

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
  // std::from_chars reads the plain decimal forms, correctly rounded as strtod rounds them, at a
  // fraction of its cost; what it refuses (a leading '+', hexadecimal, out of range) goes to
  // strtod, whose reading and errors stay those of the formats.
  if (const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
      ec == std::errc() && end == token.data() + token.size())
    return true;
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
  while (i < n) {
    while (i < n && is_blank(line[i])) ++i;
    if (i >= n || (comments && line[i] == '#')) return;
    std::size_t start = i;
    while (i < n && !is_blank(line[i]) && !(comments && line[i] == '#')) ++i;
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
  while (pos_ < text_.size() && (is_blank(text_[pos_]) || text_[pos_] == '\n')) {
    if (text_[pos_] == '\n') ++line_;
    ++pos_;
  }
  if (pos_ >= text_.size()) return false;
  std::size_t start = pos_;
  while (pos_ < text_.size() && !is_blank(text_[pos_]) && text_[pos_] != '\n') ++pos_;
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
  // Room for all of a regular file at once (anything else is read all the same).
  struct stat info;
  if (::fstat(::fileno(file.get()), &info) == 0 && S_ISREG(info.st_mode)) bytes.reserve(std::size_t(info.st_size));
  char buffer[1 << 16];
  for (;;) {
    std::size_t got = std::fread(buffer, 1, sizeof buffer, file.get());
    bytes.append(buffer, got);
    if (got < sizeof buffer) break;
  }
  if (std::ferror(file.get())) throw ImportError(path + ": cannot read (" + std::strerror(errno) + ")");
  return bytes;
}

using scene_detail::InputPoint3;

// Faces with an edge of more than two faces, or of two faces running the same way along it.
std::size_t count_nonmanifold(const Mesh& mesh, const std::vector<EdgeUse>& uses) {
  std::vector<char> bad(mesh.faces.size(), 0);
  for_each_edge(uses, [&](EdgeUses first, EdgeUses last) {
    if (last - first > 2 || (last - first == 2 && first[0].forward == first[1].forward))
      for (EdgeUses u = first; u != last; ++u) bad[u->face] = 1;
  });
  return static_cast<std::size_t>(std::count(bad.begin(), bad.end(), 1));
}

// Faces none of whose edges belongs to another face.
std::size_t count_isolated(const Mesh& mesh, const std::vector<EdgeUse>& uses) {
  std::vector<char> shares(mesh.faces.size(), 0);
  for_each_edge(uses, [&](EdgeUses first, EdgeUses last) {
    if (first->face != (last - 1)->face)  // uses are sorted by face
      for (EdgeUses u = first; u != last; ++u) shares[u->face] = 1;
  });
  return static_cast<std::size_t>(std::count(shares.begin(), shares.end(), 0));
}

// The mesh from a reader's output, checked and prepared. With keep_topology it keeps the topology
// its checks found (add_mesh_file, which adds the mesh at once), else it leaves it unset, for a
// caller may change the mesh before adding it.
Mesh finish(const std::string& path, RawMesh raw, ImportReport& report, bool keep_topology = false) {
  auto fail = [&](const std::string& problem) -> void { throw ImportError(path + ": " + problem); };
  constexpr std::size_t kMaxCount = std::numeric_limits<std::uint32_t>::max();
  if (raw.vertices.size() > kMaxCount) fail("too many vertices (at most 2^32 - 1)");
  if (raw.faces.size() > kMaxCount) fail("too many faces (at most 2^32 - 1)");
  if (raw.faces.empty())
    fail("no faces (the file has " + std::to_string(raw.vertices.size()) + " vertices and no face)");
  // Readers check every coordinate and index as they read; checked again here, where it is cheap,
  // so that no reader can let one through (and for make_mesh, whose arrays no reader has seen).
  try {
    for (std::size_t i = 0; i < raw.vertices.size(); ++i)
      for (int a = 0; a < 3; ++a)
        scene_detail::check_coordinate(raw.vertices[i][a], a, "", [&] { return "vertex " + std::to_string(i); });
  } catch (const scene_detail::FormatError& e) {
    fail(e.what());
  }
  for (std::size_t k = 0; k < raw.faces.size(); ++k)
    for (std::uint32_t v : raw.faces[k])
      if (v >= raw.vertices.size())
        fail("face " + std::to_string(k) + ": vertex index " + std::to_string(v) + " is out of range (" +
             std::to_string(raw.vertices.size()) + " vertices)");

  Mesh mesh;
  mesh.file = path;
  const std::vector<std::uint32_t> canonical = scene_detail::weld_vertices(raw.vertices);
  std::size_t welded = 0;
  for (std::uint32_t v = 0; v < canonical.size(); ++v) welded += canonical[v] != v;
  std::vector<InputPoint3> points;
  points.reserve(raw.vertices.size());
  for (const auto& v : raw.vertices) points.emplace_back(v[0], v[1], v[2]);

  // The faces prepared in chunks on every thread, then joined in file order: the same faces, and
  // the same first error, as one pass over them.
  const bool groups = !raw.face_group.empty();
  struct Chunk {
    scene_detail::PreparedFaces prepared;
    std::vector<std::uint32_t> face_index;
    std::vector<std::int32_t> face_group;
    std::size_t degenerate = 0;
    std::optional<std::string> error;  // the chunk's first, where it stopped
  };
  constexpr std::size_t kFacesPerChunk = 8192;
  std::vector<Chunk> chunks((raw.faces.size() + kFacesPerChunk - 1) / kFacesPerChunk);
  tbb::parallel_for(std::size_t(0), chunks.size(), [&](std::size_t c) {
    Chunk& chunk = chunks[c];
    for (std::size_t k = c * kFacesPerChunk; k < std::min(raw.faces.size(), (c + 1) * kFacesPerChunk); ++k) {
      auto& f = raw.faces[k];
      for (std::uint32_t& v : f) v = canonical[v];
      std::size_t made = 0;
      try {
        made = scene_detail::prepare_face(points, f, k, chunk.prepared);
      } catch (const scene_detail::FormatError& e) {
        chunk.error = e.what();
        return;
      }
      if (made == 0) ++chunk.degenerate;
      chunk.face_index.insert(chunk.face_index.end(), made, static_cast<std::uint32_t>(k));
      if (groups) chunk.face_group.insert(chunk.face_group.end(), made, raw.face_group[k]);
    }
  });
  std::size_t degenerate = 0, made = 0;
  for (const Chunk& chunk : chunks) {
    if (chunk.error) fail(*chunk.error);
    degenerate += chunk.degenerate;
    made += chunk.prepared.faces.size();
  }
  scene_detail::PreparedFaces prepared;
  prepared.faces.reserve(made);
  prepared.fan_edges.reserve(made);
  mesh.face_index.reserve(made);
  if (groups) mesh.face_group.reserve(made);
  for (Chunk& chunk : chunks) {
    std::move(chunk.prepared.faces.begin(), chunk.prepared.faces.end(), std::back_inserter(prepared.faces));
    prepared.fan_edges.insert(prepared.fan_edges.end(), chunk.prepared.fan_edges.begin(), chunk.prepared.fan_edges.end());
    prepared.fanned += chunk.prepared.fanned;
    prepared.split += chunk.prepared.split;
    mesh.face_index.insert(mesh.face_index.end(), chunk.face_index.begin(), chunk.face_index.end());
    mesh.face_group.insert(mesh.face_group.end(), chunk.face_group.begin(), chunk.face_group.end());
    chunk = Chunk();
  }
  if (prepared.faces.empty())
    fail("no faces left: all " + std::to_string(raw.faces.size()) + " faces are degenerate");
  mesh.faces = std::move(prepared.faces);
  if (prepared.fanned > 0) mesh.fan_edges = std::move(prepared.fan_edges);
  mesh.vertices = std::move(raw.vertices);
  if (groups) mesh.group_names = std::move(raw.group_names);

  // The checks below need the edge uses and components; the coplanar groups, the rest of the
  // topology (analyse_mesh), only when it is kept.
  MeshTopology topology;
  topology.uses = edge_uses(mesh);
  auto find_sides = [&] { topology.sides = component_sides(mesh, topology.uses); };
  auto find_groups = [&] {
    if (keep_topology) topology.groups = coplanar_groups(mesh, topology.uses);
  };
  // Each reads the uses alone: side by side on a large mesh (a tenth of a second each at 1M faces),
  // one after the other on a small one, which would wait longer for the scheduler to start.
  constexpr std::size_t kFacesSideBySide = 50000;
  if (keep_topology && mesh.faces.size() >= kFacesSideBySide) tbb::parallel_invoke(find_sides, find_groups);
  else find_sides(), find_groups();
  const std::vector<EdgeUse>& uses = topology.uses;
  const std::size_t nonmanifold = count_nonmanifold(mesh, uses);
  const std::size_t inward = topology.sides.inward;
  for (const auto& w : raw.warnings) report.warnings.push_back(path + ": " + w);
  if (degenerate > 0)
    report.warnings.push_back(path + ": " + std::to_string(degenerate) +
                              (degenerate == 1 ? " degenerate face skipped" : " degenerate faces skipped"));
  if (nonmanifold > 0)
    report.warnings.push_back(path + ": " + std::to_string(nonmanifold) +
                              (nonmanifold == 1 ? " face is non-manifold (kept)" : " faces are non-manifold (kept)"));
  if (inward > 0)
    report.warnings.push_back(path + ": " + std::to_string(inward) +
                              (inward == 1 ? " closed component is" : " closed components are") +
                              " wound inward (faces clockwise seen from outside): drawn as turned outward");
  const std::size_t isolated = count_isolated(mesh, uses);
  if (mesh.faces.size() > 1 && 2 * isolated > mesh.faces.size())
    report.warnings.push_back(path + ": " + std::to_string(isolated) + " of " + std::to_string(mesh.faces.size()) +
                              " faces share no edge with another face (a triangle soup? faces meet only where "
                              "their corners have equal coordinates)");
  report.degenerate_faces += degenerate;
  report.nonmanifold_faces += nonmanifold;
  report.welded_vertices += welded;
  report.fanned_faces += prepared.fanned;
  report.split_faces += prepared.split;
  report.inward_components += inward;
  if (keep_topology) mesh.topology = std::make_shared<const MeshTopology>(std::move(topology));
  return mesh;
}

Mesh parse_checked(const std::string& name, const std::string& extension, std::string bytes, ImportReport& report,
                   bool keep_topology) {
  const std::string ext = lower(extension);
  RawMesh (*reader)(const std::string&) = ext == ".off"   ? &scene_detail::read_off
                                          : ext == ".obj" ? &scene_detail::read_obj
                                          : ext == ".stl" ? &scene_detail::read_stl
                                          : ext == ".ply" ? &scene_detail::read_ply
                                                          : nullptr;
  if (!reader) throw ImportError(name + ": unknown format '" + extension + "' (expected .off, .obj, .stl or .ply)");
  if (bytes.empty()) throw ImportError(name + ": empty file");
  RawMesh raw;
  try {
    raw = reader(bytes);
  } catch (const scene_detail::FormatError& e) {
    throw ImportError(name + ": " + e.what());
  } catch (const std::bad_alloc&) {
    throw ImportError(name + ": out of memory while reading");
  }
  bytes = std::string();
  return finish(name, std::move(raw), report, keep_topology);
}

Mesh read_mesh(const std::string& path, ImportReport& report, bool keep_topology) {
  const std::string ext = extension_of(path);
  if (ext.empty()) throw ImportError(path + ": no file extension (expected .off, .obj, .stl or .ply)");
  if (!is_mesh_extension(ext))
    throw ImportError(path + ": unknown extension '" + ext + "' (expected .off, .obj, .stl or .ply)");
  return parse_checked(path, ext, read_file(path), report, keep_topology);
}

}  // namespace

Mesh load_mesh(const std::string& path, ImportReport& report) { return read_mesh(path, report, false); }

bool is_mesh_extension(const std::string& extension) {
  const std::string ext = lower(extension);
  return ext == ".off" || ext == ".obj" || ext == ".stl" || ext == ".ply";
}

Mesh parse_mesh(const std::string& name, const std::string& extension, std::string bytes, ImportReport& report) {
  return parse_checked(name, extension, std::move(bytes), report, false);
}

Mesh make_mesh(const std::string& name, std::vector<std::array<double, 3>> vertices,
               std::vector<std::vector<std::uint32_t>> faces, ImportReport& report) {
  RawMesh raw;
  raw.vertices = std::move(vertices);
  raw.faces = std::move(faces);
  return finish(name, std::move(raw), report);
}

namespace {

// Scene::add, with the mesh's topology taken as it is when `fresh` (a mesh just read, which no one
// has had the chance to change) rather than found again.
void add_to(Scene& scene, Mesh mesh, const ImportReport& report, bool fresh) {
  InputInfo& input = scene.input;
  input.files.push_back(mesh.file);
  input.faces += mesh.faces.size();
  input.vertices += mesh.vertices.size();
  input.welded_vertices += report.welded_vertices;
  input.parts.push_back(mesh.name);
  scene.warnings.insert(scene.warnings.end(), report.warnings.begin(), report.warnings.end());
  if (!fresh || !mesh.topology) mesh.topology = std::make_shared<const MeshTopology>(analyse_mesh(mesh));
  scene.meshes.push_back(std::move(mesh));
}

}  // namespace

void Scene::add(Mesh mesh, const ImportReport& report) { add_to(*this, std::move(mesh), report, false); }

void add_mesh_file(Scene& scene, const std::string& path) {
  ImportReport report;
  Mesh mesh = read_mesh(path, report, true);
  add_to(scene, std::move(mesh), report, true);
}

Scene load_scene(const std::vector<std::string>& paths) {
  Scene scene;
  for (const auto& path : paths) add_mesh_file(scene, path);
  return scene;
}

}  // namespace hlr
