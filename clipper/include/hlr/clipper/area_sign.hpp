// area_sign: the orientation of a contour (the sign of its area), filtered. On the exact kernel
// the area is first summed on the intervals Epeck keeps with every coordinate, and exactly
// (twice_signed_area, which makes every coordinate exact) only when they cannot decide: a face's
// facing in a perspective view would otherwise cost a GMP rational per corner and view. On the
// other kernels it is the sign of twice_signed_area, so that their roundings stay as they were.
#pragma once

#include <hlr/clipper/clipper.hpp>

#include <CGAL/Interval_nt.h>

namespace hlr::clip {

template <class K>
int area_sign(const Contour<K>& contour) {
  using G = Geometry<K>;
  if constexpr (G::exact_constructions) {
    CGAL::Protect_FPU_rounding<true> protect;  // every interval operation rounds outward
    using Interval = CGAL::Interval_nt<false>;
    auto interval = [](const typename G::FT& v) { return Interval(G::interval(v)); };
    const auto& pts = contour.points;
    const std::size_t n = pts.size();
    Interval sum = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const auto& p = pts[i];
      const auto& q = pts[(i + 1) % n];
      sum += interval(G::x(p)) * interval(G::y(q)) - interval(G::x(q)) * interval(G::y(p));
    }
    if (sum.inf() > 0 || sum.sup() < 0) {
      PredicateStats::add(PredicateFamily::sign, DecidedBy::interval);
      return sum.inf() > 0 ? 1 : -1;
    }
  }
  return G::sign(twice_signed_area(contour));
}

}  // namespace hlr::clip
