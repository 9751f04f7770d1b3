// Tests of circle and arc recovery (export/src/curves.cpp, hlr/export/curves.hpp): tessellated
// circles at 8 to 256 segments come back as circles within the resolution, anything that is not
// a tessellated circle (one vertex off it, an ellipse, a hexagon, a straight run) stays a polyline,
// and the pieces of a partly hidden circle become arcs of their own class.
#include <hlr/export/curves.hpp>
#include <hlr/export/lines.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace {

using namespace hlr::exporter;

constexpr double pi = 3.14159265358979323846;

// A regular n-gon round (cx, cy) from angle `phase`, counter-clockwise unless `cw`.
std::vector<Point2> polygon(double cx, double cy, double r, int n, double phase = 0, bool cw = false) {
  std::vector<Point2> p;
  for (int k = 0; k < n; ++k) {
    const double a = phase + (cw ? -1 : 1) * 2 * pi * k / n;
    p.push_back({cx + r * std::cos(a), cy + r * std::sin(a)});
  }
  return p;
}

DrawingPolyline closed(std::vector<Point2> points, bool visible = true) { return {std::move(points), true, visible, 0}; }
DrawingPolyline open(std::vector<Point2> points, bool visible = true) { return {std::move(points), false, visible, 0}; }

std::size_t arc_steps(const DrawingCurves& c) {
  std::size_t n = 0;
  for (const auto& p : c.paths)
    for (const auto& s : p.steps) n += s.arc;
  return n;
}

TEST(Curves, TessellatedCirclesComeBackWithinTheResolution) {
  std::mt19937 random(15);
  std::uniform_real_distribution<double> unit(0, 1);
  const double tol = 0.01;
  for (int n : {8, 12, 16, 24, 32, 48, 64, 100, 128, 256}) {
    for (int trial = 0; trial < 6; ++trial) {
      const double cx = -500 + 1000 * unit(random), cy = -500 + 1000 * unit(random);
      const double r = 0.5 * std::pow(400.0, unit(random));  // 0.5 to 200
      const bool cw = trial % 2 == 1;
      const DrawingCurves c = recover_curves({closed(polygon(cx, cy, r, n, 2 * pi * unit(random), cw))}, tol);
      SCOPED_TRACE(testing::Message() << n << " segments, r " << r);
      ASSERT_EQ(c.circles.size(), 1u);
      EXPECT_TRUE(c.paths.empty());
      EXPECT_LE(std::hypot(c.circles[0].centre[0] - cx, c.circles[0].centre[1] - cy), tol);
      EXPECT_LE(std::abs(c.circles[0].radius - r), tol);
      EXPECT_TRUE(c.circles[0].visible);
    }
  }
}

TEST(Curves, OneVertexOffByMoreThanTheResolutionStaysAPolyline) {
  const double tol = 0.01;
  for (int n : {8, 32, 256}) {
    SCOPED_TRACE(n);
    auto p = polygon(10, 20, 5, n);
    const double a = 2 * pi * 3 / n;
    p[3] = {10 + (5 + 2 * tol) * std::cos(a), 20 + (5 + 2 * tol) * std::sin(a)};  // 0.02 out
    const DrawingCurves off = recover_curves({closed(p)}, tol);
    EXPECT_TRUE(off.circles.empty());
    EXPECT_EQ(arc_steps(off), 0u);
    ASSERT_EQ(off.paths.size(), 1u);
    EXPECT_EQ(off.paths[0].steps.size(), std::size_t(n - 1));  // the polygon as it is
    EXPECT_TRUE(off.paths[0].closed);
    // Within the resolution it is a circle.
    p[3] = {10 + (5 + 0.5 * tol) * std::cos(a), 20 + (5 + 0.5 * tol) * std::sin(a)};
    EXPECT_EQ(recover_curves({closed(p)}, tol).circles.size(), 1u);
  }
}

