// Hidden-line classification (build_sources -> area_sort -> intersection_lines -> classify_lines,
// exact kernel) checked against the independent line oracle (line_oracle.hpp): the oracle's own
// tests, hand-checked tiny scenes, errors planted in a correct LineSet, every fixture of
// fixtures/scenes in the seven named views, along (1, 2, -3) and along (-2, 1, 0.5) with a skew up
// vector (back faces removed and kept), every shared scene in the seven named views.
#include "line_runs.hpp"
#include "surface_runs.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <map>
#include <mutex>
#include <set>

namespace hlr::hltest {
namespace {

using hidden_line::LineOptions;
using LineSetX = hidden_line::LineSet<ExactKernel>;

View view_named(const std::string& name) {
  View v;
  EXPECT_TRUE(named_view(name, v)) << name;
  return v;
}

const std::vector<Mesh>& fixture(const std::string& file) { return scene_meshes(fixture_dir() + "/" + file); }

Mesh make_mesh(const std::string& name, const std::vector<std::array<double, 3>>& vertices,
               const std::vector<std::vector<std::uint32_t>>& faces) {
  Mesh m;
  m.file = name;
  m.vertices = vertices;
  m.faces = faces;
  for (std::uint32_t f = 0; f < faces.size(); ++f) m.face_index.push_back(f);
  return m;
}

std::set<std::string> failure_kinds(const LineReport& r) {
  std::set<std::string> out;
  for (const auto& [kind, count] : r.failures) out.insert(kind);
  return out;
}

// Runs the engine and the checks; returns the LineSet for further expectations.
LineSetX run_and_check(const std::vector<Mesh>& meshes, const View& view, const std::string& label,
                       const LineOptions& options = {}, bool remove_back_faces = true,
                       const PenetrationSearch* penetrations = nullptr) {
  LineRun run = run_lines(meshes, view, options, remove_back_faces);
  const LineOracle oracle(meshes, view);
  const LineReport report = check_lines(oracle, run.set, check_options_for(options), penetrations);
  EXPECT_TRUE(report.ok()) << label << " view " << view.name << (remove_back_faces ? "" : " (back faces kept)") << ": "
                           << report.summary();
  return std::move(run.set);
}

const hidden_line::FeatureLine<ExactKernel>* find_line(const LineSetX& set, std::uint32_t mesh, std::uint32_t v0,
                                                       std::uint32_t v1) {
  for (const auto& l : set.lines)
    if (l.kind != FeatureKind::intersection && l.mesh == mesh &&
        std::minmax(l.v0, l.v1) == std::minmax(v0, v1))
      return &l;
  return nullptr;
}

VP at(const hidden_line::FeatureLine<ExactKernel>& l, const FT& t) {
  return {l.a.x + t * (l.b.x - l.a.x), l.a.y + t * (l.b.y - l.a.y), l.a.z + t * (l.b.z - l.a.z)};
}
bool same_point(const VP& p, const VP& q) { return p.x == q.x && p.y == q.y && p.z == q.z; }
FT squared_image_length(const hidden_line::FeatureLine<ExactKernel>& l) {
  const FT dx = l.b.x - l.a.x, dy = l.b.y - l.a.y;
  return dx * dx + dy * dy;
}

// ---------------------------------------------------------------------------------------------
// Hand-checked scenes.

// A square [0,2] x {0} x [0,2] (two triangles, mesh 0) and, behind it at y = 1, the triangle
// (1,1,1), (4,1,1), (4,1,4) (mesh 1). In the front view the square hides the triangle's part with
// x <= 2: its bottom edge and its hypotenuse are split at x = 2, a third of the way from vertex 0.
std::vector<Mesh> square_and_triangle() {
  return {make_mesh("square", {{0, 0, 0}, {2, 0, 0}, {2, 0, 2}, {0, 0, 2}}, {{0, 1, 2}, {0, 2, 3}}),
          make_mesh("triangle", {{1, 1, 1}, {4, 1, 1}, {4, 1, 4}}, {{0, 1, 2}})};
}

// Quad A in z = 0 over [0,2]^2 (mesh 0) and quad B in x = 1, y in [0.5, 1.5], z in [-1, 1] (mesh 1):
// they penetrate along x = 1, z = 0, y in [0.5, 1.5].
std::vector<Mesh> penetrating_quads() {
  return {make_mesh("A", {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}}, {{0, 1, 2, 3}}),
          make_mesh("B", {{1, 0.5, -1}, {1, 1.5, -1}, {1, 1.5, 1}, {1, 0.5, 1}}, {{0, 1, 2, 3}})};
}

// An open sheet in z = 1, x in [0,2], y in [0,1] (mesh 0), and behind it in y = 2 the triangle
// (-1,2,1), (3,2,1), (1,2,3) (mesh 1). In the front view the sheet is edge-on; its front edge
// (y = 0) lies over the middle half of the triangle's bottom edge and hides it.
std::vector<Mesh> sheet_before_edge() {
  return {make_mesh("sheet", {{0, 0, 1}, {2, 0, 1}, {2, 1, 1}, {0, 1, 1}}, {{0, 1, 2, 3}}),
          make_mesh("triangle", {{-1, 2, 1}, {3, 2, 1}, {1, 2, 3}}, {{0, 1, 2}})};
}

TEST(LinesHand, CubeFrontView) {
  const auto& meshes = fixture("cube.off");
  const LineSetX set = run_and_check(meshes, view_named("front"), "cube");
  // Front view: X = (1,0,0), Y = (0,0,1), Z = (0,-1,0), the unnormalized frame is orthonormal.
  ASSERT_EQ(set.lines.size(), 12u);
  std::size_t visible = 0, hidden = 0, end_on = 0, silhouettes = 0;
  for (const auto& l : set.lines) {
    EXPECT_NE(l.kind, FeatureKind::intersection);
    if (l.kind == FeatureKind::silhouette) ++silhouettes;
    if (l.pieces.empty()) {
      ++end_on;
      EXPECT_EQ(l.a.x, l.b.x);
      EXPECT_EQ(l.a.y, l.b.y);
      continue;
    }
    ASSERT_EQ(l.pieces.size(), 1u);
    EXPECT_EQ(squared_image_length(l), FT(1));
    if (l.pieces[0].visible) {
      ++visible;
      EXPECT_EQ(l.a.z, FT(0));  // the front face's outline, y = 0
      EXPECT_EQ(l.kind, FeatureKind::silhouette);
    } else {
      ++hidden;
      EXPECT_EQ(l.a.z, FT(-1));  // the back face's outline, behind the front one exactly
      EXPECT_EQ(l.kind, FeatureKind::crease);
    }
  }
  EXPECT_EQ(visible, 4u);
  EXPECT_EQ(hidden, 4u);
  EXPECT_EQ(end_on, 4u);
  EXPECT_EQ(silhouettes, 4u);
  EXPECT_EQ(set.stats.point_in_view, 4u);
  EXPECT_EQ(set.stats.visible_pieces, 4u);
  EXPECT_EQ(set.stats.hidden_pieces, 4u);
  // The same with back faces kept.
  run_and_check(meshes, view_named("front"), "cube", {}, false);
}

// The cube from an eye in front of its front face's centre: in perspective the side faces are
// back faces (the eye lies on their inner side), not edge-on as in the front view, and the edges
// along the view, end-on there, now recede to the back face's smaller outline. Everything but the
// front face's outline is hidden; the front face's edges are silhouettes (decided at the eye).
TEST(LinesHand, CubeInPerspectiveFromTheFront) {
  const auto& meshes = fixture("cube.off");
  View view = view_named("front");
  view.name = "perspective";
  view.eye = Vec3{0.5, -2, 0.5};
  const LineSetX set = run_and_check(meshes, view, "cube");
  ASSERT_EQ(set.lines.size(), 12u);
  std::size_t visible = 0, silhouettes = 0;
  for (const auto& l : set.lines) {
    ASSERT_EQ(l.pieces.size(), 1u);
    const bool front = l.a.z == FT(1) / 2 && l.b.z == FT(1) / 2;  // 1/w at y = 0, w = y + 2
    EXPECT_EQ(l.pieces[0].visible, front) << l.v0 << "-" << l.v1;
    visible += l.pieces[0].visible;
    silhouettes += l.kind == FeatureKind::silhouette;
  }
  EXPECT_EQ(visible, 4u);
  EXPECT_EQ(silhouettes, 4u);  // the front outline; the side and back faces all turn away
  run_and_check(meshes, view, "cube", {}, false);
}

// An eye inside the cube, looking toward a corner: the near plane cuts the faces that reach
// behind the eye, so the cube is cut open and its back faces (all of them, seen from inside) are
// drawn; checked against the oracle, which clips on its own.
TEST(LinesHand, EyeInsideTheCube) {
  const auto& meshes = fixture("cube.off");
  View view = direction_view({0.5, 0.5, 0.5}, {0, 0, 1});
  view.eye = Vec3{0.25, 0.375, 0.125};
  run_and_check(meshes, view, "cube from inside");
  run_and_check(meshes, view, "cube from inside", {}, false);
}

TEST(LinesHand, TriangleBehindSquareIsSplitExactly) {
  const auto meshes = square_and_triangle();
  const LineSetX set = run_and_check(meshes, view_named("front"), "square and triangle");
  EXPECT_EQ(set.lines.size(), 4u + 3u);  // square outline (the diagonal is flat), triangle outline
  for (const auto& l : set.lines) EXPECT_EQ(l.kind, FeatureKind::boundary);
  // Bottom edge 0-1 and hypotenuse 0-2 of the triangle: hidden up to x = 2, visible after.
  const VP split_bottom{2, 1, -1}, split_hyp{2, 2, -1};
  for (auto [v, split] : {std::pair{1u, split_bottom}, std::pair{2u, split_hyp}}) {
    const auto* l = find_line(set, 1, 0, v);
    ASSERT_TRUE(l) << "edge 0-" << v;
    ASSERT_EQ(l->pieces.size(), 2u) << "edge 0-" << v;
    EXPECT_TRUE(same_point(at(*l, l->pieces[0].t1), split)) << "edge 0-" << v;
    const bool from_v0 = l->a.x == FT(1);
    EXPECT_EQ(l->pieces[0].t1, from_v0 ? FT(1) / 3 : FT(2) / 3);
    EXPECT_EQ(l->pieces[0].visible, !from_v0);
    EXPECT_EQ(l->pieces[1].visible, from_v0);
  }
  const auto* right = find_line(set, 1, 1, 2);
  ASSERT_TRUE(right);
  ASSERT_EQ(right->pieces.size(), 1u);
  EXPECT_TRUE(right->pieces[0].visible);
  for (std::uint32_t v = 0; v < 4; ++v) {
    const auto* l = find_line(set, 0, v, (v + 1) % 4);
    ASSERT_TRUE(l);
    ASSERT_EQ(l->pieces.size(), 1u);
    EXPECT_TRUE(l->pieces[0].visible);
  }
}

TEST(LinesHand, PenetratingQuadsMakeOneIntersectionLine) {
  const auto meshes = penetrating_quads();
  for (const char* name : {"iso", "front", "top", "left"}) {
    const View view = view_named(name);
    const LineSetX set = run_and_check(meshes, view, "penetrating quads");
    std::vector<const hidden_line::FeatureLine<ExactKernel>*> inter;
    for (const auto& l : set.lines)
      if (l.kind == FeatureKind::intersection) inter.push_back(&l);
    ASSERT_EQ(inter.size(), 1u) << name;
    const ExactViewBasis basis(view);
    const VP p = basis.to_view(P3(1, 0.5, 0)), q = basis.to_view(P3(1, 1.5, 0));
    const auto& l = *inter[0];
    EXPECT_TRUE((same_point(l.a, p) && same_point(l.b, q)) || (same_point(l.a, q) && same_point(l.b, p))) << name;
    if (std::string(name) == "iso") {
      ASSERT_EQ(l.pieces.size(), 1u);
      EXPECT_TRUE(l.pieces[0].visible);
    }
    if (std::string(name) == "front") {
      EXPECT_TRUE(l.pieces.empty());  // seen end-on (along y)
    }
  }
}

TEST(LinesHand, IntersectionsCanBeTurnedOff) {
  const auto meshes = penetrating_quads();
  LineOptions options;
  options.intersections = false;
  const LineSetX set = run_and_check(meshes, view_named("iso"), "penetrating quads, no intersections", options);
  for (const auto& l : set.lines) EXPECT_NE(l.kind, FeatureKind::intersection);
  EXPECT_EQ(set.lines.size(), 8u);  // the two quads' outlines
}

TEST(LinesHand, EdgeOnSheetHidesTheEdgeBehindIt) {
  const auto meshes = sheet_before_edge();
  const LineSetX set = run_and_check(meshes, view_named("front"), "sheet before edge");
  const auto* bottom = find_line(set, 1, 0, 1);
  ASSERT_TRUE(bottom);
  ASSERT_EQ(bottom->pieces.size(), 3u);
  EXPECT_TRUE(bottom->pieces[0].visible);
  EXPECT_FALSE(bottom->pieces[1].visible);
  EXPECT_TRUE(bottom->pieces[2].visible);
  EXPECT_EQ(bottom->pieces[1].t0, FT(1) / 4);
  EXPECT_EQ(bottom->pieces[1].t1, FT(3) / 4);
  // The sheet's own back edge lies exactly behind its front edge.
  const auto* back = find_line(set, 0, 2, 3);
  ASSERT_TRUE(back);
  ASSERT_EQ(back->pieces.size(), 1u);
  EXPECT_FALSE(back->pieces[0].visible);
  const auto* front = find_line(set, 0, 0, 1);
  ASSERT_TRUE(front);
  ASSERT_EQ(front->pieces.size(), 1u);
  EXPECT_TRUE(front->pieces[0].visible);
  for (auto [v0, v1] : {std::pair{1u, 2u}, std::pair{0u, 3u}}) {
    const auto* side = find_line(set, 0, v0, v1);
    ASSERT_TRUE(side);
    EXPECT_TRUE(side->pieces.empty());  // along y: seen end-on
  }
}

// A region of coplanar faces seen edge-on covers what its boundary covers: the sheet cut into a
// fan of triangles draws as the one quad does, and a pair of triangles folded onto each other keeps
// the edge they share, which is the region's front.
TEST(LinesHand, EdgeOnRegionsCoverByTheirBoundary) {
  const View front = view_named("front");
  auto meshes = sheet_before_edge();
  const LineSetX quad = run_and_check(meshes, front, "sheet before edge");
  meshes[0] = make_mesh("sheet", {{0, 0, 1}, {2, 0, 1}, {2, 1, 1}, {0, 1, 1}, {1, 0.5, 1}},
                        {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}});
  const LineSetX fan = run_and_check(meshes, front, "fan sheet before edge");
  EXPECT_EQ(line_signature(fan, false), line_signature(quad, false));

