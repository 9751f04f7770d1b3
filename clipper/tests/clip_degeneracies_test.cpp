// Hand-checked clips on the exact kernel, one per degeneracy the clipper must handle exactly.
// Expected results are written as polygons of plain coordinates; they are compared with the
// output up to the starting vertex and to vertices where the contour runs straight on.
#include <hlr/clipper/clipper.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

namespace hlr::clip {
namespace {

using K = ExactKernel;
using G = Geometry<K>;
using Pt = G::Point;
using Coords = std::vector<std::pair<double, double>>;

struct Shape {
  Coords outer;
  std::vector<Coords> holes = {};
};

Polygon<K> make(LineTable<K>& lines, const Shape& s) {
  auto contour = [&](const Coords& c) {
    std::vector<Pt> pts;
    for (auto [x, y] : c) pts.push_back(G::point(x, y));
    return make_contour<K>(pts, lines);
  };
  Polygon<K> p{contour(s.outer), {}};
  for (const auto& h : s.holes) p.holes.push_back(contour(h));
  auto defect = normalize_polygon(p);
  EXPECT_FALSE(defect) << *defect;
  return p;
}

// A contour as exact vertex strings, without straight-through vertices, starting at its
// lexicographically smallest vertex; orientation is kept.
std::vector<std::string> canonical(const std::vector<Pt>& pts) {
  std::vector<Pt> corners;
  const std::size_t n = pts.size();
  for (std::size_t i = 0; i < n; ++i)
    if (G::orientation(pts[(i + n - 1) % n], pts[i], pts[(i + 1) % n]) != 0) corners.push_back(pts[i]);
  auto first = std::min_element(corners.begin(), corners.end(),
                                [](const Pt& a, const Pt& b) { return G::compare_xy(a, b) < 0; });
  std::rotate(corners.begin(), first, corners.end());
  std::vector<std::string> out;
  for (const Pt& p : corners) out.push_back(G::exact_string(p.x()) + "," + G::exact_string(p.y()));
  return out;
}

using CanonicalPolygon = std::vector<std::vector<std::string>>;  // outer, then sorted holes

std::vector<CanonicalPolygon> canonical(const std::vector<Polygon<K>>& polys) {
  std::vector<CanonicalPolygon> out;
  for (const auto& p : polys) {
    CanonicalPolygon c{canonical(p.outer.points)};
    std::vector<std::vector<std::string>> holes;
    for (const auto& h : p.holes) holes.push_back(canonical(h.points));
    std::sort(holes.begin(), holes.end());
    c.insert(c.end(), holes.begin(), holes.end());
    out.push_back(std::move(c));
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Expected shapes are given counter-clockwise outer and clockwise holes.
std::vector<CanonicalPolygon> canonical(const std::vector<Shape>& shapes) {
  LineTable<K> scratch;
  std::vector<Polygon<K>> polys;
  for (const auto& s : shapes) polys.push_back(make(scratch, s));
  return canonical(polys);
}

// Invariants every result must satisfy, checked exactly.
void check_invariants(const Polygon<K>& subject, const ClipResult<K>& r, const LineTable<K>& lines) {
  G::FT total = 0;
  auto check_contour = [&](const Contour<K>& c, bool outer) {
    ASSERT_GE(c.size(), 3u);
    ASSERT_EQ(c.points.size(), c.lines.size());
    const auto area = twice_signed_area(c);
    EXPECT_TRUE(outer ? area > 0 : area < 0) << "orientation";
    for (std::size_t i = 0; i < c.size(); ++i) {
      const Pt& a = c.points[i];
      const Pt& b = c.points[(i + 1) % c.size()];
      EXPECT_FALSE(a == b) << "zero-length edge";
      // Provenance: the edge lies on its named input edge.
      const SupportLine<K>& l = lines.at(c.lines[i]);
      K::Segment_2 seg(l.a, l.b);
      EXPECT_TRUE(seg.has_on(a) && seg.has_on(b)) << "edge " << i << " is not on line " << c.lines[i];
    }
  };
  for (const auto* list : {&r.inside, &r.outside}) {
    for (const auto& p : *list) {
      check_contour(p.outer, true);
      for (const auto& h : p.holes) check_contour(h, false);
      EXPECT_GT(twice_area(p), 0) << "zero-area piece";
      total += twice_area(p);
    }
  }
  EXPECT_EQ(total, twice_area(subject)) << "area(inside) + area(outside) != area(subject)";
}

struct Expect {
  std::vector<Shape> inside, outside;
};

void expect_clip(const Shape& subject, const Shape& clip, const Expect& expected) {
  LineTable<K> lines;
  Polygon<K> s = make(lines, subject);
  Polygon<K> c = make(lines, clip);
  ClipRegion<K> region(c, lines);
  ClipResult<K> r = clip_polygon(s, region);
  check_invariants(s, r, lines);
  EXPECT_EQ(canonical(r.inside), canonical(expected.inside)) << "inside list";
  EXPECT_EQ(canonical(r.outside), canonical(expected.outside)) << "outside list";
  // clip_list answers the same, subject by subject.
  std::vector<Polygon<K>> list{s, s};
  auto results = clip_list<K>(list, region);
  ASSERT_EQ(results.size(), 2u);
  for (const auto& lr : results) {
    EXPECT_EQ(canonical(lr.inside), canonical(r.inside));
    EXPECT_EQ(canonical(lr.outside), canonical(r.outside));
  }
}

Shape rect(double x0, double y0, double x1, double y1) { return {{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}}; }
Coords rect_hole(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x0, y1}, {x1, y1}, {x1, y0}}; }

TEST(ClipDegeneracies, ProperCrossings) {
  expect_clip(rect(0, 0, 4, 4), rect(2, 2, 6, 6),
              {{rect(2, 2, 4, 4)}, {{{{0, 0}, {4, 0}, {4, 2}, {2, 2}, {2, 4}, {0, 4}}}}});
}

TEST(ClipDegeneracies, SharedVerticesAndEdges) {
  expect_clip(rect(0, 0, 4, 4), {{{0, 0}, {4, 0}, {4, 4}}},
              {{{{{0, 0}, {4, 0}, {4, 4}}}}, {{{{0, 0}, {4, 4}, {0, 4}}}}});
}

TEST(ClipDegeneracies, VertexOnEdge) {
  expect_clip(rect(0, 0, 4, 4), {{{2, 0}, {6, 2}, {2, 4}}},
              {{{{{2, 0}, {4, 1}, {4, 3}, {2, 4}}}},
               {rect(0, 0, 2, 4), {{{2, 0}, {4, 0}, {4, 1}}}, {{{4, 3}, {4, 4}, {2, 4}}}}});
}

TEST(ClipDegeneracies, CollinearOverlappingEdges) {
  expect_clip(rect(0, 0, 4, 4), rect(2, 0, 6, 4), {{rect(2, 0, 4, 4)}, {rect(0, 0, 2, 4)}});
}

TEST(ClipDegeneracies, TouchingAlongAnEdgeFromOutside) {
  expect_clip(rect(0, 0, 2, 2), rect(2, 0, 4, 2), {{}, {rect(0, 0, 2, 2)}});
  expect_clip(rect(0, 0, 4, 4), rect(1, -2, 3, 0), {{}, {rect(0, 0, 4, 4)}});
}

TEST(ClipDegeneracies, IdenticalPolygons) {
  expect_clip(rect(0, 0, 4, 4), rect(0, 0, 4, 4), {{rect(0, 0, 4, 4)}, {}});
  // Same polygon, given clockwise and starting elsewhere.
  expect_clip(rect(0, 0, 4, 4), {{{4, 4}, {4, 0}, {0, 0}, {0, 4}}}, {{rect(0, 0, 4, 4)}, {}});
}

TEST(ClipDegeneracies, ClipInsideSubject) {
  expect_clip(rect(0, 0, 10, 10), rect(2, 2, 5, 5),
              {{rect(2, 2, 5, 5)}, {{rect(0, 0, 10, 10).outer, {rect_hole(2, 2, 5, 5)}}}});
}

TEST(ClipDegeneracies, SubjectInsideClip) {
  expect_clip(rect(2, 2, 5, 5), rect(0, 0, 10, 10), {{rect(2, 2, 5, 5)}, {}});
}

TEST(ClipDegeneracies, TouchingAtAPoint) {
  expect_clip(rect(0, 0, 2, 2), rect(2, 2, 4, 4), {{}, {rect(0, 0, 2, 2)}});
  // From inside: the outside list has a hole that touches its outer contour.
  expect_clip(rect(0, 0, 4, 4), {{{2, 0}, {3, 1}, {2, 2}, {1, 1}}},
              {{{{{2, 0}, {3, 1}, {2, 2}, {1, 1}}}},
               {{rect(0, 0, 4, 4).outer, {{{2, 0}, {1, 1}, {2, 2}, {3, 1}}}}}});
}

TEST(ClipDegeneracies, DiamondWithVerticesOnEdgesLeavesFourTouchingCorners) {
  expect_clip(rect(0, 0, 4, 4), {{{2, 0}, {4, 2}, {2, 4}, {0, 2}}},
              {{{{{2, 0}, {4, 2}, {2, 4}, {0, 2}}}},
               {{{{0, 0}, {2, 0}, {0, 2}}},
                {{{2, 0}, {4, 0}, {4, 2}}},
                {{{4, 2}, {4, 4}, {2, 4}}},
                {{{0, 2}, {2, 4}, {0, 4}}}}});
}

TEST(ClipDegeneracies, HoleTouchingOuterContour) {
  // The subject's hole touches its outer contour at (2, 0); the clip is the lower half.
  Shape subject{rect(0, 0, 4, 4).outer, {{{2, 0}, {1, 1}, {3, 1}}}};
  expect_clip(subject, rect(0, 0, 4, 2),
              {{{rect(0, 0, 4, 2).outer, {{{2, 0}, {1, 1}, {3, 1}}}}}, {rect(0, 2, 4, 4)}});
}

TEST(ClipDegeneracies, HolesTouchingEachOther) {
  // Two holes touching at (3, 3); the clip's left edge runs along the first hole's right edge.
  Coords triangle_hole{{3, 3}, {5, 3}, {4, 2}};
  Shape subject{rect(0, 0, 6, 4).outer, {rect_hole(1, 1, 3, 3), triangle_hole}};
  expect_clip(subject, rect(3, 0, 6, 4),
              {{{rect(3, 0, 6, 4).outer, {triangle_hole}}},
               {{{{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 3}, {3, 3}, {3, 4}, {0, 4}}}}});
}

TEST(ClipDegeneracies, SubjectInsideClipHole) {
  Shape clip{rect(0, 0, 10, 10).outer, {rect_hole(2, 2, 8, 8)}};
  expect_clip(rect(3, 3, 5, 5), clip, {{}, {rect(3, 3, 5, 5)}});
  // Exactly the hole: touching all along, still nothing inside.
  expect_clip(rect(2, 2, 8, 8), clip, {{}, {rect(2, 2, 8, 8)}});
}

TEST(ClipDegeneracies, ClipWithHoleInsideSubject) {
  Shape clip{rect(2, 2, 8, 8).outer, {rect_hole(4, 4, 6, 6)}};
  expect_clip(rect(0, 0, 10, 10), clip,
              {{clip}, {{rect(0, 0, 10, 10).outer, {rect_hole(2, 2, 8, 8)}}, rect(4, 4, 6, 6)}});
}

TEST(ClipDegeneracies, SubjectHoleInsideClip) {
  Shape subject{rect(0, 0, 10, 10).outer, {rect_hole(4, 4, 6, 6)}};
  expect_clip(subject, rect(3, 3, 7, 7),
              {{{rect(3, 3, 7, 7).outer, {rect_hole(4, 4, 6, 6)}}}, {{rect(0, 0, 10, 10).outer, {rect_hole(3, 3, 7, 7)}}}});
  // The clip is exactly the subject's hole.
  expect_clip(subject, rect(4, 4, 6, 6), {{}, {subject}});
}

TEST(ClipDegeneracies, ConcaveSubjectSplitIntoSeveralPieces) {
  Shape u{{{0, 0}, {6, 0}, {6, 6}, {4, 6}, {4, 2}, {2, 2}, {2, 6}, {0, 6}}};
  expect_clip(u, rect(-1, 3, 7, 5),
              {{rect(0, 3, 2, 5), rect(4, 3, 6, 5)},
               {{{{0, 0}, {6, 0}, {6, 3}, {4, 3}, {4, 2}, {2, 2}, {2, 3}, {0, 3}}}, rect(0, 5, 2, 6), rect(4, 5, 6, 6)}});
}

TEST(ClipDegeneracies, EmptyResults) {
  expect_clip(rect(0, 0, 1, 1), rect(5, 5, 6, 6), {{}, {rect(0, 0, 1, 1)}});
  // Boxes overlap but the polygons do not.
  expect_clip({{{0, 0}, {4, 0}, {0, 4}}}, {{{4, 4}, {1, 4}, {4, 1}}}, {{}, {{{{0, 0}, {4, 0}, {0, 4}}}}});
}

TEST(ClipDegeneracies, ClipEdgesThroughSubjectVertices) {
  // The diamond's edges pass exactly through the square's four corners: the square is inside.
  expect_clip(rect(0, 0, 2, 2), {{{1, -1}, {3, 1}, {1, 3}, {-1, 1}}}, {{rect(0, 0, 2, 2)}, {}});
  // Shifted right by one, its vertex (0, 1) lies on the square's left edge.
  expect_clip(rect(0, 0, 2, 2), {{{2, -1}, {4, 1}, {2, 3}, {0, 1}}},
              {{{{{1, 0}, {2, 0}, {2, 2}, {1, 2}, {0, 1}}}}, {{{{0, 0}, {1, 0}, {0, 1}}}, {{{0, 1}, {1, 2}, {0, 2}}}}});
}

TEST(ClipDegeneracies, ThirdsAreExact) {
  // Crossings at non-dyadic points: x = 4/3.
  LineTable<K> lines;
  Polygon<K> s = make(lines, {{{0, 0}, {4, 0}, {0, 4}}});
  Polygon<K> c = make(lines, {{{1, 1}, {3, -1}, {3, 3}}});
  ClipRegion<K> region(c, lines);
  auto r = clip_polygon(s, region);
  check_invariants(s, r, lines);
  ASSERT_EQ(r.inside.size(), 1u);
}

TEST(ClipNormalize, RejectsSelfIntersectionAndNamesEdges) {
  LineTable<K> lines;
  std::vector<Pt> bowtie{G::point(0, 0), G::point(2, 2), G::point(2, 0), G::point(0, 2)};
  Polygon<K> p{make_contour<K>(bowtie, lines), {}};
  auto defect = normalize_polygon(p);
  ASSERT_TRUE(defect);
  EXPECT_EQ(*defect, "outer contour edges 0 and 2 intersect (the contour is not simple)");
}

TEST(ClipNormalize, RejectsBadHolesAndDegenerateContours) {
  auto defect_of = [](const Shape& s) {
    LineTable<K> lines;
    auto contour = [&](const Coords& c) {
      std::vector<Pt> pts;
      for (auto [x, y] : c) pts.push_back(G::point(x, y));
      return make_contour<K>(pts, lines);
    };
    Polygon<K> p{contour(s.outer), {}};
    for (const auto& h : s.holes) p.holes.push_back(contour(h));
    auto d = normalize_polygon(p);
    return d ? *d : std::string();
  };
  auto has = [](const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; };
  EXPECT_EQ(defect_of({{{0, 0}, {0, 0}, {1, 1}}}), "outer contour has 2 distinct vertices, at least 3 are needed");
  EXPECT_TRUE(has(defect_of({{{0, 0}, {1, 1}, {2, 2}}}), "fold back over each other"));
  EXPECT_EQ(defect_of({rect(0, 0, 4, 4).outer, {rect_hole(5, 5, 6, 6)}}), "hole 0 lies outside the outer contour");
  EXPECT_TRUE(has(defect_of({rect(0, 0, 4, 4).outer, {rect_hole(3, 1, 5, 2)}}), "crosses"));
  EXPECT_TRUE(has(defect_of({rect(0, 0, 4, 4).outer, {rect_hole(1, 0, 2, 1)}}), "overlaps"));
  EXPECT_EQ(defect_of({rect(0, 0, 10, 10).outer, {rect_hole(1, 1, 8, 8), rect_hole(2, 2, 3, 3)}}),
            "hole 1 lies inside hole 0");
  // Repeated points are dropped, not rejected.
  EXPECT_EQ(defect_of({{{0, 0}, {0, 0}, {4, 0}, {4, 4}, {4, 4}, {0, 4}, {0, 0}}}), "");
}

TEST(ClipNormalize, ReorientsAndKeepsProvenance) {
  LineTable<K> lines;
  std::vector<Pt> cw{G::point(0, 0), G::point(0, 4), G::point(4, 4), G::point(4, 0)};
  Polygon<K> p{make_contour<K>(cw, lines), {}};
  ASSERT_FALSE(normalize_polygon(p));
  EXPECT_GT(twice_signed_area(p.outer), 0);
  for (std::size_t i = 0; i < 4; ++i) {
    const auto& l = lines[p.outer.lines[i]];
    K::Segment_2 seg(l.a, l.b);
    EXPECT_TRUE(seg.has_on(p.outer.points[i]) && seg.has_on(p.outer.points[(i + 1) % 4]));
  }
}

}  // namespace
}  // namespace hlr::clip

