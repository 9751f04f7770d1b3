// The library's entry points (export/jobs.hpp, export/polygons.hpp, kernel/scene.hpp) as a
// program calls them: progress and cancellation, shared intersections, meshes from arrays, and
// errors that name the input. That their results equal the hlr program's is checked end to end
// by tests/package (check_examples.py).
#include <hlr/export/jobs.hpp>
#include <hlr/export/polygons.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

namespace hlr::exporter {
namespace {

const std::string kAnchor = HLR_FIXTURES_DIR "/parts/anchor.off";

View iso() {
  View view;
  named_view("iso", view);
  return view;
}

bool same_pieces(const LineDrawing& a, const LineDrawing& b) {
  if (a.pieces.size() != b.pieces.size()) return false;
  for (std::size_t i = 0; i < a.pieces.size(); ++i) {
    const DrawingPiece &p = a.pieces[i], &q = b.pieces[i];
    if (p.a != q.a || p.b != q.b || p.visible != q.visible || p.kind != q.kind || p.edge != q.edge) return false;
  }
  return true;
}

TEST(Jobs, DrawLinesReportsItsStagesAndTheOutputStageHookInOrder) {
  const Scene scene = load_scene({kAnchor});
  std::vector<std::string> stages;
  DrawOptions options;
  options.progress.stage = [&](std::string_view s) { stages.emplace_back(s); };
  options.output_stage_begins = [&] { stages.emplace_back("(output stage begins)"); };
  options.drawing_rounded = [&] { stages.emplace_back("(drawing rounded)"); };
  const LineDrawing drawing = draw_lines(scene, iso(), options);
  EXPECT_GT(drawing.stats.lines, 0u);
  // No sort: a drawing's lines are classified against the polygons themselves. The output stage's
  // hook comes once, after them, and the rounding's once, last.
  ASSERT_EQ(stages.size(), 6u);
  EXPECT_EQ(stages[0], "finding where faces penetrate");
  EXPECT_NE(stages[1].find("building polygons (exact)"), std::string::npos);
  EXPECT_EQ(stages[2], "classifying feature lines");
  EXPECT_EQ(stages[3], "(output stage begins)");
  EXPECT_EQ(stages[4], "drawing coincident pieces once (ISO 128 precedence)");
  EXPECT_EQ(stages[5], "(drawing rounded)");
}

TEST(Jobs, DrawLinesStopsWhenAskedBetweenStages) {
  const Scene scene = load_scene({kAnchor});
  std::vector<std::string> stages;
  DrawOptions options;
  options.progress.stage = [&](std::string_view s) { stages.emplace_back(s); };
  // Asked to stop once the polygons are being built: the job stops before it classifies lines.
  options.progress.cancelled = [&] {
    return !stages.empty() && stages.back().find("building polygons") != std::string::npos;
  };
  EXPECT_THROW((void)draw_lines(scene, iso(), options), Cancelled);
  EXPECT_TRUE(std::none_of(stages.begin(), stages.end(), [](const std::string& s) { return s == "classifying feature lines"; }));
}

TEST(Jobs, SharedIntersectionsDrawWhatEachViewFindsItself) {
  const Scene scene = load_scene({kAnchor});
  const SceneIntersections shared(scene, true);
  for (const char* name : {"front", "iso"}) {
    View view;
    named_view(name, view);
    EXPECT_TRUE(same_pieces(draw_lines(scene, view, {}, &shared), draw_lines(scene, view))) << name;
  }
}

TEST(Jobs, MeshFromArraysDrawsAsTheSameFile) {
  const Scene from_file = load_scene({kAnchor});
  Scene from_arrays;
  ImportReport report;
  const Mesh& read = from_file.meshes.front();
  // The file's faces are polygons; the arrays give them as read (make_mesh prepares them again).
  from_arrays.add(make_mesh("anchor", read.vertices, read.faces, report), report);
  EXPECT_EQ(from_arrays.input.files, std::vector<std::string>{"anchor"});
  EXPECT_TRUE(same_pieces(draw_lines(from_arrays, iso()), draw_lines(from_file, iso())));
}

TEST(Jobs, MeshFromArraysRefusesBadIndicesNamingIt) {
  ImportReport report;
  try {
    (void)make_mesh("bracket", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 3}}, report);
    FAIL() << "no error";
  } catch (const ImportError& e) {
    EXPECT_EQ(std::string(e.what()), "bracket: face 0: vertex index 3 is out of range (3 vertices)");
  }
}

TEST(Jobs, MeshFromArraysRefusesNonFiniteAndHugeCoordinatesNamingIt) {
  // No reader has seen these: finish's own check must say it as an ImportError naming the mesh.
  ImportReport report;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const auto& [v, message] : std::vector<std::pair<Vec3, std::string>>{
           {{nan, 0, 0}, "part: vertex 1: x coordinate nan is not a finite number"},
           {{0, 1e101, 0}, "part: vertex 1: y coordinate 1e+101 is out of range (at most 1e100 in magnitude)"}}) {
    try {
      (void)make_mesh("part", {{0, 0, 0}, v, {0, 1, 0}}, {{0, 1, 2}}, report);
      ADD_FAILURE() << "no error for " << message;
    } catch (const ImportError& e) {
      EXPECT_EQ(std::string(e.what()), message);
    }
  }
}

TEST(Jobs, InexactKernelFailureNamesTheScene) {
  // What a job throws when an inexact kernel contradicts itself: one line naming the first file.
  const UserError e = hidden_line::inexact_kernel_failure(load_scene({kAnchor}), KernelKind::epick,
                                                          std::runtime_error("orientation changed"));
  EXPECT_EQ(std::string(e.what()), kAnchor + ": the epick kernel failed on this view (orientation changed); the "
                                             "exact kernel does not");
}

TEST(Jobs, ClipPolygonsNamesTheInputOfAnInvalidPolygon) {
  ClipOptions options;
  options.subject_name = "mine.json";
  const RawPolygon bow_tie{{{0, 0}, {2, 2}, {2, 0}, {0, 2}}, {}};
  const RawPolygon square{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {}};
  try {
    (void)clip_polygons({bow_tie}, {square}, options);
    FAIL() << "no error";
  } catch (const UserError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("mine.json: polygon 0 outer contour", 0), 0u) << e.what();
  }
}

TEST(Jobs, ClipPolygonsKeepsTheAreaIdentityExactly) {
  ClipOptions options;
  options.exact_values = true;
  const RawPolygon subject{{{0, 0}, {3, 0}, {3, 3}, {0, 3}}, {}};
  const RawPolygon clip{{{1, 1}, {5, 1}, {5, 5}, {1, 5}}, {}};
  const ClipOutcome outcome = clip_polygons({subject}, {clip}, options);
  EXPECT_TRUE(outcome.identity_holds);
  EXPECT_EQ(outcome.inside_area_exact, "4");
  EXPECT_EQ(outcome.outside_area_exact, "5");
  ASSERT_EQ(outcome.inside.size(), 1u);
  EXPECT_EQ(outcome.inside[0].outer_edges.size(), 4u);
}

}  // namespace
}  // namespace hlr::exporter