TEST(Curves, AnOddVertexOnAnOpenRunIsNoArcOfItsOwn) {
  // Three quarters of a 32-gon, open, with vertex 12 off by 0.02: no arc of a circle bent to take
  // it in (two such arcs would meet there, smoothly, on different circles); the odd vertex stays
  // where it is.
  auto p = polygon(0, 0, 5, 32);
  p.resize(25);
  const double a = 2 * pi * 12 / 32;
  p[12] = {5.02 * std::cos(a), 5.02 * std::sin(a)};
  const DrawingCurves c = recover_curves({open(p)}, 0.01);
  ASSERT_EQ(c.paths.size(), 1u);
  bool kept = false;
  for (const auto& s : c.paths[0].steps) {
    kept |= s.to == p[12];
    if (s.arc) {
      EXPECT_LE(std::hypot(s.centre[0], s.centre[1]), 0.01);
      EXPECT_LE(std::abs(s.radius - 5), 0.01);
    }
  }
  EXPECT_TRUE(kept);
  // Without it, the run is one arc.
  p[12] = {5 * std::cos(a), 5 * std::sin(a)};
  EXPECT_EQ(recover_curves({open(p)}, 0.01).arcs, 1u);
}

TEST(Curves, PolygonsEllipsesAndLinesAreNotCircles) {
  const double tol = 0.01;
  // Regular polygons of fewer than 8 sides have all their vertices on a circle.
  for (int n : {3, 4, 5, 6, 7}) EXPECT_TRUE(recover_curves({closed(polygon(0, 0, 10, n))}, tol).circles.empty()) << n;
  // A circle seen at a slant (the iso view): vertices near a circle over a few steps, but uneven.
  for (int n : {32, 48, 64, 128}) {
    std::vector<Point2> ellipse;
    for (const auto& p : polygon(0, 0, 6, n)) ellipse.push_back({p[0], p[1] * std::cos(54.7356 * pi / 180)});
    const DrawingCurves c = recover_curves({closed(ellipse)}, tol);
    EXPECT_TRUE(c.circles.empty()) << n;
    EXPECT_EQ(arc_steps(c), 0u) << n;
  }
  // A straight run, one bent within the tolerance, and a zigzag whose vertices lie on a circle.
  std::vector<Point2> line, bent, zigzag;
  for (int k = 0; k < 20; ++k) line.push_back({double(k), 0}), bent.push_back({double(k), 0.009 * std::sin(k)});
  for (int k = 0; k < 12; ++k) zigzag.push_back(polygon(0, 0, 10, 36)[(k % 2) * 2 + k * 3 % 36]);
  for (const auto& chain : {line, bent, zigzag}) EXPECT_EQ(arc_steps(recover_curves({open(chain)}, tol)), 0u);
}

TEST(Curves, APartlyHiddenCircleBecomesArcsOfEachClass) {
  // A 32-gon of radius 8 hidden from 40 to 130 degrees: the class changes in the middle of
  // segments (at the points where an occluding edge crosses them), as the engine splits lines.
  const int n = 32;
  const double r = 8, tol = 0.01;
  const auto p = polygon(3, -4, r, n);
  auto on_chord = [&](double degrees) {  // the point of the polygon at that angle
    const double a = degrees * pi / 180, step = 2 * pi / n;
    const int k = int(std::floor(a / step));
    const Point2 &u = p[k % n], &v = p[(k + 1) % n];
    // where the ray at angle a meets chord u v
    const double dx = std::cos(a), dy = std::sin(a);
    const double ex = v[0] - u[0], ey = v[1] - u[1];
    const double t = ((u[0] - 3) * dy - (u[1] + 4) * dx) / (ey * dx - ex * dy);
    return Point2{u[0] + t * ex, u[1] + t * ey};
  };
  std::vector<Point2> hidden{on_chord(40)}, visible{on_chord(130)};
  for (int k = 0; k < n; ++k) {
    const double a = 360.0 * k / n;
    if (a > 40 && a < 130) hidden.push_back(p[k]);
  }
  hidden.push_back(on_chord(130));
  for (int k = 0; k < 2 * n; ++k) {
    const double a = 360.0 * k / n;
    if (a > 130 && a < 400) visible.push_back(p[k % n]);
  }
  visible.push_back(on_chord(40));
  const DrawingCurves c = recover_curves({open(visible, true), open(hidden, false)}, tol);
  EXPECT_TRUE(c.circles.empty());
  ASSERT_EQ(c.paths.size(), 2u);
  EXPECT_EQ(c.arcs, 2u);
  for (const auto& path : c.paths) {
    SCOPED_TRACE(path.visible ? "visible" : "hidden");
    ASSERT_EQ(path.steps.size(), 1u);  // one arc from end to end, the chord ends included
    const PathStep& arc = path.steps[0];
    EXPECT_TRUE(arc.arc);
    EXPECT_TRUE(arc.ccw);
    EXPECT_LE(std::hypot(arc.centre[0] - 3, arc.centre[1] + 4), tol);
    EXPECT_LE(std::abs(arc.radius - r), tol);
    // It starts and ends where the class changes (moved onto the circle).
    const double start = std::atan2(path.start[1] + 4, path.start[0] - 3) * 180 / pi;
    const double end = std::atan2(arc.to[1] + 4, arc.to[0] - 3) * 180 / pi;
    EXPECT_NEAR(start, path.visible ? 130 : 40, 1e-6);
    EXPECT_NEAR(end, path.visible ? 40 : 130, 1e-6);
  }
  EXPECT_TRUE(c.paths[0].visible);
  EXPECT_FALSE(c.paths[1].visible);
  // The two arcs go round once: one circle face-on, one pair of centre marks.
  const auto faces = face_on_circles(c, tol);
  ASSERT_EQ(faces.size(), 1u);
  EXPECT_EQ(centre_marks(c, tol, 3).size(), 2u);
  // A piece of a circle alone has no centre mark.
  EXPECT_TRUE(centre_marks(recover_curves({open(hidden, false)}, tol), tol, 3).empty());
}

