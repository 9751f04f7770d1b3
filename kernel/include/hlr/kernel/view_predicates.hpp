// hlr kernel, view predicates on input points: whether three model-space points (input doubles)
// have collinear images in a view, decided from their own coordinates. The view basis is exactly
// orthogonal to the direction d (view.hpp), so the images of p, q, r are collinear exactly when
// det[q - p, r - p, d] = 0. Interval arithmetic decides almost every case; rationals of the doubles
// decide the rest, far cheaper than the exact evaluation of the points' view coordinates.
// In a perspective view the images of p, q, r are collinear exactly when p, q, r and the eye are
// coplanar: det[q - p, r - p, e - p] = 0 (collinear_seen_from).
#pragma once

#include <hlr/kernel/view.hpp>

#include <CGAL/Exact_rational.h>
#include <CGAL/Interval_nt.h>

#include <array>

namespace hlr {

namespace view_detail {
// det[q - p, r - p, d], or with `from_p` det[q - p, r - p, d - p].
template <class NT>
auto det_with_direction(const Vec3& p, const Vec3& q, const Vec3& r, const Vec3& d, bool from_p = false) {
  const NT u[3] = {NT(q[0]) - NT(p[0]), NT(q[1]) - NT(p[1]), NT(q[2]) - NT(p[2])};
  const NT v[3] = {NT(r[0]) - NT(p[0]), NT(r[1]) - NT(p[1]), NT(r[2]) - NT(p[2])};
  const NT w[3] = {from_p ? NT(d[0]) - NT(p[0]) : NT(d[0]), from_p ? NT(d[1]) - NT(p[1]) : NT(d[1]),
                   from_p ? NT(d[2]) - NT(p[2]) : NT(d[2])};
  return CGAL::sign(u[0] * (v[1] * w[2] - v[2] * w[1]) + u[1] * (v[2] * w[0] - v[0] * w[2]) +
                    u[2] * (v[0] * w[1] - v[1] * w[0]));
}
}  // namespace view_detail

inline bool collinear_in_view(const Vec3& p, const Vec3& q, const Vec3& r, const Vec3& direction) {
  {
    CGAL::Protect_FPU_rounding<true> protect;
    const auto s = view_detail::det_with_direction<CGAL::Interval_nt<false>>(p, q, r, direction);
    if (CGAL::is_certain(s)) return CGAL::get_certain(s) == CGAL::ZERO;
  }
  return view_detail::det_with_direction<CGAL::Exact_rational>(p, q, r, direction) == CGAL::ZERO;
}

inline bool collinear_seen_from(const Vec3& p, const Vec3& q, const Vec3& r, const Vec3& eye) {
  {
    CGAL::Protect_FPU_rounding<true> protect;
    const auto s = view_detail::det_with_direction<CGAL::Interval_nt<false>>(p, q, r, eye, true);
    if (CGAL::is_certain(s)) return CGAL::get_certain(s) == CGAL::ZERO;
  }
  return view_detail::det_with_direction<CGAL::Exact_rational>(p, q, r, eye, true) == CGAL::ZERO;
}

}  // namespace hlr
