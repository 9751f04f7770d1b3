// The judge must catch what it is there to catch: a hand-made correct answer passes, and each
// kind of wrong answer gets its verdict. (Tests the test harness, not the clipper.)
#include "clip_harness.hpp"

#include <cell_oracle.hpp>

#include <cstdio>

#include <gtest/gtest.h>

namespace hlr::testing {
namespace {

RawPolygon square(double x0, double y0, double x1, double y1) { return {box_contour({x0, y0, x1, y1}), {}}; }

// Subject [0,4]^2 (lines 0..3), clip [2,6]^2 (lines 4..7): the correct answer by hand.
struct Fixture {
  RawPolygon subject = square(0, 0, 4, 4), clip = square(2, 2, 6, 6);
  ExactOutput out;
  Fixture() {
    auto line = [&](double ax, double ay, double bx, double by) { out.lines.emplace_back(EPoint(ax, ay), EPoint(bx, by)); };
    line(0, 0, 4, 0), line(4, 0, 4, 4), line(4, 4, 0, 4), line(0, 4, 0, 0);
    line(2, 2, 6, 2), line(6, 2, 6, 6), line(6, 6, 2, 6), line(2, 6, 2, 2);
    ExactOutputPolygon in;
    in.polygon.outer = {EPoint(2, 2), EPoint(4, 2), EPoint(4, 4), EPoint(2, 4)};
    in.lines = {{4, 1, 2, 7}};
    in.kernel_twice_area = EFT(8);
    out.inside.push_back(in);
    ExactOutputPolygon o;
    o.polygon.outer = {EPoint(0, 0), EPoint(4, 0), EPoint(4, 2), EPoint(2, 2), EPoint(2, 4), EPoint(0, 4)};
    o.lines = {{0, 1, 4, 7, 2, 3}};
    o.kernel_twice_area = EFT(24);
    out.outside.push_back(o);
  }
  Verdict verdict() const { return judge(subject, clip, out, JudgeOptions{}).verdict; }
};

TEST(Judge, AcceptsTheRightAnswer) {
  Fixture f;
  const Evaluation e = judge(f.subject, f.clip, f.out, JudgeOptions{});
  EXPECT_TRUE(e.ok()) << e.message;
}

TEST(Judge, CatchesWrongAnswers) {
  {
    Fixture f;  // a missing piece
    f.out.inside.clear();
    EXPECT_EQ(f.verdict(), Verdict::wrong_result);
  }
  {
    Fixture f;  // wrong orientation
    std::reverse(f.out.inside[0].polygon.outer.begin(), f.out.inside[0].polygon.outer.end());
    EXPECT_EQ(f.verdict(), Verdict::invalid_output);
  }
  {
    Fixture f;  // a line id out of the table
    f.out.inside[0].lines[0][0] = 99;
    EXPECT_EQ(f.verdict(), Verdict::invalid_output);
  }
  {
    Fixture f;  // an edge naming the wrong line
    f.out.inside[0].lines[0][0] = 0;
    EXPECT_EQ(f.verdict(), Verdict::bad_provenance);
  }
  {
    Fixture f;  // an edge on the right line but beyond the input edge's ends
    f.out.lines[4] = {EPoint(3, 2), EPoint(6, 2)};
    EXPECT_EQ(f.verdict(), Verdict::bad_provenance);
  }
  {
    Fixture f;  // the inside piece twice: same union, but areas do not add up
    f.out.inside.push_back(f.out.inside[0]);
    EXPECT_EQ(f.verdict(), Verdict::bad_area);
  }
  {
    Fixture f;  // twice_area from the kernel disagrees
    f.out.inside[0].kernel_twice_area = EFT(7);
    EXPECT_EQ(f.verdict(), Verdict::bad_area);
  }
  {
    Fixture f;  // a repeated vertex (pinched contour)
    f.out.outside[0].polygon.outer.insert(f.out.outside[0].polygon.outer.begin() + 3, EPoint(4, 2));
    f.out.outside[0].lines[0].insert(f.out.outside[0].lines[0].begin() + 3, 4);
    EXPECT_EQ(f.verdict(), Verdict::invalid_output);
  }
  {
    Fixture f;  // a zero-area sliver piece
    ExactOutputPolygon s;
    s.polygon.outer = {EPoint(0, 0), EPoint(1, 0), EPoint(2, 0)};
    s.lines = {{0, 0, 0}};
    f.out.outside.push_back(s);
    EXPECT_EQ(f.verdict(), Verdict::invalid_output);
  }
  {
    Fixture f;  // a hole outside its outer contour
    f.out.inside[0].polygon.holes.push_back({EPoint(10, 10), EPoint(10, 11), EPoint(11, 10)});
    f.out.inside[0].lines.push_back({0, 0, 0});
    EXPECT_EQ(f.verdict(), Verdict::invalid_output);
  }
}

// A case where CGAL 5.5.1's Boolean operations are wrong (found by the GridHolesSubject property):
// the subject's hole touches its outer contour at (5, 2), inside the hole's edge x = 5, and the clip
// has a vertex there too. The notch (4, 3), (4, 4), (9/2, 3) lies in the subject and not in the
// clip, but CGAL's S − C leaves it out. The cell oracle decides; the clipper's answer is right.
TEST(Judge, CgalBooleanOperationsBug) {
  const RawPolygon subject{{{6, 0}, {5, 2}, {7, 4}, {5, 7}, {1, 3}}, {{{5, 1}, {5, 3}, {2, 3}}}};
  const RawPolygon clip{{{3, 3}, {4, 5}, {5, 2}, {4, 4}, {4, 3}}, {}};
  const EPoint notch(4.125, 3.25);
  EXPECT_TRUE(strictly_inside(to_exact(subject), notch));
  EXPECT_FALSE(strictly_inside(to_exact(clip), notch));
  const Evaluation e = evaluate<ExactKernel>(subject, clip);
  EXPECT_TRUE(e.ok()) << e.message;
  if (e.oracle_disagreement) std::printf("CGAL's Boolean operations are still wrong here: %s\n", e.message.c_str());
}

// The clipper itself on the fixture, through the same path the properties use.
TEST(Judge, ClipperOnTheFixture) {
  Fixture f;
  const Evaluation e = evaluate<ExactKernel>(f.subject, f.clip);
  EXPECT_TRUE(e.ok()) << e.message;
  EXPECT_EQ(e.inside_pieces, 1u);
  EXPECT_EQ(e.outside_pieces, 1u);
}

}  // namespace
}  // namespace hlr::testing
