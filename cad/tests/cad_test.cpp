// hlr_cad: the fixtures of cad_fixtures.hpp read back (parts, names, welding, the B-rep's feature
// edges), the hidden-line engine checked by the line oracle on a tessellation, and the hlr
// program end to end (draw, mesh, bad input).
#include "cad_fixtures.hpp"
#include "line_oracle.hpp"
#include "line_runs.hpp"

#include <hlr/cad/cad.hpp>
#include <hlr/kernel/features.hpp>
#include <hlr/kernel/mesh_edges.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using namespace hlr;

// The fixtures, written once per test process into a folder of its own (ctest runs tests of this
// binary in parallel processes).
const fs::path& fixtures() {
  static const fs::path dir = [] {
    fs::path d = fs::path(HLR_CAD_TEST_DIR) / ("run-" + std::to_string(::getpid()));
    fs::remove_all(d);
    fs::create_directories(d / "out");
    cad_test::write_fixtures(d.string());
    return d;
  }();
  return dir;
}

std::string fixture(const std::string& name) { return (fixtures() / name).string(); }

class CadEnvironment : public ::testing::Environment {
 public:
  void TearDown() override {
    std::error_code ignored;
    fs::remove_all(fs::path(HLR_CAD_TEST_DIR) / ("run-" + std::to_string(::getpid())), ignored);
  }
};
const auto* const kEnvironment = ::testing::AddGlobalTestEnvironment(new CadEnvironment);

View view_named(const std::string& name) {
  View v;
  EXPECT_TRUE(named_view(name, v)) << name;
  return v;
}

// Every edge of the mesh used by exactly two faces running it in opposite directions.
void expect_closed_manifold(const Mesh& mesh, const std::string& label) {
  const std::vector<EdgeUse> uses = edge_uses(mesh);
  std::size_t bad = 0, edges = 0;
  for_each_edge(uses, [&](EdgeUses first, EdgeUses last) {
    ++edges;
    if (last - first != 2 || first[0].forward == first[1].forward) ++bad;
  });
  EXPECT_EQ(bad, 0u) << label << ": " << bad << " of " << edges << " edges are not shared by two faces";
}

// ---- the model read back -----------------------------------------------------------------------

TEST(CadImport, PartsAndNames) {
  auto plate = cad::load_cad(fixture("plate.step"));
  ASSERT_EQ(plate.size(), 1u);
  EXPECT_EQ(plate[0].mesh.file, fixture("plate.step"));
  EXPECT_GT(plate[0].mesh.faces.size(), 100u);

  auto assembly = cad::load_cad(fixture("assembly.step"));
  ASSERT_EQ(assembly.size(), 2u);
  EXPECT_EQ(assembly[0].mesh.name, "base");
  EXPECT_EQ(assembly[1].mesh.name, "peg");
  // The peg's placement applied: it stands on the base's top, around (40, 40).
  double zmin = 1e9, xmax = -1e9;
  for (const auto& p : assembly[1].mesh.vertices) {
    zmin = std::min(zmin, p[2]);
    xmax = std::max(xmax, p[0]);
  }
  EXPECT_EQ(zmin, 10);
  EXPECT_EQ(xmax, 50);

  auto two = cad::load_cad(fixture("two_solids.step"));
  ASSERT_EQ(two.size(), 2u);
  EXPECT_EQ(two[0].mesh.name, "two_solids#1");  // no product names: the file's stem, numbered
  EXPECT_EQ(two[1].mesh.name, "two_solids#2");

  for (const std::string f : {"plate.iges", "plate_faces.igs", "plate.brep", "flange.step", "bracket.step"})
    EXPECT_EQ(cad::load_cad(fixture(f)).size(), 1u) << f;

  const Scene scene = cad::load_scene({fixture("assembly.step"), fixture("plate.step")});
  ASSERT_EQ(scene.meshes.size(), 3u);
  EXPECT_EQ(scene.input.parts, (std::vector<std::string>{"base", "peg", ""}));
}

TEST(CadImport, ClosedSolidsAreClosedManifoldMeshes) {
  for (const std::string f : {"plate.step", "plate.iges", "plate_faces.igs", "plate.brep", "flange.step", "bracket.step",
                              "assembly.step", "two_solids.step"})
    for (const auto& part : cad::load_cad(fixture(f))) {
      expect_closed_manifold(part.mesh, f + " " + part.mesh.name);
      EXPECT_EQ(part.report.nonmanifold_faces, 0u) << f;
      EXPECT_EQ(part.report.inward_components, 0u) << f;
      EXPECT_EQ(part.report.welded_vertices, 0u) << f << ": welded before make_mesh";
    }
}

