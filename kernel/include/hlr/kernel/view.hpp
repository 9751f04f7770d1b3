// Views: named CAD views and arbitrary directions, applied exactly (DESIGN.md, exactness rule 1).
//
// With d the look direction, the unnormalized basis X = d × up, Y = X × d, Z = −d gives view
// coordinates (X·p, Y·p, Z·p). On the exact kernel they are exact rationals of the input doubles,
// so planar faces stay planar and coplanar faces coplanar in every view; they differ from the
// orthonormal frame only by a positive scale per axis (|X|, |Y|, |Z|), applied when writing output.
// On Epick and double the same formulas run in double, which is what makes those kernels inexact.
//
// A perspective view (View::eye) maps p to (x/w, y/w, 1/w) with x = X·(p−e), y = Y·(p−e),
// w = d·(p−e) (DESIGN.md "Perspective"). The map is projective: planes stay planes, lines stay
// lines, and a larger third coordinate is nearer along each ray from the eye, so everything after
// the frame runs unchanged on these coordinates. Only points in front of the near plane
// w >= near() may be mapped: near_plane.hpp clips the faces and edges that reach behind it.
#pragma once

#include <hlr/kernel/kernel.hpp>
#include <hlr/kernel/scene.hpp>

#include <array>
#include <atomic>
#include <cstddef>
#include <new>
#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>
#include <string_view>
#include <type_traits>
#include <utility>

