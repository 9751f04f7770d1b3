// Scene import: every format reads exactly and completely, topology problems are counted, bad
// files give one ImportError line that starts with the file name.
#include <hlr/kernel/mesh_edges.hpp>
#include <hlr/kernel/scene.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <unistd.h>

namespace hlr {
namespace {

namespace fs = std::filesystem;
using V3 = std::array<double, 3>;
using Face = std::vector<std::uint32_t>;

const std::string kFixtures = HLR_FIXTURES_DIR;

// A fresh directory per test binary run, removed at exit.
class TempDir {
 public:
  TempDir() {
    path_ = fs::temp_directory_path() / ("hlr_scene_tests_" + std::to_string(::getpid()));
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  std::string write(const std::string& name, const std::string& bytes) const {
    std::string p = (path_ / name).string();
    std::ofstream out(p, std::ios::binary);
    out << bytes;
    return p;
  }
  std::string path(const std::string& name) const { return (path_ / name).string(); }

 private:
  fs::path path_;
};
const TempDir& temp() {
  static TempDir dir;
  return dir;
}

Mesh load(const std::string& path, ImportReport& report) { return load_mesh(path, report); }
Mesh load(const std::string& path) {
  ImportReport report;
  Mesh m = load_mesh(path, report);
  EXPECT_TRUE(report.warnings.empty()) << path << ": " << report.warnings.front();
  return m;
}

std::vector<std::uint32_t> iota(std::uint32_t n) {
  std::vector<std::uint32_t> v(n);
  for (std::uint32_t i = 0; i < n; ++i) v[i] = i;
  return v;
}

// Little-endian / big-endian byte writers for the binary fixtures.
template <class T>
void put(std::string& out, T value, bool big = false) {
  char b[sizeof(T)];
  std::memcpy(b, &value, sizeof(T));
  if (big != (std::endian::native == std::endian::big)) std::reverse(b, b + sizeof(T));
  out.append(b, sizeof(T));
}

std::string binary_stl(const std::vector<std::array<V3, 3>>& triangles, const std::string& header = "") {
  std::string out = header;
  out.resize(80, ' ');
  put<std::uint32_t>(out, static_cast<std::uint32_t>(triangles.size()));
  for (const auto& t : triangles) {
    for (int i = 0; i < 3; ++i) put<float>(out, 0.0f);  // normal
    for (const auto& p : t)
      for (double c : p) put<float>(out, static_cast<float>(c));
    put<std::uint16_t>(out, 0);
  }
  return out;
}

// The cube of side 0.1 as 12 triangles, outward.
std::vector<std::array<V3, 3>> cube_triangles() {
  const double s = 0.1;
  V3 v[8] = {{0, 0, 0}, {s, 0, 0}, {s, s, 0}, {0, s, 0}, {0, 0, s}, {s, 0, s}, {s, s, s}, {0, s, s}};
  int quads[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  std::vector<std::array<V3, 3>> tris;
  for (auto& q : quads) {
    tris.push_back({v[q[0]], v[q[1]], v[q[2]]});
    tris.push_back({v[q[0]], v[q[2]], v[q[3]]});
  }
  return tris;
}

const std::vector<Face> kTetraFaces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};

// --- formats ------------------------------------------------------------------------------------

TEST(SceneImport, OffTetrahedronIsExact) {
  Mesh m = load(kFixtures + "/tetra.off");
  EXPECT_EQ(m.file, kFixtures + "/tetra.off");
  ASSERT_EQ(m.vertices.size(), 4u);
  // The doubles nearest to 0.1, 0.2, 0.3, not floats widened to double.
  EXPECT_EQ(m.vertices[0], (V3{0.1, 0.2, 0.3}));
  EXPECT_NE(m.vertices[0][0], static_cast<double>(0.1f));
  EXPECT_EQ(m.vertices[3], (V3{0, 0, 1}));
  EXPECT_EQ(m.faces, kTetraFaces);
  EXPECT_EQ(m.face_index, iota(4));
  EXPECT_TRUE(m.face_group.empty());
  EXPECT_TRUE(m.group_names.empty());
}

TEST(SceneImport, OffCountsOnHeaderLineQuadsAndColorGroups) {
  Mesh m = load(kFixtures + "/cube.off");
  EXPECT_EQ(m.vertices.size(), 8u);
  ASSERT_EQ(m.faces.size(), 6u);
  EXPECT_EQ(m.faces[0], (Face{0, 3, 2, 1}));
  EXPECT_EQ(m.vertices[6], (V3{1, 1, 1}));
  EXPECT_EQ(m.face_group, (std::vector<std::int32_t>{0, 0, 1, 1, 2, 2}));
  EXPECT_EQ(m.group_names, (std::vector<std::string>{"color 255 0 0", "color 0 255 0", "color 0 0 255"}));
}

TEST(SceneImport, OffHeaderVariants) {
  // No keyword; a normal per vertex (NOFF), extra numbers ignored; CRLF line ends; comments.
  std::string p1 = temp().write("nokeyword.off", "4 4 0\r\n0.1 0 0\r\n1 0 0\r\n0 1 0\r\n0 0 1\r\n"
                                                 "3 0 2 1\r\n3 0 1 3\r\n3 0 3 2\r\n3 1 2 3\r\n");
  Mesh a = load(p1);
  EXPECT_EQ(a.vertices[0][0], 0.1);
  EXPECT_EQ(a.faces, kTetraFaces);
  std::string p2 = temp().write("noff.off", "NOFF # normals follow each point\n4 4 0\n"
                                            "0.1 0 0 -1 -1 -1\n1 0 0 1 0 0\n0 1 0 0 1 0\n0 0 1 0 0 1\n"
                                            "3 0 2 1\n3 0 1 3\n3 0 3 2 # comment\n3 1 2 3\n\n\n");
  Mesh b = load(p2);
  EXPECT_EQ(b.vertices[0], (V3{0.1, 0, 0}));
  EXPECT_EQ(b.faces, kTetraFaces);
}

TEST(SceneImport, ObjCubeWithGroupsAndMaterials) {
  ImportReport report;
  Mesh m = load(kFixtures + "/cube.obj", report);
  ASSERT_EQ(m.vertices.size(), 8u);
  EXPECT_EQ(m.vertices[1], (V3{0.1, 0, 0}));
  EXPECT_EQ(m.vertices[6], (V3{0.1, 0.1, 0.1}));  // continued line, colors ignored
  ASSERT_EQ(m.faces.size(), 6u);
  EXPECT_EQ(m.faces[0], (Face{0, 3, 2, 1}));  // 1/1/1 4/1/1 ...
  EXPECT_EQ(m.faces[1], (Face{4, 5, 6, 7}));  // 5//1 ...
  EXPECT_EQ(m.faces[4], (Face{3, 7, 6, 2}));  // -5 -1 -2 -6
  EXPECT_EQ(m.face_index, iota(6));
  EXPECT_EQ(m.face_group, (std::vector<std::int32_t>{0, 0, 1, 2, 2, 2}));
  EXPECT_EQ(m.group_names, (std::vector<std::string>{"g bottom_top, usemtl steel", "g sides, usemtl steel",
                                                     "g sides, usemtl brass"}));
  EXPECT_EQ(report.nonmanifold_faces, 0u);
  ASSERT_EQ(report.warnings.size(), 1u);
  EXPECT_EQ(report.warnings[0], kFixtures + "/cube.obj: 1 'l' statement (polyline) ignored");
}

TEST(SceneImport, ObjWithoutGroupsHasNoGroups) {
  std::string p = temp().write("plain.obj", "v 0.1 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
                                            "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  Mesh m = load(p);
  EXPECT_EQ(m.vertices[0][0], 0.1);
  EXPECT_EQ(m.faces, kTetraFaces);
  EXPECT_TRUE(m.face_group.empty());
}

TEST(SceneImport, AsciiStlMergesEqualCorners) {
  Mesh m = load(kFixtures + "/tetra.stl");
  ASSERT_EQ(m.vertices.size(), 4u);  // 12 corners, 4 points; -0 and 0 are one point
  EXPECT_EQ(m.vertices[0], (V3{0.1, 0.2, 0.3}));  // ASCII text is read as double
  EXPECT_EQ(m.vertices[1], (V3{0, 1, 0}));
  EXPECT_FALSE(std::signbit(m.vertices[1][0]));  // first appearance kept
  EXPECT_EQ(m.faces, (std::vector<Face>{{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {2, 1, 3}}));
  EXPECT_TRUE(m.face_group.empty());
}

TEST(SceneImport, BinaryStlCube) {
  for (const std::string header : {"binary cube", "solid cube (binary, though the header says solid)"}) {
    std::string p = temp().write("cube_binary.stl", binary_stl(cube_triangles(), header));
    ImportReport report;
    Mesh m = load(p, report);
    EXPECT_TRUE(report.warnings.empty());
    ASSERT_EQ(m.vertices.size(), 8u) << header;
    ASSERT_EQ(m.faces.size(), 12u);
    // Binary STL holds float32: 0.1f, widened to double without rounding.
    const double s = static_cast<double>(0.1f);
    EXPECT_EQ(m.vertices[1], (V3{0, s, 0}));  // the first triangle is cube corners 0 3 2
    EXPECT_EQ(m.vertices[2], (V3{s, s, 0}));
    EXPECT_EQ(m.faces[0], (Face{0, 1, 2}));
    EXPECT_EQ(m.faces[1], (Face{0, 2, 3}));
    EXPECT_EQ(m.face_index, iota(12));
    EXPECT_EQ(report.nonmanifold_faces, 0u);
  }
}

TEST(SceneImport, AsciiPlyWithColorsAndExtraElements) {
  Mesh m = load(kFixtures + "/tetra.ply");
  ASSERT_EQ(m.vertices.size(), 4u);
  EXPECT_EQ(m.vertices[0], (V3{0.1, 0.2, 0.3}));
  EXPECT_EQ(m.faces, kTetraFaces);
  EXPECT_EQ(m.face_group, (std::vector<std::int32_t>{0, 0, 1, 0}));
  EXPECT_EQ(m.group_names, (std::vector<std::string>{"color 255 0 0", "color 0 0 255"}));
}

// A tetrahedron as binary PLY: x y z as `coord`, an extra per-vertex list, and an extra element.
std::string binary_ply(bool big, const std::string& coord) {
  std::string out = std::string("ply\nformat ") + (big ? "binary_big_endian" : "binary_little_endian") +
                    " 1.0\ncomment made by scene_test\nelement vertex 4\nproperty " + coord + " x\nproperty " +
                    coord + " y\nproperty " + coord + " z\nproperty list uchar short junk\n"
                    "element face 4\nproperty list uchar uint vertex_indices\nproperty uchar red\n"
                    "element material 1\nproperty double shine\nend_header\n";
  const V3 v[4] = {{0.1, 0.2, 0.3}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (const auto& p : v) {
    for (double c : p) {
      if (coord == "double") put<double>(out, c, big);
      else put<float>(out, static_cast<float>(c), big);
    }
    put<std::uint8_t>(out, 2);
    put<std::int16_t>(out, -7, big);
    put<std::int16_t>(out, 300, big);
  }
  for (const auto& f : kTetraFaces) {
    put<std::uint8_t>(out, 3);
    for (auto i : f) put<std::uint32_t>(out, i, big);
    put<std::uint8_t>(out, f[0] == 1 ? 9 : 4);
  }
  put<double>(out, 0.5, big);
  return out;
}

TEST(SceneImport, BinaryPlyBothEndiansExact) {
  for (bool big : {false, true}) {
    std::string p = temp().write(big ? "be.ply" : "le.ply", binary_ply(big, "double"));
    Mesh m = load(p);
    ASSERT_EQ(m.vertices.size(), 4u);
    EXPECT_EQ(m.vertices[0], (V3{0.1, 0.2, 0.3})) << "doubles stay doubles";
    EXPECT_EQ(m.faces, kTetraFaces);
    EXPECT_EQ(m.face_group, (std::vector<std::int32_t>{0, 0, 0, 1}));
    EXPECT_EQ(m.group_names, (std::vector<std::string>{"color 4", "color 9"}));
  }
  std::string p = temp().write("float.ply", binary_ply(false, "float"));
  Mesh m = load(p);
  EXPECT_EQ(m.vertices[0][0], static_cast<double>(0.1f)) << "float32 widened without rounding";
}

// --- topology -----------------------------------------------------------------------------------

TEST(SceneImport, NonManifoldFacesAreKeptAndCounted) {
  ImportReport report;
  const std::string path = kFixtures + "/nonmanifold.off";
  Mesh m = load(path, report);
  EXPECT_EQ(m.faces.size(), 4u);
  EXPECT_EQ(m.face_index, iota(4));
  EXPECT_EQ(report.nonmanifold_faces, 3u);
  EXPECT_EQ(report.degenerate_faces, 0u);
  EXPECT_EQ(report.warnings, (std::vector<std::string>{path + ": 3 faces are non-manifold (kept)"}));
}

TEST(SceneImport, OrientationClashCountsAsNonManifold) {
  ImportReport report;
  Mesh m = load(kFixtures + "/orientation_clash.off", report);
  EXPECT_EQ(m.faces.size(), 2u);
  EXPECT_EQ(report.nonmanifold_faces, 2u);
  // The same two triangles, consistently oriented, are fine.
  std::string p = temp().write("consistent.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n3 0 1 2\n3 1 0 3\n");
  ImportReport ok;
  load(p, ok);
  EXPECT_EQ(ok.nonmanifold_faces, 0u);
  EXPECT_TRUE(ok.warnings.empty());
}

TEST(SceneImport, DegenerateFacesAreSkippedAndCounted) {
  ImportReport report;
  const std::string path = kFixtures + "/degenerate.off";
  Mesh m = load(path, report);
  EXPECT_EQ(m.vertices.size(), 7u);  // vertices are never dropped
  EXPECT_EQ(m.faces, kTetraFaces);
  EXPECT_EQ(m.face_index, (std::vector<std::uint32_t>{0, 2, 5, 7}));
  EXPECT_EQ(report.degenerate_faces, 5u);
  EXPECT_EQ(report.nonmanifold_faces, 0u);
  EXPECT_EQ(report.warnings, (std::vector<std::string>{path + ": 5 degenerate faces skipped"}));
}

TEST(SceneImport, CollinearityIsExact) {
  // The third corner's x and y differ in the last bit (0.30000000000000004 is the double after
  // 0.3), so the corners are not exactly collinear; any tolerance would call this face degenerate.
  std::string p = temp().write("near.off", "OFF\n3 1 0\n0 0 0\n0.1 0.1 0.1\n0.30000000000000004 0.3 0.3\n3 0 1 2\n");
  ImportReport report;
  Mesh m = load(p, report);
  EXPECT_EQ(m.faces.size(), 1u);
  EXPECT_EQ(report.degenerate_faces, 0u);
  // A group with only degenerate faces still keeps its group ids stable for the others.
  std::string q = temp().write("collinear.off", "OFF\n4 2 0\n0 0 0\n0.5 0.5 0.5\n1 1 1\n0 0 1\n"
                                                "3 0 1 2 1 0 0\n3 0 2 3 0 1 0\n");
  ImportReport r2;
  Mesh n = load(q, r2);
  EXPECT_EQ(r2.degenerate_faces, 1u);
  EXPECT_EQ(n.face_index, (std::vector<std::uint32_t>{1}));
  EXPECT_EQ(n.face_group, (std::vector<std::int32_t>{1}));
  EXPECT_EQ(n.group_names.size(), 2u);
}

TEST(SceneImport, ReportAccumulatesOverFiles) {
  ImportReport report;
  load(kFixtures + "/degenerate.off", report);
  load(kFixtures + "/nonmanifold.off", report);
  EXPECT_EQ(report.degenerate_faces, 5u);
  EXPECT_EQ(report.nonmanifold_faces, 3u);
  EXPECT_EQ(report.warnings.size(), 2u);
}

// add_mesh_file (load_scene) keeps the topology the import's checks found; it must be the one
// Scene::add finds for the same mesh, and load_mesh must leave it unset for the caller to change.
TEST(SceneImport, AddMeshFileKeepsTheTopologySceneAddWouldFind) {
  for (const char* name :
       {"/degenerate.off", "/nonmanifold.off", "/orientation_clash.off", "/../parts/anchor.off"}) {
    const std::string path = kFixtures + name;
    const Scene kept = load_scene({path});
    ImportReport report;
    Mesh mesh = load_mesh(path, report);
    EXPECT_EQ(mesh.topology, nullptr) << name;
    Scene found;
    found.add(std::move(mesh), report);
    ASSERT_EQ(kept.meshes.size(), 1u);
    const MeshTopology &a = *kept.meshes[0].topology, &b = *found.meshes[0].topology;
    ASSERT_EQ(a.uses.size(), b.uses.size()) << name;
    for (std::size_t i = 0; i < a.uses.size(); ++i) {
      EXPECT_EQ(a.uses[i].key, b.uses[i].key);
      EXPECT_EQ(a.uses[i].face, b.uses[i].face);
      EXPECT_EQ(a.uses[i].forward, b.uses[i].forward);
    }
    EXPECT_EQ(a.sides.component, b.sides.component) << name;
    EXPECT_EQ(a.sides.outward, b.sides.outward) << name;
    EXPECT_EQ(a.groups.group, b.groups.group) << name;
    EXPECT_EQ(kept.warnings, found.warnings) << name;
    EXPECT_EQ(kept.input.faces, found.input.faces) << name;
  }
}

// --- errors -------------------------------------------------------------------------------------

struct BadFile {
  const char* name;      // file name in the temp dir
  std::string bytes;     // its content
  const char* expected;  // a piece of the problem text
};

std::string tetra_off_with(const std::string& first_vertex) {
  return "OFF\n4 4 0\n" + first_vertex + "\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
}

std::vector<BadFile> bad_files() {
  std::string stl = binary_stl(cube_triangles());
  std::string ply = binary_ply(false, "double");
  std::string ascii_stl;
  {
    std::ifstream in(kFixtures + "/tetra.stl", std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    ascii_stl = s.str();
  }
  return {
      {"empty.off", "", "empty file"},
      {"empty.stl", "", "empty file"},
      {"blank.off", "\n  \n# nothing\n", "no OFF header"},
      {"tetra.xyz", "OFF\n", "unknown extension '.xyz'"},
      {"tetra", "OFF\n", "no file extension"},
      {"notoff.off", "PLY\n4 4 0\n", "not an OFF file"},
      {"binary.off", "OFF BINARY\n", "binary OFF is not supported"},
      {"short_vertices.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n", "truncated: the header promises 4 vertices, the file ends after 2"},
      {"short_faces.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n", "truncated: the header promises 4 faces, the file ends after 1"},
      {"short_face.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n4 0 1 2\n", "line 7: face 0: the count promises 4 vertex indices, the line has 3"},
      {"no_faces.off", "OFF\n4 0 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n", "no faces"},
      {"no_faces.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n", "no faces"},
      {"all_degenerate.off", "OFF\n3 2 0\n0 0 0\n1 1 1\n2 2 2\n3 0 1 2\n2 0 1\n", "no faces left: all 2 faces are degenerate"},
      {"nan.off", tetra_off_with("0 nan 0"), "line 3: vertex 0: y coordinate nan is not a finite number"},
      {"inf.off", tetra_off_with("0 0 -inf"), "z coordinate -inf is not a finite number"},
      {"overflow.off", tetra_off_with("1e400 0 0"), "x coordinate 1e400 is out of range (at most 1e100 in magnitude)"},
      {"huge.off", tetra_off_with("0 -1.5e100 0"), "y coordinate -1.5e100 is out of range"},
      {"text.off", tetra_off_with("0 zero 0"), "line 3: vertex 0: expected a number, found 'zero'"},
      {"two_coords.off", tetra_off_with("0 0"), "vertex 0 has 2 numbers, expected 3 coordinates"},
      {"index.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", "face 0: vertex index 3 is out of range (3 vertices)"},
      {"negative.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", "vertex index -1 is out of range"},
      {"index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", "line 4: vertex index 4 is out of range (3 vertices)"},
      {"zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", "vertex index 0 is invalid"},
      {"relative.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n", "relative vertex index -4 reaches before the first vertex"},
      {"nan.obj", "v 0 0 nan\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "line 1: vertex 1: z coordinate nan is not a finite number"},
      {"huge.obj", "v 0 0 1e101\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "z coordinate 1e101 is out of range"},
      {"short.obj", "v 0 0 0\nv 1 0 0\nv 0 1\n", "line 3: vertex 3 has 2 numbers, expected 3 coordinates"},
      {"truncated.stl", stl.substr(0, stl.size() - 20), "truncated binary STL: the header promises 12 triangles (684 bytes), the file has 664 bytes"},
      {"tiny.stl", std::string("\0\0\0\0", 4), "not an STL file"},
      {"no_endsolid.stl", ascii_stl.substr(0, ascii_stl.find("endsolid")), "truncated: the file ends before 'endsolid'"},
      {"cut_facet.stl", ascii_stl.substr(0, ascii_stl.find("vertex 1 0 0")), "truncated: the file ends inside facet 0"},
      {"nan.stl", binary_stl({std::array<V3, 3>{V3{0, 0, 0}, V3{1, 0, 0}, V3{0, std::nan(""), 0}}}), "triangle 0: y coordinate nan is not a finite number"},
      {"huge.stl", "solid x\nfacet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 2e100\nendloop\nendfacet\nendsolid\n", "line 6: facet 0: z coordinate 2e100 is out of range"},
      {"truncated.ply", ply.substr(0, ply.size() - 30), "truncated: the file ends in face"},
      {"truncated_vertex.ply", ply.substr(0, ply.find("end_header") + 11 + 40), "truncated: the file ends in vertex 1 of 4"},
      {"no_header_end.ply", "ply\nformat ascii 1.0\nelement vertex 3\n", "truncated: the header has no 'end_header'"},
      {"short.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                    "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1\n",
       "truncated: the file ends in face 0 of 1"},
      {"index.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                    "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n",
       "face 0: vertex index 7 is out of range (3 vertices)"},
      {"inf.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\nproperty double z\n"
                  "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 inf\n0 1 0\n3 0 1 2\n",
       "line 11: vertex 1: z coordinate inf is not a finite number"},
      {"noz.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nend_header\n", "the vertex element has no z property"},
      {"noply.ply", "solid x\n", "not a PLY file"},
      // A planar bow-tie quad, and a keyhole whose hole pokes out of its outer loop.
      {"bowtie.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3 4\n",
       "face 0: the polygon crosses itself (a planar face must be a simple polygon)"},
      {"bad_keyhole.off", "OFF\n6 1 0\n0 0 0\n2 0 0\n2 2 0\n0 2 0\n3 1 0\n1 3 0\n7 0 1 2 3 0 4 5\n",
       "face 0: its loops cross each other"},
  };
}

// --- welding and faces as exporters write them ------------------------------------------------

// The undirected edges of a mesh with the number of faces using each.
std::map<std::pair<std::uint32_t, std::uint32_t>, int> edge_counts(const Mesh& m) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> out;
  for (const auto& f : m.faces)
    for (std::size_t i = 0; i < f.size(); ++i) ++out[std::minmax(f[i], f[(i + 1) % f.size()])];
  return out;
}

TEST(SceneImport, TriangleSoupsAreWeldedInEveryFormat) {
  // 12 triangles with their own corners: 36 vertices, 8 distinct points.
  std::vector<std::vector<Face>> faces;
  for (const char* file : {"/soup_box.obj", "/soup_box.ply", "/../scenes/soup_box.off"}) {
    ImportReport report;
    Mesh m = load(kFixtures + file, report);
    EXPECT_EQ(m.vertices.size(), 36u) << file << ": vertices keep their numbers";
    EXPECT_EQ(report.welded_vertices, 28u) << file;
    EXPECT_TRUE(report.warnings.empty()) << file << ": " << report.warnings.front();
    const auto edges = edge_counts(m);
    EXPECT_EQ(edges.size(), 18u) << file;
    for (const auto& [edge, n] : edges) EXPECT_EQ(n, 2) << file << ": every edge shared";
    for (const auto& f : m.faces)
      for (std::uint32_t v : f)
        for (std::uint32_t w = 0; w < v; ++w) EXPECT_NE(m.vertices[w], m.vertices[v]) << "not the first copy";
    faces.push_back(m.faces);
  }
  EXPECT_EQ(faces[0], faces[1]);
  EXPECT_EQ(faces[0], faces[2]);
}

TEST(SceneImport, WeldingIsExactAndMinusZeroEqualsZero) {
  // Vertex 3 is vertex 0 (-0 == 0); vertex 4 differs from vertex 1 in the last bit: not welded.
  std::string p = temp().write("weld.off", "OFF\n6 2 0\n0 0 0\n1 0 0\n0 1 0\n-0 0 0\n1.0000000000000002 0 0\n0 -1 0\n"
                                           "3 0 1 2\n3 4 3 5\n");
  ImportReport report;
  Mesh m = load(p, report);
  EXPECT_EQ(report.welded_vertices, 1u);
  EXPECT_EQ(m.faces[1], (Face{4, 0, 5}));
}

TEST(SceneImport, UnweldableSoupIsAWarning) {
  // Three triangles that meet nowhere exactly: the user may have given a soup.
  std::string p = temp().write("soup.off", "OFF\n9 3 0\n0 0 0\n1 0 0\n0 1 0\n1.1 0 0\n1.1 1 0\n0.1 1 0\n"
                                           "5 0 0\n6 0 0\n5 1 0\n3 0 1 2\n3 3 4 5\n3 6 7 8\n");
  ImportReport report;
  load(p, report);
  ASSERT_EQ(report.warnings.size(), 1u);
  EXPECT_EQ(report.warnings[0].rfind(p + ": 3 of 3 faces share no edge with another face (a triangle soup?", 0), 0u)
      << report.warnings[0];
}

TEST(SceneImport, NonPlanarFacesAreFansFromTheFirstCorner) {
  // A planar pentagon stays one face; a twisted quad and a twisted pentagon become fans.
  std::string p = temp().write("twisted.off",
                               "OFF\n14 3 0\n0 0 0\n2 0 0\n3 1 0\n1 2 0\n-1 1 0\n"
                               "0 0 5\n1 0 5\n1 1 6\n0 1 5\n"
                               "0 0 9\n1 0 9\n2 1 9\n1 2 10\n0 1 9\n"
                               "5 0 1 2 3 4\n4 5 6 7 8\n5 9 10 11 12 13\n");
  ImportReport report;
  Mesh m = load(p, report);
  EXPECT_EQ(m.faces, (std::vector<Face>{{0, 1, 2, 3, 4}, {5, 6, 7}, {5, 7, 8}, {9, 10, 11}, {9, 11, 12}, {9, 12, 13}}));
  EXPECT_EQ(m.face_index, (std::vector<std::uint32_t>{0, 1, 1, 2, 2, 2}));
  // Internal fan edges: 5-7 (edge 2 of the first triangle, 0 of the second); 9-11 and 9-12.
  EXPECT_EQ(m.fan_edges, (std::vector<std::uint8_t>{0, 4, 1, 4, 5, 1}));
  EXPECT_EQ(report.fanned_faces, 2u);
  EXPECT_TRUE(report.warnings.empty());
}

TEST(SceneImport, KeyholeFacesAreSplitIntoTheirRegion) {
  ImportReport report;
  Mesh m = load(kFixtures + "/../scenes/keyhole_faces.off", report);
  EXPECT_EQ(report.split_faces, 2u);
  EXPECT_EQ(report.degenerate_faces, 0u);
  // Twice the area of each file face's triangles, all counter-clockwise seen from +z as the
  // outer loops run: 2 * (16 - 1.5) and 2 * (16 - 4); the floor triangle stays.
  std::map<std::uint32_t, double> area;
  for (std::size_t k = 0; k < m.faces.size(); ++k) {
    const auto& f = m.faces[k];
    ASSERT_EQ(f.size(), 3u);
    const auto &a = m.vertices[f[0]], &b = m.vertices[f[1]], &c = m.vertices[f[2]];
    const double twice = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    EXPECT_GT(twice, 0) << "triangle " << k;
    area[m.face_index[k]] += twice;
  }
  EXPECT_EQ(area[0], 29);
  EXPECT_EQ(area[1], 24);
  EXPECT_EQ(area[2], 27);
  // The hole's edges and the outer edges are used once, the triangulation's diagonals twice.
  const auto edges = edge_counts(m);
  for (auto e : {std::pair{0u, 1u}, {0u, 4u}, {4u, 5u}, {0u, 5u}, {6u, 7u}, {10u, 11u}, {10u, 13u}})
    EXPECT_EQ(edges.at(e), 1) << e.first << "-" << e.second;
  for (const auto& [edge, n] : edges) EXPECT_LE(n, 2);
}

TEST(SceneImport, InwardComponentsAreAWarning) {
  ImportReport report;
  const std::string path = kFixtures + "/../scenes/mixed_orientation.off";
  load(path, report);
  EXPECT_EQ(report.inward_components, 1u);
  EXPECT_EQ(report.warnings, (std::vector<std::string>{path + ": 1 closed component is wound inward (faces clockwise "
                                                              "seen from outside): drawn as turned outward"}));
}

// An OFF file of several megabytes is read in pieces side by side (scene_off.cpp): what it gives,
// its errors and their line numbers, must be what reading it line by line gives. A triangulated
// grid with comments, blank lines, CRLF line ends and face colors, read whole, then with errors
// planted in later pieces (the first in the file must be reported), with content after the last
// face, and with more faces promised than it has.
TEST(SceneImport, LargeOffFileIsReadAsLineByLine) {
  constexpr std::uint32_t n = 300;  // n x n vertices, 2 (n - 1)^2 triangles: about 4 MB of text
  std::vector<std::string> lines{"OFF", ""};
  std::vector<std::array<double, 3>> vertices;
  std::vector<Face> faces;
  std::vector<std::size_t> vertex_line, face_line;  // indices into `lines`
  auto decorate = [&](std::size_t k) {  // comments and blank lines here and there
    if (k % 997 == 3) lines.push_back("# a comment line");
    if (k % 1499 == 5) lines.push_back("   ");
  };
  for (std::uint32_t y = 0; y < n; ++y)
    for (std::uint32_t x = 0; x < n; ++x) {
      decorate(vertices.size());
      vertices.push_back({x * 0.25, y * 0.5, (x * 7 + y * 3) % 5 * 0.125});
      vertex_line.push_back(lines.size());
      lines.push_back(std::to_string(vertices.back()[0]) + " " + std::to_string(vertices.back()[1]) + " " +
                      std::to_string(vertices.back()[2]) + (x % 13 == 0 ? " # trailing comment\r" : ""));
    }
  std::vector<std::string> color;  // each face's, "" for none
  for (std::uint32_t y = 0; y + 1 < n; ++y)
    for (std::uint32_t x = 0; x + 1 < n; ++x) {
      const std::uint32_t v = y * n + x;
      for (const Face& f : {Face{v, v + 1, v + n + 1}, Face{v, v + n + 1, v + n}}) {
        decorate(faces.size());
        const std::size_t k = faces.size();
        faces.push_back(f);
        color.push_back(k % 7 == 0 ? "1 0 0" : k % 11 == 0 ? "0 0 1.0" : "");
        face_line.push_back(lines.size());
        lines.push_back("3 " + std::to_string(f[0]) + " " + std::to_string(f[1]) + " " + std::to_string(f[2]) +
                        (color.back().empty() ? "" : " " + color.back()));
      }
    }
  auto text = [&](std::size_t promised_faces, const std::vector<std::string>& body) {
    std::string out;
    for (std::size_t i = 0; i < body.size(); ++i)
      out += (i == 1 ? std::to_string(vertices.size()) + " " + std::to_string(promised_faces) + " 0" : body[i]) + "\n";
    return out;
  };
  ASSERT_GT(text(faces.size(), lines).size(), std::size_t(3) << 20) << "several pieces of a megabyte";

  ImportReport report;
  const Mesh m = parse_mesh("grid.off", ".off", text(faces.size(), lines), report);
  EXPECT_EQ(m.vertices, vertices);
  EXPECT_EQ(m.faces, faces);
  ASSERT_EQ(m.group_names, (std::vector<std::string>{"color 1 0 0", "(no color)", "color 0 0 1.0"}));
  ASSERT_EQ(m.face_group.size(), faces.size());
  for (std::size_t k = 0; k < faces.size(); ++k)
    ASSERT_EQ(m.face_group[k], color[k] == "1 0 0" ? 0 : color[k].empty() ? 1 : 2) << k;
  EXPECT_TRUE(report.warnings.empty());

  auto error_of = [&](std::size_t promised_faces, const std::vector<std::string>& body) {
    ImportReport ignored;
    try {
      parse_mesh("grid.off", ".off", text(promised_faces, body), ignored);
    } catch (const ImportError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  std::vector<std::string> planted = lines;
  const std::size_t late_vertex = vertices.size() - 10, late_face = faces.size() / 2;
  planted[vertex_line[late_vertex]] = "0 zero 0";
  planted[face_line[late_face]] = "3 0 1";
  EXPECT_EQ(error_of(faces.size(), planted), "grid.off: line " + std::to_string(vertex_line[late_vertex] + 1) +
                                                 ": vertex " + std::to_string(late_vertex) +
                                                 ": expected a number, found 'zero'");
  planted[vertex_line[late_vertex]] = lines[vertex_line[late_vertex]];
  EXPECT_EQ(error_of(faces.size(), planted), "grid.off: line " + std::to_string(face_line[late_face] + 1) + ": face " +
                                                 std::to_string(late_face) +
                                                 ": the count promises 3 vertex indices, the line has 2");
  EXPECT_EQ(error_of(faces.size() + 5, lines),
            "grid.off: truncated: the header promises " + std::to_string(faces.size() + 5) +
                " faces, the file ends after " + std::to_string(faces.size()));
  std::vector<std::string> longer = lines;
  longer.push_back("# after the faces");
  longer.push_back("1 2 3");
  longer.push_back("not read");
  ImportReport more;
  parse_mesh("grid.off", ".off", text(faces.size(), longer), more);
  ASSERT_EQ(more.warnings.size(), 1u);
  EXPECT_NE(more.warnings[0].find("content after the last face ignored (from line " + std::to_string(lines.size() + 2) + ")"),
            std::string::npos)
      << more.warnings[0];
}

TEST(SceneImport, BadFilesGiveOneLineNamingTheFile) {
  for (const BadFile& bad : bad_files()) {
    std::string path = temp().write(bad.name, bad.bytes);
    ImportReport report;
    try {
      load_mesh(path, report);
      ADD_FAILURE() << bad.name << ": no error";
    } catch (const ImportError& e) {
      std::string what = e.what();
      EXPECT_EQ(what.rfind(path + ": ", 0), 0u) << what;
      EXPECT_NE(what.find(bad.expected), std::string::npos) << bad.name << ": " << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
  }
}

TEST(SceneImport, UnreadableFiles) {
  const std::string missing = temp().path("does_not_exist.off");
  try {
    ImportReport report;
    load_mesh(missing, report);
    ADD_FAILURE() << "no error";
  } catch (const ImportError& e) {
    EXPECT_EQ(std::string(e.what()), missing + ": cannot open (No such file or directory)");
  }
  fs::create_directories(temp().path("folder.off"));
  try {
    ImportReport report;
    load_mesh(temp().path("folder.off"), report);
    ADD_FAILURE() << "no error";
  } catch (const ImportError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(temp().path("folder.off") + ": cannot ", 0), 0u) << e.what();
  }
}

TEST(SceneImport, TrailingContentIsAWarning) {
  std::string off = temp().write("trailing.off", tetra_off_with("0 0 0") + "3 0 1 2\n");
  ImportReport report;
  load_mesh(off, report);
  EXPECT_EQ(report.warnings, (std::vector<std::string>{off + ": content after the last face ignored (from line 11)"}));
  std::string stl = temp().write("trailing.stl", binary_stl(cube_triangles()) + "xyz");
  ImportReport r2;
  load_mesh(stl, r2);
  EXPECT_EQ(r2.warnings, (std::vector<std::string>{stl + ": 3 bytes after the last triangle ignored"}));
}

// --- shared scenes ------------------------------------------------------------------------------

// The rows of the first markdown table in `text` whose header has a column named `key`:
// column name -> cell, per row.
std::vector<std::map<std::string, std::string>> table_rows(const std::string& text, const std::string& key) {
  auto cells = [](const std::string& line) {
    std::vector<std::string> out;
    std::stringstream s(line.substr(1));
    std::string cell;
    while (std::getline(s, cell, '|')) {
      auto b = cell.find_first_not_of(' '), e = cell.find_last_not_of(' ');
      out.push_back(b == std::string::npos ? "" : cell.substr(b, e - b + 1));
    }
    return out;
  };
  std::vector<std::map<std::string, std::string>> rows;
  std::stringstream in(text);
  std::string line;
  std::vector<std::string> header;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] != '|') {
      if (!rows.empty()) break;
      header.clear();
      continue;
    }
    auto c = cells(line);
    if (header.empty()) {
      if (std::find(c.begin(), c.end(), key) != c.end()) header = c;
      continue;
    }
    if (c[0].find("---") != std::string::npos) continue;
    std::map<std::string, std::string> row;
    for (std::size_t i = 0; i < c.size() && i < header.size(); ++i) row[header[i]] = c[i];
    rows.push_back(row);
  }
  return rows;
}

TEST(SceneImport, SharedScenesMatchTheManifest) {
  const fs::path dir = HLR_SHARED_SCENES;
  if (!fs::is_directory(dir)) GTEST_SKIP() << "no shared scenes at " << dir << " (the folder beside the checkout)";
  std::ifstream manifest_file(dir / "MANIFEST.md");
  ASSERT_TRUE(manifest_file) << "no MANIFEST.md in " << dir;
  std::stringstream manifest;
  manifest << manifest_file.rdbuf();
  std::map<std::string, std::map<std::string, std::string>> files, details;
  for (auto& row : table_rows(manifest.str(), "faces")) files[row["file"]] = row;
  for (auto& row : table_rows(manifest.str(), "degenerate faces")) details[row["file"]] = row;
  ASSERT_FALSE(files.empty()) << "MANIFEST.md has no table with a 'faces' column";

  std::size_t read = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.path().extension() != ".off") continue;
    const std::string name = entry.path().filename().string();
    SCOPED_TRACE(name);
    auto it = files.find("`" + name + "`");
    ASSERT_NE(it, files.end()) << name << " is not in MANIFEST.md";
    ImportReport report;
    Mesh m = load_mesh(entry.path().string(), report);
    EXPECT_EQ(m.faces.size(), std::stoul(it->second["faces"]));
    EXPECT_EQ(m.vertices.size(), std::stoul(it->second["vertices"]));
    EXPECT_EQ(m.face_index, iota(static_cast<std::uint32_t>(m.faces.size())));
    auto d = details.find("`" + name + "`");
    if (d != details.end()) {
      EXPECT_EQ(report.degenerate_faces, std::stoul(d->second["degenerate faces"]));
    }
    // The manifest's manifold (no edge of more than two faces) and oriented (opposite directions
    // on every two-face edge) together are exactly "no non-manifold face" here.
    if (it->second["manifold"] == "yes" && it->second["oriented"].rfind("yes", 0) == 0) {
      EXPECT_EQ(report.nonmanifold_faces, 0u);
    }
    EXPECT_TRUE(report.warnings.empty()) << report.warnings.front();
    ++read;
  }
  EXPECT_EQ(read, files.size()) << "MANIFEST.md lists files that are not in " << dir;
}

}  // namespace
}  // namespace hlr