namespace hlr::clip {
namespace {

std::vector<Polygon<K>> merged(const std::vector<Coords>& faces, LineTable<K>& lines) {
  std::vector<Contour<K>> pieces;
  for (const auto& f : faces) {
    std::vector<Pt> pts;
    for (auto [x, y] : f) pts.push_back(G::point(x, y));
    pieces.push_back(make_contour<K>(pts, lines));
  }
  return merge_polygons<K>(pieces, lines);
}

TEST(MergePolygons, TessellatedSquareBecomesOnePolygon) {
  LineTable<K> lines;
  auto polys = merged({{{0, 0}, {2, 0}, {2, 2}}, {{0, 0}, {2, 2}, {0, 2}}}, lines);
  EXPECT_EQ(canonical(polys), canonical(std::vector<Shape>{rect(0, 0, 2, 2)}));
}

TEST(MergePolygons, RingOfQuadsHasAHoleAndTJunctionsAreSplit) {
  LineTable<K> lines;
  // A ring around (1,1)-(2,2); the bottom quad spans the whole width, so its top edge carries
  // T-junctions at x = 1 and x = 2.
  auto polys = merged({{{0, 0}, {3, 0}, {3, 1}, {0, 1}},
                       {{0, 1}, {1, 1}, {1, 3}, {0, 3}},
                       {{2, 1}, {3, 1}, {3, 3}, {2, 3}},
                       {{1, 2}, {2, 2}, {2, 3}, {1, 3}}},
                      lines);
  EXPECT_EQ(canonical(polys), canonical(std::vector<Shape>{{rect(0, 0, 3, 3).outer, {rect_hole(1, 1, 2, 2)}}}));
}

TEST(MergePolygons, OverlappingPiecesAreRefused) {
  LineTable<K> lines;
  EXPECT_THROW(merged({rect(0, 0, 2, 2).outer, rect(1, 1, 3, 3).outer}, lines), ClipError);
}

}  // namespace
}  // namespace hlr::clip

