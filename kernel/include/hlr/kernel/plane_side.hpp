// PlaneSide: on which side of the plane through three input points a point lies, exactly, for
// many points against one plane. The plane's cross product and the weights of its error bound are
// worked out once; each query is then one dot product in double and a comparison with a static
// error bound, and CGAL's orientation (filtered, exact) only where the bound cannot decide. The
// penetration search asks millions of these, six per pair of faces.
#pragma once

#include <hlr/kernel/kernel.hpp>
#include <hlr/kernel/view.hpp>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <array>
#include <cmath>

namespace hlr {

// The sign of S = (p - a) . n with n = (b - a) x (c - a), which is CGAL::orientation(a, b, c, p).
// Error bound: every one of the six products ap_i ab_j ac_k in S passes through at most eight
// roundings (three differences, two products and a difference in the minor n_i, the product with
// ap_i, two additions), so the computed S is within gamma_8 P of the exact one, P being the sum of
// the six products' magnitudes (the permanent), and gamma_8 = 8u / (1 - 8u), u = 2^-53. P computed
// from the rounded values is at most (1 + u)^-9 smaller; the bound 8u P (1 + 2^-30) covers both and
// the rounding of its own product. That holds without overflow and with underflow adding at most
// a few 2^-1074, which the 2^-30 margin covers while P >= 2^-900; P outside [2^-900, 2^900], an
// infinity or a NaN goes to CGAL.
class PlaneSide {
 public:
  PlaneSide(const Vec3& a, const Vec3& b, const Vec3& c) : a_(a), b_(b), c_(c) {
    const double ab[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double ac[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3, k = (i + 2) % 3;
      normal_[i] = ab[j] * ac[k] - ab[k] * ac[j];
      weight_[i] = std::abs(ab[j] * ac[k]) + std::abs(ab[k] * ac[j]);
    }
  }

  // -1, 0 or +1: CGAL::orientation(a, b, c, p).
  int operator()(const Vec3& p) const {
    if (const int s = in_double(p); s != 2) return record(DecidedBy::interval, s);
    // Epick's predicate: exact on doubles (its own filter, then expansion arithmetic).
    using IK = CGAL::Exact_predicates_inexact_constructions_kernel;
    auto point = [](const Vec3& v) { return IK::Point_3(v[0], v[1], v[2]); };
    return record(DecidedBy::doubles, static_cast<int>(CGAL::orientation(point(a_), point(b_), point(c_), point(p))));
  }

  // The sign as the static bound decides it, or 2 where it cannot (an exact zero among them).
  int in_double(const Vec3& p) const {
    const double ap[3] = {p[0] - a_[0], p[1] - a_[1], p[2] - a_[2]};
    const double s = ap[0] * normal_[0] + ap[1] * normal_[1] + ap[2] * normal_[2];
    const double permanent =
        std::abs(ap[0]) * weight_[0] + std::abs(ap[1]) * weight_[1] + std::abs(ap[2]) * weight_[2];
    if (!(permanent >= 0x1p-900 && permanent <= 0x1p900)) return 2;
    const double bound = permanent * (0x1p-50 * (1 + 0x1p-30));
    return s > bound ? 1 : s < -bound ? -1 : 2;
  }

 private:
  static int record(DecidedBy by, int sign) {
    PredicateStats::add(PredicateFamily::orientation, by);
    return sign;
  }

  Vec3 a_, b_, c_;
  double normal_[3], weight_[3];
};

// Whether the closed triangles p and q meet, given the side of each one's corners against the
// other's plane (PlaneSide: p_side[i] the side of p[i] against q's plane), every side non-zero and
// each triangle with corners on both sides: the case of nearly every pair the penetration search
// tests. It is Guigue and Devillers' test as CGAL::do_intersect(Triangle_3, Triangle_3) makes it
// after the same six orientations, which it would compute again: each triangle meets the line where
// the planes meet in a segment, from its edges around its one corner alone on its side, and the two
// segments overlap exactly when two more orientations of input points say so.
inline bool triangles_meet(const std::array<Vec3, 3>& p, const std::array<int, 3>& p_side,
                           const std::array<Vec3, 3>& q, const std::array<int, 3>& q_side) {
  using IK = CGAL::Exact_predicates_inexact_constructions_kernel;
  // The corners (s_min, t_min, s_max, t_max) that CGAL names: around the lone corner x, with its
  // neighbours in the triangle's order, (x, next, previous, x) when x is alone on the positive
  // side, (previous, x, x, next) when alone on the negative side.
  auto ends = [](const std::array<Vec3, 3>& t, const std::array<int, 3>& side) {
    const int x = side[0] == side[1] ? 2 : side[0] == side[2] ? 1 : 0;
    const int next = (x + 1) % 3, previous = (x + 2) % 3;
    auto point = [&](int k) { return IK::Point_3(t[k][0], t[k][1], t[k][2]); };
    return side[x] > 0 ? std::array{point(x), point(next), point(previous), point(x)}
                       : std::array{point(previous), point(x), point(x), point(next)};
  };
  const auto e1 = ends(p, p_side), e2 = ends(q, q_side);
  return CGAL::orientation(e1[0], e1[1], e2[0], e2[1]) != CGAL::POSITIVE &&
         CGAL::orientation(e1[2], e1[3], e2[3], e2[2]) != CGAL::POSITIVE;
}

}  // namespace hlr