  // The edge 0-1 (y = 0) is nearest; the folded triangles' other edges are at y >= 0.5 over x = 1,
  // behind the bottom edge of the triangle in y = 0.25.
  const std::vector<Mesh> folded{
      make_mesh("folded", {{0, 0, 1}, {2, 0, 1}, {1, 1, 1}, {1, 0.5, 1}}, {{0, 1, 2}, {1, 0, 3}}),
      make_mesh("triangle", {{0.5, 0.25, 1}, {1.5, 0.25, 1}, {1, 0.25, 2}}, {{0, 1, 2}})};
  const LineSetX set = run_and_check(folded, front, "folded sheet before edge");
  const auto* bottom = find_line(set, 1, 0, 1);
  ASSERT_TRUE(bottom);
  ASSERT_EQ(bottom->pieces.size(), 1u);
  EXPECT_FALSE(bottom->pieces[0].visible);
}

// hidden_line/tests/reflex_prism.off: an L-shaped prism whose top and bottom hexagons start at
// their reflex corner's neighbour, so that the first three corners of each turn the wrong way (a
// normal taken from them points inward).
std::vector<Mesh> reflex_prism() { return scene_meshes(std::string(HLR_LINES_TEST_DIR) + "/reflex_prism.off"); }

TEST(LinesHand, ReflexCornerFirstPrism) {
  const auto meshes = reflex_prism();
  // Top view: the top face is the only one toward the viewer; its six edges are the silhouette.
  const LineSetX top = run_and_check(meshes, view_named("top"), "reflex prism");
  EXPECT_EQ(top.stats.by_kind[static_cast<int>(FeatureKind::silhouette)], 6u);
  for (const View& view : named_views()) run_and_check(meshes, view, "reflex prism");
  run_and_check(meshes, direction_view({1, 2, -3}), "reflex prism");
}