namespace hlr {

using Vec3 = std::array<double, 3>;

struct View {
  std::string name;  // "front", ..., or "custom"
  Vec3 direction{0, 0, -1};
  Vec3 up{0, 1, 0};
  // Perspective from this point (looking along `direction`); none: orthographic.
  std::optional<Vec3> eye;
  // Perspective: the near plane at this fraction of the largest depth d·(p−e) of the scene's
  // vertices, taken as the exact double; none: exactly 1/1000.
  std::optional<double> near_fraction;
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
      view = View{e.name, e.direction, e.up, std::nullopt, std::nullopt};
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
  if (v.eye)
    for (double c : *v.eye)
      if (!std::isfinite(c)) return "eye is not finite";
  if (v.near_fraction && !(*v.near_fraction > 0 && *v.near_fraction < 1)) return "near fraction is not in (0, 1)";
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

namespace view_detail {
// One view coordinate of a point on the exact kernel, row · p with an exact basis row, as a single
// lazy number: its interval from the row's intervals and the point's, its exact value from the
// row's exact values and the point's when a predicate first needs it. The same number as the sum
// of products plain arithmetic would make, without its chain of lazy nodes (about eleven per point
// in an iso view), each of which an exact evaluation would visit. Point: an input point (Vec3), or
// a constructed one (an Epeck point: a penetration line's end, which would otherwise also take a
// lazy number per model coordinate). Built on CGAL's Lazy_exact_nt_rep, as CGAL's own constants
// are (CGAL/Lazy_exact_nt.h).
struct ExactRows {
  std::array<std::array<ExactKernel::FT, 3>, 3> lazy;
  // The same rows in Mpzf (each a sum of products of the view's doubles): an input point's view
  // coordinate is then an integer in Mpzf, for predicates that skip rationals (lazy_rep.hpp).
  std::array<std::array<CGAL::Mpzf, 3>, 3> mpzf;
};
template <class ET, class Point>
struct RowDotBlock;

// Row `Row` of a point's view coordinates. The three of one point share one allocation, a
// RowDotBlock, which holds the rows and the point once: a rep's deallocation gives its share of
// the block back, and the last one frees it (about 100 bytes less per point than three allocations).
// For an input point it keeps its quotient (row · p over 1, in Mpzf).
template <class ET, class Point, int Row>
class RowDotRep final
    : public std::conditional_t<std::is_same_v<Point, Vec3>, QuotientRep, CGAL::Lazy_exact_nt_rep<ET>> {
  static constexpr bool input = std::is_same_v<Point, Vec3>;
  using Base = std::conditional_t<input, QuotientRep, CGAL::Lazy_exact_nt_rep<ET>>;
  using Block = RowDotBlock<ET, Point>;

 public:
  // Under upward rounding (CGAL::Protect_FPU_rounding), as CGAL's unprotected intervals need.
  RowDotRep(const ExactRows& rows, const Point& p) : Base(interval(rows.lazy[Row], p)) {}

  // QuotientRep's, for an input point (a constructed one has no such quotient).
  std::optional<std::array<CGAL::Mpzf, 2>> quotient() const {
    if constexpr (input) {
      const Block& block = block_of(this);
      const auto& row = block.rows->mpzf[Row];
      CGAL::Mpzf sum(0);
      for (int k = 0; k < 3; ++k)
        if (row[k].sign() != CGAL::ZERO) sum = sum + row[k] * CGAL::Mpzf(block.point[k]);
      return std::array<CGAL::Mpzf, 2>{std::move(sum), CGAL::Mpzf(1)};
    } else {
      return std::nullopt;
    }
  }

  void update_exact() const override {
    const Block& block = block_of(this);
    const auto& row = block.rows->lazy[Row];
    auto coordinate = [&](int k) {
      if constexpr (input) return ET(block.point[k]);
      else return CGAL::exact(block.point)[k];
    };
    ET sum(0);
    for (int k = 0; k < 3; ++k)
      if (!CGAL::is_zero(row[k])) sum += row[k].exact() * coordinate(k);
    auto* exact = new typename Base::Indirect(std::move(sum));
    this->set_at(exact);
    this->set_ptr(exact);
  }

  // CGAL's handle deletes a rep when its count drops to zero: after the destructor, this returns
  // the rep's place in its block.
  static void operator delete(void* rep) { Block::release(static_cast<std::byte*>(rep) - Row * Block::kRepSize); }

 private:
  static const Block& block_of(const RowDotRep* rep) {
    return *std::launder(reinterpret_cast<const Block*>(reinterpret_cast<const std::byte*>(rep) - Row * Block::kRepSize));
  }
  static CGAL::Interval_nt<false> interval(const std::array<ExactKernel::FT, 3>& row, const Point& p) {
    if constexpr (input) {
      return CGAL::approx(row[0]) * p[0] + CGAL::approx(row[1]) * p[1] + CGAL::approx(row[2]) * p[2];
    } else {
      const auto& a = CGAL::approx(p);
      return CGAL::approx(row[0]) * a.x() + CGAL::approx(row[1]) * a.y() + CGAL::approx(row[2]) * a.z();
    }
  }
};

// The reps come first, so that a rep finds its block from its own address and row.
template <class ET, class Point>
struct RowDotBlock {
  static constexpr std::size_t kRepSize = sizeof(RowDotRep<ET, Point, 0>);
  static_assert(sizeof(RowDotRep<ET, Point, 1>) == kRepSize && sizeof(RowDotRep<ET, Point, 2>) == kRepSize);
  alignas(RowDotRep<ET, Point, 0>) std::byte reps[3 * kRepSize];
  std::shared_ptr<const ExactRows> rows;
  Point point;
  std::atomic<int> live{3};

  RowDotBlock(std::shared_ptr<const ExactRows> r, const Point& p) : rows(std::move(r)), point(p) {}
  // A point's three coordinates, each a lazy number owning its rep.
  static std::array<ExactKernel::FT, 3> make(std::shared_ptr<const ExactRows> rows, const Point& p) {
    auto* block = new (::operator new(sizeof(RowDotBlock))) RowDotBlock(std::move(rows), p);
    const ExactRows& r = *block->rows;
    return {ExactKernel::FT(new (block->reps) RowDotRep<ET, Point, 0>(r, p)),
            ExactKernel::FT(new (block->reps + kRepSize) RowDotRep<ET, Point, 1>(r, p)),
            ExactKernel::FT(new (block->reps + 2 * kRepSize) RowDotRep<ET, Point, 2>(r, p))};
  }
  static void release(std::byte* start) {
    auto* block = std::launder(reinterpret_cast<RowDotBlock*>(start));
    if (block->live.fetch_sub(1, std::memory_order_acq_rel) == 1) {
      block->~RowDotBlock();
      ::operator delete(static_cast<void*>(block));
    }
  }
};
}  // namespace view_detail

// The exact, unnormalized view basis for kernel K.
template <GeometryKernel K>
class ViewFrame {
 public:
  using FT = typename Geometry<K>::FT;