TEST(CadImport, DeflectionControlsTheTessellation) {
  cad::CadOptions coarse, fine;
  coarse.deflection = 1;
  fine.deflection = 0.01;
  const auto a = cad::load_cad(fixture("flange.step"), coarse), b = cad::load_cad(fixture("flange.step"), fine);
  EXPECT_LT(a[0].mesh.faces.size(), b[0].mesh.faces.size());
}

// The drawing's boundary and crease edges are the B-rep's edges: an edge of two triangles is a
// crease exactly when the triangles lie on different B-rep faces (and, without --smooth-edges,
// the B-rep edge is not tangent); inside a face only silhouettes.
TEST(CadImport, FeatureEdgesAreTheBrepEdges) {
  for (const std::string name : {"plate", "flange", "bracket"}) {
    const auto parts = cad::load_cad(fixture(name + ".step"));
    const Mesh& mesh = parts[0].mesh;
    const cad_test::BrepCounts counts = cad_test::brep_counts(name);
    std::set<std::int32_t> groups(mesh.face_group.begin(), mesh.face_group.end());
    EXPECT_EQ(int(groups.size()), counts.faces) << name;
    for (const std::string view_name : {"front", "top", "iso"}) {
      for (const bool smooth : {true, false}) {
        FeatureOptions options;
        options.smooth_edges = smooth ? SmoothEdges::full : SmoothEdges::off;
        options.crease_degrees = 1;  // must not matter
        const View view = view_named(view_name);
        std::map<std::pair<std::uint32_t, std::uint32_t>, FeatureKind> drawn;
        for (const FeatureEdge& e : feature_edges(mesh, view, options)) {
          drawn[{e.v0, e.v1}] = e.kind;
          EXPECT_NE(e.kind, FeatureKind::boundary) << name;
          EXPECT_NE(e.kind, FeatureKind::group) << name;
        }
        std::set<std::pair<std::int32_t, std::int32_t>> pairs, drawn_pairs;
        std::size_t inside_drawn = 0, silhouettes_inside = 0;
        const std::vector<EdgeUse> uses = edge_uses(mesh);
        for_each_edge(uses, [&](EdgeUses first, EdgeUses last) {
          ASSERT_EQ(last - first, 2);
          const std::int32_t g = mesh.face_group[first[0].face], h = mesh.face_group[first[1].face];
          const auto it = drawn.find({edge_low(first->key), edge_high(first->key)});
          if (g == h) {
            if (it != drawn.end() && it->second != FeatureKind::silhouette) ++inside_drawn;
            if (it != drawn.end()) ++silhouettes_inside;
            return;
          }
          pairs.insert(std::minmax(g, h));
          if (it != drawn.end()) drawn_pairs.insert(std::minmax(g, h));
        });
        const std::string label = name + " " + view_name + (smooth ? " smooth" : "");
        EXPECT_EQ(inside_drawn, 0u) << label << ": tessellation edges inside a B-rep face drawn";
        EXPECT_EQ(int(pairs.size()), counts.face_pairs) << label;
        // Every pair of faces meeting at a B-rep edge is drawn there; tangent ones only when smooth
        // (unless a silhouette runs along them).
        if (smooth) {
          EXPECT_EQ(int(drawn_pairs.size()), counts.face_pairs) << label;
        } else {
          EXPECT_GE(int(drawn_pairs.size()), counts.face_pairs - counts.tangent_pairs) << label;
        }
        if (name == "plate" || name == "flange") {
          EXPECT_EQ(counts.tangent_pairs, 0) << label;
          // Looking along the holes' axes, their sides are edge-on: no silhouette inside a face.
          if (view_name == "top") {
            EXPECT_EQ(silhouettes_inside, 0u) << label;
          }
        }
        if (name == "bracket") {
          EXPECT_EQ(counts.tangent_pairs, 4) << label;  // two fillets, two sides each
        }
      }
    }
  }
}