TEST(LinesHand, InconsistentOrientationNextToAnEdgeOnFace) {
  // Two triangles on the edge 0-1, both running it 0 -> 1 (inconsistent orientation). In the front
  // view one faces the viewer, the other lies in z = 0, edge-on. Not a closed solid, so its two
  // sides are alike: one face is seen, the other edge-on, whichever is flipped: a silhouette.
  const std::vector<std::array<double, 3>> v{{0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {0.5, 1, 0}};
  const View front = view_named("front");
  for (bool facing_first : {true, false}) {
    const std::vector<Mesh> meshes{make_mesh(
        "pair", v, facing_first ? std::vector<std::vector<std::uint32_t>>{{0, 1, 2}, {0, 1, 3}}
                                : std::vector<std::vector<std::uint32_t>>{{0, 1, 3}, {0, 1, 2}})};
    const LineSetX set = run_and_check(meshes, front, facing_first ? "facing face first" : "edge-on face first");
    const auto* l = find_line(set, 0, 0, 1);
    ASSERT_TRUE(l);
    EXPECT_EQ(l->kind, FeatureKind::silhouette);
  }
}

TEST(LinesHand, QuadWithRepeatedPoint) {
  // Corners 1 and 2 of the quad are distinct vertices at the same point: the edge 1-2 has zero
  // length and no pieces in any view.
  const std::vector<Mesh> meshes{
      make_mesh("repeated", {{0, 0, 0}, {2, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}}, {{0, 1, 2, 3, 4}})};
  for (const View& view : named_views()) {
    const LineSetX set = run_and_check(meshes, view, "repeated point");
    const auto* l = find_line(set, 0, 1, 2);
    ASSERT_TRUE(l) << view.name;
    EXPECT_TRUE(l->pieces.empty()) << view.name;
  }
}

TEST(LinesHand, TrianglesCrossingAtASharedVertex) {
  // Two triangles of one mesh share vertex 0 and cross each other along (0,0,0)-(2,0,0).
  const std::vector<Mesh> meshes{make_mesh("crossing", {{0, 0, 0}, {2, -1, 0}, {2, 1, 0}, {2, 0, -1}, {2, 0, 1}},
                                           {{0, 1, 2}, {0, 3, 4}})};
  for (const View& view : named_views()) {
    const LineSetX set = run_and_check(meshes, view, "crossing");
    EXPECT_EQ(set.stats.by_kind[static_cast<int>(FeatureKind::intersection)], 1u) << view.name;
  }
}

// ---------------------------------------------------------------------------------------------
// The oracle on cases whose answers are known by hand.

std::map<FeatureKind, std::size_t> kind_counts(const std::vector<OracleFeature>& features) {
  std::map<FeatureKind, std::size_t> out;
  for (const auto& f : features) ++out[f.kind];
  return out;
}

// --smooth-edges thin on the filleted bracket (fixtures/parts/): the engine against the oracle,
// which finds the smooth edges by its own brute-force rule; the tangent lines in every view (seen
// end-on in the front and back views: lines without pieces).
TEST(LinesHand, SmoothEdgesOfTheFilletedBracket) {
  const auto meshes = scene_meshes(std::string(HLR_PART_FIXTURES) + "/filleted_bracket.off");
  LineOptions options;
  options.features.smooth_edges = SmoothEdges::thin;
  for (const char* name : {"front", "back", "top", "bottom", "left", "right", "iso"}) {
    const LineSetX set = run_and_check(meshes, view_named(name), "filleted_bracket", options);
    // Four tangent lines; in views where one of them lies beside a face seen edge-on it is a
    // silhouette instead (features.hpp: silhouette first).
    const std::size_t smooth = set.stats.by_kind[static_cast<int>(FeatureKind::smooth)];
    EXPECT_TRUE(smooth == 3 || smooth == 4) << name << ": " << smooth;
  }
  EXPECT_EQ(kind_counts(oracle_features(meshes, view_named("iso"), 30, SmoothEdges::thin))[FeatureKind::smooth], 4u);
  EXPECT_EQ(kind_counts(oracle_features(meshes, view_named("iso"), 30, SmoothEdges::off))[FeatureKind::smooth], 0u);
}

TEST(LineOracle, FeaturesOfTheCube) {
  const auto& meshes = fixture("cube.off");
  using K = FeatureKind;
  using Counts = std::map<FeatureKind, std::size_t>;
  // Front: the front face's outline is silhouette, the other eight edges are creases.
  EXPECT_EQ(kind_counts(oracle_features(meshes, view_named("front"), 30)), (Counts{{K::silhouette, 4}, {K::crease, 8}}));
  // Iso: three faces toward the viewer, the outline hexagon is silhouette.
  EXPECT_EQ(kind_counts(oracle_features(meshes, view_named("iso"), 30)), (Counts{{K::silhouette, 6}, {K::crease, 6}}));
  // 90 degrees: cos rounds to 6.1e-17 > 0, the right angles are above it; 100: they are not.
  EXPECT_EQ(kind_counts(oracle_features(meshes, view_named("iso"), 90)), (Counts{{K::silhouette, 6}, {K::crease, 6}}));
  EXPECT_EQ(kind_counts(oracle_features(meshes, view_named("iso"), 100)), (Counts{{K::silhouette, 6}}));
  // The edge 0-4 (bottom/front) is a silhouette in front view, 2-6 (bottom/back) a crease.
  for (const auto& f : oracle_features(meshes, view_named("front"), 30)) {
    if (f.v0 == 0 && f.v1 == 4) {
      EXPECT_EQ(f.kind, K::silhouette);
    }
    if (f.v0 == 2 && f.v1 == 6) {
      EXPECT_EQ(f.kind, K::crease);
    }
    EXPECT_EQ(f.faces.size(), 2u);
  }
}

TEST(LineOracle, FeaturesOfFlatAndFoldedSheets) {
  using K = FeatureKind;
  using Counts = std::map<FeatureKind, std::size_t>;
  // A flat square of two triangles: the diagonal is no feature, unless the triangles are of
  // different groups.
  Mesh flat = make_mesh("flat", {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 3}});
  EXPECT_EQ(kind_counts(oracle_features({flat}, view_named("top"), 30)), (Counts{{K::boundary, 4}}));
  flat.face_group = {0, 1};
  EXPECT_EQ(kind_counts(oracle_features({flat}, view_named("top"), 30)), (Counts{{K::boundary, 4}, {K::group, 1}}));
  // The second triangle flipped (inconsistent orientation): oriented alike, still flat.
  Mesh flipped = make_mesh("flipped", flat.vertices, {{0, 1, 2}, {0, 3, 2}});
  EXPECT_EQ(kind_counts(oracle_features({flipped}, view_named("iso"), 30)), (Counts{{K::boundary, 4}}));
  // Folded along the diagonal 0-2, by 54.7 degrees: a crease at 54, none at 55.
  const Mesh folded = make_mesh("folded", {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 1}}, {{0, 1, 2}, {0, 2, 3}});
  // Face 1 normal: (1,1,0) x (0,1,1) = (1,-1,1); face 0: (0,0,1); cos = 1/sqrt(3): 54.7 degrees.
  EXPECT_EQ(kind_counts(oracle_features({folded}, view_named("top"), 54)), (Counts{{K::boundary, 4}, {K::crease, 1}}));
  EXPECT_EQ(kind_counts(oracle_features({folded}, view_named("top"), 55)), (Counts{{K::boundary, 4}}));
  // Three faces on one edge: non-manifold, a crease whatever the angle.
  const Mesh fan = make_mesh("fan", {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0}, {0.5, 0, 1}},
                             {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
  EXPECT_EQ(kind_counts(oracle_features({fan}, view_named("top"), 30))[K::crease], 1u);
  // Silhouette: the fold seen from the side where one face is front-facing and the other not.
  const Mesh roof = make_mesh("roof", {{0, 0, 0}, {1, 0, 0}, {1, 1, 1}, {0, 1, 1}, {1, 2, 0}, {0, 2, 0}},
                              {{0, 1, 2, 3}, {3, 2, 4, 5}});
  // Looking along +y: face 0 (normal (0,-1,1)) faces the viewer (Z = (0,-1,0)), face 1 does not.
  EXPECT_EQ(kind_counts(oracle_features({roof}, view_named("front"), 30))[K::silhouette], 1u);
  EXPECT_EQ(kind_counts(oracle_features({roof}, view_named("top"), 30))[K::silhouette], 0u);
}

