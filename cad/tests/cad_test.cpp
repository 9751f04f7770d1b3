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
        options.smooth_edges = smooth;
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

// The engine on a CAD tessellation against the line oracle, with the drawing's own feature set
// (the oracle knows Mesh::source_edges too).
TEST(CadImport, LineOracleOnTheBracket) {
  cad::CadOptions coarse;
  coarse.deflection = 0.5;
  coarse.angular_degrees = 30;
  std::vector<Mesh> meshes;
  for (auto& part : cad::load_cad(fixture("bracket.step"), coarse)) meshes.push_back(std::move(part.mesh));
  for (const bool smooth : {false, true}) {
    for (const std::string view_name : {"front", "iso"}) {
      hidden_line::LineOptions options;
      options.features.smooth_edges = smooth;
      const View view = view_named(view_name);
      hltest::LineRun run = hltest::run_lines(meshes, view, options);
      const hltest::LineOracle oracle(meshes, view);
      const hltest::LineReport report = hltest::check_lines(oracle, run.set, hltest::check_options_for(options));
      EXPECT_TRUE(report.ok()) << view_name << (smooth ? " smooth" : "") << ": " << report.summary();
      EXPECT_GT(run.set.lines.size(), 0u);
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
