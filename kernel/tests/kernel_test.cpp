// The traits interface answers the same on every kernel where the answer is representable, and
// the exact kernel keeps what double rounds away.
#include <hlr/kernel/kernel.hpp>
#include <hlr/kernel/double_orientation.hpp>
#include <hlr/kernel/exact_output.hpp>
#include <hlr/kernel/line_box.hpp>
#include <hlr/kernel/line_parameters.hpp>
#include <hlr/kernel/plane_side.hpp>
#include <hlr/kernel/view_predicates.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <algorithm>
#include <thread>
#include <optional>

namespace hlr {
namespace {

template <class K>
class GeometryTest : public ::testing::Test {};
using Kernels = ::testing::Types<ExactKernel, EpickKernel, DoubleKernel>;
TYPED_TEST_SUITE(GeometryTest, Kernels);

TYPED_TEST(GeometryTest, PredicatesOnRepresentableInput) {
  using G = Geometry<TypeParam>;
  auto a = G::point(0, 0), b = G::point(2, 0), c = G::point(1, 1), d = G::point(1, -1);
  EXPECT_EQ(G::orientation(a, b, c), 1);
  EXPECT_EQ(G::orientation(a, b, d), -1);
  EXPECT_EQ(G::orientation(a, b, G::point(5, 0)), 0);
  EXPECT_EQ(G::compare_xy(a, b), -1);
  EXPECT_EQ(G::compare_xy(G::point(1, 2), G::point(1, 1)), 1);
  EXPECT_TRUE(G::equal(G::point(1, 1), c));
  auto x = G::line_intersection(a, G::point(2, 2), G::point(0, 2), b);
  EXPECT_TRUE(G::equal(x, G::point(1, 1)));
  EXPECT_THROW(G::line_intersection(a, b, c, G::point(2, 1)), std::runtime_error);
}

TEST(ExactKernel, IntersectionsAreExactRationals) {
  using G = Geometry<ExactKernel>;
  // Lines y = x / 3 and x = 1 meet at (1, 1/3), which no double holds.
  auto p = G::line_intersection(G::point(0, 0), G::point(3, 1), G::point(1, -5), G::point(1, 5));
  EXPECT_EQ(G::exact_string(G::x(p)), "1");
  EXPECT_EQ(G::exact_string(G::y(p)), "1/3");
  // The point lies exactly on the line it came from.
  EXPECT_EQ(G::orientation(G::point(0, 0), G::point(3, 1), p), 0);
}

TEST(DoubleKernel, RoundsWhereExactDoesNot) {
  using D = Geometry<DoubleKernel>;
  auto p = D::line_intersection(D::point(0, 0), D::point(3, 1), D::point(1, -5), D::point(1, 5));
  // 1/3 rounded: the double kernel's point is off the line (or on it only by luck of rounding).
  EXPECT_EQ(D::exact_string(D::y(p)), "6004799503160661/18014398509481984");
}

TEST(Kernel, NamesRoundTrip) {
  for (auto kind : {KernelKind::exact, KernelKind::epick, KernelKind::floating}) {
    KernelKind parsed;
    ASSERT_TRUE(parse_kernel_kind(kernel_name(kind), parsed));
    EXPECT_EQ(parsed, kind);
  }
  KernelKind k;
  EXPECT_FALSE(parse_kernel_kind("float", k));
}

}  // namespace
}  // namespace hlr

namespace hlr {
namespace {

TEST(ExactKernel, ToDoubleRoundsToNearest) {
  using G = Geometry<ExactKernel>;
  // 13/6 lies between 2.1666666666666665 and 2.166666666666667; the first is nearer.
  auto p = G::line_intersection(G::point(0, 0), G::point(6, 13), G::point(1, -5), G::point(1, 5));
  EXPECT_EQ(G::to_double(G::y(p)), 2.1666666666666665);
  EXPECT_EQ(G::to_double(ExactKernel::FT(0.1)), 0.1);
}

}  // namespace
}  // namespace hlr

