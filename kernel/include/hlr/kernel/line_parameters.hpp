// Parameters along an image line a + t (b − a), with (dx, dy) = b − a, as one number each.
//
// On the exact kernel a parameter written as arithmetic on lazy numbers is a tree of about ten
// lazy nodes: each is allocated, and each that is ever evaluated exactly costs a once-flag (a
// futex call), rational arithmetic and an MPFR refresh of its interval. The line classifier makes
// a parameter for every crossing and corner, and the output rounds the points at them, so here a
// parameter is one lazy node that keeps its points (exact_parameter.hpp): its exact value, and
// its rounding, come from their doubles where they are doubles, else from their exact values. Its
// interval is the one the tree would have (the same operations in the same order), so every
// filtered decision is the same; on the other kernels it is the plain formula.
#pragma once

#include <hlr/kernel/kernel.hpp>

namespace hlr {
namespace detail {

// A point's coordinates, whether it is a CGAL point (exact or approximate) or the double kernel's.
template <class P>
decltype(auto) x_of(const P& p) {
  if constexpr (requires { p.x(); }) return p.x();
  else return (p.x);
}
template <class P>
decltype(auto) y_of(const P& p) {
  if constexpr (requires { p.y(); }) return p.y();
  else return (p.y);
}

// t where the line a + t (dx, dy) meets the line through c and d (not parallel to it).
struct CrossingParameter {
  template <class P, class T>
  T operator()(const P& a, const T& dx, const T& dy, const P& c, const P& d) const {
    const T ex = x_of(d) - x_of(c), ey = y_of(d) - y_of(c);
    const T rx = x_of(c) - x_of(a), ry = y_of(c) - y_of(a);
    return T((rx * ey - ry * ex) / (dx * ey - dy * ex));
  }
};
// t of a point q on the line, from its abscissa or from its ordinate.
struct ParameterAlongX {
  template <class P, class T>
  T operator()(const P& a, const P& q, const T& dx) const { return T((x_of(q) - x_of(a)) / dx); }
};
struct ParameterAlongY {
  template <class P, class T>
  T operator()(const P& a, const P& q, const T& dy) const { return T((y_of(q) - y_of(a)) / dy); }
};

}  // namespace detail

// t where the line a + t (b − a), with (dx, dy) = b − a, meets the line through c and d (not
// parallel to it). On the exact kernel a rep that keeps a, b, c and d (exact_parameter.hpp).
template <class K>
typename Geometry<K>::FT crossing_parameter(const typename Geometry<K>::Point& a, const typename Geometry<K>::Point& b,
                                            const typename Geometry<K>::FT& dx, const typename Geometry<K>::FT& dy,
                                            const typename Geometry<K>::Point& c, const typename Geometry<K>::Point& d) {
  if constexpr (Geometry<K>::exact_constructions) {
    CGAL::Protect_FPU_rounding<true> protect;
    const auto approx =
        detail::CrossingParameter()(CGAL::approx(a), CGAL::approx(dx), CGAL::approx(dy), CGAL::approx(c), CGAL::approx(d));
    using Rep = parameter_detail::ParameterOf<parameter_detail::Along::crossing>;
    return typename Geometry<K>::FT(new Rep(approx, {a, b, c, d}));
  } else {
    return detail::CrossingParameter()(a, dx, dy, c, d);
  }
}

// t of a point q on the line a + t (b − a), from its abscissa (d = dx) or its ordinate (d = dy).
template <class K>
typename Geometry<K>::FT parameter_along(const typename Geometry<K>::Point& a, const typename Geometry<K>::Point& b,
                                         const typename Geometry<K>::Point& q, const typename Geometry<K>::FT& d,
                                         bool along_x) {
  if constexpr (Geometry<K>::exact_constructions) {
    using parameter_detail::Along, parameter_detail::ParameterOf;
    CGAL::Protect_FPU_rounding<true> protect;
    const auto& aa = CGAL::approx(a);
    const auto& aq = CGAL::approx(q);
    if (along_x) return typename Geometry<K>::FT(new ParameterOf<Along::x>(detail::ParameterAlongX()(aa, aq, CGAL::approx(d)), {a, b, q}));
    return typename Geometry<K>::FT(new ParameterOf<Along::y>(detail::ParameterAlongY()(aa, aq, CGAL::approx(d)), {a, b, q}));
  } else {
    return along_x ? detail::ParameterAlongX()(a, q, d) : detail::ParameterAlongY()(a, q, d);
  }
}

}  // namespace hlr