TEST(Curves, ASlotIsTwoArcsAndTwoLines) {
  // Two half circles of radius 5 joined by lines 20 long, as one closed chain.
  std::vector<Point2> slot;
  for (int k = 0; k <= 16; ++k) slot.push_back({20 + 5 * std::sin(pi * k / 16), 5 * std::cos(pi * k / 16)});
  for (int k = 0; k <= 16; ++k) slot.push_back({-5 * std::sin(pi * k / 16), -5 * std::cos(pi * k / 16)});
  const DrawingCurves c = recover_curves({closed(slot)}, 0.01);
  EXPECT_TRUE(c.circles.empty());
  ASSERT_EQ(c.paths.size(), 1u);
  EXPECT_TRUE(c.paths[0].closed);
  EXPECT_EQ(c.arcs, 2u);
  std::size_t lines = 0;
  for (const auto& s : c.paths[0].steps) lines += !s.arc;
  EXPECT_EQ(lines, 2u);
  EXPECT_TRUE(face_on_circles(c, 0.01).empty());  // half circles: no centre marks
}

TEST(Curves, ConcentricCirclesShareTheMarksOfTheLargest) {
  const DrawingCurves c =
      recover_curves({closed(polygon(0, 0, 10, 48)), closed(polygon(0, 0, 4, 32), false), closed(polygon(30, 0, 2, 16))}, 0.01);
  ASSERT_EQ(c.circles.size(), 3u);
  EXPECT_FALSE(c.circles[1].visible);
  const auto marks = centre_marks(c, 0.01, 3);
  ASSERT_EQ(marks.size(), 4u);
  EXPECT_NEAR(marks[0].a[0], -13, 1e-9);
  EXPECT_NEAR(marks[0].b[0], 13, 1e-9);
  EXPECT_NEAR(marks[3].a[1], -5, 1e-9);
}

TEST(Curves, NoToleranceNoCurves) {
  const DrawingCurves c = recover_curves({closed(polygon(0, 0, 10, 64))}, 0);
  EXPECT_TRUE(c.circles.empty());
  ASSERT_EQ(c.paths.size(), 1u);
  EXPECT_EQ(c.paths[0].steps.size(), 63u);
}

TEST(Curves, SheetLinesRecoverAtTheSheetsResolution) {
  // A 64-gon of radius 10: at 1:1 its vertices are 0.01 mm on the sheet apart from the circle
  // only if they are on it; one vertex 0.05 off is a polygon at 1:1 and a circle at 1:10.
  auto p = polygon(0, 0, 10, 64);
  p[5][0] += 0.05;
  LineDrawing d;
  for (std::size_t k = 0; k < p.size(); ++k) d.segments.push_back({p[k], p[(k + 1) % p.size()], true, 0});
  DrawingStyle style{*sheet_by_name("A4"), std::nullopt, true};
  EXPECT_EQ(sheet_lines_at(d, style, 1.0).curves.circles.size(), 0u);
  EXPECT_EQ(sheet_lines_at(d, style, 0.1).curves.circles.size(), 1u);
  style.circles = false;
  EXPECT_EQ(sheet_lines_at(d, style, 0.1).curves.circles.size(), 0u);
  style.circles = true;
  style.centre_lines = false;
  EXPECT_TRUE(sheet_lines_at(d, style, 0.1).centre_lines.empty());
}

}  // namespace