// --smooth-edges thin: the tangent B-rep edges (Mesh::source_edges bit 2) are kind smooth, and
// the feature set is full's with those creases made smooth (silhouettes stay silhouettes).
TEST(CadImport, TangentEdgesAreSmoothEdges) {
  const Mesh mesh = cad::load_cad(fixture("bracket.step"))[0].mesh;
  std::set<std::pair<std::uint32_t, std::uint32_t>> tangent;
  for (std::uint32_t f = 0; f < mesh.faces.size(); ++f)
    for (std::size_t i = 0; i < mesh.faces[f].size(); ++i)
      if (mesh.source_edges[f] >> (i + 4) & 1u)
        tangent.insert(std::minmax(mesh.faces[f][i], mesh.faces[f][(i + 1) % mesh.faces[f].size()]));
  ASSERT_FALSE(tangent.empty());
  for (const std::string view_name : {"front", "top", "iso"}) {
    auto drawn = [&](SmoothEdges mode) {
      FeatureOptions options;
      options.smooth_edges = mode;
      std::map<std::pair<std::uint32_t, std::uint32_t>, FeatureKind> out;
      for (const FeatureEdge& e : feature_edges(mesh, view_named(view_name), options)) out[{e.v0, e.v1}] = e.kind;
      return out;
    };
    const auto full = drawn(SmoothEdges::full), thin = drawn(SmoothEdges::thin), off = drawn(SmoothEdges::off);
    ASSERT_EQ(full.size(), thin.size()) << view_name;
    std::size_t smooth = 0;
    for (const auto& [edge, kind] : thin) {
      ASSERT_TRUE(full.count(edge)) << view_name;
      if (kind == FeatureKind::smooth) {
        ++smooth;
        EXPECT_TRUE(tangent.count(edge)) << view_name;
        EXPECT_EQ(full.at(edge), FeatureKind::crease) << view_name;
        EXPECT_FALSE(off.count(edge)) << view_name;
      } else {
        EXPECT_EQ(full.at(edge), kind) << view_name;
        EXPECT_TRUE(kind == FeatureKind::silhouette || !tangent.count(edge)) << view_name;
      }
    }
    EXPECT_GT(smooth, 0u) << view_name;
  }
}

// The engine on a CAD tessellation against the line oracle, with the drawing's own feature set
// (the oracle knows Mesh::source_edges too).
TEST(CadImport, LineOracleOnTheBracket) {
  cad::CadOptions coarse;
  coarse.deflection = 0.5;
  coarse.angular_degrees = 30;
  std::vector<Mesh> meshes;
  for (auto& part : cad::load_cad(fixture("bracket.step"), coarse)) meshes.push_back(std::move(part.mesh));
  for (const SmoothEdges smooth : {SmoothEdges::off, SmoothEdges::full, SmoothEdges::thin}) {
    for (const std::string view_name : {"front", "iso"}) {
      hidden_line::LineOptions options;
      options.features.smooth_edges = smooth;
      const View view = view_named(view_name);
      hltest::LineRun run = hltest::run_lines(meshes, view, options);
      const hltest::LineOracle oracle(meshes, view);
      const hltest::LineReport report = hltest::check_lines(oracle, run.set, hltest::check_options_for(options));
      EXPECT_TRUE(report.ok()) << view_name << " smooth " << int(smooth) << ": " << report.summary();
      EXPECT_GT(run.set.lines.size(), 0u);
      const std::size_t smooth_lines = run.set.stats.by_kind[static_cast<int>(FeatureKind::smooth)];
      if (smooth == SmoothEdges::thin) EXPECT_GT(smooth_lines, 0u) << view_name;
      else EXPECT_EQ(smooth_lines, 0u) << view_name;
    }
  }
}

TEST(CadImport, BadModels) {
  auto message = [](const std::string& path, const cad::CadOptions& options = {}) -> std::string {
    try {
      cad::load_cad(path, options);
    } catch (const ImportError& e) {
      return e.what();
    }
    return "(no error)";
  };
  const fs::path dir = fixtures();
  std::ofstream(dir / "garbage.step") << "this is not ISO-10303-21\n";
  std::ofstream(dir / "empty.step");
  std::ofstream(dir / "garbage.iges") << "hello\n";
  std::ofstream(dir / "garbage.brep") << "hello\n";
  EXPECT_EQ(message((dir / "garbage.step").string()).rfind((dir / "garbage.step").string() + ": not a STEP file", 0), 0u);
  EXPECT_EQ(message((dir / "empty.step").string()), (dir / "empty.step").string() + ": empty file");
  EXPECT_NE(message((dir / "garbage.iges").string()).find(": not an IGES file"), std::string::npos)
      << message((dir / "garbage.iges").string());
  EXPECT_NE(message((dir / "garbage.brep").string()).find(": not an OpenCASCADE .brep file"), std::string::npos);
  EXPECT_NE(message((dir / "missing.step").string()).find(": cannot open"), std::string::npos);
  EXPECT_NE(message(fixture("wire_only.step")).find(": no faces"), std::string::npos) << message(fixture("wire_only.step"));
  cad::CadOptions bad;
  bad.deflection = -1;
  EXPECT_NE(message(fixture("plate.step"), bad).find("--deflection"), std::string::npos);
  bad.deflection = std::nan("");
  EXPECT_NE(message(fixture("plate.step"), bad).find("--deflection"), std::string::npos);
}