TEST(LineOracle, PointVisibility) {
  const auto& cube = fixture("cube.off");
  const LineOracle oracle(cube, view_named("front"));
  // Front view: view (x, y, z) = (X, Z, -Y) in model terms.
  EXPECT_FALSE(oracle.hidden({FT(1) / 2, 0, 0}));            // on the front face's outline
  EXPECT_TRUE(oracle.hidden({FT(1) / 2, 0, -1}));            // the back edge behind it
  EXPECT_TRUE(oracle.hidden({FT(1) / 2, FT(1) / 2, -1}));    // the back face's middle
  EXPECT_FALSE(oracle.hidden({FT(1) / 2, FT(1) / 2, 0}));    // the front face itself
  EXPECT_FALSE(oracle.hidden({FT(3) / 2, FT(1) / 2, -5}));   // beside the cube
  EXPECT_TRUE(oracle.hidden({1, 1, -FT(1) / 2}));            // behind a corner (closed faces)
  // Edge-on sheet: hides what lies exactly behind its projection, and only that.
  const auto sheet = sheet_before_edge();
  const LineOracle s(sheet, view_named("front"));
  EXPECT_TRUE(s.hidden({1, 1, -2}));
  EXPECT_TRUE(s.hidden({0, 1, -2}));   // the sheet's end, closed
  EXPECT_FALSE(s.hidden({-FT(1) / 2, 1, -2}));
  EXPECT_FALSE(s.hidden({1, 1, 0}));   // the sheet's front edge itself
  EXPECT_TRUE(s.hidden({1, 1, -1}));   // its back edge
  const auto f = s.hiding_face({1, 1, -2});
  ASSERT_TRUE(f);
  EXPECT_EQ(f->mesh, 0u);
}

