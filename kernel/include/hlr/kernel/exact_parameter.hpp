// Parameters along image lines as lazy numbers that keep their points, and quotients rounded
// without rationals.
//
// Output rounds every piece end a + t (b − a) and every parameter t of an exact drawing, and most
// t are where a line crosses a face's edge: on Epeck a quotient of sums of products whose exact
// value is made of GMP rationals, a gcd per operation, behind once-flags (about 60% of the output
// stage of an axis view, docs/BENCHMARKS.md "Twenty-eighth run"). In an axis view (and wherever
// their intervals are single doubles) the points' coordinates are doubles, so t and the point at
// t are quotients of sums of products of doubles, exact in CGAL::Mpzf, and their nearest doubles
// take a few multiplications: the same exact numbers, so the same doubles.
#pragma once

#include <hlr/kernel/crossing_point.hpp>
#include <hlr/kernel/lazy_rep.hpp>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Mpzf.h>

#include <array>
#include <cmath>
#include <limits>
#include <optional>

namespace hlr {

// The double nearest to num / den, ties to the lower one (as Geometry::to_double rounds); nothing
// when den is 0 or the quotient is not in the normal range of doubles.
inline std::optional<double> nearest_quotient(CGAL::Mpzf num, CGAL::Mpzf den) {
  using Z = CGAL::Mpzf;
  if (den.sign() == CGAL::ZERO) return std::nullopt;
  if (den.sign() == CGAL::NEGATIVE) {
    num = -num;
    den = -den;
  }
  if (num.sign() == CGAL::ZERO) return 0.0;
  constexpr double up = std::numeric_limits<double>::infinity();
  // lo, the largest double at most num / den, from a guess a few units in the last place off.
  double lo = num.to_double() / den.to_double();
  auto at_most = [&](double x) { return Z(x) * den <= num; };
  for (int step = 0; !at_most(lo); ++step) {
    if (step == 8 || !std::isnormal(lo)) return std::nullopt;
    lo = std::nextafter(lo, -up);
  }
  for (int step = 0; at_most(std::nextafter(lo, up)); ++step) {
    if (step == 8 || !std::isnormal(lo)) return std::nullopt;
    lo = std::nextafter(lo, up);
  }
  const double hi = std::nextafter(lo, up);
  if (!std::isnormal(lo) || !std::isnormal(hi)) return std::nullopt;
  if (Z(lo) * den == num) return lo;
  // num / den − lo <= hi − num / den, that is 2 num <= (lo + hi) den.
  return num + num <= (Z(lo) + Z(hi)) * den ? lo : hi;
}

namespace parameter_detail {

using Point2 = CGAL::Epeck::Point_2;
using ET = CGAL::Epeck::FT::Exact_type;

// t on the line a + t (b − a): where it crosses the line through c and d, or where a point q on
// it lies by the abscissa or the ordinate; as numerator and denominator, in any number type.
template <class T>
std::array<T, 2> crossing(const T& ax, const T& ay, const T& bx, const T& by, const T& cx, const T& cy, const T& dx,
                          const T& dy) {
  const T ex = dx - cx, ey = dy - cy;
  return {(cx - ax) * ey - (cy - ay) * ex, (bx - ax) * ey - (by - ay) * ex};
}
template <class T>
std::array<T, 2> along(const T& a, const T& b, const T& q) {
  return {q - a, b - a};
}

enum class Along : std::uint8_t { crossing, x, y };

// A parameter's lazy rep: its interval is the one CGAL's lazy construction would give (the caller
// makes it with the same operations), and it keeps the points, so that its exact value, and its
// rounding, can be had from their doubles when they are points of doubles or image points of input
// vertices (crossing_point.hpp's affine_of).
template <Along kind>
class ParameterOf final : public QuotientRep {
  static constexpr std::size_t N = kind == Along::crossing ? 4 : 3;

 public:
  // Crossing: a, b, c, d; along an axis: a, b, q.
  ParameterOf(const CGAL::Interval_nt<false>& approx, std::array<Point2, N> points)
      : QuotientRep(approx), points_(std::move(points)) {}