// ---- the hlr program ------------------------------------------------------------------------------

struct Outcome {
  int exit_code = -1;
  std::string out, err;
};

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

Outcome hlr_run(std::vector<std::string> args) {
  args.insert(args.begin(), HLR_BINARY);
  std::vector<char*> argv;
  for (auto& s : args) argv.push_back(s.data());
  argv.push_back(nullptr);
  const std::string out_log = (fixtures() / "stdout").string(), err_log = (fixtures() / "stderr").string();
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, out_log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, 2, err_log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  Outcome run;
  if (rc != 0) {
    ADD_FAILURE() << "cannot start " << argv[0];
    return run;
  }
  int status = 0;
  waitpid(pid, &status, 0);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  run.out = slurp(out_log);
  run.err = slurp(err_log);
  return run;
}

std::string out(const std::string& name) { return (fixtures() / "out" / name).string(); }

// The lines of a hlr-lines/1 document as comparable text: ends, visibility and mesh edge; the
// kind as drawn (a CAD crease is a mesh file's group edge, see below).
std::multiset<std::string> line_texts(const json& doc) {
  std::multiset<std::string> texts;
  for (const auto& l : doc["lines"]) {
    std::string kind = l["kind"];
    if (kind == "group") kind = "crease";
    texts.insert(l["a"].dump() + l["b"].dump() + (l["visible"].get<bool>() ? " v " : " h ") + kind + " " +
                 l["edge"].dump());
  }
  return texts;
}

// The same part as STEP and as the OFF `hlr mesh` writes from it: the same drawing. The OFF keeps
// the B-rep faces as face colours, so its group edges are the STEP's B-rep edges (tangent ones
// included, hence --smooth-edges on the STEP) and --crease 180 leaves the crease rule out.
TEST(CadCli, StepAndItsMeshDrawAlike) {
  for (const std::string name : {"bracket", "plate"}) {
    const Outcome mesh = hlr_run({"mesh", fixture(name + ".step"), "-o", out(name + ".off")});
    ASSERT_EQ(mesh.exit_code, 0) << mesh.err;
    EXPECT_EQ(mesh.err, "");
    for (const std::string view : {"iso", "front", "top"}) {
      const Outcome a = hlr_run({"draw", fixture(name + ".step"), "--smooth-edges", "--view", view, "-o", out("a.json")});
      const Outcome b = hlr_run({"draw", out(name + ".off"), "--crease", "180", "--view", view, "-o", out("b.json")});
      ASSERT_EQ(a.exit_code, 0) << a.err;
      ASSERT_EQ(b.exit_code, 0) << b.err;
      const json ja = json::parse(slurp(out("a.json"))), jb = json::parse(slurp(out("b.json")));
      EXPECT_GT(ja["lines"].size(), 0u);
      EXPECT_TRUE(line_texts(ja) == line_texts(jb)) << name << " " << view;
      EXPECT_EQ(ja["stats"]["lines_by_kind"]["boundary"], 0) << name;
      EXPECT_EQ(ja["stats"]["lines_by_kind"]["group"], 0) << name;
    }
  }
}

// --smooth-edges thin on a STEP: the bracket's fillet boundaries as kind smooth, the visible ones
// in the SVG's thin group and on the DXF's layer THIN; the other lines as with full.
TEST(CadCli, SmoothEdgesThinOnAStep) {
  const Outcome thin = hlr_run({"draw", fixture("bracket.step"), "--smooth-edges", "thin", "--view", "iso", "-o",
                                out("t.json"), "-o", out("t.svg"), "-o", out("t.dxf")});
  ASSERT_EQ(thin.exit_code, 0) << thin.err;
  const Outcome full = hlr_run({"draw", fixture("bracket.step"), "--smooth-edges", "full", "--view", "iso", "-o", out("f.json")});
  ASSERT_EQ(full.exit_code, 0) << full.err;
  const json jt = json::parse(slurp(out("t.json"))), jf = json::parse(slurp(out("f.json")));
  EXPECT_GT(jt["stats"]["lines_by_kind"]["smooth"].get<int>(), 0);
  EXPECT_EQ(jt["stats"]["lines_by_kind"]["crease"].get<int>() + jt["stats"]["lines_by_kind"]["smooth"].get<int>(),
            jf["stats"]["lines_by_kind"]["crease"].get<int>());
  EXPECT_EQ(jt["lines"].size(), jf["lines"].size());
  const std::string svg = slurp(out("t.svg"));
  EXPECT_NE(svg.find("<g id=\"thin\" class=\"thin\""), std::string::npos);
  EXPECT_NE(slurp(out("t.dxf")).find("\nTHIN\n"), std::string::npos);
}