TEST(LineOracle, HiddenIntervals) {
  // The triangle's bottom edge behind the square: hidden over (0, 1/3).
  const auto meshes = square_and_triangle();
  const LineOracle oracle(meshes, view_named("front"));
  const VP a = oracle.vertex(1, 0), b = oracle.vertex(1, 1);
  auto h = oracle.hidden_intervals(a, b);
  ASSERT_EQ(h.size(), 1u);
  EXPECT_EQ(h[0].lo, FT(0));
  EXPECT_EQ(h[0].hi, FT(1) / 3);
  h = oracle.hidden_intervals(b, a);
  ASSERT_EQ(h.size(), 1u);
  EXPECT_EQ(h[0].lo, FT(2) / 3);
  EXPECT_EQ(h[0].hi, FT(1));
  // Behind the edge-on sheet: the middle half.
  const auto sheet = sheet_before_edge();
  const LineOracle s(sheet, view_named("front"));
  h = s.hidden_intervals(s.vertex(1, 0), s.vertex(1, 1));
  ASSERT_EQ(h.size(), 1u);
  EXPECT_EQ(h[0].lo, FT(1) / 4);
  EXPECT_EQ(h[0].hi, FT(3) / 4);
  // A segment crossing behind the edge-on sheet (in front of the triangle): one hidden point only,
  // no interval.
  const FT z = -FT(3) / 2;
  EXPECT_TRUE(s.hidden({1, 1, z}));
  EXPECT_FALSE(s.hidden({1, FT(3) / 2, z}));
  EXPECT_TRUE(s.hidden_intervals({1, 0, z}, {1, 2, z}).empty());
}

// Cross-check of the two visibility oracles: along segments between vertices of the fixtures, at
// parameters unlikely to be special (k/97 + 1/1000003), the point oracle agrees with the
// intervals.
TEST(LineOracle, PointAndIntervalOraclesAgree) {
  std::size_t checked = 0, hidden = 0;
  for (const auto& file : fixture_files()) {
    const auto& meshes = fixture(file);
    for (const View& view : {view_named("iso"), view_named("front"), view_named("top"), direction_view({1, 2, -3})}) {
      const LineOracle oracle(meshes, view);
      const auto& vs = meshes[0].vertices;
      const std::size_t n = vs.size();
      for (std::size_t i = 0; i < n; i += 3)
        for (std::size_t j = i + 1; j < n; j += 5) {
          const VP a = oracle.vertex(0, static_cast<std::uint32_t>(i)), b = oracle.vertex(0, static_cast<std::uint32_t>(j));
          if (a.x == b.x && a.y == b.y) continue;
          const auto intervals = oracle.hidden_intervals(a, b);
          for (int k = 0; k < 97; k += 4) {
            const FT t = FT(k) / 97 + FT(1) / 1000003;
            const VP p{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), a.z + t * (b.z - a.z)};
            bool in = false;
            for (const auto& h : intervals) in = in || (h.lo < t && t < h.hi);
            const bool point = oracle.hidden(p);
            ++checked;
            hidden += point;
            EXPECT_EQ(point, in) << file << " " << view.name << " vertices " << i << "-" << j << " t = " << k
                                 << "/97 + 1/1000003";
          }
        }
    }
  }
  EXPECT_GT(checked, 1000u);
  EXPECT_GT(hidden, 100u);
}

TEST(LineOracle, Penetrations) {
  EXPECT_TRUE(find_penetrations(fixture("cube.off")).found.empty());
  EXPECT_TRUE(find_penetrations(fixture("stacked_boxes.off")).found.empty());  // touching is not crossing
  EXPECT_TRUE(find_penetrations(fixture("t_junction.off")).found.empty());
  const auto quads = find_penetrations(penetrating_quads());
  ASSERT_EQ(quads.found.size(), 2u);  // each quad is cut into two triangles; B's pair crosses A's pair
  EXPECT_FALSE(find_penetrations(fixture("penetrating_boxes.off")).found.empty());
  // Two triangles sharing a vertex and crossing there.
  const Mesh crossing = make_mesh("crossing", {{0, 0, 0}, {2, -1, 0}, {2, 1, 0}, {2, 0, -1}, {2, 0, 1}},
                                  {{0, 1, 2}, {0, 3, 4}});
  const auto x = find_penetrations({crossing});
  ASSERT_EQ(x.found.size(), 1u);
  EXPECT_EQ(x.found[0].midpoint, P3(1, 0, 0));
  // A non-convex face (the L-shaped top of reflex_prism.off, reflex corner first) is cut into
  // triangles too: a triangle piercing it is found.
  auto pierced = reflex_prism();
  pierced.push_back(make_mesh("spike", {{0.5, 0.5, 0.5}, {0.5, 1.5, 0.5}, {0.5, 1, 1.5}}, {{0, 1, 2}}));
  const auto p = find_penetrations(pierced);
  EXPECT_EQ(p.faces_skipped, 0u);
  ASSERT_FALSE(p.found.empty());
  for (const auto& pen : p.found) {
    EXPECT_EQ(pen.f, (FaceRef{0, 0}));  // the top
    EXPECT_EQ(pen.g, (FaceRef{1, 0}));
  }
  for (const View& view : named_views()) {
    const LineSetX set = run_and_check(pierced, view, "pierced reflex prism", {}, true, &p);
    EXPECT_EQ(set.stats.by_kind[static_cast<int>(FeatureKind::intersection)], 1u) << view.name;
  }
}

// ---------------------------------------------------------------------------------------------
// The checks catch what they are for: errors planted in correct LineSets are reported.

