// hlr kernel layer: the three number models hlr runs on, behind one small traits interface.
//
//   ExactKernel   CGAL Epeck: exact predicates and exact constructions. What users get.
//   EpickKernel   CGAL Epick: exact predicates, constructions rounded to double.
//   DoubleKernel  plain double everywhere: the naive baseline for the stability chart.
//
// Algorithms are templates over K and reach geometry only through Geometry<K>, so the same code
// runs on all three. Every robustness decision lives here, not in the algorithms.
#pragma once

#include <hlr/kernel/crossing_point.hpp>
#include <hlr/kernel/exact_parameter.hpp>
#include <hlr/kernel/interval_orientation.hpp>
#include <hlr/kernel/lazy_rep.hpp>

#include <CGAL/Bbox_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <atomic>
#include <concepts>
#include <cstdint>
#include <utility>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>
#include <string_view>
#include <type_traits>

namespace hlr {

using ExactKernel = CGAL::Exact_predicates_exact_constructions_kernel;
using EpickKernel = CGAL::Exact_predicates_inexact_constructions_kernel;

struct DoublePoint {
  double x = 0, y = 0;
};
struct DoubleKernel {
  using FT = double;
  using Point_2 = DoublePoint;
};

enum class KernelKind { exact, epick, floating };

// "exact" | "epick" | "double"; returns false on an unknown name.
inline bool parse_kernel_kind(std::string_view name, KernelKind& kind) {
  if (name == "exact") kind = KernelKind::exact;
  else if (name == "epick") kind = KernelKind::epick;
  else if (name == "double") kind = KernelKind::floating;
  else return false;
  return true;
}

inline const char* kernel_name(KernelKind kind) {
  switch (kind) {
    case KernelKind::exact: return "exact";
    case KernelKind::epick: return "epick";
    case KernelKind::floating: return "double";
  }
  return "?";
}

// Calls solve.template operator()<K>(kind) with the kernel type of `kind`: the one place where a
// run-time kernel choice becomes a type.
template <class Solve>
decltype(auto) with_kernel(KernelKind kind, Solve&& solve) {
  switch (kind) {
    case KernelKind::epick: return solve.template operator()<EpickKernel>(kind);
    case KernelKind::floating: return solve.template operator()<DoubleKernel>(kind);
    case KernelKind::exact: break;
  }
  return solve.template operator()<ExactKernel>(kind);
}

// The kind of kernel type K.
template <class K>
constexpr KernelKind kernel_kind_of() {
  if constexpr (std::is_same_v<K, ExactKernel>) return KernelKind::exact;
  else if constexpr (std::is_same_v<K, EpickKernel>) return KernelKind::epick;
  else return KernelKind::floating;
}

// An exact number written without rounding: "p/q", or "p" when q = 1.
inline std::string exact_rational_string(const ExactKernel::FT& v) {
  using ET = ExactKernel::FT::Exact_type;
  const ET& e = CGAL::exact(v);
  typename CGAL::Fraction_traits<ET>::Numerator_type num, den;
  typename CGAL::Fraction_traits<ET>::Decompose()(e, num, den);
  std::ostringstream out;
  out << num;
  if (den != 1) out << '/' << den;
  return out.str();
}
// A double is a dyadic rational, written as such.
inline std::string exact_string_of_double(double d) { return exact_rational_string(ExactKernel::FT(d)); }

// How the exact kernel's predicates were decided, counted when the environment has
// HLR_PREDICATE_STATS (hlr prints them on exit): without arithmetic (the same point twice), by
// interval arithmetic on the approximations Epeck keeps, exactly on doubles (points whose
// coordinates are doubles, without GMP), or by exact rational arithmetic.
enum class PredicateFamily { orientation, comparison, sign, count };
enum class DecidedBy { identity, interval, doubles, exact, count };
struct PredicateStats {
  static inline const bool enabled = std::getenv("HLR_PREDICATE_STATS") != nullptr;
  static inline std::atomic<std::uint64_t> counts[int(PredicateFamily::count)][int(DecidedBy::count)] = {};
  static void add(PredicateFamily f, DecidedBy d) {
    if (enabled) counts[int(f)][int(d)].fetch_add(1, std::memory_order_relaxed);
  }
};

// Signs are returned as int: -1, 0, +1.
template <class K>
struct Geometry;

// FT's exact number type when it is a lazy number, else FT itself.
template <class FT, class = void>
struct ExactTypeOf {
  using type = FT;
};
template <class FT>
struct ExactTypeOf<FT, std::void_t<typename FT::Exact_type>> {
  using type = typename FT::Exact_type;
};

template <class K>
struct CgalGeometry {
  using FT = typename K::FT;
  using Point = typename K::Point_2;
  static constexpr bool exact_constructions = std::is_same_v<K, ExactKernel>;

