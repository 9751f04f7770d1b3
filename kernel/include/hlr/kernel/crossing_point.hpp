// Crossings of image lines as lazy points that keep their lines, and orientations and comparisons
// of such points decided from the lines' doubles.
//
// The area sort and the clipper cut polygons at crossings of support lines. On Epeck a crossing is
// a lazy point whose exact coordinates are quotients of GMP rationals, and where the interval
// filters cannot decide a predicate (corners collinear in an axis view, crossings on one line),
// CGAL evaluates the points and the predicate in rationals, a gcd per operation: two thirds of the
// area sort of `hlr surfaces` on a CAD part seen from the front (docs/BENCHMARKS.md, "Twenty-ninth
// run"). The crossing of two lines through points of doubles is (X / W, Y / W) with X, Y and W
// sums of products of those doubles, exact in CGAL::Mpzf; an orientation of such points is the sign
// of a 3 × 3 determinant of them times the signs of the W, a comparison the sign of X W' − X' W
// times theirs: decided exactly without a rational (DESIGN.md rule 3, constructed points kept as
// their support lines).
#pragma once

#include <hlr/kernel/lazy_rep.hpp>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Mpzf.h>

#include <array>
#include <optional>
#include <stdexcept>
#include <utility>

namespace hlr {

// The crossing of the line through a, b with the line through c, d, in the arithmetic of
// `Kernel` (CGAL's interval or exact kernel). On intervals, a denominator that may be zero throws
// CGAL's uncertain-conversion exception.
template <class Kernel>
struct LineCrossing {
  using result_type = typename Kernel::Point_2;
  result_type operator()(const result_type& a, const result_type& b, const result_type& c,
                         const result_type& d) const {
    using T = typename Kernel::FT;
    const T abx = b.x() - a.x(), aby = b.y() - a.y(), cdx = d.x() - c.x(), cdy = d.y() - c.y();
    const T den = abx * cdy - aby * cdx;
    if (den == 0) throw std::runtime_error("line_intersection: lines are parallel");
    const T t = ((c.x() - a.x()) * cdy - (c.y() - a.y()) * cdx) / den;
    return result_type(a.x() + t * abx, a.y() + t * aby);
  }
};

namespace crossing_detail {

using Epeck = CGAL::Epeck;
using Point2 = Epeck::Point_2;
using ApproxPoint2 = Epeck::Approximate_kernel::Point_2;
using LazyPoint2 = CGAL::Lazy_rep<ApproxPoint2, Epeck::Exact_kernel::Point_2, Epeck::E2A>;
using Z = CGAL::Mpzf;
using Homogeneous = std::array<Z, 3>;  // (X, Y, W), W != 0: the point (X / W, Y / W)

class CrossingPointRep final : public LazyPoint2 {
 public:
  // `approx` holds the crossing of the lines a b and c d.
  CrossingPointRep(const ApproxPoint2& approx, std::array<Point2, 4> points)
      : LazyPoint2(approx), points_(std::move(points)) {}

  // The crossing in homogeneous coordinates, when a, b, c and d are points of doubles; else nothing.
  std::optional<Homogeneous> homogeneous() const {
    std::array<double, 8> v;
    for (int i = 0; i < 4; ++i) {
      const ApproxPoint2& p = CGAL::approx(points_[i]);
      if (!is_double_point(p)) return std::nullopt;
      v[2 * i] = p.x().inf();
      v[2 * i + 1] = p.y().inf();
    }
    // a + t (b − a) with t = num / den, as in LineCrossing, times den.
    const Z ax(v[0]), ay(v[1]), cx(v[4]), cy(v[5]);
    const Z abx = Z(v[2]) - ax, aby = Z(v[3]) - ay, cdx = Z(v[6]) - cx, cdy = Z(v[7]) - cy;
    const Z den = abx * cdy - aby * cdx;
    const Z num = (cx - ax) * cdy - (cy - ay) * cdx;
    return Homogeneous{ax * den + num * abx, ay * den + num * aby, den};
  }

