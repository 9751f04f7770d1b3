// area_sign: the orientation of a contour (the sign of its area), filtered. On the exact kernel
// the area is first summed on the intervals Epeck keeps with every coordinate; where they cannot
// decide, exactly on the doubles when every coordinate is one, else by twice_signed_area (which
// makes every coordinate exact): a face's facing in a perspective view would otherwise cost a GMP
// rational per corner and view. On the other kernels it is the sign of twice_signed_area, so that
// their roundings stay as they were.
#pragma once

#include <hlr/clipper/clipper.hpp>

#include <CGAL/Interval_nt.h>
#include <CGAL/Mpzf.h>

#include <algorithm>

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
    // Corners whose coordinates are doubles (input vertices in the axis views, where faces seen
    // edge-on have area 0): products and sums of doubles are exact in CGAL::Mpzf, without the
    // lazy nodes and rationals of twice_signed_area.
    if (std::all_of(pts.begin(), pts.end(), [](const auto& p) { return G::is_double(CGAL::approx(p)); })) {
      PredicateStats::add(PredicateFamily::sign, DecidedBy::doubles);
      auto value = [](const typename G::FT& v) { return CGAL::Mpzf(G::interval(v).first); };
      CGAL::Mpzf twice_area = 0;
      for (std::size_t i = 0; i < n; ++i) {
        const auto& p = pts[i];
        const auto& q = pts[(i + 1) % n];
        twice_area = twice_area + (value(G::x(p)) * value(G::y(q)) - value(G::x(q)) * value(G::y(p)));
      }
      return static_cast<int>(CGAL::sign(twice_area));
    }
  }
  return G::sign(twice_signed_area(contour));
}

}  // namespace hlr::clip