  // A key shared exactly by copies of one point (on the exact kernel, its representation): equal
  // keys mean equal points without arithmetic. 0 on kernels whose points are plain values.
  static std::uintptr_t identity(const Point& p) {
    if constexpr (exact_constructions) return static_cast<std::uintptr_t>(p.id());
    else return 0;
  }
  // Copies of one Epeck point. (CGAL::identical would compare the two objects' addresses here: its
  // Handle overload loses to the generic template for Point_2.)
  static bool same(const Point& a, const Point& b) { return exact_constructions && identity(a) == identity(b); }
  // Copies of one lazy number, known without arithmetic; false on kernels of plain values. (The
  // member compares representations; the free CGAL::identical would compare the two objects'
  // addresses for a Lazy_exact_nt, its template beating the Handle overload.)
  static bool same_number(const FT& a, const FT& b) {
    if constexpr (exact_constructions) return a.identical(b);
    else return false;
  }

  static Point point(double x, double y) { return Point(x, y); }
  // On the exact kernel, a point whose coordinates keep quotients of doubles (an input vertex's image
  // in a general view) keeps them (crossing_point.hpp's coordinate_point), for predicates decided
  // without rationals.
  static Point point(const FT& x, const FT& y) requires(!std::is_same_v<FT, double>) {
    if constexpr (exact_constructions) {
      const auto &ix = CGAL::approx(x), &iy = CGAL::approx(y);
      if (ix.inf() != ix.sup() || iy.inf() != iy.sup())
        if (auto p = coordinate_point(x, y)) return std::move(*p);
    }
    return Point(x, y);
  }
  static int sign(const FT& v) {
    if constexpr (exact_constructions)
      if (PredicateStats::enabled) {
        const auto i = CGAL::approx(v);
        PredicateStats::add(PredicateFamily::sign, i.inf() > 0 || i.sup() < 0 || (i.inf() == 0 && i.sup() == 0)
                                                       ? DecidedBy::interval
                                                       : DecidedBy::exact);
      }
    return static_cast<int>(CGAL::sign(v));
  }
  static int orientation(const Point& a, const Point& b, const Point& c) {
    // Two corners that are one shared Epeck point (a mesh vertex in two faces) make the
    // orientation 0: known without the interval filter, which cannot certify a zero and would
    // fall back to exact arithmetic.
    if constexpr (exact_constructions) {
      if (same(a, b) || same(b, c) || same(a, c)) {
        PredicateStats::add(PredicateFamily::orientation, DecidedBy::identity);
        return 0;
      }
      // Points whose coordinates are doubles (input vertices in the axis views, strip corners):
      // Epick's orientation is exact on doubles, with a static filter and, for the collinear
      // cases the filter cannot settle, expansion arithmetic (Mpzf) instead of GMP rationals.
      const auto &ia = CGAL::approx(a), &ib = CGAL::approx(b), &ic = CGAL::approx(c);
      if (const int o = orientation_of_intervals(ia, ib, ic); o != 2) {
        PredicateStats::add(PredicateFamily::orientation, DecidedBy::interval);
        return o;
      }
      auto record = [&](DecidedBy by) {
        if (!PredicateStats::enabled) return;
        CGAL::Protect_FPU_rounding<true> protect;
        const auto o = CGAL::orientation(ia, ib, ic);
        PredicateStats::add(PredicateFamily::orientation, CGAL::is_certain(o) ? DecidedBy::interval : by);
      };
      if (is_double(ia) && is_double(ib) && is_double(ic)) {
        record(DecidedBy::doubles);
        using E = EpickKernel::Point_2;
        return static_cast<int>(CGAL::orientation(E(ia.x().inf(), ia.y().inf()), E(ib.x().inf(), ib.y().inf()),
                                                  E(ic.x().inf(), ic.y().inf())));
      }
      // Crossings of lines through points of doubles (crossing_point.hpp): exact without rationals.
      if (const auto o = orientation_from_doubles(a, b, c)) {
        record(DecidedBy::doubles);
        return *o;
      }
      record(DecidedBy::exact);
    }
    return static_cast<int>(CGAL::orientation(a, b, c));
  }
  // Comparisons first look at the interval approximations Epeck keeps with every point, which
  // decide almost every case without CGAL's filter machinery; ties go to CGAL's exact predicate.
  static int compare_x(const Point& a, const Point& b) {
    if constexpr (exact_constructions) {
      if (same(a, b)) return counted(DecidedBy::identity, 0);
      const int c = compare_intervals(CGAL::approx(a).x(), CGAL::approx(b).x());
      if (c != 2) return counted(DecidedBy::interval, c);
      if (const auto d = compare_from_doubles(a, b, 0)) return counted(DecidedBy::doubles, *d);
      PredicateStats::add(PredicateFamily::comparison, DecidedBy::exact);
    }
    return static_cast<int>(CGAL::compare_x(a, b));
  }
  static int compare_y(const Point& a, const Point& b) {
    if constexpr (exact_constructions) {
      if (same(a, b)) return counted(DecidedBy::identity, 0);
      const int c = compare_intervals(CGAL::approx(a).y(), CGAL::approx(b).y());
      if (c != 2) return counted(DecidedBy::interval, c);
      if (const auto d = compare_from_doubles(a, b, 1)) return counted(DecidedBy::doubles, *d);
      PredicateStats::add(PredicateFamily::comparison, DecidedBy::exact);
    }
    return static_cast<int>(CGAL::compare_y(a, b));
  }
  static int compare_xy(const Point& a, const Point& b) {
    if constexpr (exact_constructions) {
      if (same(a, b)) return counted(DecidedBy::identity, 0);
      const int c = compare_intervals(CGAL::approx(a).x(), CGAL::approx(b).x());
      if (c == -1 || c == 1) return counted(DecidedBy::interval, c);
      if (c == 0) {
        const int d = compare_intervals(CGAL::approx(a).y(), CGAL::approx(b).y());
        if (d != 2) return counted(DecidedBy::interval, d);
      }
      if (const auto d = compare_from_doubles(a, b, 2)) return counted(DecidedBy::doubles, *d);
      PredicateStats::add(PredicateFamily::comparison, DecidedBy::exact);
    }
    return static_cast<int>(CGAL::compare_xy(a, b));
  }
  static bool equal(const Point& a, const Point& b) {
    if constexpr (exact_constructions) {
      if (same(a, b)) return true;
      if (compare_intervals(CGAL::approx(a).x(), CGAL::approx(b).x()) % 2 != 0 ||
          compare_intervals(CGAL::approx(a).y(), CGAL::approx(b).y()) % 2 != 0)
        return false;
    }
    return a == b;
  }
  static int counted(DecidedBy by, int result) {
    PredicateStats::add(PredicateFamily::comparison, by);
    return result;
  }
  // Whether an interval point is one point of doubles: its approximation is then its exact value.
  template <class IntervalPoint>
  static bool is_double(const IntervalPoint& p) {
    return is_double_point(p);
  }
  // -1 or +1 when the intervals are apart, 0 when both are the same single number, 2 otherwise.
  template <class Interval>
  static int compare_intervals(const Interval& a, const Interval& b) {
    if (a.sup() < b.inf()) return -1;
    if (a.inf() > b.sup()) return 1;
    if (a.inf() == a.sup() && b.inf() == b.sup()) return 0;  // the same double, exactly
    return 2;
  }