TEST(LineChecks, CatchPlantedErrors) {
  const auto meshes = square_and_triangle();
  const View front = view_named("front");
  const LineOracle oracle(meshes, front);
  const LineSetX good = run_lines(meshes, front).set;
  ASSERT_TRUE(check_lines(oracle, good, {}).ok()) << check_lines(oracle, good, {}).summary();
  auto kinds = [&](const LineSetX& set) { return failure_kinds(check_lines(oracle, set, {})); };
  auto index = [&](const LineSetX& set, std::uint32_t mesh, std::uint32_t v0, std::uint32_t v1) {
    for (std::size_t i = 0; i < set.lines.size(); ++i)
      if (set.lines[i].mesh == mesh && std::minmax(set.lines[i].v0, set.lines[i].v1) == std::minmax(v0, v1)) return i;
    ADD_FAILURE() << "no line " << mesh << ":" << v0 << "-" << v1;
    return std::size_t(0);
  };
  const std::size_t bottom = index(good, 1, 0, 1), right = index(good, 1, 1, 2);
  ASSERT_EQ(good.lines[bottom].pieces.size(), 2u);
  {  // one piece of a split line flipped
    LineSetX bad = good;
    auto& p = bad.lines[bottom].pieces[0];
    p.visible = !p.visible;
    const auto k = kinds(bad);
    EXPECT_TRUE(k.count("(a) consecutive pieces alike")) << ::testing::PrintToString(k);
    EXPECT_TRUE(k.count("(b) visibility")) << ::testing::PrintToString(k);
  }
  {  // a whole visible line said hidden
    LineSetX bad = good;
    bad.lines[right].pieces[0].visible = false;
    EXPECT_EQ(kinds(bad), (std::set<std::string>{"(b) visibility", "stats"}));
  }
  {  // an edge dropped
    LineSetX bad = good;
    bad.lines.erase(bad.lines.begin() + static_cast<std::ptrdiff_t>(right));
    EXPECT_TRUE(kinds(bad).count("(c) missing edge"));
    EXPECT_TRUE(kinds(bad).count("stats"));
  }
  {  // an edge twice, an edge of the wrong kind
    LineSetX bad = good;
    bad.lines.push_back(bad.lines[right]);
    bad.lines[bottom].kind = FeatureKind::crease;
    const auto k = kinds(bad);
    EXPECT_TRUE(k.count("(c) duplicate edge")) << ::testing::PrintToString(k);
    EXPECT_TRUE(k.count("(c) kind")) << ::testing::PrintToString(k);
  }
  {  // a non-feature edge added: the square's flat diagonal
    LineSetX bad = good;
    auto extra = bad.lines[index(good, 0, 0, 1)];
    extra.v0 = 0;
    extra.v1 = 2;
    extra.b = oracle.vertex(0, 2);
    bad.lines.push_back(extra);
    EXPECT_TRUE(kinds(bad).count("(c) extra edge"));
  }
  {  // a split point moved in one piece only: gap
    LineSetX bad = good;
    bad.lines[bottom].pieces[0].t1 = FT(1) / 2;
    const auto k = kinds(bad);
    EXPECT_TRUE(k.count("(a) gap or overlap")) << ::testing::PrintToString(k);
  }
  {  // a split point moved in both pieces: coverage is fine, visibility is not
    LineSetX bad = good;
    bad.lines[bottom].pieces[0].t1 = FT(1) / 2;
    bad.lines[bottom].pieces[1].t0 = FT(1) / 2;
    EXPECT_EQ(kinds(bad), (std::set<std::string>{"(b) visibility"}));
  }
  {  // by a tiny amount
    LineSetX bad = good;
    const FT t = bad.lines[bottom].pieces[0].t1 + FT(1) / (1 << 30);
    bad.lines[bottom].pieces[0].t1 = t;
    bad.lines[bottom].pieces[1].t0 = t;
    EXPECT_EQ(kinds(bad), (std::set<std::string>{"(b) visibility"}));
  }
  {  // the last piece stops short, the first starts late
    LineSetX bad = good;
    bad.lines[right].pieces[0].t1 = FT(99) / 100;
    bad.lines[bottom].pieces[0].t0 = FT(1) / 100;
    const auto k = kinds(bad);
    EXPECT_TRUE(k.count("(a) last piece does not end at 1")) << ::testing::PrintToString(k);
    EXPECT_TRUE(k.count("(a) first piece does not start at 0")) << ::testing::PrintToString(k);
  }
  {  // an endpoint moved; a line without pieces
    LineSetX bad = good;
    bad.lines[right].a.z = bad.lines[right].a.z + 1;
    bad.lines[bottom].pieces.clear();
    const auto k = kinds(bad);
    EXPECT_TRUE(k.count("(c) endpoints")) << ::testing::PrintToString(k);
    EXPECT_TRUE(k.count("(a) no pieces")) << ::testing::PrintToString(k);
  }
}

TEST(LineChecks, CatchPlantedIntersectionErrors) {
  const auto meshes = penetrating_quads();
  const View iso = view_named("iso");
  const LineOracle oracle(meshes, iso);
  const LineSetX good = run_lines(meshes, iso).set;
  ASSERT_TRUE(check_lines(oracle, good, {}).ok()) << check_lines(oracle, good, {}).summary();
  auto kinds = [&](const LineSetX& set) { return failure_kinds(check_lines(oracle, set, {})); };
  std::size_t i = 0;
  while (i < good.lines.size() && good.lines[i].kind != FeatureKind::intersection) ++i;
  ASSERT_LT(i, good.lines.size());
  {  // the intersection line dropped
    LineSetX bad = good;
    bad.lines.erase(bad.lines.begin() + static_cast<std::ptrdiff_t>(i));
    const auto k = kinds(bad);
    EXPECT_TRUE(k.count("(d) penetration not on any intersection line")) << ::testing::PrintToString(k);
  }
  {  // shortened to a quarter: the penetration midpoints are no longer on it
    LineSetX bad = good;
    auto& l = bad.lines[i];
    l.b = {l.a.x + (l.b.x - l.a.x) / 4, l.a.y + (l.b.y - l.a.y) / 4, l.a.z + (l.b.z - l.a.z) / 4};
    const auto k = kinds(bad);
    EXPECT_TRUE(k.count("(d) penetration not on any intersection line")) << ::testing::PrintToString(k);
  }
  {  // moved off the faces
    LineSetX bad = good;
    bad.lines[i].a.z = bad.lines[i].a.z + 1;
    bad.lines[i].b.z = bad.lines[i].b.z + 1;
    const auto k = kinds(bad);
    EXPECT_TRUE(k.count("(d) intersection point not on two faces in different planes")) << ::testing::PrintToString(k);
  }
  {  // intersections were not asked for
    LineCheckOptions o;
    o.intersections = false;
    EXPECT_TRUE(failure_kinds(check_lines(oracle, good, o)).count("(d) intersection lines when none were asked for"));
  }
}

// ---------------------------------------------------------------------------------------------
// Every fixture, every named view and (1, 2, -3), back faces removed and kept.

struct FixtureView {
  std::string file;
  View view;
  std::string label;  // the view's part of the test name
};
void PrintTo(const FixtureView& p, std::ostream* os) { *os << p.file << " " << p.label; }

