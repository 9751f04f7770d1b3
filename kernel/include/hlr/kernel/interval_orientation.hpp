// orientation_of_intervals: the orientation of three points known by intervals (the
// approximations Epeck keeps with every point), decided in double with a static error bound,
// without the two changes of the FPU's rounding mode that CGAL's filtered predicate makes per
// call; 2 when the bound cannot decide (the caller then asks CGAL). Geometry<Epeck> puts it in
// front of CGAL's orientation, which the area sort and the clipper call millions of times.
#pragma once

#include <algorithm>
#include <cmath>

namespace hlr {

// The corners are taken at the lower ends of their intervals. Each difference of two coordinates
// U = fl(lo_b - lo_a) is then within E = w + A u (1 + u) of the difference of the true coordinates,
// w being the widest interval, A the largest |U| and u = 2^-53 (the rounding of a difference is
// at most |U| u). So the determinant U1 U2 - U3 U4 of the true differences is within 4AE + 2E^2
// of that of the U, and its evaluation in double within 4A^2 u (1 + 2u) of that. The bound is
// taken 1 + 2^-30 times larger, which covers the roundings of its own evaluation and of w. Far
// from the origin the differences stay small, and so does the bound. Differences outside
// [2^-400, 2^400] are left to CGAL: there underflow or overflow would break the bound.
template <class IntervalPoint>
int orientation_of_intervals(const IntervalPoint& a, const IntervalPoint& b, const IntervalPoint& c) {
  const double lo[6] = {a.x().inf(), a.y().inf(), b.x().inf(), b.y().inf(), c.x().inf(), c.y().inf()};
  const double hi[6] = {a.x().sup(), a.y().sup(), b.x().sup(), b.y().sup(), c.x().sup(), c.y().sup()};
  double w = 0;
  for (int k = 0; k < 6; ++k) w = std::max(w, hi[k] - lo[k]);
  const double u1 = lo[2] - lo[0], u2 = lo[5] - lo[1], u3 = lo[3] - lo[1], u4 = lo[4] - lo[0];
  const double largest = std::max({std::abs(u1), std::abs(u2), std::abs(u3), std::abs(u4)});
  constexpr double kTiny = 0x1p-400, kHuge = 0x1p400, u = 0x1p-53;
  if (!(largest >= kTiny && largest <= kHuge && w <= kHuge)) return 2;  // also infinities and NaN
  const double det = u1 * u2 - u3 * u4;
  const double e = w + largest * u * (1 + u);
  const double bound = (4 * largest * e + 2 * e * e + 4 * largest * largest * u * (1 + 2 * u)) * (1 + 0x1p-30);
  if (det > bound) return 1;
  if (det < -bound) return -1;
  return 2;
}

}  // namespace hlr