  // The intersection of the line through a, b with the line through c, d (not parallel).
  // On the exact kernel the crossing is one lazy point that keeps the four points
  // (crossing_point.hpp), whose predicates need no rationals where those are points of doubles.
  // Where a line is known to be axis-parallel (its points' coordinates are one double), the
  // crossing's interval takes that coordinate itself, so that crossings along the line (a strip
  // border) compare without exact arithmetic.
  static Point line_intersection(const Point& a, const Point& b, const Point& c, const Point& d) {
    if constexpr (exact_constructions) {
      const auto &ia = CGAL::approx(a), &ib = CGAL::approx(b), &ic = CGAL::approx(c), &id = CGAL::approx(d);
      typename K::Approximate_kernel::Point_2 approx;
      try {
        CGAL::Protect_FPU_rounding<true> protect;
        approx = LineCrossing<typename K::Approximate_kernel>()(ia, ib, ic, id);
      } catch (const CGAL::Uncertain_conversion_exception&) {
        // The intervals cannot tell the lines apart from parallel ones: the point computed exactly
        // at once, from the points' doubles where it can be, else by CGAL's lazy construction.
        if (auto p = crossing_point_from_doubles({a, b, c, d})) return std::move(*p);
        using Crossing = CGAL::Lazy_construction<K, LineCrossing<typename K::Approximate_kernel>,
                                                 LineCrossing<typename K::Exact_kernel>>;
        return Crossing()(a, b, c, d);
      }
      const bool ax = compare_intervals(ia.x(), ib.x()) == 0, cx = compare_intervals(ic.x(), id.x()) == 0;
      const bool ay = compare_intervals(ia.y(), ib.y()) == 0, cy = compare_intervals(ic.y(), id.y()) == 0;
      if (ax || cx || ay || cy)
        approx = typename K::Approximate_kernel::Point_2(ax ? ia.x() : cx ? ic.x() : approx.x(),
                                                         ay ? ia.y() : cy ? ic.y() : approx.y());
      return crossing_point(approx, {a, b, c, d});
    } else {
      typename K::Line_2 l1(a, b), l2(c, d);
      auto result = CGAL::intersection(l1, l2);
      if (result)
        if (const Point* p = boost::get<Point>(&*result)) return *p;
      throw std::runtime_error("line_intersection: lines are parallel");
    }
  }
  static Point midpoint(const Point& a, const Point& b) { return CGAL::midpoint(a, b); }