class LineFixtureViews : public ::testing::TestWithParam<FixtureView> {};

TEST_P(LineFixtureViews, Contract) {
  const auto& p = GetParam();
  const auto& meshes = fixture(p.file);
  const PenetrationSearch pen = find_penetrations(meshes);
  const LineSetX set = run_and_check(meshes, p.view, p.file, {}, true, &pen);
  run_and_check(meshes, p.view, p.file, {}, false, &pen);
  // Winding is no input: the same mesh with every face reversed draws the same lines.
  EXPECT_EQ(line_signature(run_lines(reversed_meshes(meshes), p.view).set), line_signature(set))
      << p.file << " reversed";
  // Nor is the screen subdivision: strips of one, two or five sources draw the same lines.
  for (std::size_t per_strip : {1, 2, 5}) {
    hidden_line::AreaSortOptions sort;
    sort.sources_per_strip = per_strip;
    EXPECT_EQ(line_signature(run_lines(meshes, p.view, {}, true, sort).set), line_signature(set))
        << p.file << " in strips of " << per_strip;
  }
}

std::vector<FixtureView> fixture_views() {
  std::vector<FixtureView> out;
  for (const auto& file : fixture_files()) {
    for (const auto& view : named_views()) out.push_back({file, view, view.name});
    out.push_back({file, direction_view({1, 2, -3}), "custom"});
    // An up vector that is not orthogonal to the direction, with a non-dyadic component.
    out.push_back({file, direction_view({-2, 1, 0.5}, {0.3, 0.1, 1}), "skew"});
  }
  return out;
}

INSTANTIATE_TEST_SUITE_P(Fixtures, LineFixtureViews, ::testing::ValuesIn(fixture_views()),
                         [](const auto& info) { return test_name(info.param.file) + "_" + info.param.label; });

// Every fixture in perspective (surface_runs.hpp perspective_view): far, close (strong
// perspective) and eyes whose near plane cuts the scene. The projective map is exact, so every
// check of the contract carries over; the oracle clips by the near plane on its own.

struct PerspectiveCase {
  std::string file;
  int which = 0;
};
void PrintTo(const PerspectiveCase& p, std::ostream* os) { *os << p.file << " perspective " << p.which; }

class LinePerspectiveViews : public ::testing::TestWithParam<PerspectiveCase> {};

TEST_P(LinePerspectiveViews, Contract) {
  const auto& p = GetParam();
  const auto& meshes = fixture(p.file);
  const View view = perspective_view(meshes, p.which);
  if (const auto defect = perspective_defect(meshes, view)) GTEST_SKIP() << *defect;
  try {
    const PenetrationSearch pen = find_penetrations(meshes);
    const LineSetX set = run_and_check(meshes, view, p.file, {}, true, &pen);
    run_and_check(meshes, view, p.file, {}, false, &pen);
    EXPECT_EQ(line_signature(run_lines(reversed_meshes(meshes), view).set), line_signature(set))
        << p.file << " reversed";
    hidden_line::AreaSortOptions sort;
    sort.sources_per_strip = 2;
    EXPECT_EQ(line_signature(run_lines(meshes, view, {}, true, sort).set), line_signature(set))
        << p.file << " in strips of 2";
  } catch (const UserError& e) {
    // A polygon face that the near plane cuts into several pieces is refused (near_plane.hpp).
    EXPECT_GE(p.which, 3) << e.what();
    GTEST_SKIP() << e.what();
  }
}

std::vector<PerspectiveCase> perspective_cases() {
  std::vector<PerspectiveCase> out;
  for (const auto& file : fixture_files())
    for (int which = 0; which < kPerspectiveViews; ++which) out.push_back({file, which});
  return out;
}

INSTANTIATE_TEST_SUITE_P(Fixtures, LinePerspectiveViews, ::testing::ValuesIn(perspective_cases()),
                         [](const auto& info) { return test_name(info.param.file) + "_" + std::to_string(info.param.which); });

// Meshes as real exporters write them (fixtures/scenes/real_mesh_fixtures.py); the fixture runs
// above check them against the oracle in every view, these check what they are for.

TEST(LinesHand, InwardMeshesAreCulledAsTurnedOutward) {
  // Inward-wound box in iso: three of its twelve edges are hidden, as for the outward box.
  const auto& meshes = fixture("inward_box.off");
  const LineSetX set = run_and_check(meshes, view_named("iso"), "inward_box");
  std::size_t hidden_lines = 0;
  for (const auto& l : set.lines)
    hidden_lines += std::all_of(l.pieces.begin(), l.pieces.end(), [](const auto& p) { return !p.visible; });
  EXPECT_EQ(set.lines.size(), 12u);
  EXPECT_EQ(hidden_lines, 3u);
  const ViewFrame<ExactKernel> frame(view_named("iso"));
  const auto sources = hidden_line::build_sources<ExactKernel>(meshes, frame);
  EXPECT_EQ(sources.stats.inward_components, 1u);
  EXPECT_EQ(sources.stats.back_faces_removed, 3u);
  // One inward and one outward component: each culled the right way.
  const auto mixed = hidden_line::build_sources<ExactKernel>(fixture("mixed_orientation.off"), frame);
  EXPECT_EQ(mixed.stats.inward_components, 1u);
  EXPECT_EQ(mixed.stats.back_faces_removed, 6u);
  // A box with one face flipped is not consistently oriented: none of its faces is culled.
  const auto inconsistent = hidden_line::build_sources<ExactKernel>(fixture("mixed_consistency.off"), frame);
  EXPECT_EQ(inconsistent.stats.back_faces_removed, 3u);
}

TEST(LinesHand, TriangleSoupsDrawAsTheWeldedMesh) {
  // soup_box in three formats against the same box as 6 quads on 8 shared vertices.
  const Mesh box = make_mesh("box", {{0, 0, 0}, {3, 0, 0}, {3, 2, 0}, {0, 2, 0}, {0, 0, 1}, {3, 0, 1}, {3, 2, 1}, {0, 2, 1}},
                             {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 4, 7, 3}, {1, 2, 6, 5}});
  for (const char* name : {"iso", "front", "top"}) {
    const View view = view_named(name);
    const auto want = line_signature(run_and_check({box}, view, "box"), false);
    for (const std::string& file : {fixture_dir() + "/soup_box.off", fixture_dir() + "/../meshes/soup_box.obj",
                                   fixture_dir() + "/../meshes/soup_box.ply"}) {
      const auto& meshes = scene_meshes(file);
      EXPECT_EQ(line_signature(run_and_check(meshes, view, file), false), want) << file << " " << name;
    }
  }
}

