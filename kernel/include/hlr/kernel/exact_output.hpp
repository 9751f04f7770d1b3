// Constructed points by their recipes: correctly rounded output without lazy numbers, and lazy
// exact points that do no exact arithmetic until a predicate needs it.
//
// Output rounds every line end once, correctly (Geometry::to_double). For an intersection line's
// end on Epeck that means evaluating its view coordinate X·p exactly: a lazy node per product
// and sum over rationals whose every operation takes a gcd, each node behind a once-flag (a futex
// call) and an MPFR refresh of its interval, about 10 µs per coordinate. Yet such an end is
// either an input point or where an edge u w crosses the plane through three input points a, b,
// c: p = (s_u w − s_w u) / (s_u − s_w) with s the signed volumes against the plane, so in an
// orthographic view X·p is a quotient of two sums of products of doubles, exact in CGAL::Mpzf
// (binary floating point of any length: no gcd, no heap for short numbers), and its nearest
// double takes a few multiplications. It is the same exact number, so the same double.
#pragma once

#include <hlr/kernel/lazy_rep.hpp>
#include <hlr/kernel/view.hpp>

#include <CGAL/Mpzf.h>

#include <array>
#include <optional>

namespace hlr {

// How a constructed model point was built from the input doubles.
struct ModelPointRecipe {
  enum class Kind : std::uint8_t { unknown, input_point, edge_crossing };
  Kind kind = Kind::unknown;
  Vec3 u{}, w{};     // input_point: u; edge_crossing: the edge from u to w ...
  Vec3 a{}, b{}, c{};  // ... where it crosses the plane through these (not collinear)
};

// The signed volumes (p − a)·((b − a) × (c − a)) of the points p of an edge u w against the plane
// through a, b, c, exactly; the plane's normal is made once for both.
inline std::array<CGAL::Mpzf, 2> edge_volumes(const ModelPointRecipe& r) {
  using Z = CGAL::Mpzf;
  const Vec3 &a = r.a, &b = r.b, &c = r.c;
  const Z ux = Z(b[0]) - Z(a[0]), uy = Z(b[1]) - Z(a[1]), uz = Z(b[2]) - Z(a[2]);
  const Z vx = Z(c[0]) - Z(a[0]), vy = Z(c[1]) - Z(a[1]), vz = Z(c[2]) - Z(a[2]);
  const Z nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
  auto volume = [&](const Vec3& p) { return (Z(p[0]) - Z(a[0])) * nx + (Z(p[1]) - Z(a[1])) * ny + (Z(p[2]) - Z(a[2])) * nz; };
  return {volume(r.u), volume(r.w)};
}

// The point as numerators and a common denominator: p = (n[0], n[1], n[2]) / n[3].
inline std::array<CGAL::Mpzf, 4> homogeneous(const ModelPointRecipe& r) {
  using Z = CGAL::Mpzf;
  if (r.kind == ModelPointRecipe::Kind::input_point) return {Z(r.u[0]), Z(r.u[1]), Z(r.u[2]), Z(1)};
  const auto [su, sw] = edge_volumes(r);
  std::array<Z, 4> n;
  for (int k = 0; k < 3; ++k) n[k] = su * Z(r.w[k]) - sw * Z(r.u[k]);
  n[3] = su - sw;
  return n;
}

namespace exact_output_detail {
using LazyPoint3 = CGAL::Lazy_rep<ExactKernel::Approximate_kernel::Point_3, ExactKernel::Exact_kernel::Point_3,
                                  ExactKernel::E2A>;
class RecipePointRep final : public LazyPoint3 {
 public:
  RecipePointRep(const ModelPointRecipe& recipe, const std::array<CGAL::Interval_nt<false>, 3>& approx)
      : LazyPoint3(ExactKernel::Approximate_kernel::Point_3(approx[0], approx[1], approx[2])), recipe_(recipe) {}