// The line oracle on the tessellation `hlr mesh` writes, read back as a mesh file: its B-rep faces
// are face groups, so its feature set is the drawing's (every B-rep edge, no edge inside a face).
TEST(CadCli, LineOracleOnTheWrittenMesh) {
  const Outcome run = hlr_run({"mesh", fixture("plate.step"), "--deflection", "0.5", "-o", out("plate_oracle.off")});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  ImportReport report;
  const std::vector<Mesh> meshes{load_mesh(out("plate_oracle.off"), report)};
  for (const std::string view_name : {"top", "iso"}) {
    hidden_line::LineOptions options;
    options.features.crease_degrees = 180;  // groups only: the B-rep's edges
    const View view = view_named(view_name);
    hltest::LineRun lines = hltest::run_lines(meshes, view, options);
    const hltest::LineOracle oracle(meshes, view);
    const hltest::LineReport check = hltest::check_lines(oracle, lines.set, hltest::check_options_for(options));
    EXPECT_TRUE(check.ok()) << view_name << ": " << check.summary();
    EXPECT_GT(lines.set.stats.by_kind[static_cast<int>(FeatureKind::group)], 0u) << view_name;
  }
}

// BRepMesh meshes faces in parallel: the tessellation, and so the drawing, must not depend on
// the number of threads (a plate with a grid of holes has many faces to share out).
TEST(CadCli, TessellationIsTheSameForAnyThreadCount) {
  cad_test::write_bench_parts(fixtures().string(), {6});
  for (const std::string name : {"grid_6x6", "flange", "bracket", "assembly"}) {
    std::string meshes[2];
    for (int threads : {1, 2}) {
      const std::string path = out(name + "-t" + std::to_string(threads) + ".off");
      const Outcome run = hlr_run({"mesh", fixture(name + ".step"), "--threads", std::to_string(threads), "-o", path});
      ASSERT_EQ(run.exit_code, 0) << run.err;
      meshes[threads - 1] = slurp(path);
    }
    EXPECT_GT(meshes[0].size(), 0u) << name;
    EXPECT_TRUE(meshes[0] == meshes[1]) << name << ": the OFF written with 1 and with 2 threads differ";
  }
}

TEST(CadCli, MeshFormatsReadBackAlike) {
  const auto parts = cad::load_cad(fixture("plate.step"));
  const Mesh& mesh = parts[0].mesh;
  for (const std::string ext : {".off", ".obj", ".stl", ".ply"}) {
    const Outcome run = hlr_run({"mesh", fixture("plate.step"), "-o", out("plate" + ext)});
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_NE(run.out.find("wrote " + out("plate" + ext)), std::string::npos) << run.out;
    ImportReport report;
    const Mesh back = load_mesh(out("plate" + ext), report);
    EXPECT_EQ(back.faces.size(), mesh.faces.size()) << ext;
    EXPECT_EQ(back.vertices.size(), mesh.vertices.size()) << ext;
    if (ext != ".stl") {
      EXPECT_TRUE(back.vertices == mesh.vertices) << ext;
      EXPECT_TRUE(back.faces == mesh.faces) << ext;
      std::set<std::int32_t> groups(back.face_group.begin(), back.face_group.end());
      std::set<std::int32_t> want(mesh.face_group.begin(), mesh.face_group.end());
      EXPECT_EQ(groups.size(), want.size()) << ext;
    }
  }
}