  void update_exact() const override {
    using EK = Epeck::Exact_kernel;
    EK::Point_2 p;
    if (const auto h = homogeneous()) {
      const EK::FT w((*h)[2]);
      p = EK::Point_2(EK::FT((*h)[0]) / w, EK::FT((*h)[1]) / w);
    } else {
      p = LineCrossing<EK>()(CGAL::exact(points_[0]), CGAL::exact(points_[1]), CGAL::exact(points_[2]),
                             CGAL::exact(points_[3]));
    }
    auto* exact = new typename LazyPoint2::Indirect(std::move(p));
    this->set_at(exact);
    this->set_ptr(exact);
  }

 private:
  std::array<Point2, 4> points_;
};

// A point's homogeneous coordinates from doubles: its own where they are doubles, its lines' where
// it is a crossing of lines through points of doubles; else nothing.
inline std::optional<Homogeneous> homogeneous_of(const Point2& p) {
  const ApproxPoint2& a = CGAL::approx(p);
  if (is_double_point(a)) return Homogeneous{Z(a.x().inf()), Z(a.y().inf()), Z(1)};
  const auto* crossing = rep_as<CrossingPointRep>(p);
  return crossing ? crossing->homogeneous() : std::nullopt;
}

inline int sign(const Z& z) { return static_cast<int>(z.sign()); }

}  // namespace crossing_detail

// The crossing of the lines a b and c d (not parallel) as a lazy point that keeps them, given its
// interval approximation (LineCrossing on the points' intervals).
inline CGAL::Epeck::Point_2 crossing_point(const crossing_detail::ApproxPoint2& approx,
                                           std::array<CGAL::Epeck::Point_2, 4> points) {
  using Rep = crossing_detail::CrossingPointRep;
  return CGAL::Epeck::Point_2(CGAL::Epeck::Point_2::Rep(new Rep(approx, std::move(points))));
}

// orientation(a, b, c) (−1, 0 or +1) when every point is one of doubles or a crossing of lines
// through points of doubles; else nothing.
inline std::optional<int> orientation_from_doubles(const CGAL::Epeck::Point_2& a, const CGAL::Epeck::Point_2& b,
                                                   const CGAL::Epeck::Point_2& c) {
  using crossing_detail::homogeneous_of, crossing_detail::sign, crossing_detail::Z;
  const auto p = homogeneous_of(a);
  if (!p) return std::nullopt;
  const auto q = homogeneous_of(b);
  if (!q) return std::nullopt;
  const auto r = homogeneous_of(c);
  if (!r) return std::nullopt;
  const auto &[px, py, pw] = *p;
  const auto &[qx, qy, qw] = *q;
  const auto &[rx, ry, rw] = *r;
  // det [p; q; r] = pw qw rw · orientation's determinant of the points (X / W, Y / W).
  const Z det = px * (qy * rw - ry * qw) - py * (qx * rw - rx * qw) + pw * (qx * ry - rx * qy);
  return sign(det) * sign(pw) * sign(qw) * sign(rw);
}

// compare_x(a, b) (axis 0), compare_y (axis 1) or compare_xy (axis 2) under the same condition as
// orientation_from_doubles; else nothing.
inline std::optional<int> compare_from_doubles(const CGAL::Epeck::Point_2& a, const CGAL::Epeck::Point_2& b,
                                               int axis) {
  using crossing_detail::homogeneous_of, crossing_detail::sign;
  const auto p = homogeneous_of(a);
  if (!p) return std::nullopt;
  const auto q = homogeneous_of(b);
  if (!q) return std::nullopt;
  const int w = sign((*p)[2]) * sign((*q)[2]);
  auto compare = [&](int k) { return w * sign((*p)[k] * (*q)[2] - (*q)[k] * (*p)[2]); };
  if (axis < 2) return compare(axis);
  const int x = compare(0);
  return x != 0 ? x : compare(1);
}

}  // namespace hlr
