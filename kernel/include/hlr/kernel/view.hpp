// Views: named CAD views and arbitrary directions, applied exactly (DESIGN.md, exactness rule 1).
//
// With d the look direction, the unnormalized basis X = d × up, Y = X × d, Z = −d gives view
// coordinates (X·p, Y·p, Z·p). On the exact kernel they are exact rationals of the input doubles,
// so planar faces stay planar and coplanar faces coplanar in every view; they differ from the
// orthonormal frame only by a positive scale per axis (|X|, |Y|, |Z|), applied when writing output.
// On Epick and double the same formulas run in double, which is what makes those kernels inexact.
#pragma once

#include <hlr/kernel/kernel.hpp>

#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>

namespace hlr {

using Vec3 = std::array<double, 3>;

struct View {
  std::string name;  // "front", ..., or "custom"
  Vec3 direction{0, 0, -1};
  Vec3 up{0, 1, 0};
};

// The named views of DESIGN.md for Z-up models; false for an unknown name.
inline bool named_view(std::string_view name, View& view) {
  struct Entry {
    const char* name;
    Vec3 direction, up;
  };
  static const Entry table[] = {
      {"front", {0, 1, 0}, {0, 0, 1}},  {"back", {0, -1, 0}, {0, 0, 1}}, {"top", {0, 0, -1}, {0, 1, 0}},
      {"bottom", {0, 0, 1}, {0, -1, 0}}, {"right", {-1, 0, 0}, {0, 0, 1}}, {"left", {1, 0, 0}, {0, 0, 1}},
      {"iso", {-1, 1, -1}, {0, 0, 1}},
  };
  for (const auto& e : table) {
    if (name == e.name) {
      view = {e.name, e.direction, e.up};
      return true;
    }
  }
  return false;
}

inline constexpr const char* named_view_list = "front, back, top, bottom, left, right, iso";

// Why a view cannot be used, or nothing. Decided exactly: up parallel to direction means the
// exact cross product is zero.
inline std::optional<std::string> view_defect(const View& v) {
  for (double c : v.direction)
    if (!std::isfinite(c)) return "view direction is not finite";
  for (double c : v.up)
    if (!std::isfinite(c)) return "up vector is not finite";
  if (v.direction == Vec3{0, 0, 0}) return "view direction is zero";
  if (v.up == Vec3{0, 0, 0}) return "up vector is zero";
  using FT = ExactKernel::FT;
  const FT d[3] = {v.direction[0], v.direction[1], v.direction[2]};
  const FT u[3] = {v.up[0], v.up[1], v.up[2]};
  if (CGAL::is_zero(d[1] * u[2] - d[2] * u[1]) && CGAL::is_zero(d[2] * u[0] - d[0] * u[2]) &&
      CGAL::is_zero(d[0] * u[1] - d[1] * u[0]))
    return "up vector is parallel to the view direction";
  return std::nullopt;
}

template <class K>
struct ViewPoint {
  typename Geometry<K>::FT x, y, z;
};

// The exact, unnormalized view basis for kernel K.
template <GeometryKernel K>
class ViewFrame {
 public:
  using FT = typename Geometry<K>::FT;

  explicit ViewFrame(const View& view) : view_(view) {
    const FT d[3] = {FT(view.direction[0]), FT(view.direction[1]), FT(view.direction[2])};
    const FT u[3] = {FT(view.up[0]), FT(view.up[1]), FT(view.up[2])};
    cross(d, u, x_);
    cross(x_, d, y_);
    for (int i = 0; i < 3; ++i) z_[i] = -d[i];
    for (int i = 0; i < 3; ++i) {
      const FT* axis = i == 0 ? x_ : i == 1 ? y_ : z_;
      for (int k = 0; k < 3; ++k)
        coefficient_[i][k] = CGAL::is_zero(axis[k]) ? 0 : axis[k] == FT(1) ? 1 : axis[k] == FT(-1) ? -1 : 2;
      double sq = 0;
      for (int k = 0; k < 3; ++k) sq += CGAL::to_double(axis[k]) * CGAL::to_double(axis[k]);
      scale_[i] = std::sqrt(sq);
    }
  }

  ViewPoint<K> to_view(const Vec3& p) const { return to_view(FT(p[0]), FT(p[1]), FT(p[2])); }
  // A model-space point given in the kernel's number type (a constructed point, on ExactKernel).
  ViewPoint<K> to_view(const FT& px, const FT& py, const FT& pz) const {
    const FT q[3] = {px, py, pz};
    return {dot(0, q), dot(1, q), dot(2, q)};
  }

  // An exact model-space point (a constructed one: a penetration line's end). The inexact
  // kernels take it rounded, which is what makes them inexact.
  ViewPoint<K> to_view(const ExactKernel::Point_3& p) const {
    if constexpr (std::is_same_v<FT, ExactKernel::FT>) return to_view(p.x(), p.y(), p.z());
    else return to_view(Vec3{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
  }

  // |X|, |Y|, |Z| in double: divide a view coordinate by these to get model units.
  double scale(int axis) const { return scale_[axis]; }
  // A view coordinate as output writes it: in model units, the exact value correctly rounded to
  // double, then divided by the axis scale (irrational in general, so this is as close as output
  // gets); never -0.
  double rounded(const FT& value, int axis) const { return Geometry<K>::to_double(value) / scale_[axis] + 0.0; }
  const View& view() const { return view_; }

  // The orthonormal frame in double, row-major 4x4 (the JSON's world_to_view).
  std::array<std::array<double, 4>, 4> world_to_view() const {
    std::array<std::array<double, 4>, 4> m{};
    for (int i = 0; i < 3; ++i) {
      const FT* axis = i == 0 ? x_ : i == 1 ? y_ : z_;
      for (int k = 0; k < 3; ++k) m[i][k] = CGAL::to_double(axis[k]) / scale_[i] + 0.0;  // + 0.0: no -0
    }
    m[3][3] = 1;
    return m;
  }

 private:
  static void cross(const FT a[3], const FT b[3], FT out[3]) {
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
  }
  // X·q, Y·q or Z·q. Terms with a basis coefficient of 0 are left out and coefficients of ±1 are
  // not multiplied (named views have small integer bases): the same exact number as a smaller
  // expression, whose exact evaluation, when a predicate needs one, costs less.
  FT dot(int axis, const FT q[3]) const {
    const FT* a = axis == 0 ? x_ : axis == 1 ? y_ : z_;
    std::optional<FT> sum;
    for (int k = 0; k < 3; ++k) {
      const int c = coefficient_[axis][k];
      if (c == 0) continue;
      const FT term = c == 1 ? q[k] : c == -1 ? -q[k] : a[k] * q[k];
      sum = sum ? *sum + term : term;
    }
    return sum ? *sum : FT(0);
  }

  View view_;
  FT x_[3], y_[3], z_[3];
  int coefficient_[3][3];  // per axis and component: 0, 1 or -1 when the coefficient is that, else 2
  double scale_[3];
};

}  // namespace hlr