  // An orthographic view (a perspective one needs its scene: the near plane depends on it).
  explicit ViewFrame(const View& view) : view_(view) {
    if (view.eye) throw std::invalid_argument("a perspective frame needs its scene");
    make_basis();
  }
  // Any view of these meshes. Perspective: the scene must have a vertex in front of the eye
  // (perspective_defect in near_plane.hpp says so first).
  ViewFrame(const View& view, const std::vector<Mesh>& meshes) : view_(view) {
    make_basis();
    if (view.eye) fit_near(meshes);
  }

  bool perspective() const { return view_.eye.has_value(); }
  // Perspective: d·(p−e), the depth of a model point along the (unnormalized) look direction.
  FT eye_depth(const FT& px, const FT& py, const FT& pz) const {
    return d_[0] * (px - e_[0]) + d_[1] * (py - e_[1]) + d_[2] * (pz - e_[2]);
  }
  FT eye_depth(const Vec3& p) const { return eye_depth(FT(p[0]), FT(p[1]), FT(p[2])); }
  // Perspective: ν, the depth of the near plane; what lies at a smaller depth is clipped away.
  const FT& near() const { return near_; }

 private:
  void make_basis() {
    const View& view = view_;
    const FT d[3] = {FT(view.direction[0]), FT(view.direction[1]), FT(view.direction[2])};
    const FT u[3] = {FT(view.up[0]), FT(view.up[1]), FT(view.up[2])};
    cross(d, u, x_);
    cross(x_, d, y_);
    for (int i = 0; i < 3; ++i) z_[i] = -d[i];
    if constexpr (std::is_same_v<FT, ExactKernel::FT>) {
      auto rows = std::make_shared<view_detail::ExactRows>();
      for (int k = 0; k < 3; ++k) rows->lazy[0][k] = x_[k], rows->lazy[1][k] = y_[k], rows->lazy[2][k] = z_[k];
      using Z = CGAL::Mpzf;
      const Z dz[3] = {Z(view.direction[0]), Z(view.direction[1]), Z(view.direction[2])};
      const Z uz[3] = {Z(view.up[0]), Z(view.up[1]), Z(view.up[2])};
      auto cross_z = [](const Z a[3], const Z b[3]) {
        return std::array<Z, 3>{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
      };
      rows->mpzf[0] = cross_z(dz, uz);
      rows->mpzf[1] = cross_z(rows->mpzf[0].data(), dz);
      for (int k = 0; k < 3; ++k) rows->mpzf[2][k] = -dz[k];
      rows_ = std::move(rows);
    }
    for (int i = 0; i < 3; ++i) {
      const FT* axis = i == 0 ? x_ : i == 1 ? y_ : z_;
      for (int k = 0; k < 3; ++k)
        coefficient_[i][k] = CGAL::is_zero(axis[k]) ? 0 : axis[k] == FT(1) ? 1 : axis[k] == FT(-1) ? -1 : 2;
      double sq = 0;
      for (int k = 0; k < 3; ++k) sq += CGAL::to_double(axis[k]) * CGAL::to_double(axis[k]);
      scale_[i] = std::sqrt(sq);
    }
    if (view.eye) {
      // Written coordinates are (x̂/ŵ, ŷ/ŵ, 1/ŵ): x/w times |d|/|X|, y/w times |d|/|Y|, 1/w times |d|.
      const double length_d = scale_[2];
      scale_[0] /= length_d;
      scale_[1] /= length_d;
      scale_[2] = 1 / length_d;
      for (int k = 0; k < 3; ++k) {
        d_[k] = d[k];
        e_[k] = FT((*view.eye)[k]);
      }
    }
  }
  // ν = fraction · the largest depth over the vertices, exact.
  void fit_near(const std::vector<Mesh>& meshes) {
    std::optional<FT> deepest;
    for (const Mesh& mesh : meshes)
      for (const Vec3& p : mesh.vertices) {
        const FT w = eye_depth(p);
        if (!deepest || *deepest < w) deepest = w;
      }
    if (!deepest || !CGAL::is_positive(*deepest)) throw std::invalid_argument("the whole scene is behind the eye");
    near_ = view_.near_fraction ? *deepest * FT(*view_.near_fraction) : *deepest / FT(1000);
  }

 public:

  ViewPoint<K> to_view(const Vec3& p) const {
    if constexpr (std::is_same_v<FT, ExactKernel::FT>)
      if (!view_.eye) return row_dots(p);
    return to_view(FT(p[0]), FT(p[1]), FT(p[2]));
  }
  // A model-space point given in the kernel's number type (a constructed point, on ExactKernel).
  // Perspective: the point must lie in front of the near plane (eye_depth >= near()).
  ViewPoint<K> to_view(const FT& px, const FT& py, const FT& pz) const {
    if (!view_.eye) {
      const FT q[3] = {px, py, pz};
      return {dot(0, q), dot(1, q), dot(2, q)};
    }
    const FT q[3] = {px - e_[0], py - e_[1], pz - e_[2]};
    const FT w = -dot(2, q);  // Z = −d
    return {dot(0, q) / w, dot(1, q) / w, FT(1) / w};
  }

  // An exact model-space point (a constructed one: a penetration line's end). The inexact
  // kernels take it rounded, which is what makes them inexact.
  ViewPoint<K> to_view(const ExactKernel::Point_3& p) const {
    if constexpr (std::is_same_v<FT, ExactKernel::FT>) {
      if (!view_.eye) return row_dots(p);
      return to_view(p.x(), p.y(), p.z());
    }
    else return to_view(Vec3{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
  }

  // A model-space segment's part in front of the near plane, in view coordinates (the whole
  // segment in an orthographic view); nothing when it lies wholly behind it. Its ends keep their
  // order.
  std::optional<std::pair<ViewPoint<K>, ViewPoint<K>>> to_view_clipped(const ExactKernel::Point_3& a,
                                                                      const ExactKernel::Point_3& b) const {
    if (!view_.eye) return std::pair{to_view(a), to_view(b)};
    auto coordinates = [](const ExactKernel::Point_3& p) -> std::array<FT, 3> {
      if constexpr (std::is_same_v<FT, ExactKernel::FT>) return {p.x(), p.y(), p.z()};
      else return {FT(CGAL::to_double(p.x())), FT(CGAL::to_double(p.y())), FT(CGAL::to_double(p.z()))};
    };
    std::array<FT, 3> p = coordinates(a), q = coordinates(b);
    const FT wp = eye_depth(p[0], p[1], p[2]), wq = eye_depth(q[0], q[1], q[2]);
    const bool p_behind = wp < near_, q_behind = wq < near_;
    if (p_behind && q_behind) return std::nullopt;
    if (p_behind || q_behind) {
      // The crossing, from the end in front (as near_plane.hpp makes them).
      const std::array<FT, 3>& front = p_behind ? q : p;
      const std::array<FT, 3>& back = p_behind ? p : q;
      const FT wf = p_behind ? wq : wp, wb = p_behind ? wp : wq;
      const FT t = (wf - near_) / (wf - wb);
      std::array<FT, 3> c;
      for (int k = 0; k < 3; ++k) c[k] = front[k] + t * (back[k] - front[k]);
      (p_behind ? p : q) = c;
    }
    return std::pair{to_view(p[0], p[1], p[2]), to_view(q[0], q[1], q[2])};
  }

  // |X|, |Y|, |Z| in double: divide a view coordinate by these to get model units.
  double scale(int axis) const { return scale_[axis]; }
  // A view coordinate as output writes it: in model units, the exact value correctly rounded to
  // double, then divided by the axis scale (irrational in general, so this is as close as output
  // gets); never -0.
  double rounded(const FT& value, int axis) const { return Geometry<K>::to_double(value) / scale_[axis] + 0.0; }
  // rounded(p's x or y, axis), without evaluating p exactly where it keeps how it was made.
  double rounded(const typename Geometry<K>::Point& p, int axis) const {
    return Geometry<K>::to_double(p, axis) / scale_[axis] + 0.0;
  }
  // rounded(a + t (b - a), axis), without building that number.
  double rounded_between(const FT& a, const FT& b, const FT& t, int axis) const {
    return Geometry<K>::to_double_between(a, b, t) / scale_[axis] + 0.0;
  }
  const View& view() const { return view_; }

  // The orthonormal frame in double, row-major 4x4 (the JSON's world_to_view), from the basis
  // correctly rounded: an approximation Epeck keeps would depend on what the run had evaluated
  // exactly, and so on the order in which threads met the work. Perspective:
  // rows [X̂, −X̂·e], [Ŷ, −Ŷ·e], [0, 0, 0, 1], [d̂, −d̂·e], so that a model point as the column
  // (x, y, z, 1), divided by the fourth component of its image, gives the written coordinates.
  std::array<std::array<double, 4>, 4> world_to_view() const {
    std::array<std::array<double, 4>, 4> m{};
    if (!view_.eye) {
      for (int i = 0; i < 3; ++i) {
        const FT* axis = i == 0 ? x_ : i == 1 ? y_ : z_;
        for (int k = 0; k < 3; ++k) m[i][k] = Geometry<K>::to_double(axis[k]) / scale_[i] + 0.0;  // + 0.0: no -0
      }
      m[3][3] = 1;
      return m;
    }
    const Vec3& e = *view_.eye;
    double length[3] = {0, 0, 0};
    for (int k = 0; k < 3; ++k) {
      length[0] += Geometry<K>::to_double(x_[k]) * Geometry<K>::to_double(x_[k]);
      length[1] += Geometry<K>::to_double(y_[k]) * Geometry<K>::to_double(y_[k]);
      length[2] += Geometry<K>::to_double(z_[k]) * Geometry<K>::to_double(z_[k]);
    }
    const int row_of_axis[3] = {0, 1, 3};
    for (int i = 0; i < 3; ++i) {
      const FT* axis = i == 0 ? x_ : i == 1 ? y_ : z_;
      const double sign = i == 2 ? -1 : 1;  // the last row is d̂ = −Ẑ
      double offset = 0;
      auto& row = m[row_of_axis[i]];
      for (int k = 0; k < 3; ++k) {
        row[k] = sign * Geometry<K>::to_double(axis[k]) / std::sqrt(length[i]) + 0.0;
        offset -= row[k] * e[k];
      }
      row[3] = offset + 0.0;
    }
    m[2][3] = 1;
    return m;
  }

 private:
  // An orthographic view point on the exact kernel: one RowDotRep per coordinate, in one block.
  template <class Point>
  ViewPoint<K> row_dots(const Point& p) const {
    CGAL::Protect_FPU_rounding<true> protect;
    auto [x, y, z] = view_detail::RowDotBlock<ExactKernel::FT::Exact_type, Point>::make(rows_, p);
    return {std::move(x), std::move(y), std::move(z)};
  }
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
  std::shared_ptr<const view_detail::ExactRows> rows_;  // the exact kernel's X, Y, Z, for RowDotRep
  FT d_[3], e_[3], near_;  // perspective: the direction, the eye, ν
  int coefficient_[3][3];  // per axis and component: 0, 1 or -1 when the coefficient is that, else 2
  double scale_[3];
};

}  // namespace hlr
