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
// their support lines). In a general view (iso) the image of an input vertex is not a point of
// doubles but has coordinates that are dot products of the view's rows with doubles, integers in
// Mpzf: CoordinatePointRep keeps them, so that such points and the crossings of their lines are
// decided the same way.
#pragma once

#include <hlr/kernel/lazy_rep.hpp>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Mpzf.h>

#include <array>
#include <atomic>
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

// A point rep's homogeneous coordinates, made on first use by whichever thread comes first (one
// that loses the race drops its copy) and kept: the predicates that need them ask for the same
// points again and again (a vertex's ring, a line's crossings in order).
class HomogeneousOnce {
 public:
  HomogeneousOnce() = default;
  HomogeneousOnce(const HomogeneousOnce&) = delete;
  HomogeneousOnce& operator=(const HomogeneousOnce&) = delete;
  ~HomogeneousOnce() {
    const Homogeneous* v = value_.load(std::memory_order_relaxed);
    if (v != none()) delete v;
  }
  // The coordinates, or null where `make` gives nothing.
  template <class Make>
  const Homogeneous* get(Make&& make) const {
    const Homogeneous* v = value_.load(std::memory_order_acquire);
    if (!v) {
      std::optional<Homogeneous> made = make();
      const Homogeneous* mine = made ? new Homogeneous(std::move(*made)) : none();
      if (value_.compare_exchange_strong(v, mine, std::memory_order_acq_rel, std::memory_order_acquire)) v = mine;
      else if (mine != none()) delete mine;
    }
    return v == none() ? nullptr : v;
  }

 private:
  static const Homogeneous* none() {
    static const Homogeneous nothing{};
    return &nothing;
  }
  mutable std::atomic<const Homogeneous*> value_{nullptr};
};

// A point made from two lazy numbers that keep quotients of doubles (lazy_rep.hpp's QuotientRep:
// in a general view, the image of an input vertex, whose coordinates are dot products with the
// view's rows). CGAL's own point would hide them; this one keeps them, so that predicates on the
// point can be decided from those doubles (homogeneous_of).
class CoordinatePointRep final : public LazyPoint2 {
 public:
  CoordinatePointRep(const ApproxPoint2& approx, CGAL::Epeck::FT x, CGAL::Epeck::FT y)
      : LazyPoint2(approx), x_(std::move(x)), y_(std::move(y)) {}

  // (x, y) = (X / W, Y / W) from the coordinates' quotients, when their parts are doubles; else null.
  const Homogeneous* homogeneous() const {
    return homogeneous_.get([&]() -> std::optional<Homogeneous> {
      const auto x = quotient_of(x_);
      if (!x) return std::nullopt;
      const auto y = quotient_of(y_);
      if (!y) return std::nullopt;
      return Homogeneous{(*x)[0] * (*y)[1], (*y)[0] * (*x)[1], (*x)[1] * (*y)[1]};
    });
  }

  void update_exact() const override {
    auto* exact = new typename LazyPoint2::Indirect(Epeck::Exact_kernel::Point_2(CGAL::exact(x_), CGAL::exact(y_)));
    this->set_at(exact);
    this->set_ptr(exact);
  }

 private:
  CGAL::Epeck::FT x_, y_;
  HomogeneousOnce homogeneous_;
};

// A point's homogeneous coordinates with W = 1, when it is a point of doubles (written to `own`)
// or a CoordinatePointRep whose coordinates are integers in Mpzf (view coordinates of input
// vertices); else null.
inline const Homogeneous* affine_of(const Point2& p, Homogeneous& own) {
  const ApproxPoint2& a = CGAL::approx(p);
  if (is_double_point(a)) {
    own = {Z(a.x().inf()), Z(a.y().inf()), Z(1)};
    return &own;
  }
  const auto* coordinates = rep_as<CoordinatePointRep>(p);
  const Homogeneous* h = coordinates ? coordinates->homogeneous() : nullptr;
  return h && (*h)[2] == Z(1) ? h : nullptr;
}

// The crossing of the lines a b and c d in homogeneous coordinates, when the points are points of
// doubles or image points of input vertices (affine_of); else nothing. W is 0 for parallel lines.
inline std::optional<Homogeneous> crossing_of(const std::array<Point2, 4>& points) {
  std::array<Homogeneous, 4> own;
  std::array<const Homogeneous*, 4> v;
  for (int i = 0; i < 4; ++i)
    if (!(v[i] = affine_of(points[i], own[i]))) return std::nullopt;
  // a + t (b − a) with t = num / den, as in LineCrossing, times den.
  const Z &ax = (*v[0])[0], &ay = (*v[0])[1], &cx = (*v[2])[0], &cy = (*v[2])[1];
  const Z abx = (*v[1])[0] - ax, aby = (*v[1])[1] - ay, cdx = (*v[3])[0] - cx, cdy = (*v[3])[1] - cy;
  const Z den = abx * cdy - aby * cdx;
  const Z num = (cx - ax) * cdy - (cy - ay) * cdx;
  return Homogeneous{ax * den + num * abx, ay * den + num * aby, den};
}

