// hlr kernel, view predicates on input points: whether three model-space points (input doubles)
// have collinear images in a view, decided from their own coordinates. The view basis is exactly
// orthogonal to the direction d (view.hpp), so the images of p, q, r are collinear exactly when
// det[q - p, r - p, d] = 0. Interval arithmetic decides almost every case; the doubles' exact sums
// and products (CGAL::Mpzf) decide the rest, far cheaper than the exact evaluation of the points'
// view coordinates.
// In a perspective view the images of p, q, r are collinear exactly when p, q, r and the eye are
// coplanar: det[q - p, r - p, e - p] = 0 (collinear_seen_from).
//
// Depth in an orthographic view, from model space (ModelPlane): the view map is linear with a
// positive determinant (|d|² |X|², view.hpp), so it keeps the sign of every orientation of four
// points, and the images of p, q, r turn counter-clockwise exactly when det[q - p, r - p, d] < 0
// (Binet–Cauchy: (X·u)(Y·w) - (Y·u)(X·w) = (X × Y)·(u × w), X × Y = -|X|² d). So whether a point
// lies nearer to the viewer than a plane through three input points, and where a line crosses
// that plane, are decided on the input doubles, without the plane's view-space equation.
#pragma once

#include <hlr/kernel/filtered_sign.hpp>
#include <hlr/kernel/view.hpp>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Mpzf.h>

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
  return view_detail::det_with_direction<CGAL::Mpzf>(p, q, r, direction) == CGAL::ZERO;
}

inline bool collinear_seen_from(const Vec3& p, const Vec3& q, const Vec3& r, const Vec3& eye) {
  {
    CGAL::Protect_FPU_rounding<true> protect;
    const auto s = view_detail::det_with_direction<CGAL::Interval_nt<false>>(p, q, r, eye, true);
    if (CGAL::is_certain(s)) return CGAL::get_certain(s) == CGAL::ZERO;
  }
  return view_detail::det_with_direction<CGAL::Mpzf>(p, q, r, eye, true) == CGAL::ZERO;
}

// The plane through three input points (not collinear) in an orthographic view along d.
class ModelPlane {
 public:
  using Point3 = ExactKernel::Point_3;
  using FT = ExactKernel::FT;

  ModelPlane(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& direction)
      : ModelPlane(a, b, c, -sign_of_det(a, b, c, direction)) {}
  // The same plane again from its points and turn(), without the determinant: where many planes
  // are kept, a turn each is kept rather than three points.
  static ModelPlane with_turn(const Vec3& a, const Vec3& b, const Vec3& c, int turn) { return {a, b, c, turn}; }
  int turn() const { return turn_; }

  // +1 where the plane lies strictly nearer to the viewer than p at p's image, -1 where farther,
  // 0 where p lies in it: the sign of z_plane(p) - z(p) = -volume(p) / n_z, with n_z the sign of
  // the images' turn.
  int nearer_than(const Vec3& p) const { return -turn_ * volume_sign(p); }
  int nearer_than(const Point3& p) const { return -turn_ * volume_sign(p); }

  // The parameter t where the segment p0 + t (p1 - p0) meets the plane, for ends strictly on
  // either side: volume(p0) / (volume(p0) - volume(p1)), the same in view space (a linear map
  // keeps ratios along a line). Of input points, one lazy number (CrossingRep).
  FT crossing(const Vec3& p0, const Vec3& p1) const {
    CGAL::Protect_FPU_rounding<true> protect;
    return FT(new CrossingRep<FT::Exact_type>({a_, b_, c_}, p0, p1));
  }
  FT crossing(const Point3& p0, const Point3& p1) const {
    const FT v0 = volume(p0), v1 = volume(p1);
    return v0 / (v0 - v1);
  }

 private:
  ModelPlane(const Vec3& a, const Vec3& b, const Vec3& c, int turn) : a_(a), b_(b), c_(c), turn_(turn) {}

