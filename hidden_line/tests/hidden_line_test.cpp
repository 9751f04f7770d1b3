// The hidden-surface solution (build_sources + area_sort) on the exact kernel, checked against the
// independent oracle (surface_oracle.hpp) on every fixture of fixtures/scenes and every shared
// scene, in the seven named views; consolidation checked across views; and what each degenerate
// fixture is there for.
#include "surface_runs.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <set>

namespace hlr::hltest {
namespace {

using hidden_line::SourceOptions;

SourceOptions with_back_faces(bool remove) {
  SourceOptions o;
  o.remove_back_faces = remove;
  return o;
}

View view_named(const std::string& name) {
  View v;
  EXPECT_TRUE(named_view(name, v)) << name;
  return v;
}

const std::vector<Mesh>& fixture(const std::string& file) { return scene_meshes(fixture_dir() + "/" + file); }

// The file's faces from `first` on as a second mesh: two parts of an assembly. Import welds equal
// coordinates within a file, so fixtures whose components share corners are one mesh as read.
std::vector<Mesh> as_two_parts(const std::vector<Mesh>& meshes, std::uint32_t first) {
  Mesh a = meshes.front(), b = meshes.front();
  a.faces.resize(first);
  a.face_index.resize(first);
  b.faces.erase(b.faces.begin(), b.faces.begin() + first);
  b.face_index.erase(b.face_index.begin(), b.face_index.begin() + first);
  return {a, b};
}

// Solves on the exact kernel and checks every invariant; returns the map for further expectations.
XMap solve_and_check(const std::vector<Mesh>& meshes, const View& view, bool remove_back_faces, bool region_checks,
                     const std::string& label) {
  Solved solved = solve<ExactKernel>(meshes, view, with_back_faces(remove_back_faces));
  const SceneOracle oracle(meshes, view);
  CheckOptions options;
  options.remove_back_faces = remove_back_faces;
  options.region_checks = region_checks;
  const CheckReport report = check_map(oracle, solved.map, options);
  EXPECT_TRUE(report.ok()) << label << " view " << view.name << (remove_back_faces ? "" : " (back faces kept)") << ": "
                           << report.summary();
  EXPECT_EQ(report.visible_checked, solved.map.visible.size());
  EXPECT_EQ(report.hidden_checked, solved.map.hidden.size());
  // Cut into strips of two sources, the solution is another partition that passes the same checks.
  hidden_line::AreaSortOptions strips;
  strips.sources_per_strip = 2;
  const CheckReport in_strips =
      check_map(oracle, solve<ExactKernel>(meshes, view, with_back_faces(remove_back_faces), strips).map, options);
  EXPECT_TRUE(in_strips.ok()) << label << " view " << view.name << " in strips: " << in_strips.summary();
  return std::move(solved.map);
}

// ---------------------------------------------------------------------------------------------
// The oracle itself, on cases whose answers are known by hand.

TEST(SurfaceOracle, InteriorPointOfPolygonWithHole) {
  const std::vector<P2> outer{{0, 0}, {4, 0}, {4, 4}, {0, 4}};
  const std::vector<std::vector<P2>> holes{{{1, 1}, {1, 3}, {3, 3}, {3, 1}}};
  auto q = interior_point(outer, holes);
  ASSERT_TRUE(q);
  EXPECT_TRUE(strictly_inside(outer, holes, *q));
  EXPECT_EQ(locate(holes[0], *q), -1);
  EXPECT_EQ(locate(outer, P2(4, 2)), 0);
  EXPECT_EQ(locate(outer, P2(5, 2)), -1);
  EXPECT_EQ(locate(outer, P2(0, 0)), 0);
}

TEST(SurfaceOracle, DepthAndCoverageOfTheCube) {
  // Unit cube in the front view: at (1/2, 1/2) the front face (y = 0, so z = 0) and the back face
  // (z = -1 in the unnormalized frame, Z = -d = (0, -1, 0)) cover the point; the front is nearest.
  const auto& meshes = fixture("cube.off");
  const SceneOracle oracle(meshes, view_named("front"));
  const auto probe = oracle.probe(P2(FT(1) / 2, FT(1) / 2));
  EXPECT_EQ(probe.faces.size(), 2u);
  ASSERT_TRUE(probe.max_z);
  EXPECT_EQ(*probe.max_z, FT(0));
  EXPECT_FALSE(oracle.probe(P2(2, 2)).max_z);
  // Facing: front face 2 toward the viewer, back face 3 away, the four others edge-on.
  EXPECT_EQ(oracle.face({0, 2}).facing, 1);
  EXPECT_EQ(oracle.face({0, 3}).facing, -1);
  for (std::uint32_t f : {0u, 1u, 4u, 5u}) EXPECT_EQ(oracle.face({0, f}).facing, 0) << f;
  EXPECT_TRUE(oracle.face({0, 0}).closed);
}

TEST(SurfaceOracle, FixturesAreClosedAndOutwardWhereMeantToBe) {
  // Closed components of the fixtures have a positive signed volume (faces counter-clockwise seen
  // from outside; closed_sides measures it with the divergence theorem on the exact coordinates).
  // The fixtures of inward meshes (real_mesh_fixtures.py) have one inward component on purpose.
  const std::set<std::string> inward{"inward_box.off", "inward_prism.off", "mixed_orientation.off"};
  for (const std::string& file : fixture_files()) {
    const std::vector<int> sides = closed_sides(fixture(file).front());
    std::set<int> seen(sides.begin(), sides.end());
    seen.erase(0);
    if (inward.count(file)) {
      EXPECT_TRUE(seen.count(-1)) << file;
    } else {
      EXPECT_FALSE(seen.count(-1)) << file;
    }
  }
  EXPECT_EQ(closed_sides(fixture("cube.off").front()), std::vector<int>(6, 1));
}

// The checks catch what they are for: errors planted in a correct map are reported.
TEST(SurfaceChecks, CatchPlantedErrors) {
  const auto meshes = as_two_parts(fixture("stacked_boxes.off"), 6);
  const View top = view_named("top");
  const SceneOracle oracle(meshes, top);
  const XMap good = solve<ExactKernel>(meshes, top, {}).map;
  ASSERT_TRUE(check_map(oracle, good, {}).ok());
  ASSERT_FALSE(good.hidden.empty());
  auto kinds = [&](const XMap& map) {
    std::set<std::string> out;
    for (const auto& [kind, count] : check_map(oracle, map, {}).failures) out.insert(kind);
    return out;
  };
  {  // a hidden fragment reported visible: overlap, and a nearer face at its point
    XMap bad = good;
    bad.visible.push_back({bad.hidden[0].polygon, bad.hidden[0].source, -1});
    bad.hidden.erase(bad.hidden.begin());
    const auto k = kinds(bad);
    EXPECT_TRUE(k.count("(b) visible fragments overlap")) << ::testing::PrintToString(k);
    EXPECT_TRUE(k.count("(c) a face is strictly nearer")) << ::testing::PrintToString(k);
  }
  {  // a visible fragment reported hidden by the source behind it
    XMap bad = good;
    std::size_t i = 0;
    while (bad.visible[i].source != 1) ++i;
    bad.hidden.push_back({bad.visible[i].polygon, 1, 0});
    bad.visible.erase(bad.visible.begin() + static_cast<std::ptrdiff_t>(i));
    const auto k = kinds(bad);
    EXPECT_TRUE(k.count("(b) visible union != sources union")) << ::testing::PrintToString(k);
    EXPECT_TRUE(k.count("(d) point outside the occluder") || k.count("(d) occluder not strictly nearer"))
        << ::testing::PrintToString(k);
  }
  {  // a fragment lost
    XMap bad = good;
    bad.hidden.pop_back();
    EXPECT_TRUE(kinds(bad).count("(a) fragment areas"));
  }
  {  // a fragment moved by a little
    XMap bad = good;
    for (auto& p : bad.visible[0].polygon.outer) p = P2(p.x() + FT(1) / 1024, p.y());
    const auto k = kinds(bad);
    EXPECT_TRUE(k.count("(a) fragments cover the source")) << ::testing::PrintToString(k);
  }
  {  // a wrong plane, a face dropped from the sources
    XMap bad = good;
    bad.sources[0].plane.c = bad.sources[0].plane.c + 1;
    bad.sources.back().faces.push_back(0);
    const auto k = kinds(bad);
    EXPECT_TRUE(k.count("sources: plane")) << ::testing::PrintToString(k);
    EXPECT_TRUE(k.count("sources: kept faces")) << ::testing::PrintToString(k);
  }
}

// ---------------------------------------------------------------------------------------------
// Every invariant, every fixture, every named view, with and without back-face removal.

struct FixtureView {
  std::string file;
  View view;
};

void PrintTo(const FixtureView& p, std::ostream* os) { *os << p.file << " " << p.view.name; }

class FixtureViews : public ::testing::TestWithParam<FixtureView> {};

TEST_P(FixtureViews, Invariants) {
  const auto& p = GetParam();
  const auto& meshes = fixture(p.file);
  solve_and_check(meshes, p.view, true, true, p.file);
  solve_and_check(meshes, p.view, false, true, p.file);
}

std::vector<FixtureView> fixture_views() {
  std::vector<FixtureView> out;
  for (const auto& file : fixture_files()) {
    for (const auto& view : named_views()) out.push_back({file, view});
    out.push_back({file, direction_view({1, 2, -3})});
  }
  return out;
}

INSTANTIATE_TEST_SUITE_P(Fixtures, FixtureViews, ::testing::ValuesIn(fixture_views()),
                         [](const auto& info) { return test_name(info.param.file) + "_" + info.param.view.name; });

// The same invariants in perspective (surface_runs.hpp perspective_view), near-plane cuts included.
class FixturePerspective : public ::testing::TestWithParam<std::pair<std::string, int>> {};

TEST_P(FixturePerspective, Invariants) {
  const auto& [file, which] = GetParam();
  const auto& meshes = fixture(file);
  const View view = perspective_view(meshes, which);
  if (const auto defect = perspective_defect(meshes, view)) GTEST_SKIP() << *defect;
  try {
    solve_and_check(meshes, view, true, true, file);
    solve_and_check(meshes, view, false, true, file);
  } catch (const UserError& e) {
    EXPECT_GE(which, 3) << e.what();  // a polygon face cut into several pieces by the near plane
    GTEST_SKIP() << e.what();
  }
}

std::vector<std::pair<std::string, int>> fixture_perspectives() {
  std::vector<std::pair<std::string, int>> out;
  for (const auto& file : fixture_files())
    for (int which = 0; which < kPerspectiveViews; ++which) out.emplace_back(file, which);
  return out;
}

INSTANTIATE_TEST_SUITE_P(Fixtures, FixturePerspective, ::testing::ValuesIn(fixture_perspectives()),
                         [](const auto& info) { return test_name(info.param.first) + "_" + std::to_string(info.param.second); });

TEST(FixtureFolder, HasTheDegenerateScenes) {
  const auto files = fixture_files();
  const std::set<std::string> have(files.begin(), files.end());
  for (const char* f : {"cube.off", "stacked_boxes.off", "plate_with_hole.off", "l_bracket.off", "edge_on.off",
                        "t_junction.off", "penetrating_boxes.off", "cyclic_sticks.off", "open_sheet.off",
                        "coincident_faces.off", "ring_with_fill.off"})
    EXPECT_TRUE(have.count(f)) << f;
}

// ---------------------------------------------------------------------------------------------
// What each fixture is there for. Face numbers are the fixture files' own (see
// fixtures/scenes/README.md); a box's faces come in the order bottom, top, front (y min),
// back (y max), left (x min), right (x max).

std::vector<std::vector<std::uint32_t>> source_faces(const XMap& map) {
  std::vector<std::vector<std::uint32_t>> out;
  for (const auto& s : map.sources) out.push_back(s.faces);
  return out;
}
using Lists = std::vector<std::vector<std::uint32_t>>;

FT visible_area(const XMap& map) {
  FT sum = 0;
  for (const auto& f : map.visible) sum += testing::twice_area(f.polygon);
  return sum;
}
FT hidden_area(const XMap& map) {
  FT sum = 0;
  for (const auto& f : map.hidden) sum += testing::twice_area(f.polygon);
  return sum;
}

TEST(FixtureExpectations, CubeFrontIsOneFace) {
  const XMap map = solve_and_check(fixture("cube.off"), view_named("front"), true, true, "cube");
  EXPECT_EQ(source_faces(map), (Lists{{2}}));  // the front face; 4 edge-on, the back face removed
  EXPECT_EQ(map.visible.size(), 1u);
  EXPECT_TRUE(map.hidden.empty());
  EXPECT_EQ(map.source_stats.edge_on_faces_removed, 4u);
  EXPECT_EQ(map.source_stats.back_faces_removed, 1u);
  EXPECT_EQ(visible_area(map), FT(2));
}

TEST(FixtureExpectations, CubeInEveryAxisViewIsOneFaceAndInIsoThree) {
  for (const auto& view : named_views()) {
    const XMap map = solve_and_check(fixture("cube.off"), view, true, true, "cube");
    const std::size_t want = view.name == "iso" ? 3 : 1;
    EXPECT_EQ(map.sources.size(), want) << view.name;
    EXPECT_EQ(map.visible.size(), want) << view.name;
    EXPECT_TRUE(map.hidden.empty()) << view.name;
  }
  // With back faces kept, the back face is hidden by the front face in the front view.
  const XMap map = solve_and_check(fixture("cube.off"), view_named("front"), false, true, "cube");
  EXPECT_EQ(source_faces(map), (Lists{{2}, {3}}));
  ASSERT_EQ(map.hidden.size(), 1u);
  EXPECT_EQ(map.hidden[0].source, 1u);
  EXPECT_EQ(map.hidden[0].occluder, 0);
}

TEST(FixtureExpectations, StackedBoxesAreNotConsolidatedAcrossComponents) {
  // Both boxes' front faces lie in y = 0 and touch along z = 1, but the boxes are separate
  // parts: consolidation only merges coplanar faces joined by a mesh edge.
  const auto parts = as_two_parts(fixture("stacked_boxes.off"), 6);
  const XMap front = solve_and_check(parts, view_named("front"), true, true, "stacked");
  EXPECT_EQ(source_faces(front), (Lists{{2}, {2}}));
  EXPECT_EQ(front.visible.size(), 2u);
  EXPECT_TRUE(front.hidden.empty());
  EXPECT_EQ(visible_area(front), FT(10));  // 3 x 1 + 2 x 1, doubled
  // Top view: the upper box's top (face 7) hides a 2 x 2 part of the lower box's top (face 1).
  const XMap top = solve_and_check(parts, view_named("top"), true, true, "stacked");
  EXPECT_EQ(source_faces(top), (Lists{{1}, {1}}));
  EXPECT_EQ(visible_area(top), FT(12));
  EXPECT_EQ(hidden_area(top), FT(8));
  for (const auto& h : top.hidden) {
    EXPECT_EQ(h.source, 0u);
    EXPECT_EQ(h.occluder, 1);
  }
}

TEST(FixtureExpectations, PlateWithHoleIsOnePolygonWithAHole) {
  const XMap top = solve_and_check(fixture("plate_with_hole.off"), view_named("top"), true, true, "plate");
  ASSERT_EQ(top.sources.size(), 1u);  // the four top trapezoids, consolidated
  EXPECT_EQ(top.sources[0].faces, (std::vector<std::uint32_t>{0, 1, 2, 3}));
  EXPECT_EQ(top.sources[0].polygon.holes.size(), 1u);
  EXPECT_EQ(top.visible.size(), 1u);
  EXPECT_EQ(visible_area(top), FT(24));
  // Back faces kept: the bottom ring is hidden by the top ring exactly, and the hole's walls are
  // edge-on.
  const XMap all = solve_and_check(fixture("plate_with_hole.off"), view_named("top"), false, true, "plate");
  EXPECT_EQ(all.sources.size(), 2u);
  EXPECT_EQ(hidden_area(all), FT(24));
  EXPECT_EQ(all.source_stats.edge_on_faces_removed, 8u);
}

TEST(FixtureExpectations, LBracketFrontIsOneLShapedPolygon) {
  const XMap front = solve_and_check(fixture("l_bracket.off"), view_named("front"), true, true, "L");
  EXPECT_EQ(source_faces(front), (Lists{{0, 1}}));  // pentagon + quad
  EXPECT_EQ(front.visible.size(), 1u);
  EXPECT_EQ(visible_area(front), FT(10));
  // Left view (looking along +x): the two quads of the side x = 0 are one source.
  const XMap left = solve_and_check(fixture("l_bracket.off"), view_named("left"), true, true, "L");
  EXPECT_EQ(source_faces(left), (Lists{{9, 10}}));
}

TEST(FixtureExpectations, EdgeOnSheetAndThinPlate) {
  // Front view: the open sheet (face 12, in x = 3/2) is edge-on and dropped; the thin plate's front
  // (face 8, y = -2, x in [0.9, 1]) hides a 0.1 x 2 strip of the cube's front face (face 2).
  const XMap front = solve_and_check(fixture("edge_on.off"), view_named("front"), true, true, "edge_on");
  EXPECT_EQ(source_faces(front), (Lists{{2}, {8}}));
  ASSERT_EQ(front.hidden.size(), 1u);
  EXPECT_EQ(front.hidden[0].source, 0u);
  EXPECT_EQ(front.hidden[0].occluder, 1);
  EXPECT_EQ(testing::twice_area(front.hidden[0].polygon), 2 * (FT(1) - FT(0.9)) * 2);
  // Right view: the sheet is seen face-on, the plate's and the cube's right faces touch along a
  // line in projection (y = 0) without overlapping.
  const XMap right = solve_and_check(fixture("edge_on.off"), view_named("right"), true, true, "edge_on");
  EXPECT_EQ(right.sources.size(), 3u);
  EXPECT_EQ(right.visible.size(), 3u);
}

TEST(FixtureExpectations, TJunctionTouchesWithoutOverlap) {
  const XMap front = solve_and_check(fixture("t_junction.off"), view_named("front"), true, true, "t_junction");
  EXPECT_EQ(source_faces(front), (Lists{{2}, {8}}));
  EXPECT_EQ(front.visible.size(), 2u);
  EXPECT_TRUE(front.hidden.empty());
  const XMap iso = solve_and_check(fixture("t_junction.off"), view_named("iso"), true, true, "t_junction");
  EXPECT_EQ(iso.sources.size(), 6u);
  EXPECT_FALSE(iso.hidden.empty());  // the post hides part of the base's top
}

TEST(FixtureExpectations, PenetratingBoxesAreSplit) {
  for (const char* name : {"iso", "front"}) {
    const XMap map = solve_and_check(fixture("penetrating_boxes.off"), view_named(name), true, true, "penetrating");
    EXPECT_GT(map.sort_stats.penetration_splits, 0u) << name;
  }
}

TEST(FixtureExpectations, CyclicSticksResolve) {
  const XMap top = solve_and_check(fixture("cyclic_sticks.off"), view_named("top"), true, true, "sticks");
  EXPECT_GT(top.sort_stats.recursions, 0u);
  EXPECT_EQ(top.sort_stats.penetration_splits, 0u);  // the sticks do not touch
  // Each stick's top is partly hidden by exactly one other stick: A by C, B by A, C by B.
  std::set<std::pair<std::uint32_t, std::int32_t>> pairs;
  for (const auto& h : top.hidden) pairs.insert({h.source, h.occluder});
  EXPECT_EQ(pairs, (std::set<std::pair<std::uint32_t, std::int32_t>>{{0, 2}, {1, 0}, {2, 1}}));
}

TEST(FixtureExpectations, OpenSheetKeepsBothSides) {
  const XMap top = solve_and_check(fixture("open_sheet.off"), view_named("top"), true, true, "sheet");
  EXPECT_EQ(top.source_stats.back_faces_removed, 0u);
  EXPECT_EQ(source_faces(top), (Lists{{0, 1}, {2, 3}}));
  EXPECT_FALSE(top.hidden.empty());  // the flap hides part of the base
  const XMap bottom = solve_and_check(fixture("open_sheet.off"), view_named("bottom"), true, true, "sheet");
  EXPECT_EQ(source_faces(bottom), (Lists{{0, 1}, {2, 3}}));
  for (const auto& h : bottom.hidden) EXPECT_EQ(h.occluder, 0);  // seen from below, the base is in front
}

TEST(FixtureExpectations, CoincidentFacesTieToTheLowerSource) {
  for (const char* name : {"top", "bottom", "iso"}) {
    const XMap map = solve_and_check(fixture("coincident_faces.off"), view_named(name), true, true, "coincident");
    ASSERT_EQ(map.sources.size(), 2u) << name;
    EXPECT_GT(map.sort_stats.coplanar_ties, 0u) << name;
    for (const auto& v : map.visible) EXPECT_EQ(v.source, 0u) << name;
    ASSERT_FALSE(map.hidden.empty()) << name;
    for (const auto& h : map.hidden) {
      EXPECT_EQ(h.source, 1u) << name;
      EXPECT_EQ(h.occluder, 0) << name;
    }
    EXPECT_EQ(hidden_area(map), testing::twice_area(map.sources[1].polygon)) << name;
  }
}

TEST(FixtureExpectations, RingAndFillMeetExactly) {
  // Separate parts: the ring (a polygon with a hole) and its fill touch along the whole hole.
  const XMap apart = solve_and_check(as_two_parts(fixture("ring_with_fill.off"), 8), view_named("top"), true, true, "ring");
  ASSERT_EQ(apart.sources.size(), 2u);
  EXPECT_EQ(apart.sources[0].polygon.holes.size(), 1u);
  EXPECT_EQ(apart.visible.size(), 2u);
  EXPECT_TRUE(apart.hidden.empty());
  EXPECT_EQ(apart.sort_stats.coplanar_ties, 0u);
  EXPECT_EQ(visible_area(apart), FT(18));
  // Sharing the hole's vertices: one coplanar, connected group, one square without a hole; so is
  // the one-file version, whose equal corners import welds.
  for (const char* file : {"ring_with_fill_shared.off", "ring_with_fill.off"}) {
    const XMap shared = solve_and_check(fixture(file), view_named("top"), true, true, "ring");
    ASSERT_EQ(shared.sources.size(), 1u);
    EXPECT_TRUE(shared.sources[0].polygon.holes.empty());
    EXPECT_EQ(shared.sources[0].polygon.outer.size(), 4u);
    EXPECT_EQ(visible_area(shared), FT(18));
  }
}

TEST(FixtureExpectations, AreaSortDepthSoupResolves) {
  // Four triangles found by the property test (fixtures/scenes/area_sort_depth.off). In the top
  // view their pairwise overlaps need penetration splits and repeated recursion; the area sort
  // reaches recursion depth 6 with 4 sources, beyond the guard in area_sort_impl.hpp (sources + 1),
  // and throws "area sort recursion does not converge". With the guard lifted the same input
  // resolves at depth 6 and passes every check here.
  for (const View& view : {view_named("top"), direction_view({1, 2, -3})}) {
    EXPECT_NO_THROW(solve_and_check(fixture("area_sort_depth.off"), view, true, true, "area_sort_depth")) << view.name;
  }
}

// ---------------------------------------------------------------------------------------------
// (e) Consolidation is a fact of the model: the same faces form the same sources in every view.

std::vector<View> consolidation_views() {
  auto views = named_views();
  views.push_back(direction_view({1, 2, -3}));
  return views;
}

// Compares the face groups of every view with those of the first, over the faces kept in both.
void expect_same_groups(const std::vector<Mesh>& meshes, const std::string& label) {
  for (bool remove : {false, true}) {
    const auto views = consolidation_views();
    std::vector<XMap> maps;
    std::vector<std::set<std::pair<std::uint32_t, std::uint32_t>>> kept;
    for (const auto& view : views) {
      const ViewFrame<ExactKernel> frame(view);
      auto sources = hidden_line::build_sources<ExactKernel>(meshes, frame, with_back_faces(remove));
      XMap map;
      for (const auto& s : sources.polygons) map.sources.push_back({s.mesh, s.faces, {}, {}});
      std::set<std::pair<std::uint32_t, std::uint32_t>> k;
      for (const auto& s : sources.polygons)
        for (std::uint32_t f : s.faces) k.insert({s.mesh, f});
      maps.push_back(std::move(map));
      kept.push_back(std::move(k));
    }
    for (std::size_t i = 0; i < views.size(); ++i)
      for (std::size_t j = i + 1; j < views.size(); ++j) {
        auto both = [&](std::uint32_t m, std::uint32_t f) { return kept[i].count({m, f}) && kept[j].count({m, f}); };
        const auto gi = face_groups(maps[i], both);
        const auto gj = face_groups(maps[j], both);
        EXPECT_EQ(gi, gj) << label << ": views " << views[i].name << " and " << views[j].name
                          << (remove ? "" : " (back faces kept)");
        // Edge-on and back faces leave whole groups: no group is kept in part.
        auto partial = [&](const XMap& map) {
          for (const auto& s : map.sources) {
            std::size_t in = 0;
            for (std::uint32_t f : s.faces) in += both(s.mesh, f);
            if (in != 0 && in != s.faces.size()) return true;
          }
          return false;
        };
        EXPECT_FALSE(partial(maps[i]) || partial(maps[j])) << label << ": " << views[i].name << "/" << views[j].name;
      }
  }
}

TEST(Consolidation, SameGroupsInEveryViewOnEveryFixture) {
  for (const auto& file : fixture_files()) expect_same_groups(fixture(file), file);
}

// ---------------------------------------------------------------------------------------------
// The shared scenes (../shared/scenes): every invariant in every named view, the Polygon_set_2
// region checks (b) included. Measured (Release, this project's 2-core build machine, shared):
// they cost 1 to 5 s per view on fandisk (13k faces, ~5k sources), 65 to 175 s per view on
// refined_elephant (89k faces, ~45k sources, soak label only), so they run on every scene. The
// guard below only keeps a future, much larger scene from running for hours; above it, (a) is
// still checked exactly per source (area identity) and (c), (d) at every fragment.

constexpr std::size_t kRegionSources = 100000;

struct SceneView {
  std::string file;
  View view;
};
void PrintTo(const SceneView& p, std::ostream* os) { *os << p.file << " " << p.view.name; }

class SceneViews : public ::testing::TestWithParam<SceneView> {};
class SceneConsolidation : public ::testing::TestWithParam<std::string> {};

TEST_P(SceneViews, Invariants) {
  const auto& p = GetParam();
  if (!shared_scenes_present()) GTEST_SKIP() << "no shared scenes at " << shared_scene_dir();
  const auto& meshes = scene_meshes(shared_scene_dir() + "/" + p.file);
  using clock = std::chrono::steady_clock;
  const auto t0 = clock::now();
  Solved solved = solve<ExactKernel>(meshes, p.view, {});
  const auto t1 = clock::now();
  const SceneOracle oracle(meshes, p.view);
  CheckOptions options;
  options.region_checks = solved.map.sources.size() <= kRegionSources;
  const CheckReport report = check_map(oracle, solved.map, options);
  const auto t2 = clock::now();
  EXPECT_TRUE(report.ok()) << p.file << " view " << p.view.name << ": " << report.summary();
  EXPECT_EQ(report.visible_checked, solved.map.visible.size());
  EXPECT_EQ(report.hidden_checked, solved.map.hidden.size());
  std::printf("[ timing   ] %s %s: %zu sources, %zu visible, %zu hidden; solve %.2f s (sources %.2f, sort %.2f), "
              "checks %.2f s%s\n",
              p.file.c_str(), p.view.name.c_str(), solved.map.sources.size(), solved.map.visible.size(),
              solved.map.hidden.size(), std::chrono::duration<double>(t1 - t0).count(), solved.sources_seconds,
              solved.sort_seconds, std::chrono::duration<double>(t2 - t1).count(),
              options.region_checks ? "" : " (no region checks)");
}

TEST_P(SceneConsolidation, SameGroupsInEveryView) {
  if (!shared_scenes_present()) GTEST_SKIP() << "no shared scenes at " << shared_scene_dir();
  expect_same_groups(scene_meshes(shared_scene_dir() + "/" + GetParam()), GetParam());
}

std::vector<std::string> all_scene_files() {
  auto files = shared_scene_files();
  for (const auto& f : soak_scene_files()) files.push_back(f);
  return files;
}

std::vector<SceneView> scene_views() {
  std::vector<SceneView> out;
  for (const auto& file : all_scene_files())
    for (const auto& view : named_views()) out.push_back({file, view});
  return out;
}

INSTANTIATE_TEST_SUITE_P(Scenes, SceneViews, ::testing::ValuesIn(scene_views()),
                         [](const auto& info) { return test_name(info.param.file) + "_" + info.param.view.name; });
INSTANTIATE_TEST_SUITE_P(Scenes, SceneConsolidation, ::testing::ValuesIn(all_scene_files()),
                         [](const auto& info) { return test_name(info.param); });

}  // namespace
}  // namespace hlr::hltest