namespace hlr::clip {
namespace {

TEST(ClipDegeneracies, ClipHoleTouchingOuterAwayFromSubject) {
  // The clip's hole touches its outer contour at (5, 5), outside the subject's box, where one of
  // the outer edges through (5, 5) reaches the subject's box and the other does not (found on
  // anchor.off in the iso view).
  Shape clip{{{0, 0}, {10, 0}, {10, 10}, {0, 10}, {0, 8}, {5, 5}, {9, 1}, {0, 1}}, {{{5, 5}, {6, 8}, {8, 6}}}};
  LineTable<K> lines;
  Polygon<K> s = make(lines, {{{6, 2}, {9, 2}, {6, 7}}});
  Polygon<K> c = make(lines, clip);
  ClipRegion<K> region(c, lines);
  ClipResult<K> r = clip_polygon(s, region);
  check_invariants(s, r, lines);
  // Inside: the subject above the line x + y = 10, less the hole's part; outside: the rest.
  EXPECT_EQ(r.inside.size(), 1u);
  EXPECT_EQ(r.outside.size(), 2u);
}

// side_of_polygon_on_line knows the edges along the line without arithmetic; it must say what
// side_of_polygon says for every point on the line: its ends and points constructed on it. Grid
// corners, so that corners on the line, edges along it and points on the boundary are common.
TEST(SideOfPolygonOnLine, AgreesWithSideOfPolygon) {
  std::mt19937 rng(20261204);
  auto grid = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
  // A closed polyline around a centre, corners snapped to the grid (it may touch or cross itself:
  // both functions count crossings alike).
  auto star = [&](LineTable<K>& lines, int cx, int cy, int radius) {
    std::vector<Pt> pts;
    const int n = grid(3, 9);
    for (int k = 0; k < n; ++k) {
      const double angle = 2 * std::numbers::pi * (k + 0.4 * grid(0, 2)) / n;
      const double r = grid(1, radius);
      pts.push_back(G::point(cx + std::round(r * std::cos(angle)), cy + std::round(r * std::sin(angle))));
    }
    return make_contour<K>(pts, lines);
  };
  int on_boundary = 0, along_edge = 0;
  for (int draw = 0; draw < 3000; ++draw) {
    LineTable<K> lines;
    Polygon<K> polygon{star(lines, 0, 0, 5), {}};
    if (grid(0, 1)) polygon.holes.push_back(star(lines, grid(-1, 1), grid(-1, 1), 2));
    // The line: through two grid points, or along an edge of the outer contour.
    Pt a = G::point(grid(-5, 5), grid(-5, 5)), b = G::point(grid(-5, 5), grid(-5, 5));
    if (grid(0, 1)) {
      const std::size_t i = std::size_t(grid(0, int(polygon.outer.size()) - 1));
      a = polygon.outer.points[i];
      b = polygon.outer.points[(i + 1) % polygon.outer.size()];
    }
    if (G::equal(a, b)) continue;
    std::vector<int> sides;
    for (const Contour<K>* c = &polygon.outer; c; c = c == &polygon.outer && !polygon.holes.empty() ? &polygon.holes[0] : nullptr)
      for (const Pt& p : c->points) sides.push_back(G::orientation(a, b, p));
    std::vector<const Contour<K>*> holes;
    for (const auto& h : polygon.holes) holes.push_back(&h);
    for (int k = -8; k <= 16; ++k) {
      const G::FT t = G::FT(k) / G::FT(8);
      const Pt q = k == 0 ? a : k == 8 ? b : G::point(a.x() + t * (b.x() - a.x()), a.y() + t * (b.y() - a.y()));
      const int expected = side_of_polygon(polygon, q);
      ASSERT_EQ(side_of_polygon_on_line<K>(polygon.outer, holes, sides, q), expected) << "draw " << draw << ", t = " << k << "/8";
      on_boundary += expected == 0;
    }
    for (std::size_t i = 0; i < polygon.outer.size(); ++i)
      along_edge += sides[i] == 0 && sides[(i + 1) % polygon.outer.size()] == 0;
  }
  // The draws reach the cases the shortcut is for.
  EXPECT_GT(on_boundary, 10000);
  EXPECT_GT(along_edge, 1500);
}

}  // namespace
}  // namespace hlr::clip