TEST(CadCli, AssemblyPartsInTheDrawing) {
  const Outcome run = hlr_run({"draw", fixture("assembly.step"), "--view", "front", "-o", out("asm.json"), "-o",
                               out("asm.dxf")});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const json doc = json::parse(slurp(out("asm.json")));
  EXPECT_EQ(doc["input"]["parts"], json::array({"base", "peg"}));
  const std::string dxf = slurp(out("asm.dxf"));
  EXPECT_NE(dxf.find("BASE-VISIBLE"), std::string::npos);  // a layer pair per part
  EXPECT_NE(dxf.find("PEG-VISIBLE"), std::string::npos);
  for (const std::string cmd : {"surfaces", "shadows", "sheet"}) {
    std::vector<std::string> args{cmd, fixture("plate.step"), "-o", out("plate_" + cmd + (cmd == "shadows" ? ".json" : ".svg"))};
    if (cmd == "shadows") args.insert(args.end(), {"--sun", "1,2,-4"});
    const Outcome r = hlr_run(args);
    EXPECT_EQ(r.exit_code, 0) << cmd << ": " << r.err;
  }
}

// ---- true curves ---------------------------------------------------------------------------------

// The ENTITIES of a DXF as (type, group code -> value) for the codes a curve has.
struct DxfEntity {
  std::string type;
  std::map<int, double> value;
};
std::vector<DxfEntity> dxf_entities(const std::string& text) {
  std::istringstream in(text);
  std::vector<DxfEntity> out;
  bool entities = false;
  for (std::string code, value; std::getline(in, code) && std::getline(in, value);) {
    const int c = std::stoi(code);
    if (!value.empty() && value.back() == '\r') value.pop_back();
    if (c == 2 && value == "ENTITIES") entities = true;
    if (!entities) continue;
    if (c == 0) {
      if (value == "ENDSEC") break;
      out.push_back({value, {}});
    } else if (!out.empty() && (c == 10 || c == 11 || c == 20 || c == 21 || (c >= 40 && c <= 42) || c == 50 || c == 51)) {
      out.back().value[c] = std::stod(value);
    }
  }
  return out;
}

// The circles of the B-rep (OCC, read from the STEP file by the fixtures' code, not hlr's) in a
// view, grouped where their images coincide (a through hole's two rims seen face-on): each group's
// entities in the DXF must go round it exactly once in all, visible and hidden together (ISO 128
// precedence drops a hidden run under an equal visible one), so there are at least as many
// entities as groups, and fewer groups than face-on edges where rims coincide. Face-on: CIRCLE or
// ARC of the B-rep's centre and radius; at a slant: ELLIPSE of its centre, major radius and ratio
// |cos|; edge-on (front and right views of these parts): none, and no circle recovered either.
struct CurveImage {
  double x, y, radius, ratio;  // centre and radius in the view; ellipse: minor over major
  int edges = 0;
  double turns = 0;  // what the DXF's entities on it sweep, in turns
};