  void update_exact() const override {
    using ET = ExactKernel::Exact_kernel::FT;
    const std::array<CGAL::Mpzf, 4> n = homogeneous(recipe_);
    const ET den(n[3]);
    auto* exact = new ExactKernel::Exact_kernel::Point_3(ET(ET(n[0]) / den), ET(ET(n[1]) / den), ET(ET(n[2]) / den));
    this->set_at(exact);
    this->set_ptr(exact);
  }
  const ModelPointRecipe& recipe() const { return recipe_; }

 private:
  ModelPointRecipe recipe_;
};

// p's rep when lazy_point made it, else null.
inline const RecipePointRep* recipe_rep(const ExactKernel::Point_3& p) {
  return rep_as<RecipePointRep>(p);
}
}  // namespace exact_output_detail

// The recipe's point as a lazy exact point, given intervals that hold it: its exact coordinates
// (homogeneous: one rational division each) are made only when a predicate needs them, which for
// the crossings of penetration lines few do.
inline ExactKernel::Point_3 lazy_point(const ModelPointRecipe& recipe,
                                       const std::array<CGAL::Interval_nt<false>, 3>& approx) {
  return ExactKernel::Point_3(ExactKernel::Point_3::Rep(new exact_output_detail::RecipePointRep(recipe, approx)));
}

// A lazy_point made again: the same recipe and intervals in a rep of its own (any other point is
// returned as it is). For moving the points a computation keeps away from those it dropped.
inline ExactKernel::Point_3 remade(const ExactKernel::Point_3& p) {
  const auto* made = exact_output_detail::recipe_rep(p);
  if (!made) return p;
  const auto& a = p.approx();
  return lazy_point(made->recipe(), {a[0], a[1], a[2]});
}

// How `p` was built, read back from the point itself, so that nothing else need keep it: a
// lazy_point's recipe; an input point where every interval is a single double (an interval holds
// the exact value, so that double is the coordinate); else unknown.
inline ModelPointRecipe recipe_of(const ExactKernel::Point_3& p) {
  if (const auto* made = exact_output_detail::recipe_rep(p)) return made->recipe();
  const auto& a = p.approx();
  for (int k = 0; k < 3; ++k)
    if (a[k].inf() != a[k].sup()) return {};
  return {ModelPointRecipe::Kind::input_point, Vec3{a[0].inf(), a[1].inf(), a[2].inf()}};
}

// Orthographic views: the view coordinates of recipe points, rounded as ViewFrame::rounded does
// the same exact numbers (before its division by the axis scale).
class RecipeRounding {
 public:
  explicit RecipeRounding(const View& view) {
    if (view.eye) return;  // perspective coordinates are quotients of these: left to the general path
    const Row d = {Z(view.direction[0]), Z(view.direction[1]), Z(view.direction[2])};
    const Row u = {Z(view.up[0]), Z(view.up[1]), Z(view.up[2])};
    const Row x = cross(d, u);  // ViewFrame's basis: X = d × up, Y = X × d, Z = −d
    basis_ = {{x, cross(x, d), {-d[0], -d[1], -d[2]}}};
  }

  // The nearest doubles to the point's view coordinates, or nothing where the general path must
  // round them (an unknown recipe, a perspective view, a value out of the normal range).
  std::optional<std::array<double, 3>> nearest(const ModelPointRecipe& r) const {
    if (!basis_ || r.kind == ModelPointRecipe::Kind::unknown) return std::nullopt;
    const std::array<Z, 4> n = homogeneous(r);
    std::array<double, 3> out;
    for (int axis = 0; axis < 3; ++axis) {
      const Row& a = (*basis_)[axis];
      const std::optional<double> v = nearest_quotient(a[0] * n[0] + a[1] * n[1] + a[2] * n[2], n[3]);
      if (!v) return std::nullopt;
      out[axis] = *v;
    }
    return out;
  }

 private:
  using Z = CGAL::Mpzf;
  using Row = std::array<Z, 3>;
  static Row cross(const Row& a, const Row& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  }
  std::optional<std::array<Row, 3>> basis_;
};

}  // namespace hlr