class CrossingPointRep final : public LazyPoint2 {
 public:
  // `approx` holds the crossing of the lines a b and c d.
  CrossingPointRep(const ApproxPoint2& approx, std::array<Point2, 4> points)
      : LazyPoint2(approx), points_(std::move(points)) {}

  // The crossing in homogeneous coordinates (crossing_of), or null.
  const Homogeneous* homogeneous() const { return homogeneous_.get([&] { return crossing_of(points_); }); }

  void update_exact() const override {
    using EK = Epeck::Exact_kernel;
    EK::Point_2 p;
    if (const Homogeneous* h = homogeneous()) {
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
  HomogeneousOnce homogeneous_;
};

// A point's homogeneous coordinates from doubles: its own where they are doubles (written to `own`)
// or it keeps them (CoordinatePointRep), its lines' where it is a crossing of lines through such
// points; else null.
inline const Homogeneous* homogeneous_of(const Point2& p, Homogeneous& own) {
  const ApproxPoint2& a = CGAL::approx(p);
  if (is_double_point(a)) {
    own = {Z(a.x().inf()), Z(a.y().inf()), Z(1)};
    return &own;
  }
  if (const auto* crossing = rep_as<CrossingPointRep>(p)) return crossing->homogeneous();
  if (const auto* coordinates = rep_as<CoordinatePointRep>(p)) return coordinates->homogeneous();
  return nullptr;
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

// The crossing of the lines a b and c d as crossing_point makes it, its interval from its exact
// homogeneous coordinates, when those come from doubles (crossing_detail::crossing_of) and the lines
// are not parallel; else nothing. For lines whose intervals cannot tell them from parallel ones.
inline std::optional<CGAL::Epeck::Point_2> crossing_point_from_doubles(std::array<CGAL::Epeck::Point_2, 4> points) {
  const auto h = crossing_detail::crossing_of(points);
  if (!h || (*h)[2].sign() == CGAL::ZERO) return std::nullopt;
  using I = CGAL::Interval_nt<false>;
  CGAL::Protect_FPU_rounding<true> protect;
  const I w((*h)[2].to_interval());
  const crossing_detail::ApproxPoint2 approx(I((*h)[0].to_interval()) / w, I((*h)[1].to_interval()) / w);
  return crossing_point(approx, std::move(points));
}

// The point (x, y) as a lazy point that keeps x and y, when both keep quotients of doubles
// (QuotientRep); else nothing.
inline std::optional<CGAL::Epeck::Point_2> coordinate_point(const CGAL::Epeck::FT& x, const CGAL::Epeck::FT& y) {
  if (!rep_as<QuotientRep>(x) || !rep_as<QuotientRep>(y)) return std::nullopt;
  using Rep = crossing_detail::CoordinatePointRep;
  const crossing_detail::ApproxPoint2 approx(CGAL::approx(x), CGAL::approx(y));
  return CGAL::Epeck::Point_2(CGAL::Epeck::Point_2::Rep(new Rep(approx, x, y)));
}

// orientation(a, b, c) (−1, 0 or +1) when every point has homogeneous coordinates from doubles
// (homogeneous_of); else nothing.
inline std::optional<int> orientation_from_doubles(const CGAL::Epeck::Point_2& a, const CGAL::Epeck::Point_2& b,
                                                   const CGAL::Epeck::Point_2& c) {
  using crossing_detail::homogeneous_of, crossing_detail::sign, crossing_detail::Z;
  crossing_detail::Homogeneous own[3];
  const auto* p = homogeneous_of(a, own[0]);
  if (!p) return std::nullopt;
  const auto* q = homogeneous_of(b, own[1]);
  if (!q) return std::nullopt;
  const auto* r = homogeneous_of(c, own[2]);
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
  crossing_detail::Homogeneous own[2];
  const auto* p = homogeneous_of(a, own[0]);
  if (!p) return std::nullopt;
  const auto* q = homogeneous_of(b, own[1]);
  if (!q) return std::nullopt;
  const int w = sign((*p)[2]) * sign((*q)[2]);
  auto compare = [&](int k) { return w * sign((*p)[k] * (*q)[2] - (*q)[k] * (*p)[2]); };
  if (axis < 2) return compare(axis);
  const int x = compare(0);
  return x != 0 ? x : compare(1);
}

}  // namespace hlr