TEST(CadCli, TrueCirclesFromTheBrep) {
  constexpr double two_pi = 2 * 3.14159265358979323846;
  for (const std::string name : {"plate", "flange"}) {
    const std::vector<cad_test::BrepCircle> circles = cad_test::brep_circles(fixture(name + ".step"));
    ASSERT_GT(circles.size(), 4u) << name;
    const Mesh mesh = cad::load_cad(fixture(name + ".step"))[0].mesh;
    std::array<double, 3> lo = mesh.vertices[0], hi = lo;
    for (const auto& v : mesh.vertices)
      for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], v[k]), hi[k] = std::max(hi[k], v[k]);
    const double size = std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]), tolerance = 1e-9 * size;
    // Merged at the sheet's resolution (the default), and not (no circle recovered from polygons).
    for (const bool merged : {true, false}) {
      for (const std::string view_name : {"front", "top", "right", "iso"}) {
        const std::string label = name + " " + view_name + (merged ? "" : " unmerged");
        const View view = view_named(view_name);
        const Vec3 d = view.direction, up = view.up;
        Vec3 x{d[1] * up[2] - d[2] * up[1], d[2] * up[0] - d[0] * up[2], d[0] * up[1] - d[1] * up[0]};
        Vec3 y{x[1] * d[2] - x[2] * d[1], x[2] * d[0] - x[0] * d[2], x[0] * d[1] - x[1] * d[0]};
        auto unit = [](Vec3& v) {
          const double n = std::hypot(v[0], v[1], v[2]);
          for (double& c : v) c /= n;
        };
        unit(x), unit(y);
        auto dot = [](const Vec3& a, const std::array<double, 3>& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
        std::vector<CurveImage> face_on, slanted;
        std::size_t face_on_edges = 0;
        for (const auto& c : circles) {
          const Vec3 cross{c.normal[1] * d[2] - c.normal[2] * d[1], c.normal[2] * d[0] - c.normal[0] * d[2],
                           c.normal[0] * d[1] - c.normal[1] * d[0]};
          const double cosine = std::abs(dot(d, c.normal)) / std::hypot(d[0], d[1], d[2]);
          if (cosine == 0) continue;  // edge-on: a segment, drawn as lines
          const bool parallel = cross[0] == 0 && cross[1] == 0 && cross[2] == 0;
          face_on_edges += parallel;
          std::vector<CurveImage>& list = parallel ? face_on : slanted;
          const CurveImage image{dot(x, c.centre), dot(y, c.centre), c.radius, parallel ? 1 : cosine};
          auto same = [&](const CurveImage& o) {
            return std::abs(o.x - image.x) <= tolerance && std::abs(o.y - image.y) <= tolerance &&
                   std::abs(o.radius - image.radius) <= tolerance && std::abs(o.ratio - image.ratio) <= 1e-9;
          };
          auto it = std::find_if(list.begin(), list.end(), same);
          if (it == list.end()) it = list.insert(list.end(), image);
          ++it->edges;
        }
        std::vector<std::string> args{"draw", fixture(name + ".step"), "--view", view_name, "-o", out(name + ".dxf"), "-o",
                                      out(name + ".svg"), "-o", out(name + ".json")};
        if (!merged) args.insert(args.end(), {"--merge-distance", "0"});
        const Outcome run = hlr_run(args);
        ASSERT_EQ(run.exit_code, 0) << run.err;
        std::size_t dxf_circles = 0, dxf_arcs = 0, dxf_curves = 0;
        for (const DxfEntity& e : dxf_entities(slurp(out(name + ".dxf")))) {
          const bool circle = e.type == "CIRCLE", arc = e.type == "ARC", ellipse = e.type == "ELLIPSE";
          if (!circle && !arc && !ellipse) continue;
          ++dxf_curves;
          dxf_circles += circle;
          dxf_arcs += arc;
          auto v = [&](int code) { return e.value.count(code) ? e.value.at(code) : 0.0; };
          std::vector<CurveImage>& list = ellipse ? slanted : face_on;
          const double radius = ellipse ? std::hypot(v(11), v(21)) : v(40);
          // 1e-9 of the size, as the issue asks; and face-on, the B-rep's own radius and its centre
          // rounded once (a circle recovered from the polygon is off by some 1e-12 of the size).
          const double close = ellipse ? tolerance : 1e-14 * size;
          const auto it = std::find_if(list.begin(), list.end(), [&](const CurveImage& c) {
            return std::abs(c.x - v(10)) <= close && std::abs(c.y - v(20)) <= close &&
                   (ellipse ? std::abs(c.radius - radius) <= tolerance && std::abs(c.ratio - v(40)) <= 1e-9
                            : c.radius == radius);
          });
          ASSERT_NE(it, list.end()) << label << ": " << e.type << " at (" << v(10) << ", " << v(20) << ") r " << radius
                                    << " is no B-rep circle";
          double sweep = circle ? 360 : ellipse ? (v(42) - v(41)) * 360 / two_pi : v(51) - v(50);
          while (sweep <= 0) sweep += 360;
          it->turns += sweep / 360;
        }
        EXPECT_EQ(slanted.empty() && face_on.empty(), dxf_curves == 0) << label;
        for (const CurveImage& c : face_on)
          EXPECT_NEAR(c.turns, 1, 1e-9) << label << ": the circle at (" << c.x << ", " << c.y << ") r " << c.radius;
        // At a slant a hole's hidden rim touches the silhouette lines of its wall, and the sheet's
        // merge (at the drawing's resolution) trims the rim's runs that run along them.
        for (const CurveImage& c : slanted) {
          if (!merged) EXPECT_NEAR(c.turns, 1, 1e-9) << label << ": the ellipse at (" << c.x << ", " << c.y << ")";
          EXPECT_LE(c.turns, 1 + 1e-9) << label << ": the ellipse at (" << c.x << ", " << c.y << ") r " << c.radius;
          EXPECT_GE(c.turns, 0.9) << label << ": the ellipse at (" << c.x << ", " << c.y << ") r " << c.radius;
        }
        if (view_name == "top") EXPECT_GE(dxf_curves, face_on.size()) << label;
        if (view_name == "top") EXPECT_GT(face_on_edges, face_on.size()) << label;  // rims that coincide
        if (view_name == "front" || view_name == "right") EXPECT_EQ(dxf_curves, 0u) << label;  // every circle edge-on
        // The SVG draws the DXF's circles (one <circle> each) and its ellipses (arcs "A rx ry ..."
        // with rx != ry, at most 3/8 of a turn each).
        const std::string svg = slurp(out(name + ".svg"));
        std::size_t svg_circles = 0, svg_elliptic = 0;
        for (std::size_t at = svg.find("<circle"); at != std::string::npos; at = svg.find("<circle", at + 1)) ++svg_circles;
        for (std::size_t at = svg.find('A'); at != std::string::npos; at = svg.find('A', at + 1)) {
          double rx = 0, ry = 0;
          if (std::sscanf(svg.c_str() + at, "A%lf %lf ", &rx, &ry) == 2 && rx != ry) ++svg_elliptic;
        }
        EXPECT_EQ(svg_circles, dxf_circles) << label;
        EXPECT_GE(svg_elliptic, dxf_curves - dxf_circles - dxf_arcs) << label;
        EXPECT_EQ(svg_elliptic == 0, dxf_curves == dxf_circles + dxf_arcs) << label;
        const json doc = json::parse(slurp(out(name + ".json")));
        EXPECT_EQ(doc["stats"]["circles"].get<std::size_t>(), dxf_circles) << label;
      }
    }
  }
}