  using IK = CGAL::Exact_predicates_inexact_constructions_kernel;
  static int sign_of_det(const Vec3& p, const Vec3& q, const Vec3& r, const Vec3& d) {
    return filtered_sign<CGAL::Mpzf>(
        [&]<class NT>(std::type_identity<NT>) { return view_detail::det_with_direction<NT>(p, q, r, d); });
  }
  static IK::Point_3 ip(const Vec3& v) { return {v[0], v[1], v[2]}; }
  // sign((b - a) × (c - a) · (p - a)): Epick's orientation, exact on doubles.
  int volume_sign(const Vec3& p) const { return CGAL::orientation(ip(a_), ip(b_), ip(c_), ip(p)); }
  int volume_sign(const Point3& p) const {
    // The point's interval or exact coordinates as they are: p.x() would make a lazy number.
    return filtered_sign([&]<class NT>(std::type_identity<NT>) {
      if constexpr (std::is_same_v<NT, CGAL::Exact_rational>) {
        const auto& e = CGAL::exact(p);
        return CGAL::sign(volume<NT>({a_, b_, c_}, NT(e.x()), NT(e.y()), NT(e.z())));
      } else {
        const auto& i = CGAL::approx(p);
        return CGAL::sign(volume<NT>({a_, b_, c_}, NT(i.x()), NT(i.y()), NT(i.z())));
      }
    });
  }
  // (b - a) × (c - a) · (p - a) in NT, from the doubles and p's coordinates in NT.
  template <class NT>
  static NT volume(const std::array<Vec3, 3>& plane, const NT& px, const NT& py, const NT& pz) {
    const auto& [a, b, c] = plane;
    const NT ax(a[0]), ay(a[1]), az(a[2]);
    const NT qx = px - ax, qy = py - ay, qz = pz - az;
    const NT ux = NT(b[0]) - ax, uy = NT(b[1]) - ay, uz = NT(b[2]) - az;
    const NT wx = NT(c[0]) - ax, wy = NT(c[1]) - ay, wz = NT(c[2]) - az;
    return qx * (uy * wz - uz * wy) + qy * (uz * wx - ux * wz) + qz * (ux * wy - uy * wx);
  }
  FT volume(const Point3& p) const { return volume<FT>({a_, b_, c_}, p.x(), p.y(), p.z()); }

  // The crossing parameter of two input points as one lazy number: its interval from the doubles
  // in interval arithmetic, its exact value from them when a comparison first needs it, instead of
  // the thirty-odd lazy nodes of the same expression in FT (CGAL/Lazy_exact_nt.h's pattern, as
  // view.hpp's RowDotRep).
  template <class ET>
  class CrossingRep final : public CGAL::Lazy_exact_nt_rep<ET> {
    using Base = CGAL::Lazy_exact_nt_rep<ET>;

   public:
    // Under upward rounding (CGAL::Protect_FPU_rounding), as CGAL's unprotected intervals need.
    CrossingRep(const std::array<Vec3, 3>& plane, const Vec3& p0, const Vec3& p1)
        : Base(ratio<CGAL::Interval_nt<false>>(plane, p0, p1)), plane_(plane), p0_(p0), p1_(p1) {}
    void update_exact() const override {
      auto* exact = new typename Base::Indirect(ratio<ET>(plane_, p0_, p1_));
      this->set_at(exact);
      this->set_ptr(exact);
    }

   private:
    template <class NT>
    static NT ratio(const std::array<Vec3, 3>& plane, const Vec3& p0, const Vec3& p1) {
      const NT v0 = volume<NT>(plane, NT(p0[0]), NT(p0[1]), NT(p0[2]));
      const NT v1 = volume<NT>(plane, NT(p1[0]), NT(p1[1]), NT(p1[2]));
      return v0 / (v0 - v1);
    }
    std::array<Vec3, 3> plane_;
    Vec3 p0_, p1_;
  };

  Vec3 a_, b_, c_;
  int turn_;  // orientation of the images of a, b, c: the sign of the plane's view normal's z
};

}  // namespace hlr