namespace hlr {
namespace {

// The shortcuts of the exact traits (identical points, interval filters) against CGAL's exact
// evaluation, on random values and on values snapped to a coarse grid (zeros and ties in most
// draws), near the origin and far from it, and of mixed magnitude (1e-9 next to 1e9).
TEST(ExactKernel, FilteredShortcutsAgreeWithExactEvaluation) {
  using G = Geometry<ExactKernel>;
  using FT = ExactKernel::FT;
  std::mt19937_64 random(20261202);
  std::uniform_real_distribution<double> unit(-1, 1);
  auto value = [&](int mode) {
    switch (mode) {
      case 0: return unit(random);
      case 1: return std::round(unit(random) * 4) / 4;                       // coarse grid
      case 2: return 1e9 + std::round(unit(random) * 8);                     // far from the origin
      default: return unit(random) < 0 ? unit(random) * 1e-9 : unit(random) * 1e9;  // mixed magnitude
    }
  };
  std::size_t zeros = 0;
  for (int i = 0; i < 20000; ++i) {
    const int mode = i % 4;
    // Constructed numbers (a quotient, a difference), as planes and view points are.
    const FT a = FT(value(mode)) / FT(3), b = FT(value(mode)) - FT(value(mode)), c = FT(value(mode));
    const FT x = FT(value(mode)), y = FT(value(mode));
    const FT z = mode == 1 && i % 8 == 1 ? a * x + b * y + c : FT(value(mode));  // a tie now and then
    const int want = CGAL::sign(CGAL::exact(a) * CGAL::exact(x) + CGAL::exact(b) * CGAL::exact(y) + CGAL::exact(c) -
                                CGAL::exact(z));
    ASSERT_EQ(G::sign_above(a, b, c, x, y, z), want) << i;
    zeros += want == 0;

    const auto p = G::point(value(mode), value(mode)), q = G::point(value(mode), value(mode));
    // The same point object, a constructed point on the line (collinear, not a single double), or
    // a point of two doubles.
    const auto r = i % 3 == 0 ? p : i % 3 == 1 ? G::midpoint(p, q) : G::point(value(mode), value(mode));
    ASSERT_EQ(G::orientation(p, q, r), static_cast<int>(CGAL::orientation(p, q, r))) << i;
    ASSERT_EQ(G::equal(p, r), p == r) << i;
    // Three points of doubles on one line (2q - p is exact on the grids), decided on the doubles.
    if (mode == 1 || mode == 2) {
      const double px = value(mode), py = value(mode), qx = value(mode), qy = value(mode);
      const auto s = G::point(px, py), t = G::point(qx, qy), u = G::point(2 * qx - px, 2 * qy - py);
      ASSERT_EQ(G::orientation(s, t, u), static_cast<int>(CGAL::orientation(s, t, u))) << i;
      ASSERT_EQ(G::orientation(s, t, u), 0) << i;
    }
  }
  EXPECT_GT(zeros, 100u) << "the draws must hit ties";
}

// The double filter in front of CGAL's orientation (interval_orientation.hpp) on points whose
// intervals have width (crossings of lines), where its error bound matters: a decided sign must be
// the exact one, on crossings exactly on a line (orientation 0), nudged off it by an ulp, far from
// the origin and of mixed magnitude; and it must decide the ordinary cases itself.
TEST(ExactKernel, IntervalOrientationFilterIsExactWhereItDecides) {
  using G = Geometry<ExactKernel>;
  std::mt19937_64 random(20261203);
  std::uniform_real_distribution<double> unit(-1, 1);
  auto value = [&](int mode) {
    switch (mode) {
      case 0: return unit(random);
      case 1: return std::round(unit(random) * 4) / 4;                              // coarse grid
      case 2: return 1e8 + unit(random);                                            // far from the origin
      default: return unit(random) < 0 ? unit(random) * 1e-9 : unit(random) * 1e9;  // mixed magnitude
    }
  };
  auto random_point = [&](int mode) { return G::point(value(mode), value(mode)); };
  // Whether the lines through a, b and c, d cross (are not parallel), decided before constructing
  // their crossing: the construction throws on parallel lines, from within a lazy evaluation.
  auto cross = [](const auto& a, const auto& b, const auto& c, const auto& d) {
    return a != b && c != d && !CGAL::is_zero(CGAL::determinant(b - a, d - c));
  };
  // A constructed point: the crossing of two random lines.
  auto crossing = [&](int mode) {
    for (;;) {
      const auto a = random_point(mode), b = random_point(mode), c = random_point(mode), d = random_point(mode);
      if (cross(a, b, c, d)) return G::line_intersection(a, b, c, d);
    }
  };
  // A constructed point exactly on the line through p and q: its crossing with another line.
  auto on_line = [&](const ExactKernel::Point_2& p, const ExactKernel::Point_2& q, int mode) {
    for (;;) {
      const auto c = random_point(mode), d = crossing(mode);
      if (cross(p, q, c, d)) return G::line_intersection(p, q, c, d);
    }
  };
  std::size_t decided = 0, zeros = 0, ordinary = 0, ordinary_decided = 0;
  for (int i = 0; i < 8000; ++i) {
    const int mode = i % 4;
    const auto p = crossing(mode);
    auto q = crossing(mode);
    while (q == p) q = crossing(mode);  // the grid repeats crossings
    ExactKernel::Point_2 r;
    switch (i / 4 % 3) {
      case 0: r = crossing(mode); break;                                         // ordinary
      case 1: r = on_line(p, q, mode); break;                                    // on the line pq
      default: {                                                                 // an ulp off it
        const auto on = on_line(p, q, mode);
        const double x = CGAL::to_double(on.x());
        r = G::point(std::nextafter(x, HUGE_VAL), CGAL::to_double(on.y()));
      }
    }
    const int want = static_cast<int>(CGAL::orientation(CGAL::exact(p), CGAL::exact(q), CGAL::exact(r)));
    const int got = orientation_of_intervals(CGAL::approx(p), CGAL::approx(q), CGAL::approx(r));
    zeros += want == 0;
    if (got != 2) {
      ++decided;
      ASSERT_EQ(got, want) << i;
    }
    ASSERT_EQ(G::orientation(p, q, r), want) << i;
    if (i / 4 % 3 == 0 && mode != 3) {
      ++ordinary;
      ordinary_decided += got != 2;
    }
  }
  EXPECT_GT(zeros, 1000u) << "the draws must hit exact zeros";
  EXPECT_GT(decided, 2000u);
  EXPECT_GT(ordinary_decided, ordinary * 99 / 100) << "the filter must settle what is far from degenerate";
}

// A random double of the kinds that break predicates, by mode: 0 plain, 1 on a coarse grid (exact
// zeros and ties), 2 far from the origin (on a grid there), 3 of mixed magnitude.
double hard_value(std::mt19937_64& random, int mode) {
  std::uniform_real_distribution<double> unit(-1, 1);
  switch (mode) {
    case 0: return unit(random);
    case 1: return std::round(unit(random) * 2) / 2;
    case 2: return 1e8 + std::round(unit(random) * 4);
    default: return unit(random) < 0 ? unit(random) * 1e-9 : unit(random) * 1e9;
  }
}

// Crossings of lines through points of doubles keep their lines (crossing_point.hpp): orientations
// and comparisons of them and of points of doubles are decided from those doubles where the
// intervals cannot decide. Against rationals made from the same doubles without the crossings'
// reps: three crossings on one line (exact zeros), ties of coordinates on a grid, far from the
// origin and of mixed magnitude; crossings of crossings take the general path and must agree too.
// Half the draws take image points of input points in a general view (iso and random directions)
// instead of points of doubles, which keep their coordinates (CoordinatePointRep); every point's
// rounded coordinates (G::to_double(p, axis)) must be the nearest doubles of the exact ones.
TEST(ExactKernel, CrossingsDecideFromTheirLinesDoubles) {
  using G = Geometry<ExactKernel>;
  using EK = ExactKernel::Exact_kernel;
  using Q = EK::FT;
  std::mt19937_64 random(20261207);
  std::uniform_real_distribution<double> unit(-1, 1);
  struct Drawn {
    ExactKernel::Point_2 point;
    EK::Point_2 exact;  // made from the doubles in rationals, apart from the point's rep
    int kind;           // 0 a point of doubles or an input point's image, 1 a crossing of lines through such points, 2 other
  };
  std::optional<ViewFrame<ExactKernel>> frame;  // set: points are images of input points
  std::array<Q, 3> rows[2];                      // the frame's X and Y in rationals
  auto double_point = [&](int mode) {
    if (!frame) {
      const double x = hard_value(random, mode), y = hard_value(random, mode);
      return Drawn{G::point(x, y), EK::Point_2(x, y), 0};
    }
    const Vec3 p{hard_value(random, mode), hard_value(random, mode), hard_value(random, mode)};
    const auto v = frame->to_view(p);
    Q c[2];
    for (int k = 0; k < 2; ++k) c[k] = rows[k][0] * Q(p[0]) + rows[k][1] * Q(p[1]) + rows[k][2] * Q(p[2]);
    return Drawn{G::point(v.x, v.y), EK::Point_2(c[0], c[1]), 0};
  };
  auto set_frame = [&](int i, int mode) {
    frame.reset();
    if (i % 8 < 4) return;
    View view;
    do {
      if (i % 2) named_view("iso", view);
      else view.direction = {hard_value(random, mode), hard_value(random, mode), hard_value(random, mode)},
           view.up = {unit(random), unit(random), unit(random)};
    } while (view_defect(view));
    frame.emplace(view);
    auto cross = [](const std::array<Q, 3>& a, const std::array<Q, 3>& b) {
      return std::array<Q, 3>{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    };
    const std::array<Q, 3> d{view.direction[0], view.direction[1], view.direction[2]};
    rows[0] = cross(d, {Q(view.up[0]), Q(view.up[1]), Q(view.up[2])});
    rows[1] = cross(rows[0], d);
  };
  auto nearest = [](const Q& e) { return G::to_double(ExactKernel::FT(e)); };  // a plain rep: the general path
  auto crossing_of = [&](const Drawn& a, const Drawn& b, const Drawn& c, const Drawn& d) -> std::optional<Drawn> {
    if (a.exact == b.exact || c.exact == d.exact || CGAL::is_zero(CGAL::determinant(b.exact - a.exact, d.exact - c.exact)))
      return std::nullopt;
    return Drawn{G::line_intersection(a.point, b.point, c.point, d.point),
                 LineCrossing<EK>()(a.exact, b.exact, c.exact, d.exact),
                 a.kind == 0 && b.kind == 0 && c.kind == 0 && d.kind == 0 ? 1 : 2};
  };
  // A crossing of the line u v with a random line through points of doubles.
  auto on_line = [&](const Drawn& u, const Drawn& v, int mode) {
    for (;;)
      if (auto c = crossing_of(u, v, double_point(mode), double_point(mode))) return *c;
  };
  std::size_t zeros = 0, ties = 0, by_doubles = 0, general = 0, images = 0;
  for (int i = 0; i < 8000; ++i) {
    const int mode = i % 4;
    set_frame(i, mode);
    images += frame.has_value();
    Drawn u = double_point(mode), v = double_point(mode);
    while (u.exact == v.exact) v = double_point(mode);
    std::array<Drawn, 3> p;
    switch (i / 4 % 4) {
      case 0:  // three crossings on the line u v
        for (auto& d : p) d = on_line(u, v, mode);
        break;
      case 1:  // u, v and a crossing on their line
        p = {u, v, on_line(u, v, mode)};
        break;
      case 2:  // a crossing of two crossings' line: the general path
        p[0] = on_line(u, v, mode);
        p[1] = on_line(u, v, mode);
        p[2] = double_point(mode);
        if (auto c = crossing_of(p[0], p[2], u, double_point(mode))) p[2] = *c;
        break;
      default:  // crossings of random lines
        for (auto& d : p)
          for (;;)
            if (auto c = crossing_of(double_point(mode), double_point(mode), double_point(mode), double_point(mode))) {
              d = *c;
              break;
            }
    }
    for (const Drawn& d : p) {  // before a predicate may have evaluated the point exactly
      ASSERT_EQ(G::to_double(d.point, 0), nearest(d.exact.x())) << i;
      ASSERT_EQ(G::to_double(d.point, 1), nearest(d.exact.y())) << i;
    }
    const int want = static_cast<int>(CGAL::orientation(p[0].exact, p[1].exact, p[2].exact));
    zeros += want == 0;
    ASSERT_EQ(G::orientation(p[0].point, p[1].point, p[2].point), want) << i;
    const auto direct = orientation_from_doubles(p[0].point, p[1].point, p[2].point);
    if (p[0].kind < 2 && p[1].kind < 2 && p[2].kind < 2) {
      ASSERT_TRUE(direct.has_value()) << i;
      ++by_doubles;
    } else {
      ++general;
    }
    if (direct) ASSERT_EQ(*direct, want) << i;
    for (int j = 0; j < 3; ++j) {
      const Drawn &a = p[j], &b = p[(j + 1) % 3];
      const int want_x = static_cast<int>(CGAL::compare_x(a.exact, b.exact));
      const int want_y = static_cast<int>(CGAL::compare_y(a.exact, b.exact));
      ties += want_x == 0 || want_y == 0;
      ASSERT_EQ(G::compare_x(a.point, b.point), want_x) << i;
      ASSERT_EQ(G::compare_y(a.point, b.point), want_y) << i;
      ASSERT_EQ(G::compare_xy(a.point, b.point), static_cast<int>(CGAL::compare_xy(a.exact, b.exact))) << i;
      if (const auto c = compare_from_doubles(a.point, b.point, 0)) ASSERT_EQ(*c, want_x) << i;
      if (const auto c = compare_from_doubles(a.point, b.point, 1)) ASSERT_EQ(*c, want_y) << i;
    }
    // The exact point a crossing evaluates to: from its homogeneous coordinates, one division each.
    for (const Drawn& d : p) ASSERT_EQ(CGAL::exact(d.point), d.exact) << i;
  }
  EXPECT_GT(zeros, 2000u) << "the draws must hit exact zeros";
  EXPECT_GT(ties, 500u) << "the draws must hit ties of coordinates";
  EXPECT_GT(by_doubles, 4000u);
  EXPECT_GT(general, 500u);
  EXPECT_EQ(images, 4000u);
}

// PlaneSide's static bound: a decided side must be the exact one (the determinant in rationals),
// for points on the plane (exact zeros), an ulp off it, and ordinary ones, with coordinates random,
// on a coarse grid, far from the origin and of mixed magnitude; ordinary cases (not exactly on the plane) it must settle itself.
TEST(ExactKernel, PlaneSideIsTheExactOrientation) {
  using Q = CGAL::Exact_rational;
  std::mt19937_64 random(20261205);
  auto exact_side = [](const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& p) {
    Q u[3], v[3], w[3];
    for (int k = 0; k < 3; ++k) u[k] = Q(b[k]) - Q(a[k]), v[k] = Q(c[k]) - Q(a[k]), w[k] = Q(p[k]) - Q(a[k]);
    const Q det = w[0] * (u[1] * v[2] - u[2] * v[1]) + w[1] * (u[2] * v[0] - u[0] * v[2]) + w[2] * (u[0] * v[1] - u[1] * v[0]);
    return static_cast<int>(CGAL::sign(det));
  };
  std::size_t zeros = 0, ordinary = 0, ordinary_decided = 0;
  for (int i = 0; i < 20000; ++i) {
    const int mode = i % 4;
    auto point = [&] { return Vec3{hard_value(random, mode), hard_value(random, mode), hard_value(random, mode)}; };
    const Vec3 a = point(), b = point(), c = point();
    Vec3 p = point();
    const int kind = i / 4 % 3;
    if (kind > 0) {  // on the plane where the sum is exact (the grids), an ulp off it after
      for (int k = 0; k < 3; ++k) p[k] = b[k] + c[k] - a[k];
      if (kind == 2) p[i % 3] = std::nextafter(p[i % 3], HUGE_VAL);
    }
    const int want = exact_side(a, b, c, p);
    zeros += want == 0;
    const PlaneSide side(a, b, c);
    ASSERT_EQ(side(p), want) << i;
    const int in_double = side.in_double(p);
    if (in_double != 2) {
      ASSERT_EQ(in_double, want) << i;
    }
    if (kind == 0 && want != 0) ++ordinary, ordinary_decided += in_double != 2;
  }
  EXPECT_GT(zeros, 2000u) << "the draws must hit exact zeros";
  EXPECT_GT(ordinary_decided, ordinary * 99 / 100) << "the bound must settle ordinary cases";
}

// triangles_meet against CGAL::do_intersect, on pairs of triangles each with corners strictly on
// both sides of the other's plane, with coordinates random, on a coarse grid (where the segments
// on the planes' line touch end to end: the final orientations' zeros), far from the origin and of
// mixed magnitude. The second triangle is drawn near the first, so that about half the pairs meet.
TEST(ExactKernel, TrianglesMeetAsCgalSays) {
  using IK = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::mt19937_64 random(20261207);
  std::size_t tested = 0, met = 0;
  for (int i = 0; i < 40000; ++i) {
    const int mode = i % 4;
    auto point = [&] { return Vec3{hard_value(random, mode), hard_value(random, mode), hard_value(random, mode)}; };
    std::array<Vec3, 3> p{point(), point(), point()}, q{point(), point(), point()};
    if (i % 8 < 4)  // q moved to p's centre where that is exact (the grids)
      for (Vec3& v : q)
        for (int k = 0; k < 3; ++k) v[k] = (v[k] - p[0][k]) + (p[1][k] + p[2][k]) / 2;
    auto ik = [](const Vec3& v) { return IK::Point_3(v[0], v[1], v[2]); };
    if (CGAL::collinear(ik(p[0]), ik(p[1]), ik(p[2])) || CGAL::collinear(ik(q[0]), ik(q[1]), ik(q[2]))) continue;
    const PlaneSide p_plane(p[0], p[1], p[2]), q_plane(q[0], q[1], q[2]);
    std::array<int, 3> p_side, q_side;
    for (int k = 0; k < 3; ++k) p_side[k] = q_plane(p[k]), q_side[k] = p_plane(q[k]);
    auto straddles = [](const std::array<int, 3>& side) {
      return side[0] * side[1] * side[2] != 0 && !(side[0] == side[1] && side[1] == side[2]);
    };
    if (!straddles(p_side) || !straddles(q_side)) continue;
    const bool want = CGAL::do_intersect(IK::Triangle_3(ik(p[0]), ik(p[1]), ik(p[2])), IK::Triangle_3(ik(q[0]), ik(q[1]), ik(q[2])));
    ASSERT_EQ(triangles_meet(p, p_side, q, q_side), want) << i;
    ++tested, met += want;
  }
  EXPECT_GT(tested, 4000u);
  EXPECT_GT(met, tested / 5);
  EXPECT_LT(met, tested * 4 / 5);
}

// orientation_of_doubles (the clipper's pair test): a decided orientation must be the exact one
// (in rationals) for points on a line (exact zeros on the grids), an ulp off it, and ordinary ones,
// with coordinates random, on a coarse grid, far from the origin, of mixed magnitude, and near the
// ends of the double range where products underflow or overflow; ordinary ones it must settle.
TEST(ExactKernel, DoubleOrientationFilterIsExactWhereItDecides) {
  using Q = CGAL::Exact_rational;
  std::mt19937_64 random(20261206);
  std::uniform_real_distribution<double> unit(-1, 1);
  auto value = [&](int mode) {
    if (mode < 4) return hard_value(random, mode);
    return unit(random) * (mode == 4 ? 0x1p-520 : 0x1p505);  // products underflow, or pass 2^1000
  };
  std::size_t zeros = 0, decided = 0, ordinary = 0, ordinary_decided = 0;
  for (int i = 0; i < 30000; ++i) {
    const int mode = i % 6;
    double a[2] = {value(mode), value(mode)}, b[2] = {value(mode), value(mode)}, c[2] = {value(mode), value(mode)};
    const int kind = i / 6 % 3;
    if (kind > 0) {  // on the line ab where the sum is exact (the grids), an ulp off it after
      c[0] = 2 * b[0] - a[0], c[1] = 2 * b[1] - a[1];
      if (kind == 2) c[i % 2] = std::nextafter(c[i % 2], HUGE_VAL);
    }
    const Q det = (Q(a[0]) - Q(c[0])) * (Q(b[1]) - Q(c[1])) - (Q(a[1]) - Q(c[1])) * (Q(b[0]) - Q(c[0]));
    const int want = static_cast<int>(CGAL::sign(det));
    zeros += want == 0;
    const int got = orientation_of_doubles(a[0], a[1], b[0], b[1], c[0], c[1]);
    if (got != 2) {
      ++decided;
      ASSERT_EQ(got, want) << i;
    }
    if (kind == 0 && want != 0 && mode < 4) ++ordinary, ordinary_decided += got != 2;
  }
  EXPECT_GT(zeros, 2000u) << "the draws must hit exact zeros";
  EXPECT_GT(decided, 7000u);
  EXPECT_GT(ordinary_decided, ordinary * 99 / 100) << "the filter must settle what is far from degenerate";
}

// The view coordinates of an input point are one lazy number each (view.hpp's RowDotRep): their
// intervals must hold, and their exact values be, the dot products with the exact basis of
// DESIGN.md rule 1 (X = d × up, Y = X × d, Z = -d), for named views and random directions and up
// vectors, on random points, on a coarse grid, far from the origin and of mixed magnitude, and on
// constructed points.
TEST(ExactKernel, ViewCoordinatesAreTheExactDotProducts) {
  using Q = CGAL::Exact_rational;
  std::mt19937_64 random(20261205);
  std::uniform_real_distribution<double> unit(-1, 1);
  auto value = [&](int mode) { return hard_value(random, mode); };
  auto cross = [](const std::array<Q, 3>& a, const std::array<Q, 3>& b) {
    return std::array<Q, 3>{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  };
  std::size_t checked = 0;
  for (int i = 0; i < 4000; ++i) {
    const int mode = i % 4;
    View view;
    if (i % 4 == 0) named_view(i % 8 ? "iso" : "top", view);
    else view.direction = {value(mode), value(mode), value(mode)}, view.up = {unit(random), unit(random), unit(random)};
    if (view_defect(view)) continue;
    const ViewFrame<ExactKernel> frame(view);
    const std::array<Q, 3> d{view.direction[0], view.direction[1], view.direction[2]};
    const std::array<Q, 3> up{view.up[0], view.up[1], view.up[2]};
    const std::array<Q, 3> x = cross(d, up), y = cross(x, d), z{-d[0], -d[1], -d[2]};
    const Vec3 p{value(mode), value(mode), value(mode)};
    const auto v = frame.to_view(p);
    const ExactKernel::FT* coordinates[3] = {&v.x, &v.y, &v.z};
    const std::array<Q, 3>* rows[3] = {&x, &y, &z};
    for (int k = 0; k < 3; ++k) {
      const auto approx = CGAL::to_interval(*coordinates[k]);  // before the exact value is asked for
      const Q want = (*rows[k])[0] * Q(p[0]) + (*rows[k])[1] * Q(p[1]) + (*rows[k])[2] * Q(p[2]);
      // Its quotient (lazy_rep.hpp), the same number in Mpzf, and its rounding from it.
      const auto quotient = quotient_of(*coordinates[k]);
      ASSERT_TRUE(quotient.has_value()) << i << " axis " << k;
      ASSERT_EQ(Q((*quotient)[0]) / Q((*quotient)[1]), want) << i << " axis " << k;
      ASSERT_EQ(Geometry<ExactKernel>::to_double(*coordinates[k]), Geometry<ExactKernel>::to_double(ExactKernel::FT(want)))
          << i << " axis " << k;
      ASSERT_EQ(Q(coordinates[k]->exact()), want) << i << " axis " << k;
      ASSERT_LE(Q(approx.first), want) << i << " axis " << k;
      ASSERT_GE(Q(approx.second), want) << i << " axis " << k;
    }
    // A constructed point (a penetration line's end): the same.
    const Vec3 q{value(mode), value(mode), value(mode)};
    const auto m = CGAL::midpoint(ExactKernel::Point_3(p[0], p[1], p[2]), ExactKernel::Point_3(q[0], q[1], q[2]));
    const auto w = frame.to_view(m);
    const ExactKernel::FT* constructed[3] = {&w.x, &w.y, &w.z};
    for (int k = 0; k < 3; ++k) {
      const auto approx = CGAL::to_interval(*constructed[k]);
      const Q mid[3] = {(Q(p[0]) + Q(q[0])) / 2, (Q(p[1]) + Q(q[1])) / 2, (Q(p[2]) + Q(q[2])) / 2};
      const Q want = (*rows[k])[0] * mid[0] + (*rows[k])[1] * mid[1] + (*rows[k])[2] * mid[2];
      ASSERT_FALSE(quotient_of(*constructed[k]).has_value()) << i << " axis " << k;
      ASSERT_EQ(Q(constructed[k]->exact()), want) << i << " axis " << k;
      ASSERT_LE(Q(approx.first), want) << i << " axis " << k;
      ASSERT_GE(Q(approx.second), want) << i << " axis " << k;
    }
    ++checked;
  }
  EXPECT_GT(checked, 3500u);
}

// A point's three view coordinates share one allocation (view.hpp's RowDotBlock): each must keep
// its exact value until its own last handle goes, in whatever order the three go, after the frame
// is gone and on another thread (the sanitized build checks the memory).
TEST(ExactKernel, ViewCoordinatesOutliveEachOtherAndTheFrame) {
  using Q = CGAL::Exact_rational;
  View view;
  named_view("iso", view);
  const std::array<Q, 3> d{view.direction[0], view.direction[1], view.direction[2]};
  const std::array<Q, 3> up{view.up[0], view.up[1], view.up[2]};
  auto cross = [](const std::array<Q, 3>& a, const std::array<Q, 3>& b) {
    return std::array<Q, 3>{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  };
  const std::array<Q, 3> x = cross(d, up), y = cross(x, d), z{-d[0], -d[1], -d[2]};
  const Vec3 p{0.25, -3.5, 1e9 + 0.5};
  const std::array<Q, 3> mid{(Q(p[0]) + 1) / 2, (Q(p[1]) + 2) / 2, (Q(p[2]) + 3) / 2};
  int order[3] = {0, 1, 2};
  do {
    for (const bool constructed : {false, true}) {
      std::array<std::optional<ExactKernel::FT>, 3> kept;
      {
        const ViewFrame<ExactKernel> frame(view);
        const auto v = constructed ? frame.to_view(CGAL::midpoint(ExactKernel::Point_3(p[0], p[1], p[2]),
                                                                  ExactKernel::Point_3(1, 2, 3)))
                                   : frame.to_view(p);
        kept = {v.x, v.y, v.z};
      }
      const std::array<Q, 3>* rows[3] = {&x, &y, &z};
      for (const int axis : order) {
        const auto& row = *rows[axis];
        const Q want = constructed ? row[0] * mid[0] + row[1] * mid[1] + row[2] * mid[2]
                                   : row[0] * Q(p[0]) + row[1] * Q(p[1]) + row[2] * Q(p[2]);
        Q got;
        std::thread([&] { got = Q(kept[std::size_t(axis)]->exact()); }).join();
        EXPECT_EQ(got, want) << "axis " << axis << (constructed ? ", constructed point" : ", input point");
        kept[std::size_t(axis)].reset();
      }
    }
  } while (std::next_permutation(order, order + 3));
}

// ModelPlane decides, on the input doubles, what the view-space plane of three points decides after
// the exact view map: which side of the plane a point is on seen from the viewer, and where a
// segment crosses it. Checked against that evaluation on Epeck for random views, on random points,
// on a coarse grid (points in the plane, edge-on planes skipped), far from the origin and of mixed
// magnitude, with input points and with exact constructed ones (points in the plane among them).
TEST(ExactKernel, ModelPlaneAgreesWithTheViewSpacePlane) {
  using FT = ExactKernel::FT;
  using Point3 = ExactKernel::Point_3;
  std::mt19937_64 random(20261204);
  std::uniform_real_distribution<double> unit(-1, 1);
  auto value = [&](int mode) { return hard_value(random, mode); };
  auto point = [&](int mode) { return Vec3{value(mode), value(mode), value(mode)}; };
  auto exact_point = [](const Vec3& p) { return Point3(p[0], p[1], p[2]); };
  std::size_t checked = 0, zeros = 0, crossings = 0;
  for (int i = 0; i < 6000; ++i) {
    const int mode = i % 4;
    View view;
    if (i % 3 == 0) named_view(i % 2 ? "iso" : "front", view);
    else view.direction = {std::round(unit(random) * 2), std::round(unit(random) * 2), unit(random)}, view.up = {0, 0, 1};
    if (view_defect(view)) continue;
    const ViewFrame<ExactKernel> frame(view);
    const Vec3 a = point(mode), b = point(mode), c = point(mode);
    const auto va = frame.to_view(a), vb = frame.to_view(b), vc = frame.to_view(c);
    const FT ux = vb.x - va.x, uy = vb.y - va.y, uz = vb.z - va.z, wx = vc.x - va.x, wy = vc.y - va.y, wz = vc.z - va.z;
    const FT nx = uy * wz - uz * wy, ny = uz * wx - ux * wz, nz = ux * wy - uy * wx;
    if (CGAL::is_zero(nz)) continue;  // edge-on (or collinear): no source has such a plane
    const FT pa = -nx / nz, pb = -ny / nz, pc = va.z - pa * va.x - pb * va.y;
    auto f = [&](const ViewPoint<ExactKernel>& q) { return pa * q.x + pb * q.y + pc - q.z; };
    const ModelPlane plane(a, b, c, view.direction);
    // An input point, or an exact point: one of the plane (a + s (b - a) + t (c - a)) or off it.
    const Vec3 q = point(mode), r = point(mode);
    const FT s(std::round(unit(random) * 4) / 4), t(std::round(unit(random) * 4) / 4);
    const Point3 in_plane = exact_point(a) + s * (exact_point(b) - exact_point(a)) + t * (exact_point(c) - exact_point(a));
    const Point3 off = CGAL::midpoint(exact_point(q), exact_point(r));
    ASSERT_EQ(plane.nearer_than(q), CGAL::sign(f(frame.to_view(q)))) << i;
    ASSERT_EQ(plane.nearer_than(in_plane), 0) << i;
    ASSERT_EQ(plane.nearer_than(off), CGAL::sign(f(frame.to_view(off)))) << i;
    zeros += plane.nearer_than(q) == 0;
    ++checked;
    const FT f0 = f(frame.to_view(q)), f1 = f(frame.to_view(r));
    if (CGAL::sign(f0) * CGAL::sign(f1) < 0) {
      ASSERT_EQ(plane.crossing(q, r), f0 / (f0 - f1)) << i;
      ASSERT_EQ(plane.crossing(exact_point(q), exact_point(r)), f0 / (f0 - f1)) << i;
      ++crossings;
    }
  }
  EXPECT_GT(checked, 3000u);
  EXPECT_GT(zeros, 100u) << "the grid must put input points in the plane";
  EXPECT_GT(crossings, 500u);
}

// line_misses_box is a filter: "true" must be the exact answer (every corner of the box strictly
// on one side of the line), on constructed points and on a coarse grid where lines pass through
// corners; and it must say so for most boxes that the line clearly misses.
TEST(ExactKernel, LineMissesBoxOnlyWhenEveryCornerIsOnOneSide) {
  using G = Geometry<ExactKernel>;
  using FT = ExactKernel::FT;
  std::mt19937_64 random(20261203);
  std::uniform_int_distribution<int> grid(-4, 4);
  std::size_t misses = 0, clear = 0;
  for (int i = 0; i < 20000; ++i) {
    // Line ends on a grid of quarters, or constructed (a third of a grid point): not one double.
    auto end = [&] {
      const double x = grid(random) / 4.0, y = grid(random) / 4.0;
      return i % 2 ? G::point(x, y) : G::point(FT(x) / FT(3), FT(y) / FT(3));
    };
    const auto a = end(), b = end();
    if (G::equal(a, b)) continue;
    double x0 = grid(random) / 4.0, x1 = grid(random) / 4.0, y0 = grid(random) / 4.0, y1 = grid(random) / 4.0;
    if (x1 < x0) std::swap(x0, x1);
    if (y1 < y0) std::swap(y0, y1);
    int positive = 0, negative = 0;
    for (const double x : {x0, x1})
      for (const double y : {y0, y1}) {
        const int side = G::orientation(a, b, G::point(x, y));
        positive += side > 0;
        negative += side < 0;
      }
    const bool exact_miss = positive == 4 || negative == 4;
    const bool filtered = line_misses_box<ExactKernel>(a, b, CGAL::Bbox_2(x0, y0, x1, y1));
    ASSERT_TRUE(!filtered || exact_miss) << i;
    misses += filtered;
    clear += exact_miss;
  }
  EXPECT_GT(misses, clear * 9 / 10) << "the filter should decide most clear misses";
  EXPECT_FALSE(line_misses_box<DoubleKernel>(DoublePoint{0, 0}, DoublePoint{1, 0}, CGAL::Bbox_2(0, 1, 1, 2)));
}

}  // namespace
}  // namespace hlr

namespace hlr {
namespace {

// nearest_quotient against Geometry::to_double of the same rational: quotients of snapped values
// (many exact, many ties between two doubles) and of random ones, of either sign, and the ties
// 2^53 + 1 and its negative, which go to the lower double.
TEST(ExactOutput, NearestQuotientRoundsAsToDouble) {
  using G = Geometry<ExactKernel>;
  using ET = ExactKernel::FT::Exact_type;
  using Z = CGAL::Mpzf;
  auto expected = [](const Z& num, const Z& den) { return G::to_double(ExactKernel::FT(ET(ET(num) / ET(den)))); };
  const Z big = Z(9007199254740992.0) + Z(1);
  EXPECT_EQ(nearest_quotient(big, Z(1)), 9007199254740992.0);
  EXPECT_EQ(nearest_quotient(-big, Z(1)), -9007199254740994.0);
  EXPECT_EQ(nearest_quotient(big, Z(-1)), -9007199254740994.0);
  EXPECT_EQ(nearest_quotient(Z(1), Z(0)), std::nullopt);
  EXPECT_EQ(nearest_quotient(Z(0), Z(3)), 0.0);
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> any(-1e3, 1e3);
  std::uniform_int_distribution<int> grid(-8, 8);
  for (int i = 0; i < 20000; ++i) {
    const bool snapped = i % 2 == 0;
    auto value = [&] { return snapped ? grid(random) / 4.0 : any(random); };
    const Z num = Z(value()) * Z(value()) + Z(value()) * Z(std::ldexp(value(), 60));
    const Z den = Z(value()) * Z(value()) - Z(value());
    if (den.sign() == CGAL::ZERO) continue;
    const std::optional<double> got = nearest_quotient(num, den);
    ASSERT_TRUE(got.has_value() || num.sign() != CGAL::ZERO) << i;
    if (got) {
      ASSERT_EQ(*got, expected(num, den)) << i;
    } else {
      const double e = expected(num, den);
      EXPECT_FALSE(std::isnormal(e) && std::isnormal(std::nextafter(e, HUGE_VAL))) << i << " " << e;
    }
  }
}

// Crossing and along-axis parameters (exact_parameter.hpp): the interval CGAL's lazy construction
// of the same formula gives, the exact rational, and t and the points at t rounded as the general
// path rounds the same rationals; with coordinates random, snapped (coincidences, ties), far from
// the origin, of mixed magnitude, and, in a fifth of the draws, thirds (not doubles: the general
// path).
TEST(ExactParameter, AgreesWithTheLazyConstructionAndRoundsAsToDouble) {
  using G = Geometry<ExactKernel>;
  using FT = ExactKernel::FT;
  using ET = FT::Exact_type;
  using P = ExactKernel::Point_2;
  auto reference = [](const ET& e) { return G::to_double(FT(e)); };  // a plain rep: the general path
  auto same_interval = [](const FT& x, const FT& y) {
    return CGAL::approx(x).inf() == CGAL::approx(y).inf() && CGAL::approx(x).sup() == CGAL::approx(y).sup();
  };
  std::mt19937_64 random(20261207);
  std::size_t by_quotient = 0, general = 0;
  for (int i = 0; i < 20000; ++i) {
    const int mode = i % 5;
    auto coordinate = [&]() -> FT {
      if (mode == 4) return FT(hard_value(random, 1)) / FT(3);  // not a double
      return FT(hard_value(random, mode));
    };
    FT c8[8];
    for (FT& c : c8) c = coordinate();
    const P a(c8[0], c8[1]), b(c8[2], c8[3]), c(c8[4], c8[5]), d(c8[6], c8[7]);
    const FT dx = c8[2] - c8[0], dy = c8[3] - c8[1];
    const ET e[8] = {c8[0].exact(), c8[1].exact(), c8[2].exact(), c8[3].exact(),
                     c8[4].exact(), c8[5].exact(), c8[6].exact(), c8[7].exact()};
    auto check = [&](const FT& t, const FT& old, const ET& num, const ET& den) {
      ASSERT_TRUE(same_interval(t, old)) << i;
      const ET exact = num / den;
      const auto* rep = rep_as<QuotientRep>(t);
      ASSERT_NE(rep, nullptr);
      (rep->quotient() ? by_quotient : general) += 1;
      // Rounded before anything evaluates t exactly, then its value.
      ASSERT_EQ(G::to_double(t), reference(exact)) << i;
      for (int k = 0; k < 2; ++k) {
        const FT& from = k == 0 ? c8[0] : c8[1];
        const FT& to = k == 0 ? c8[2] : c8[3];
        ASSERT_EQ(G::to_double_between(from, to, t), reference(from.exact() + exact * (to.exact() - from.exact())))
            << i << " axis " << k;
      }
      ASSERT_EQ(t.exact(), exact) << i;
      ASSERT_EQ(t.exact(), old.exact()) << i;
    };
    const ET den = (e[2] - e[0]) * (e[7] - e[5]) - (e[3] - e[1]) * (e[6] - e[4]);
    if (!CGAL::is_zero(den)) {
      const FT old = CGAL::Lazy_construction_nt<ExactKernel, detail::CrossingParameter, detail::CrossingParameter>()(
          a, dx, dy, c, d);
      const ET num = (e[4] - e[0]) * (e[7] - e[5]) - (e[5] - e[1]) * (e[6] - e[4]);
      check(crossing_parameter<ExactKernel>(a, b, dx, dy, c, d), old, num, den);
    }
    for (const bool along_x : {true, false}) {
      const int k = along_x ? 0 : 1;
      if (CGAL::is_zero(e[2 + k] - e[k])) continue;
      const FT& delta = along_x ? dx : dy;
      const FT old = along_x ? CGAL::Lazy_construction_nt<ExactKernel, detail::ParameterAlongX, detail::ParameterAlongX>()(a, c, delta)
                             : CGAL::Lazy_construction_nt<ExactKernel, detail::ParameterAlongY, detail::ParameterAlongY>()(a, c, delta);
      check(parameter_along<ExactKernel>(a, b, c, delta, along_x), old, e[4 + k] - e[k], e[2 + k] - e[k]);
    }
  }
  EXPECT_GT(by_quotient, 20000u);
  EXPECT_GT(general, 5000u);
}

// A crossing exactly halfway between two doubles rounds to the lower one, as Geometry::to_double
// rounds: t = 1 + 2^-53 on the line from (0, 0) to (1, 0), and its negative.
TEST(ExactParameter, TiesGoToTheLowerDouble) {
  using G = Geometry<ExactKernel>;
  using FT = ExactKernel::FT;
  using P = ExactKernel::Point_2;
  const double up = 1 + 0x1p-52;
  for (const double sign : {1.0, -1.0}) {
    const P a(0, 0), b(sign, 0), c(sign, -1), d(sign * up, 1);
    const FT t = crossing_parameter<ExactKernel>(a, b, FT(sign), FT(0), c, d);
    EXPECT_EQ(G::to_double(t), 1.0);  // t = 1 + 2^-53 either way
    EXPECT_EQ(G::to_double_between(FT(0), FT(sign), t), sign > 0 ? 1.0 : -up);
  }
}

// RecipeRounding gives the view coordinates ViewFrame gives, rounded, for a crossing of an edge
// with a plane and for an input point, in a general and in a named view.
TEST(ExactOutput, RecipesRoundAsTheViewFrame) {
  using G = Geometry<ExactKernel>;
  using FT = ExactKernel::FT;
  for (const View& view : {View{"custom", {1, 2, -3}, {0, 0, 1}}, View{"iso", {-1, 1, -1}, {0, 0, 1}}}) {
    const ViewFrame<ExactKernel> frame(view);
    const RecipeRounding rounding(view);
    std::mt19937_64 random(11);
    std::uniform_real_distribution<double> any(-10, 10);
    for (int i = 0; i < 500; ++i) {
      auto point = [&] { return Vec3{any(random), any(random), any(random)}; };
      ModelPointRecipe r{ModelPointRecipe::Kind::edge_crossing, point(), point(), point(), point(), point()};
      if (i % 5 == 0) r.kind = ModelPointRecipe::Kind::input_point;
      const auto n = homogeneous(r);
      if (n[3].sign() == CGAL::ZERO) continue;
      using ET = FT::Exact_type;
      FT p[3];
      for (int k = 0; k < 3; ++k) p[k] = FT(ET(ET(n[k]) / ET(n[3])));
      const ViewPoint<ExactKernel> v = frame.to_view(p[0], p[1], p[2]);
      const auto got = rounding.nearest(r);
      ASSERT_TRUE(got.has_value()) << i;
      EXPECT_EQ((*got)[0], G::to_double(v.x)) << i;
      EXPECT_EQ((*got)[1], G::to_double(v.y)) << i;
      EXPECT_EQ((*got)[2], G::to_double(v.z)) << i;
    }
  }
  EXPECT_FALSE(RecipeRounding(View{"p", {0, 0, -1}, {0, 1, 0}, Vec3{0, 0, 5}}).nearest({ModelPointRecipe::Kind::input_point}));
}

// lazy_point is the crossing of the edge u w with the plane through a, b, c that Epeck constructs:
// equal to it exactly (comparisons that only the exact coordinates settle), on random, grid-snapped
// and mixed-magnitude input (1e-9 next to 1e9), and its predicates are that point's; remade gives
// the same point in a new rep.
TEST(ExactOutput, LazyPointIsTheEpeckCrossing) {
  using K = ExactKernel;
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> any(-10, 10);
  std::uniform_int_distribution<int> grid(-4, 4);
  std::uniform_int_distribution<int> exponent(-30, 30);
  int checked = 0;
  for (int i = 0; i < 3000; ++i) {
    auto value = [&] {
      if (i % 3 == 0) return grid(random) / 2.0;
      if (i % 3 == 1) return std::ldexp(any(random), exponent(random));
      return any(random);
    };
    auto point = [&] { return Vec3{value(), value(), value()}; };
    const ModelPointRecipe r{ModelPointRecipe::Kind::edge_crossing, point(), point(), point(), point(), point()};
    auto p3 = [](const Vec3& v) { return K::Point_3(v[0], v[1], v[2]); };
    if (CGAL::collinear(p3(r.a), p3(r.b), p3(r.c))) continue;
    const K::Plane_3 plane(p3(r.a), p3(r.b), p3(r.c));
    if (plane.oriented_side(p3(r.u)) * plane.oriented_side(p3(r.w)) >= 0) continue;  // not across it
    const auto crossing = CGAL::intersection(K::Segment_3(p3(r.u), p3(r.w)), plane);
    ASSERT_TRUE(crossing) << i;
    const K::Point_3& expected = boost::get<K::Point_3>(*crossing);
    const auto& box = CGAL::approx(expected);
    const K::Point_3 got = lazy_point(r, {box.x(), box.y(), box.z()});
    ASSERT_EQ(CGAL::compare_xyz(got, expected), CGAL::EQUAL) << i;
    ASSERT_TRUE(plane.has_on(got)) << i;
    const K::Point_3 q = p3(point()), s = p3(point());
    ASSERT_EQ(CGAL::orientation(p3(r.u), q, s, got), CGAL::orientation(p3(r.u), q, s, expected)) << i;
    // Made again (after got's exact coordinates were made above): a rep of its own, the same point.
    const K::Point_3 again = remade(got);
    ASSERT_NE(again.id(), got.id()) << i;
    ASSERT_EQ(CGAL::compare_xyz(again, expected), CGAL::EQUAL) << i;
    ++checked;
  }
  EXPECT_GT(checked, 1000);
}

// The recipe read back from a point: a lazy point's own (also once remade), an input point's
// doubles, and nothing for a point CGAL constructed, which output rounds the general way.
TEST(ExactOutput, RecipeOfReadsBackHowThePointWasMade) {
  using K = ExactKernel;
  const ModelPointRecipe r{ModelPointRecipe::Kind::edge_crossing, {0, 0, -1}, {0, 0, 2}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const ModelPointRecipe made = recipe_of(lazy_point(r, {CGAL::Interval_nt<false>(0), 0, 0}));
  EXPECT_EQ(made.kind, r.kind);
  for (const auto& [x, y] : {std::pair{made.u, r.u}, {made.w, r.w}, {made.a, r.a}, {made.b, r.b}, {made.c, r.c}})
    EXPECT_EQ(x, y);
  const ModelPointRecipe again = recipe_of(remade(lazy_point(r, {CGAL::Interval_nt<false>(0), 0, 0})));
  EXPECT_EQ(again.kind, r.kind);
  EXPECT_EQ(again.w, r.w);
  const K::Point_3 plain(0.1, -2.5, 1e300);
  EXPECT_EQ(remade(plain).id(), plain.id()) << "a point without a recipe is returned as it is";
  const ModelPointRecipe input = recipe_of(plain);
  EXPECT_EQ(input.kind, ModelPointRecipe::Kind::input_point);
  EXPECT_EQ(input.u, (Vec3{0.1, -2.5, 1e300}));
  EXPECT_EQ(recipe_of(CGAL::midpoint(K::Point_3(0, 0, 0), K::Point_3(0.1, 0, 0))).kind, ModelPointRecipe::Kind::input_point)
      << "halving a double is exact: the constructed midpoint's intervals are single doubles";
  EXPECT_EQ(recipe_of(K::Point_3(0, 0, 0) + (K::Point_3(1, 0, 0) - K::Point_3(0, 0, 0)) / 3).kind,
            ModelPointRecipe::Kind::unknown);
}

}  // namespace
}  // namespace hlr
