// drawing_segments (ISO 128 precedence) checked exactly against the classified pieces it is made
// from, on the fixtures and a few shared CAD meshes in every named view:
//   - drawn segments of one class never overlap (collinear with a shared stretch);
//   - a drawn hidden segment never overlaps a visible piece;
//   - the middle of every visible piece lies on a drawn visible segment, and the middle of every
//     hidden piece on a drawn segment of either class (nothing goes missing);
//   - every drawn segment lies on a piece of its class.
#include <hlr/hidden_line/lines.hpp>

#include <gtest/gtest.h>

#include <filesystem>

namespace hlr::hltest {
namespace {

using K = ExactKernel;
using G = Geometry<K>;
using P = G::Point;

struct Segment {
  P a, b;
};

// Whether q lies on the closed segment s, exactly.
bool on(const Segment& s, const P& q) {
  return G::orientation(s.a, s.b, q) == 0 && G::compare_xy(s.a, q) * G::compare_xy(q, s.b) >= 0;
}
// Whether two segments are collinear and share a stretch of positive length.
bool overlap(const Segment& s, const Segment& t) {
  if (G::orientation(s.a, s.b, t.a) != 0 || G::orientation(s.a, s.b, t.b) != 0) return false;
  auto strictly_inside = [](const Segment& u, const P& q) {
    return G::compare_xy(u.a, q) * G::compare_xy(q, u.b) > 0;
  };
  const bool same = (G::equal(s.a, t.a) && G::equal(s.b, t.b)) || (G::equal(s.a, t.b) && G::equal(s.b, t.a));
  return same || strictly_inside(s, t.a) || strictly_inside(s, t.b) || strictly_inside(t, s.a) ||
         strictly_inside(t, s.b);
}

void check_precedence(const std::vector<Mesh>& meshes, const View& view, const std::string& label) {
  SCOPED_TRACE(label + " " + view.name);
  const ViewFrame<K> frame(view);
  auto sources = hidden_line::build_sources<K>(meshes, frame);
  const auto map = hidden_line::area_sort<K>(sources);
  const auto lines = hidden_line::classify_lines<K>(meshes, frame, sources, map, hidden_line::intersection_lines(meshes));
  const auto drawn = hidden_line::drawing_segments<K>(lines);

  std::vector<Segment> pieces[2];  // [visible]
  for (const auto& l : lines.lines)
    for (const auto& p : l.pieces) {
      auto at = [&](const G::FT& t) { return P(l.a.x + t * (l.b.x - l.a.x), l.a.y + t * (l.b.y - l.a.y)); };
      pieces[p.visible].push_back({at(p.t0), at(p.t1)});
    }
  std::vector<Segment> segments[2];
  for (const auto& d : drawn) segments[d.visible].push_back({d.a, d.b});

  for (int c = 0; c < 2; ++c)
    for (std::size_t i = 0; i < segments[c].size(); ++i) {
      for (std::size_t j = i + 1; j < segments[c].size(); ++j)
        EXPECT_FALSE(overlap(segments[c][i], segments[c][j])) << (c ? "visible" : "hidden") << " segments " << i << ", " << j;
      const Segment& s = segments[c][i];
      bool lies_on_piece = false;
      for (const Segment& p : pieces[c]) lies_on_piece |= on(p, s.a) && on(p, s.b);
      EXPECT_TRUE(lies_on_piece) << (c ? "visible" : "hidden") << " segment " << i << " is on no piece of its class";
    }
  for (const Segment& h : segments[0])
    for (const Segment& v : pieces[1]) EXPECT_FALSE(overlap(h, v)) << "a hidden segment is drawn over a visible piece";
  for (int c = 0; c < 2; ++c)
    for (const Segment& p : pieces[c]) {
      const P mid = G::midpoint(p.a, p.b);
      bool drawn_there = false;
      for (const Segment& s : segments[1]) drawn_there |= on(s, mid);
      if (c == 0)
        for (const Segment& s : segments[0]) drawn_there |= on(s, mid);
      EXPECT_TRUE(drawn_there) << (c ? "visible" : "hidden") << " piece not drawn";
    }
}

std::vector<Mesh> load(const std::filesystem::path& path) {
  ImportReport report;
  return {load_mesh(path.string(), report)};
}

const char* const kViews[] = {"front", "back", "top", "bottom", "left", "right", "iso"};

TEST(Precedence, Fixtures) {
  for (const auto& entry : std::filesystem::directory_iterator(HLR_SCENE_FIXTURES_DIR)) {
    if (entry.path().extension() != ".off") continue;
    const auto meshes = load(entry.path());
    for (const char* name : kViews) {
      View view;
      ASSERT_TRUE(named_view(name, view));
      check_precedence(meshes, view, entry.path().filename().string());
    }
  }
}

// CAD parts on axis views: many edges coincide in the image.
TEST(Precedence, SharedCadParts) {
  const std::filesystem::path dir = HLR_SHARED_SCENES;
  if (!std::filesystem::exists(dir)) GTEST_SKIP() << dir << " is absent";
  for (const char* file : {"cube_quad.off", "part.off", "joint.off", "openscad_example003.off"}) {
    const auto meshes = load(dir / file);
    for (const char* name : kViews) {
      View view;
      ASSERT_TRUE(named_view(name, view));
      check_precedence(meshes, view, file);
    }
  }
}

// Smooth lines (--smooth-edges thin) on the filleted bracket: their visible pieces are drawn as
// thin segments, after visible and hidden lines (a thin segment overlaps no piece of another
// line), their hidden pieces not at all; every other segment lies on a piece of a line that is
// not smooth, and every visible smooth piece is drawn by a segment of some class.
TEST(Precedence, SmoothLinesAreThinAndLast) {
  const auto meshes = load(std::filesystem::path(HLR_PART_FIXTURES) / "filleted_bracket.off");
  hidden_line::LineOptions options;
  options.features.smooth_edges = SmoothEdges::thin;
  std::size_t thin_drawn = 0;
  for (const char* name : kViews) {
    View view;
    ASSERT_TRUE(named_view(name, view));
    SCOPED_TRACE(name);
    const ViewFrame<K> frame(view);
    auto sources = hidden_line::build_sources<K>(meshes, frame);
    const auto map = hidden_line::area_sort<K>(sources);
    const auto lines = hidden_line::classify_lines<K>(meshes, frame, sources, map, {}, options);
    const auto drawn = hidden_line::drawing_segments<K>(lines);
    std::vector<Segment> smooth_visible, others;  // pieces
    for (const auto& l : lines.lines)
      for (const auto& p : l.pieces) {
        auto at = [&](const G::FT& t) { return P(l.a.x + t * (l.b.x - l.a.x), l.a.y + t * (l.b.y - l.a.y)); };
        if (l.kind != FeatureKind::smooth) others.push_back({at(p.t0), at(p.t1)});
        else if (p.visible) smooth_visible.push_back({at(p.t0), at(p.t1)});
      }
    for (const auto& d : drawn) {
      const Segment s{d.a, d.b};
      const bool smooth = d.line < lines.lines.size() && lines.lines[d.line].kind == FeatureKind::smooth;
      EXPECT_EQ(d.thin, smooth);
      bool lies_on_piece = false;
      for (const Segment& p : smooth ? smooth_visible : others) lies_on_piece |= on(p, s.a) && on(p, s.b);
      EXPECT_TRUE(lies_on_piece) << (smooth ? "a thin segment is on no visible smooth piece" : "a segment is on no piece");
      if (!d.thin) continue;
      ++thin_drawn;
      EXPECT_TRUE(d.visible);
      for (const Segment& p : others) EXPECT_FALSE(overlap(s, p)) << "a thin segment is drawn over another line";
    }
    for (const Segment& p : smooth_visible) {
      const P mid = G::midpoint(p.a, p.b);
      bool drawn_there = false;
      for (const auto& d : drawn) drawn_there |= on({d.a, d.b}, mid);
      EXPECT_TRUE(drawn_there) << "a visible smooth piece is not drawn";
    }
  }
  EXPECT_GT(thin_drawn, 0u);
}


// Collinear lines whose computed directions fall on either side of the half turn: an image line
// exactly vertical (x = 1/3) whose ends' intervals differ (1/3 and 1 - 2/3), so that its direction
// is computed a hair left or right of vertical, beside one whose ends have one interval. Precedence
// files lines by angle; these must still be found collinear, so that their overlap is drawn once.
TEST(Precedence, CollinearLinesAcrossTheHalfTurn) {
  using FT = G::FT;
  const FT third = FT(1) / FT(3), other_third = FT(1) - FT(2) / FT(3);
  auto line = [](FT ax, FT ay, FT bx, FT by) {
    hidden_line::FeatureLine<K> l;
    l.a = {ax, ay, FT(0)};
    l.b = {bx, by, FT(0)};
    l.pieces.push_back({FT(0), FT(1), true});
    return l;
  };
  for (int flip = 0; flip < 2; ++flip) {
    hidden_line::LineSet<K> lines;
    lines.lines.push_back(flip ? line(other_third, FT(0), third, FT(1)) : line(third, FT(0), other_third, FT(1)));
    lines.lines.push_back(line(third, FT(2), third, FT(1) / FT(2)));  // downward, over y in [1/2, 2]
    const auto drawn = hidden_line::drawing_segments<K>(lines);
    for (std::size_t i = 0; i < drawn.size(); ++i)
      for (std::size_t j = i + 1; j < drawn.size(); ++j)
        EXPECT_FALSE(overlap({drawn[i].a, drawn[i].b}, {drawn[j].a, drawn[j].b})) << "flip " << flip;
    EXPECT_EQ(drawn.size(), 2u) << "flip " << flip;  // the first line, and what the second adds
  }
}

}  // namespace
}  // namespace hlr::hltest