  static FT x(const Point& p) { return p.x(); }
  static FT y(const Point& p) { return p.y(); }
  // sign(a x + b y + c - z): where a plane z = a x + b y + c lies against depth z at (x, y). Decided
  // on the interval approximations Epeck keeps when they suffice, before any lazy node is built.
  static int sign_above(const FT& a, const FT& b, const FT& c, const FT& px, const FT& py, const FT& z) {
    if constexpr (exact_constructions) {
      CGAL::Protect_FPU_rounding<true> protect;
      const auto v = CGAL::approx(a) * CGAL::approx(px) + CGAL::approx(b) * CGAL::approx(py) + CGAL::approx(c) -
                     CGAL::approx(z);
      if (v.inf() > 0 || v.sup() < 0) {
        PredicateStats::add(PredicateFamily::sign, DecidedBy::interval);
        return v.inf() > 0 ? 1 : -1;
      }
    }
    return sign(a * px + b * py + c - z);
  }
  // The double nearest to v (ties to the lower one): output is rounded once, correctly.
  static double to_double(const FT& v) {
    if constexpr (exact_constructions) {
      const std::pair<double, double> approx = CGAL::to_interval(v);
      if (approx.first == approx.second) return approx.first;
      if (const auto d = nearest_by_quotient(v)) return *d;
      return nearest_double(CGAL::exact(v));
    } else {
      return CGAL::to_double(v);
    }
  }
  // to_double of p's x (axis 0) or y (axis 1), from p's homogeneous coordinates in Mpzf where it
  // has them (crossing_point.hpp), without evaluating p in rationals.
  static double to_double(const Point& p, int axis) {
    if constexpr (exact_constructions) {
      const auto& c = axis == 0 ? CGAL::approx(p).x() : CGAL::approx(p).y();
      if (c.inf() == c.sup()) return c.inf();
      crossing_detail::Homogeneous own;
      if (const auto* h = crossing_detail::homogeneous_of(p, own))
        if (const auto d = nearest_quotient((*h)[axis], (*h)[2])) return *d;
    }
    return to_double(axis == 0 ? p.x() : p.y());
  }
  // to_double(a + t (b - a)), the point at t of the segment from a to b, without lazy nodes for
  // it: output rounds every inner point of every line, and each lazy node evaluated exactly costs
  // a once-flag (a futex call) and an MPFR interval refresh on top of its rational arithmetic.
  static double to_double_between(const FT& a, const FT& b, const FT& t) {
    if constexpr (exact_constructions) {
      {
        CGAL::Protect_FPU_rounding<true> protect;
        const auto v = CGAL::approx(a) + CGAL::approx(t) * (CGAL::approx(b) - CGAL::approx(a));
        if (v.inf() == v.sup()) return v.inf();
      }
      if (const auto d = nearest_between(a, b, t)) return *d;
      using ET = typename FT::Exact_type;
      const ET& ea = CGAL::exact(a);
      return nearest_double(ET(ea + CGAL::exact(t) * (CGAL::exact(b) - ea)));
    } else {
      return CGAL::to_double(a + t * (b - a));
    }
  }
  // A double near v, for candidate filters and rough orders only, never for a decision: a bound
  // made from it must be widened (on the exact kernel it is the approximation Epeck keeps).
  static double rough_double(const FT& v) { return CGAL::to_double(v); }
  // An interval of doubles that contains v: where [lo, hi] settles a question, no exact
  // arithmetic is needed.
  static std::pair<double, double> interval(const FT& v) { return CGAL::to_interval(v); }
  // v as a number that sums without building lazy nodes: a long sum of lazy numbers is a chain as
  // deep as it is long, and evaluating it exactly recurses deep enough to overflow the stack.
  using Exact = std::conditional_t<exact_constructions, typename ExactTypeOf<FT>::type, FT>;
  static decltype(auto) exact(const FT& v) {
    if constexpr (exact_constructions) return CGAL::exact(v);
    else return v;
  }
  // On the exact kernel, the box of the approximation Epeck keeps, read as CGAL's bbox() would,
  // without its two changes of the FPU's rounding mode (a third of a line test's time).
  static CGAL::Bbox_2 bbox(const Point& p) {
    if constexpr (exact_constructions) {
      const auto& a = CGAL::approx(p);
      return {a.x().inf(), a.y().inf(), a.x().sup(), a.y().sup()};
    } else {
      return p.bbox();
    }
  }

