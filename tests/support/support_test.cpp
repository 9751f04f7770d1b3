// Tests of the test support itself: the generators give valid, deterministic polygons; the exact
// validity check accepts and rejects what it should; the CGAL oracle computes what it should.
#include "cgal_oracle.hpp"
#include "clip_conversions.hpp"
#include "oracle.hpp"
#include "polygon_generators.hpp"

#include <gtest/gtest.h>

namespace hlr::testing {
namespace {

RawPolygon square(double x0, double y0, double x1, double y1) { return {box_contour({x0, y0, x1, y1}), {}}; }

TEST(Generators, ValidAndDeterministic) {
  for (std::uint64_t seed = 0; seed < 200; ++seed) {
    Rng a(seed), b(seed);
    const int n = 3 + static_cast<int>(seed % 30);
    const RawPolygon star = random_star(a, n, 5, 1, 2);
    EXPECT_EQ(star.outer, random_star(b, n, 5, 1, 2).outer);
    EXPECT_TRUE(is_valid(star)) << validity_defect(star);
    EXPECT_EQ(star.outer.size(), static_cast<std::size_t>(n));
    const RawPolygon comb = random_comb(a, n + 8, 10);
    EXPECT_TRUE(is_valid(comb)) << validity_defect(comb) << to_json({comb});
    const RawPolygon spiral = random_spiral(a, n + 8, 10);
    EXPECT_TRUE(is_valid(spiral)) << validity_defect(spiral) << to_json({spiral});
    const RawPolygon holed = with_random_holes(a, spiral, 3, 6);
    EXPECT_TRUE(is_valid(holed)) << validity_defect(holed) << to_json({holed});
    const RawPolygon grid = random_grid_polygon(a, 8, 12, true);
    EXPECT_TRUE(is_valid(grid)) << validity_defect(grid) << to_json({grid});
    for (const auto& c : {grid.outer}) {
      for (const auto& p : c) {
        EXPECT_EQ(p[0], std::floor(p[0]));
        EXPECT_GE(p[0], 0);
        EXPECT_LE(p[0], 8);
      }
    }
  }
}

TEST(Generators, HolesAreAdded) {
  int with_holes = 0;
  for (std::uint64_t seed = 0; seed < 50; ++seed) {
    Rng rng(seed);
    const RawPolygon p = with_random_holes(rng, random_star(rng, 12, 10), 3, 5);
    with_holes += !p.holes.empty();
  }
  EXPECT_GT(with_holes, 40);
}

// Grid polygons on one small grid meet degenerately in most cases.
TEST(Generators, GridDegeneraciesAreFrequent) {
  int shared = 0, on_edge = 0, overlap = 0, any = 0;
  const int n = 400;
  for (int seed = 0; seed < n; ++seed) {
    Rng rng(seed);
    const RawPolygon a = random_grid_polygon(rng, 8, 12, seed % 2 == 0);
    const RawPolygon b = random_grid_polygon(rng, 8, 12, seed % 3 == 0);
    const Degeneracies d = find_degeneracies(a, b);
    shared += d.shared_vertex;
    on_edge += d.vertex_on_edge;
    overlap += d.collinear_overlap;
    any += d.any();
  }
  std::printf("grid 8x8, %d pairs: shared vertex %d, vertex on edge %d, collinear overlap %d, any %d\n", n, shared,
              on_edge, overlap, any);
  EXPECT_GT(any, n * 3 / 4);
  EXPECT_GT(shared, n / 2);
  EXPECT_GT(on_edge, n / 2);
  EXPECT_GT(overlap, n / 3);
}

TEST(Validity, AcceptsAndRejects) {
  EXPECT_TRUE(is_valid(square(0, 0, 4, 4)));
  EXPECT_TRUE(is_valid(reversed(square(0, 0, 4, 4))));
  // Bow tie.
  EXPECT_FALSE(is_valid(RawPolygon{{{0, 0}, {2, 2}, {2, 0}, {0, 2}}, {}}));
  // Repeated vertex (a pinch).
  EXPECT_FALSE(is_valid(RawPolygon{{{0, 0}, {2, 0}, {1, 1}, {2, 2}, {0, 2}, {1, 1}}, {}}));
  // Zero-length edge, too few points, zero area, fold-back spike.
  EXPECT_FALSE(is_valid(RawPolygon{{{0, 0}, {2, 0}, {2, 0}, {0, 2}}, {}}));
  EXPECT_FALSE(is_valid(RawPolygon{{{0, 0}, {2, 0}}, {}}));
  EXPECT_FALSE(is_valid(RawPolygon{{{0, 0}, {1, 0}, {2, 0}}, {}}));
  EXPECT_FALSE(is_valid(RawPolygon{{{0, 0}, {2, 0}, {3, 0}, {1, 0}, {1, 2}}, {}}));
  // A straight-through vertex is fine.
  EXPECT_TRUE(is_valid(RawPolygon{{{0, 0}, {1, 0}, {2, 0}, {2, 2}}, {}}));

  RawPolygon p = square(0, 0, 8, 8);
  p.holes.push_back(box_contour({2, 2, 4, 4}));
  EXPECT_TRUE(is_valid(p));
  // Holes touching the outer contour at a vertex on an edge, and at a shared vertex.
  RawPolygon touch = square(0, 0, 8, 8);
  touch.holes.push_back({{4, 0}, {5, 2}, {3, 2}});
  touch.holes.push_back({{8, 8}, {6, 7}, {7, 6}});
  EXPECT_TRUE(is_valid(touch)) << validity_defect(touch);
  // Two holes touching at a point.
  RawPolygon two = square(0, 0, 8, 8);
  two.holes.push_back(box_contour({1, 1, 3, 3}));
  two.holes.push_back(box_contour({3, 3, 5, 5}));
  EXPECT_TRUE(is_valid(two)) << validity_defect(two);
  // Hole sharing an edge piece with the outer contour.
  RawPolygon along = square(0, 0, 8, 8);
  along.holes.push_back(box_contour({0, 2, 2, 4}));
  EXPECT_FALSE(is_valid(along));
  // Hole crossing the outer contour; hole outside; hole around the outer contour.
  RawPolygon cross = square(0, 0, 8, 8);
  cross.holes.push_back(box_contour({6, 6, 10, 10}));
  EXPECT_FALSE(is_valid(cross));
  RawPolygon outside = square(0, 0, 8, 8);
  outside.holes.push_back(box_contour({10, 10, 12, 12}));
  EXPECT_FALSE(is_valid(outside));
  RawPolygon around = square(2, 2, 4, 4);
  around.holes.push_back(box_contour({0, 0, 8, 8}));
  EXPECT_FALSE(is_valid(around));
  // A hole leaving the outer contour between two boundary points (concave outer).
  RawPolygon notch{{{0, 0}, {8, 0}, {8, 8}, {4, 4}, {0, 8}}, {}};
  RawPolygon leak = notch;
  leak.holes.push_back({{2, 6}, {6, 6}, {4, 2}});  // (2,6),(6,6) on the notch edges, edge between them outside
  EXPECT_FALSE(is_valid(leak)) << "hole edge between boundary points runs outside";
  // Overlapping holes; nested holes; holes sharing an edge.
  RawPolygon overlap = square(0, 0, 8, 8);
  overlap.holes.push_back(box_contour({1, 1, 4, 4}));
  overlap.holes.push_back(box_contour({3, 3, 6, 6}));
  EXPECT_FALSE(is_valid(overlap));
  RawPolygon nested = square(0, 0, 8, 8);
  nested.holes.push_back(box_contour({1, 1, 6, 6}));
  nested.holes.push_back(box_contour({2, 2, 3, 3}));
  EXPECT_FALSE(is_valid(nested));
  RawPolygon shared = square(0, 0, 8, 8);
  shared.holes.push_back(box_contour({1, 1, 3, 3}));
  shared.holes.push_back(box_contour({3, 1, 5, 3}));
  EXPECT_FALSE(is_valid(shared));
  // A hole through a vertex of another hole, crossing it.
  RawPolygon through = square(0, 0, 8, 8);
  through.holes.push_back(box_contour({1, 1, 3, 3}));
  through.holes.push_back({{2, 2}, {5, 4}, {4, 5}});
  EXPECT_FALSE(is_valid(through));
}

TEST(Oracle, BooleanOperations) {
  const ExactRegion a = ExactRegion::from(square(0, 0, 4, 4)), b = ExactRegion::from(square(2, 2, 6, 6));
  EXPECT_EQ(a.intersection(b).twice_area(), 8);
  EXPECT_EQ(a.difference(b).twice_area(), 24);
  EXPECT_EQ(a.join(b).twice_area(), 56);
  EXPECT_FALSE(same_region(a, b));
  EXPECT_TRUE(same_region(a, ExactRegion::from(reversed(square(0, 0, 4, 4)))));
  // A polygon with holes touching its outer contour, as a region: outer minus holes.
  RawPolygon touch = square(0, 0, 8, 8);
  touch.holes.push_back({{4, 0}, {5, 2}, {3, 2}});
  touch.holes.push_back({{8, 8}, {6, 7}, {7, 6}});
  const ExactRegion t = ExactRegion::from(touch);
  EXPECT_EQ(t.twice_area(), twice_area(to_exact(touch)));
  EXPECT_EQ(t.twice_area(), 128 - 4 - 3);
  // The union of pieces equals the region they tile.
  std::vector<EPolygon> pieces{to_exact(square(0, 0, 2, 4)), to_exact(square(2, 0, 4, 4))};
  EXPECT_TRUE(same_region(ExactRegion::from(pieces), a));
  EXPECT_EQ(ExactRegion::from(pieces).polygon_count(), 1u);
}

TEST(Conversions, CgalPolygonWithHolesIsValidForCgal) {
  // Holes touching the outer contour inside its edges and each other: after the split, CGAL's own
  // validity check accepts the polygon, and it is the same region.
  RawPolygon touch = reversed(square(0, 0, 8, 8));
  touch.holes.push_back({{4, 0}, {5, 2}, {3, 2}});
  touch.holes.push_back({{8, 8}, {6, 7}, {7, 6}});
  touch.holes.push_back({{5, 2}, {6, 4}, {4, 4}});
  ASSERT_TRUE(is_valid(touch)) << validity_defect(touch);
  const CgalPolygonWithHoles pwh = to_cgal_polygon(touch);
  CGAL::Gps_segment_traits_2<EK> traits;
  EXPECT_TRUE(CGAL::is_valid_polygon_with_holes(pwh, traits));
  EXPECT_EQ(pwh.outer_boundary().size(), 5u);  // split at (4, 0); (8, 8) is a corner already
  CgalPolygonSet set(pwh);
  EXPECT_TRUE(same_region(ExactRegion(std::make_shared<const ExactRegion::Impl>(ExactRegion::Impl{set})),
                          ExactRegion::from(touch)));
  // Clipper polygons to a CGAL polygon set.
  clip::LineTable<ExactKernel> lines;
  clip::Polygon<ExactKernel> p;
  ASSERT_FALSE(to_clip_polygon<ExactKernel>(touch, lines, p).has_value());
  std::vector<clip::Polygon<ExactKernel>> ps{p};
  const CgalPolygonSet from_clip = to_cgal_set<ExactKernel>(ps);
  EXPECT_EQ(from_clip.number_of_polygons_with_holes(), 1u);
}

TEST(Conversions, ClipPolygonKeepsInputEdgesAsLines) {
  clip::LineTable<ExactKernel> lines;
  clip::Polygon<ExactKernel> p;
  RawPolygon raw = reversed(square(0, 0, 4, 4));
  raw.holes.push_back(box_contour({1, 1, 2, 2}));
  EXPECT_FALSE(to_clip_polygon<ExactKernel>(raw, lines, p).has_value());
  EXPECT_EQ(lines.size(), 8u);
  const EPolygon e = to_exact<ExactKernel>(p);
  EXPECT_FALSE(polygon_defect(e, true).has_value()) << *polygon_defect(e, true);
  for (std::size_t i = 0; i < p.outer.size(); ++i) {
    const auto& l = lines[p.outer.lines[i]];
    EXPECT_TRUE(segment_within(l.a, l.b, p.outer.points[i], p.outer.points[(i + 1) % p.outer.size()]));
  }
}

}  // namespace
}  // namespace hlr::testing