TEST(LinesHand, NonPlanarQuadsAreFans) {
  // The saddle z = x y on a 5 x 5 grid: each quad is the fan from its first corner, whose diagonal
  // runs from vertex k to k + 6. Where the two triangles face opposite ways the diagonal would be a
  // silhouette; as a fan edge it is a line only by the crease rule.
  const Mesh& mesh = fixture("twisted_quads.off").front();
  ASSERT_EQ(mesh.faces.size(), 32u);
  auto facing = [&](const std::vector<std::uint32_t>& f, const Vec3& d) {
    const auto &a = mesh.vertices[f[0]], &b = mesh.vertices[f[1]], &c = mesh.vertices[f[2]];
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, w[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double n[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
    return (n[0] * d[0] + n[1] * d[1] + n[2] * d[2]) < 0;  // small integers: exact
  };
  std::size_t folded = 0;
  for (const auto& view : named_views()) {
    for (std::size_t q = 0; q < 16; ++q)
      folded += facing(mesh.faces[2 * q], view.direction) != facing(mesh.faces[2 * q + 1], view.direction);
    const LineSetX set = run_and_check(fixture("twisted_quads.off"), view, "twisted_quads");
    for (const auto& l : set.lines)
      if (l.v1 - l.v0 == 6) {
        EXPECT_EQ(l.kind, FeatureKind::crease) << l.v0 << "-" << l.v1 << " in " << view.name;
      }
  }
  EXPECT_GT(folded, 0u) << "no view folds a quad: the test tests nothing";
}

TEST(LinesHand, PenetratingBoxesHaveIntersectionLines) {
  for (const char* name : {"iso", "front", "top"}) {
    const LineSetX set = run_and_check(fixture("penetrating_boxes.off"), view_named(name), "penetrating_boxes");
    EXPECT_GT(set.stats.by_kind[static_cast<int>(FeatureKind::intersection)], 0u) << name;
  }
}

// ---------------------------------------------------------------------------------------------
// The shared scenes, every named view.

struct SceneView {
  std::string file;
  View view;
};
void PrintTo(const SceneView& p, std::ostream* os) { *os << p.file << " " << p.view.name; }

class LineSceneViews : public ::testing::TestWithParam<SceneView> {};

const PenetrationSearch& scene_penetrations(const std::string& path) {
  static std::mutex mutex;
  static std::map<std::string, PenetrationSearch> cache;
  std::lock_guard lock(mutex);
  auto it = cache.find(path);
  if (it == cache.end()) it = cache.emplace(path, find_penetrations(scene_meshes(path))).first;
  return it->second;
}

TEST_P(LineSceneViews, Contract) {
  const auto& p = GetParam();
  if (!shared_scenes_present()) GTEST_SKIP() << "no shared scenes at " << shared_scene_dir();
  const std::string path = shared_scene_dir() + "/" + p.file;
  const auto& meshes = scene_meshes(path);
  using clock = std::chrono::steady_clock;
  auto t0 = clock::now();
  const PenetrationSearch& pen = scene_penetrations(path);
  auto t1 = clock::now();
  LineRun run = run_lines(meshes, p.view);
  auto t2 = clock::now();
  const LineOracle oracle(meshes, p.view);
  const LineReport report = check_lines(oracle, run.set, {}, &pen);
  auto t3 = clock::now();
  EXPECT_TRUE(report.ok()) << p.file << " view " << p.view.name << ": " << report.summary();
  EXPECT_EQ(line_signature(run_lines(reversed_meshes(meshes), p.view).set), line_signature(run.set))
      << p.file << " view " << p.view.name << " with every face reversed";
  auto secs = [](auto a, auto b) { return std::chrono::duration<double>(b - a).count(); };
  std::printf("[ timing   ] %s %s: %zu lines (%zu intersection), %zu visible / %zu hidden pieces; engine %.2f s "
              "(sources %.2f, sort %.2f, intersections %.2f, classify %.2f), oracle %.2f s (+ penetrations %.2f s, "
              "%zu found)\n",
              p.file.c_str(), p.view.name.c_str(), run.set.lines.size(),
              run.set.stats.by_kind[static_cast<int>(FeatureKind::intersection)], run.set.stats.visible_pieces,
              run.set.stats.hidden_pieces, secs(t1, t2), run.sources_seconds, run.sort_seconds,
              run.intersections_seconds, run.classify_seconds, secs(t2, t3), secs(t0, t1), pen.found.size());
}

std::vector<SceneView> scene_views() {
  std::vector<SceneView> out;
  auto files = shared_scene_files();
  for (const auto& f : soak_scene_files()) files.push_back(f);
  for (const auto& file : files)
    for (const auto& view : named_views()) out.push_back({file, view});
  return out;
}

INSTANTIATE_TEST_SUITE_P(Scenes, LineSceneViews, ::testing::ValuesIn(scene_views()),
                         [](const auto& info) { return test_name(info.param.file) + "_" + info.param.view.name; });

// The shared scenes in perspective: a close eye (strong perspective) and one whose near plane cuts
// the scene.
class LineScenePerspective : public ::testing::TestWithParam<PerspectiveCase> {};

TEST_P(LineScenePerspective, Contract) {
  const auto& p = GetParam();
  if (!shared_scenes_present()) GTEST_SKIP() << "no shared scenes at " << shared_scene_dir();
  const std::string path = shared_scene_dir() + "/" + p.file;
  const auto& meshes = scene_meshes(path);
  const View view = perspective_view(meshes, p.which);
  if (const auto defect = perspective_defect(meshes, view)) GTEST_SKIP() << *defect;
  try {
    LineRun run = run_lines(meshes, view);
    const LineOracle oracle(meshes, view);
    const LineReport report = check_lines(oracle, run.set, {}, &scene_penetrations(path));
    EXPECT_TRUE(report.ok()) << p.file << " view " << view.name << ": " << report.summary();
  } catch (const UserError& e) {
    EXPECT_GE(p.which, 3) << e.what();
    GTEST_SKIP() << e.what();
  }
}

std::vector<PerspectiveCase> scene_perspective_cases() {
  std::vector<PerspectiveCase> out;
  auto files = shared_scene_files();
  for (const auto& f : soak_scene_files()) files.push_back(f);
  for (const auto& file : files)
    for (int which : {1, 3}) out.push_back({file, which});
  return out;
}

INSTANTIATE_TEST_SUITE_P(Scenes, LineScenePerspective, ::testing::ValuesIn(scene_perspective_cases()),
                         [](const auto& info) { return test_name(info.param.file) + "_" + std::to_string(info.param.which); });

}  // namespace
}  // namespace hlr::hltest