  std::optional<std::array<CGAL::Mpzf, 2>> quotient() const override {
    std::array<double, 2 * N> v;
    bool doubles = true;
    for (std::size_t i = 0; i < N && doubles; ++i) {
      const auto& p = CGAL::approx(points_[i]);
      for (int k = 0; k < 2; ++k) {
        if ((kind == Along::x && k == 1) || (kind == Along::y && k == 0)) continue;
        const auto& c = k == 0 ? p.x() : p.y();
        if (c.inf() != c.sup()) doubles = false;  // an interval of one double holds that double
        v[2 * i + k] = c.inf();
      }
    }
    if (doubles) return terms<CGAL::Mpzf>([&](std::size_t i, int k) { return CGAL::Mpzf(v[2 * i + k]); });
    // Image points of input vertices in a general view: their coordinates in Mpzf.
    std::array<crossing_detail::Homogeneous, N> own;
    std::array<const crossing_detail::Homogeneous*, N> z;
    for (std::size_t i = 0; i < N; ++i)
      if (!(z[i] = crossing_detail::affine_of(points_[i], own[i]))) return std::nullopt;
    return terms<CGAL::Mpzf>([&](std::size_t i, int k) -> const CGAL::Mpzf& { return (*z[i])[k]; });
  }

  void update_exact() const override {
    ET t;
    if (const auto q = quotient()) {
      t = ET((*q)[0]) / ET((*q)[1]);
    } else {
      const auto [num, den] = terms<ET>([&](std::size_t i, int k) -> const ET& {
        const auto& p = CGAL::exact(points_[i]);
        return k == 0 ? p.x() : p.y();
      });
      t = num / den;
    }
    auto* exact = new Indirect(std::move(t));
    this->set_at(exact);
    this->set_ptr(exact);
  }

 private:
  template <class T, class Coordinate>
  static std::array<T, 2> terms(Coordinate&& c) {
    if constexpr (kind == Along::crossing) return crossing<T>(c(0, 0), c(0, 1), c(1, 0), c(1, 1), c(2, 0), c(2, 1), c(3, 0), c(3, 1));
    else if constexpr (kind == Along::x) return along<T>(c(0, 0), c(1, 0), c(2, 0));
    else return along<T>(c(0, 1), c(1, 1), c(2, 1));
  }
  std::array<Point2, N> points_;
};

}  // namespace parameter_detail

// The double nearest to v, when v keeps a quotient of doubles (lazy_rep.hpp's QuotientRep: a
// parameter whose points are doubles, a view coordinate of an input point); else nothing.
inline std::optional<double> nearest_by_quotient(const CGAL::Epeck::FT& v) {
  const auto q = quotient_of(v);
  if (!q) return std::nullopt;
  return nearest_quotient((*q)[0], (*q)[1]);
}

// The double nearest to a + t (b − a), when a, b and t are each a double or keep a quotient of
// doubles; else nothing.
inline std::optional<double> nearest_between(const CGAL::Epeck::FT& a, const CGAL::Epeck::FT& b,
                                             const CGAL::Epeck::FT& t) {
  using Z = CGAL::Mpzf;
  const auto q = quotient_of(t);
  if (!q) return std::nullopt;
  const auto& [num, den] = *q;
  const auto &ia = CGAL::approx(a), &ib = CGAL::approx(b);
  if (ia.inf() == ia.sup() && ib.inf() == ib.sup()) {
    const Z za(ia.inf());
    return nearest_quotient(za * den + num * (Z(ib.inf()) - za), den);
  }
  // a = na / da, b = nb / db: (na db den + num (nb da − na db)) / (da db den).
  auto part = [](const CGAL::Epeck::FT& v, const CGAL::Interval_nt<false>& i) -> std::optional<std::array<Z, 2>> {
    if (i.inf() == i.sup()) return std::array<Z, 2>{Z(i.inf()), Z(1)};
    return quotient_of(v);
  };
  const auto pa = part(a, ia), pb = part(b, ib);
  if (!pa || !pb) return std::nullopt;
  const auto &[na, da] = *pa;
  const auto &[nb, db] = *pb;
  const Z na_db = na * db;
  return nearest_quotient(na_db * den + num * (nb * da - na_db), da * db * den);
}

}  // namespace hlr
