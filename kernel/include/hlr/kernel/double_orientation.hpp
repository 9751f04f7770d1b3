// orientation_of_doubles: the orientation of three points whose coordinates are doubles, given as
// doubles, decided in double with Shewchuk's static error bound for orient2d; 2 when the bound
// cannot decide (the caller then asks the kernel). The clipper keeps the doubles of input
// vertices beside its edges and decides most of its pair tests here, without reading the
// intervals of Epeck's points (interval_orientation.hpp does that).
#pragma once

#include <cmath>

namespace hlr {

// Shewchuk's bound (Adaptive Precision Floating-Point Arithmetic, 1997, "ccwerrboundA"): with
// L = (ax - cx)(by - cy) and R = (ay - cy)(bx - cx) in double, the computed L - R is within
// (3 + 16u) u (|L| + |R|) of the exact determinant, u = 2^-53, the roundings of the bound's own
// evaluation included, when nothing underflows or overflows. A product that underflows is off by
// at most 2^-1074, far below the bound once |L| + |R| >= 2^-900; below that, past 2^1000, or on an
// infinity or NaN, the caller decides.
inline int orientation_of_doubles(double ax, double ay, double bx, double by, double cx, double cy) {
  const double left = (ax - cx) * (by - cy), right = (ay - cy) * (bx - cx);
  const double det = left - right, magnitude = std::abs(left) + std::abs(right);
  if (!(magnitude >= 0x1p-900 && magnitude <= 0x1p1000)) return 2;
  const double bound = 3.3306690738754716e-16 * magnitude;  // (3 + 16u) u, rounded up
  if (det > bound) return 1;
  if (det < -bound) return -1;
  return 2;
}

}  // namespace hlr