  static std::string exact_string(const FT& v) {
    if constexpr (exact_constructions) return exact_rational_string(v);
    else return exact_string_of_double(CGAL::to_double(v));
  }

 private:
  template <class ET>
  static double nearest_double(const ET& e) {
    const std::pair<double, double> tight = CGAL::to_interval(e);
    if (tight.first == tight.second) return tight.first;
    return e - ET(tight.first) <= ET(tight.second) - e ? tight.first : tight.second;
  }
};

template <>
struct Geometry<ExactKernel> : CgalGeometry<ExactKernel> {};
template <>
struct Geometry<EpickKernel> : CgalGeometry<EpickKernel> {};

// Plain double: every predicate is the naive formula, with no filter and no fallback.
template <>
struct Geometry<DoubleKernel> {
  using FT = double;
  using Point = DoublePoint;
  static constexpr bool exact_constructions = false;

  static Point point(double x, double y) { return {x, y}; }
  static int sign(double v) { return (v > 0) - (v < 0); }
  static int orientation(const Point& a, const Point& b, const Point& c) {
    return sign((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
  }
  static int compare_x(const Point& a, const Point& b) { return sign(a.x - b.x); }
  static int compare_y(const Point& a, const Point& b) { return sign(a.y - b.y); }
  static int compare_xy(const Point& a, const Point& b) {
    int c = compare_x(a, b);
    return c != 0 ? c : compare_y(a, b);
  }
  static bool equal(const Point& a, const Point& b) { return a.x == b.x && a.y == b.y; }
  static Point line_intersection(const Point& a, const Point& b, const Point& c, const Point& d) {
    double rx = b.x - a.x, ry = b.y - a.y, sx = d.x - c.x, sy = d.y - c.y;
    double den = rx * sy - ry * sx;
    if (den == 0) throw std::runtime_error("line_intersection: lines are parallel");
    double t = ((c.x - a.x) * sy - (c.y - a.y) * sx) / den;
    return {a.x + t * rx, a.y + t * ry};
  }
  static Point midpoint(const Point& a, const Point& b) { return {(a.x + b.x) / 2, (a.y + b.y) / 2}; }
  static std::uintptr_t identity(const Point&) { return 0; }
  static double x(const Point& p) { return p.x; }
  static double y(const Point& p) { return p.y; }
  static int sign_above(double a, double b, double c, double px, double py, double z) {
    return sign(a * px + b * py + c - z);
  }
  static bool same_number(double, double) { return false; }
  static double to_double(double v) { return v; }
  static double to_double(const Point& p, int axis) { return axis == 0 ? p.x : p.y; }
  static double to_double_between(double a, double b, double t) { return a + t * (b - a); }
  static double rough_double(double v) { return v; }
  static std::pair<double, double> interval(double v) { return {v, v}; }
  using Exact = double;
  static double exact(double v) { return v; }
  static CGAL::Bbox_2 bbox(const Point& p) { return {p.x, p.y, p.x, p.y}; }
  static std::string exact_string(double v) { return exact_string_of_double(v); }
};

// What an algorithm may ask of a kernel: every geometric question and construction hlr's
// algorithms make goes through these operations of Geometry<K>, so that a kernel is a choice of
// number model and nothing else (the clipper, the area sort and the line classifier are templates
// over K and reach numbers only here).
template <class K>
concept GeometryKernel = requires(const typename Geometry<K>::Point& p, const typename Geometry<K>::FT& v, double d) {
  typename Geometry<K>::Exact;
  { Geometry<K>::exact_constructions } -> std::convertible_to<bool>;
  // points
  { Geometry<K>::point(d, d) } -> std::same_as<typename Geometry<K>::Point>;
  { Geometry<K>::x(p) } -> std::convertible_to<typename Geometry<K>::FT>;
  { Geometry<K>::y(p) } -> std::convertible_to<typename Geometry<K>::FT>;
  { Geometry<K>::identity(p) } -> std::same_as<std::uintptr_t>;
  { Geometry<K>::same_number(v, v) } -> std::same_as<bool>;
  { Geometry<K>::bbox(p) } -> std::same_as<CGAL::Bbox_2>;
  // predicates (signs and comparisons as -1, 0, +1)
  { Geometry<K>::sign(v) } -> std::same_as<int>;
  { Geometry<K>::orientation(p, p, p) } -> std::same_as<int>;
  { Geometry<K>::compare_x(p, p) } -> std::same_as<int>;
  { Geometry<K>::compare_y(p, p) } -> std::same_as<int>;
  { Geometry<K>::compare_xy(p, p) } -> std::same_as<int>;
  { Geometry<K>::equal(p, p) } -> std::same_as<bool>;
  { Geometry<K>::sign_above(v, v, v, v, v, v) } -> std::same_as<int>;
  // constructions from support lines
  { Geometry<K>::line_intersection(p, p, p, p) } -> std::same_as<typename Geometry<K>::Point>;
  { Geometry<K>::midpoint(p, p) } -> std::same_as<typename Geometry<K>::Point>;
  // numbers out: rounded once for output, rough for filters, enclosed, exact for long sums
  { Geometry<K>::to_double(v) } -> std::same_as<double>;
  { Geometry<K>::to_double_between(v, v, v) } -> std::same_as<double>;
  { Geometry<K>::rough_double(v) } -> std::same_as<double>;
  { Geometry<K>::interval(v) } -> std::same_as<std::pair<double, double>>;
  { Geometry<K>::exact(v) } -> std::convertible_to<typename Geometry<K>::Exact>;
  { Geometry<K>::exact_string(v) } -> std::same_as<std::string>;
};
static_assert(GeometryKernel<ExactKernel> && GeometryKernel<EpickKernel> && GeometryKernel<DoubleKernel>);

}  // namespace hlr