// Bad input: one line "hlr: FILE: problem" (or the option's), exit code not 0, no file written.
TEST(CadCli, BadInputIsOneLineAndNoFile) {
  const fs::path dir = fixtures();
  std::ofstream(dir / "not_step.step") << "solid box\nendsolid\n";
  std::ofstream(dir / "empty.stp");
  std::ofstream(dir / "not_iges.igs") << "nothing\n";
  struct Case {
    std::vector<std::string> args;
    std::string needle;
    int exit_code;
  };
  const std::vector<Case> cases = {
      {{"draw", (dir / "not_step.step").string()}, "not_step.step: not a STEP file", 1},
      {{"draw", (dir / "empty.stp").string()}, "empty.stp: empty file", 1},
      {{"draw", (dir / "not_iges.igs").string()}, "not_iges.igs: not an IGES file", 1},
      {{"draw", fixture("wire_only.step")}, "wire_only.step: no faces", 1},
      {{"draw", (dir / "missing.step").string()}, "missing.step: cannot open", 1},
      {{"draw", fixture("plate.step"), "--deflection", "0"}, "--deflection", 2},
      {{"draw", fixture("plate.step"), "--deflection", "-0.1"}, "--deflection", 2},
      {{"draw", fixture("plate.step"), "--deflection", "nan"}, "--deflection", 2},
      {{"mesh", (dir / "not_step.step").string()}, "not_step.step: not a STEP file", 1},
  };
  for (const Case& c : cases) {
    fs::remove_all(dir / "bad");
    fs::create_directories(dir / "bad");
    std::vector<std::string> args = c.args;
    args.insert(args.end(), {"-o", (dir / "bad" / (c.args[0] == "mesh" ? "x.off" : "x.svg")).string()});
    const Outcome run = hlr_run(args);
    const std::string label = c.args[0] + " " + c.args[1];
    EXPECT_EQ(run.exit_code, c.exit_code) << label << ": " << run.err;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << label << ": " << run.err;
    EXPECT_EQ(run.err.rfind("hlr: ", 0), 0u) << run.err;
    EXPECT_NE(run.err.find(c.needle), std::string::npos) << label << ": " << run.err;
    EXPECT_EQ(run.out, "") << label;
    EXPECT_TRUE(fs::is_empty(dir / "bad")) << label << ": a file was written";
  }
}

// Without its OpenCASCADE module (occ_module.hpp) the program still runs on meshes, and a CAD
// file gets one line naming the file and the module, and no output.
TEST(CadCli, MissingModuleIsOneLineAndNoFile) {
  const fs::path dir = fixtures() / "no-module";
  fs::create_directories(dir);
  ::setenv("HLR_CAD_MODULE", (dir / "missing_hlr_cad_occ.so").c_str(), 1);
  const Outcome run = hlr_run({"draw", fixture("plate.step"), "-o", (dir / "x.svg").string()});
  ::unsetenv("HLR_CAD_MODULE");
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  EXPECT_EQ(run.err.rfind("hlr: " + fixture("plate.step") + ": CAD input needs hlr's OpenCASCADE module", 0), 0u)
      << run.err;
  EXPECT_NE(run.err.find("missing_hlr_cad_occ.so"), std::string::npos) << run.err;
  EXPECT_TRUE(fs::is_empty(dir));
}

}  // namespace
