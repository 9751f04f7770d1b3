// fuzzy_cull (fuzzy_cull.hpp): Lim's fuzzy projection cube over the eyes' bounding box, its
// approximated umbrae in a depth buffer per cube face, and the faces found behind them.
#include <hlr/hidden_line/fuzzy_cull.hpp>
#include <hlr/hidden_line/jobs.hpp>
#include <hlr/kernel/mesh_edges.hpp>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

namespace hlr::hidden_line {
namespace {

using IK = CGAL::Exact_predicates_inexact_constructions_kernel;
using Interval = CGAL::Interval_nt_advanced;  // needs the FPU rounding upward: Protect_FPU_rounding

struct Box {
  Vec3 lo, hi;
  Vec3 corner(int c) const { return {c & 1 ? hi[0] : lo[0], c & 2 ? hi[1] : lo[1], c & 4 ? hi[2] : lo[2]}; }
};

// The group's viewpoints: a box of eyes B (perspective views), or a box of directions (orthographic
// views: the light views of a sun study). A direction d of the group, with d_k of sign s on the
// group's axis k, is taken as the ratios q = d / |d_k|: q_k = s, and the other two lie in
// [q_lo, q_hi] (the ratios of the group's directions, rounded outward).
struct Viewpoints {
  bool parallel = false;
  Box box;               // perspective: the eyes' box
  int k = 2, s = -1;     // parallel: the axis every direction runs along with sign s
  Vec3 q_lo{}, q_hi{};   // parallel: the ratio box (components other than k)
  Vec3 q0{};             // parallel: the ratios of the umbrae's one direction, in the box
  // Parallel: the ratio corner c (0..3) of the box, as a direction (q_i, q_j, s).
  Vec3 direction(int c) const {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    Vec3 d{};
    d[k] = s;
    d[i] = c & 1 ? q_hi[i] : q_lo[i];
    d[j] = c & 2 ? q_hi[j] : q_lo[j];
    return d;
  }
};

// A face of the fuzzy projection cube: directions whose component along `k` has sign `s`,
// sampled at (u, w) = (d_i, d_j) / (s d_k). For a group of directions (parallel) its one face
// samples lines instead: (u, w) is where a line of the group meets the plane x_k = limit, which
// lies before every vertex along s k.
struct CubeFace {
  int k, i, j, s;
  double limit;  // B's extent along k on this side (parallel: the plane of the lines' feet)
  bool beyond(const Vec3& p) const { return s > 0 ? p[k] > limit : p[k] < limit; }
  double depth(const Vec3& p) const { return s * p[k]; }
};

// Widening of a computed direction coordinate: its few roundings err by far less.
double widen(double x) { return 1e-12 * (1 + std::abs(x)); }

// A face of the cube as pixels: n x n over [u0, u0 + n hu] x [w0, w0 + n hw].
class Grid {
 public:
  Grid(int resolution, double u0, double u1, double w0, double w1)
      : n_(resolution), u0_(u0), w0_(w0), hu_((u1 - u0) / resolution), hw_((w1 - w0) / resolution),
        depth_(std::size_t(resolution) * resolution, std::numeric_limits<double>::infinity()),
        stamp_(std::size_t(resolution) * resolution, 0), local_(std::size_t(resolution) * resolution, 0),
        local_stamp_(std::size_t(resolution) * resolution, 0) {}

  void reset() { std::fill(depth_.begin(), depth_.end(), std::numeric_limits<double>::infinity()); }
  int size() const { return n_; }
  // The pixels a coordinate range may reach, one more on each side (the floor of a computed
  // quotient may be off by one), unclamped; the range's ends are widened first.
  std::pair<long, long> span_u(double lo, double hi) const {
    return {index(lo - widen(lo), u0_, hu_) - 1, index(hi + widen(hi), u0_, hu_) + 1};
  }
  std::pair<long, long> span_w(double lo, double hi) const {
    return {index(lo - widen(lo), w0_, hw_) - 1, index(hi + widen(hi), w0_, hw_) + 1};
  }
  double centre_u(long a) const { return u0_ + (double(a) + 0.5) * hu_; }
  double centre_w(long b) const { return w0_ + (double(b) + 0.5) * hw_; }
  double& depth(long a, long b) { return depth_[std::size_t(b) * n_ + a]; }
  std::uint32_t& stamp(long a, long b) { return stamp_[std::size_t(b) * n_ + a]; }
  // Per pixel, for the region being stamped: the largest depth of its faces over the pixel.
  double& local(long a, long b) { return local_[std::size_t(b) * n_ + a]; }
  std::uint32_t& local_stamp(long a, long b) { return local_stamp_[std::size_t(b) * n_ + a]; }

 private:
  long index(double x, double origin, double h) const {
    const double q = std::floor((x - origin) / h);
    if (!(q > -2)) return -2;  // also NaN
    if (q > n_ + 1) return n_ + 1;
    return long(q);
  }
  int n_;
  double u0_, w0_, hu_, hw_;
  std::vector<double> depth_;
  std::vector<std::uint32_t> stamp_;
  std::vector<double> local_;
  std::vector<std::uint32_t> local_stamp_;
};

// The rectangle of directions from the corners of B to the points (all beyond the cube face);
// parallel: of the feet of the group's lines through the points. A foot is linear in the ratios,
// so the box's corners give its extremes; it is widened by far more than its three roundings
// (the lines' feet are differences of nearly equal numbers: widened relative to the terms).
struct Extent {
  double u0 = HUGE_VAL, u1 = -HUGE_VAL, w0 = HUGE_VAL, w1 = -HUGE_VAL;
  void add(const CubeFace& f, const Viewpoints& vp, const Vec3& p) {
    if (vp.parallel) {
      const double t = f.s * (p[f.k] - f.limit);  // > 0
      for (int c = 0; c < 4; ++c) {
        const Vec3 d = vp.direction(c);
        const double du = t * d[f.i], dw = t * d[f.j];
        const double u = p[f.i] - du, w = p[f.j] - dw;
        const double mu = 1e-12 * (1 + std::abs(p[f.i]) + std::abs(du)), mw = 1e-12 * (1 + std::abs(p[f.j]) + std::abs(dw));
        u0 = std::min(u0, u - mu), u1 = std::max(u1, u + mu), w0 = std::min(w0, w - mw), w1 = std::max(w1, w + mw);
      }
      return;
    }
    for (int c = 0; c < 8; ++c) {
      const Vec3 v = vp.box.corner(c);
      const double den = f.s * (p[f.k] - v[f.k]);  // > 0: p is beyond B, and distinct doubles differ
      const double u = (p[f.i] - v[f.i]) / den, w = (p[f.j] - v[f.j]) / den;
      u0 = std::min(u0, u), u1 = std::max(u1, u), w0 = std::min(w0, w), w1 = std::max(w1, w);
    }
  }
};

// Whether the ray from v along the cube direction (cu, cw, 1) (coordinates i, j, s k) certainly
// meets the closed triangle a, b, c (all beyond v along s k): the direction lies in the cone the
// triangle spans from v, by the signs of three determinants, each certain on intervals.
bool ray_meets(const CubeFace& f, const Vec3& v, const Vec3& a, const Vec3& b, const Vec3& c, double cu, double cw) {
  auto rel = [&](const Vec3& p) {
    return std::array<Interval, 3>{Interval(p[f.i]) - Interval(v[f.i]), Interval(p[f.j]) - Interval(v[f.j]),
                                   (Interval(p[f.k]) - Interval(v[f.k])) * Interval(f.s)};
  };
  const auto A = rel(a), B = rel(b), C = rel(c);
  const std::array<Interval, 3> D{Interval(cu), Interval(cw), Interval(1)};
  auto det = [](const std::array<Interval, 3>& x, const std::array<Interval, 3>& y, const std::array<Interval, 3>& z) {
    return x[0] * (y[1] * z[2] - y[2] * z[1]) - x[1] * (y[0] * z[2] - y[2] * z[0]) + x[2] * (y[0] * z[1] - y[1] * z[0]);
  };
  const Interval o = det(A, B, C);
  const int sign = o.inf() > 0 ? 1 : o.sup() < 0 ? -1 : 0;
  if (sign == 0) return false;
  for (const Interval& d : {det(A, B, D), det(B, C, D), det(C, A, D)})
    if (sign > 0 ? !(d.inf() >= 0) : !(d.sup() <= 0)) return false;
  return true;
}

// The triangles of a face: its fan from the first corner (faces are planar and simple).
template <class Visit>
void for_each_fan_triangle(const std::vector<std::uint32_t>& face, Visit&& visit) {
  for (std::size_t k = 2; k < face.size(); ++k) visit(face[0], face[k - 1], face[k]);
}

struct MeshFacts {
  std::vector<EdgeUse> uses;
  std::vector<std::int8_t> side;  // per face: +1 or -1 when B lies strictly on that side of it
  std::vector<bool> occluder;     // per face: kept by every view from B, in front of every near plane
  std::vector<bool> back;         // per face: a back face of a closed component from all of B
};

// The side of the plane through a, b, c that every viewpoint lies strictly on (+1, -1), or 0.
// Perspective: exact orientation tests against B's corners. Parallel: a viewer at infinity
// against the direction d lies on the side of -d, the sign of -det(b - a, c - a, d), linear in
// the ratios (so the box's corners decide), certain on intervals.
int side_of_viewpoints(const Viewpoints& vp, const std::array<IK::Point_3, 8>& corners, const Vec3& a, const Vec3& b,
                       const Vec3& c) {
  int side = 0;
  if (!vp.parallel) {
    const IK::Point_3 pa(a[0], a[1], a[2]), pb(b[0], b[1], b[2]), pc(c[0], c[1], c[2]);
    for (const auto& corner : corners) {
      const int o = CGAL::orientation(pa, pb, pc, corner);
      if (o == 0 || (side != 0 && o != side)) return 0;
      side = o;
    }
    return side;
  }
  CGAL::Protect_FPU_rounding<true> rounding;
  std::array<Interval, 3> x, y;
  for (int t = 0; t < 3; ++t) x[t] = Interval(b[t]) - Interval(a[t]), y[t] = Interval(c[t]) - Interval(a[t]);
  for (int corner = 0; corner < 4; ++corner) {
    const Vec3 d = vp.direction(corner);
    const Interval det = d[0] * (x[1] * y[2] - x[2] * y[1]) - d[1] * (x[0] * y[2] - x[2] * y[0]) + d[2] * (x[0] * y[1] - x[1] * y[0]);
    const int o = det.sup() < 0 ? 1 : det.inf() > 0 ? -1 : 0;
    if (o == 0 || (side != 0 && o != side)) return 0;
    side = o;
  }
  return side;
}

MeshFacts mesh_facts(const Mesh& mesh, const Viewpoints& vp, const std::vector<bool>& deep_vertex) {
  MeshFacts facts;
  facts.uses = edge_uses(mesh);
  const ComponentSides sides = component_sides(mesh, facts.uses);
  const std::size_t nf = mesh.faces.size();
  facts.side.assign(nf, 0);
  facts.occluder.assign(nf, false);
  facts.back.assign(nf, false);
  std::array<IK::Point_3, 8> corners;
  for (int c = 0; c < 8; ++c) {
    const Vec3 p = vp.box.corner(c);
    corners[c] = IK::Point_3(p[0], p[1], p[2]);
  }
  for (std::uint32_t f = 0; f < nf; ++f) {
    const auto& face = mesh.faces[f];
    // Every fan triangle with all of B strictly on one side, the same for all: then the face is
    // seen from one side from anywhere in B, and its fan covers it once.
    int side = 0;
    bool one_side = true;
    for_each_fan_triangle(face, [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
      if (!one_side) return;
      const int o = side_of_viewpoints(vp, corners, mesh.vertices[a], mesh.vertices[b], mesh.vertices[c]);
      if (o == 0 || (side != 0 && o != side)) {
        one_side = false;
        return;
      }
      side = o;
    });
    if (!one_side) continue;
    facts.side[f] = std::int8_t(side);
    // A back face of a closed component is left out of a view's sources (a component wound inward
    // counts as turned outward): only faces that every view keeps can hide anything.
    const int outward = sides.outward[f];
    const bool kept = outward == 0 || outward == side;
    facts.back[f] = !kept;
    bool deep = true;
    for (std::uint32_t v : face) deep = deep && deep_vertex[v];
    facts.occluder[f] = kept && deep;
  }
  return facts;
}

// Per mesh, per vertex: deeper than the near plane of every view, with a margin far above the
// rounding of these sums.
std::vector<std::vector<bool>> deep_vertices(const std::vector<Mesh>& meshes, const std::vector<View>& views) {
  std::vector<std::vector<bool>> deep(meshes.size());
  for (std::size_t m = 0; m < meshes.size(); ++m) deep[m].assign(meshes[m].vertices.size(), true);
  for (const View& view : views) {
    if (!view.eye) continue;  // orthographic: no near plane
    const Vec3& e = *view.eye;
    const Vec3& d = view.direction;
    double deepest = -HUGE_VAL, magnitude = 0;
    for (const Mesh& mesh : meshes)
      for (const Vec3& p : mesh.vertices) {
        double w = 0, size = 0;
        for (int k = 0; k < 3; ++k) w += d[k] * (p[k] - e[k]), size += std::abs(d[k] * (p[k] - e[k]));
        deepest = std::max(deepest, w);
        magnitude = std::max(magnitude, size);
      }
    const double fraction = view.near_fraction ? *view.near_fraction : 1.0 / 1000;
    const double near = deepest * fraction, margin = 1e-9 * magnitude;
    for (std::size_t m = 0; m < meshes.size(); ++m)
      for (std::size_t v = 0; v < meshes[m].vertices.size(); ++v) {
        const Vec3& p = meshes[m].vertices[v];
        double w = 0;
        for (int k = 0; k < 3; ++k) w += d[k] * (p[k] - e[k]);
        if (!(w > near + margin)) deep[m][v] = false;
      }
  }
  return deep;
}


// The viewpoints of a group of views: all perspective (the eyes' box), or all orthographic (the
// directions' ratio box on the axis where every direction has the largest share, all of one sign
// there). Nothing when the directions share no such axis.
std::optional<Viewpoints> viewpoints_of(const std::vector<View>& views) {
  Viewpoints vp;
  const bool perspective = bool(views.front().eye);
  for (const View& v : views)
    if (bool(v.eye) != perspective) throw std::invalid_argument("fuzzy culling needs views that are all perspective or all orthographic");
  if (perspective) {
    vp.box = Box{*views.front().eye, *views.front().eye};
    for (const View& v : views)
      for (int k = 0; k < 3; ++k) vp.box.lo[k] = std::min(vp.box.lo[k], (*v.eye)[k]), vp.box.hi[k] = std::max(vp.box.hi[k], (*v.eye)[k]);
    return vp;
  }
  vp.parallel = true;
  double best = 0;
  for (int k = 0; k < 3; ++k) {
    double share = HUGE_VAL;
    const double sign = views.front().direction[k] > 0 ? 1 : -1;
    for (const View& v : views) {
      const Vec3& d = v.direction;
      const double m = std::max({std::abs(d[0]), std::abs(d[1]), std::abs(d[2])});
      share = sign * d[k] > 0 && std::isfinite(m) ? std::min(share, sign * d[k] / m) : 0;
      if (share == 0) break;
    }
    if (share > best) best = share, vp.k = k, vp.s = int(sign);
  }
  if (best == 0) return std::nullopt;
  const int i = (vp.k + 1) % 3, j = (vp.k + 2) % 3;
  vp.q_lo = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, vp.q_hi = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (const View& v : views)
    for (int t : {i, j}) {
      // The rounded quotient is within an ulp of the ratio: one step outward holds it.
      const double q = v.direction[t] / std::abs(v.direction[vp.k]);
      vp.q_lo[t] = std::min(vp.q_lo[t], std::nextafter(q, -HUGE_VAL));
      vp.q_hi[t] = std::max(vp.q_hi[t], std::nextafter(q, HUGE_VAL));
    }
  for (int t : {i, j}) vp.q0[t] = vp.q_lo[t] / 2 + vp.q_hi[t] / 2;  // within the box
  vp.q0[vp.k] = vp.s;
  return vp;
}

// The faces of the cube the group uses: all six around B, or the one face of a group of directions,
// its plane of feet one unit (and more) before every vertex along s k.
std::vector<CubeFace> cube_faces(const Viewpoints& vp, const std::vector<Mesh>& meshes) {
  std::vector<CubeFace> out;
  if (!vp.parallel) {
    for (int k = 0; k < 3; ++k)
      for (int s : {1, -1}) out.push_back({k, (k + 1) % 3, (k + 2) % 3, s, s > 0 ? vp.box.hi[k] : vp.box.lo[k]});
    return out;
  }
  double least = HUGE_VAL;  // the smallest depth s x_k of a vertex
  for (const Mesh& mesh : meshes)
    for (const Vec3& p : mesh.vertices) least = std::min(least, vp.s * p[vp.k]);
  if (!(least < HUGE_VAL)) least = 0;
  const double limit = vp.s * (least - 1 - std::abs(least));
  out.push_back({vp.k, (vp.k + 1) % 3, (vp.k + 2) % 3, vp.s, limit});
  return out;
}

// The pixels of a cube face: directions with |u|, |w| <= reach around B; for a group of
// directions, the feet of the lines through every vertex, and three pixels more around.
Grid grid_of(const CubeFace& cube, const Viewpoints& vp, const std::vector<Mesh>& meshes, const FuzzyOptions& options) {
  if (!vp.parallel) return Grid(options.resolution, -options.reach, options.reach, -options.reach, options.reach);
  Extent all;
  for (const Mesh& mesh : meshes)
    for (const Vec3& p : mesh.vertices) all.add(cube, vp, p);
  if (!(all.u0 <= all.u1)) all = Extent{0, 1, 0, 1};
  const double n = options.resolution;
  const double mu = (all.u1 - all.u0) * 3 / n + 1e-9 * (1 + std::abs(all.u0) + std::abs(all.u1));
  const double mw = (all.w1 - all.w0) * 3 / n + 1e-9 * (1 + std::abs(all.w0) + std::abs(all.w1));
  return Grid(options.resolution, all.u0 - mu, all.u1 + mu, all.w0 - mw, all.w1 + mw);
}

}  // namespace

FuzzyCull fuzzy_cull(const std::vector<Mesh>& meshes, const std::vector<View>& views, const FuzzyOptions& options,
                     StopToken stop) {
  const auto start = std::chrono::steady_clock::now();
  FuzzyCull out;
  out.culled.resize(meshes.size());
  for (std::size_t m = 0; m < meshes.size(); ++m) {
    out.culled[m].assign(meshes[m].faces.size(), false);
    out.patches += meshes[m].faces.size();
  }
  if (views.empty() || options.resolution < 4 || !(options.reach > 0)) {
    out.seconds = seconds_since(start);
    return out;
  }
  const auto vp = viewpoints_of(views);
  if (!vp) {  // directions of no common axis: nothing is culled
    out.seconds = seconds_since(start);
    return out;
  }
  const Vec3 v0 = vp->parallel ? Vec3{} : *views.front().eye;  // the umbrae's one viewpoint, in B

  const auto deep = deep_vertices(meshes, views);
  std::vector<MeshFacts> facts;
  for (std::size_t m = 0; m < meshes.size(); ++m) {
    stop.check();
    facts.push_back(mesh_facts(meshes[m], *vp, deep[m]));
    out.occluders += std::count(facts.back().occluder.begin(), facts.back().occluder.end(), true);
  }

  CGAL::Protect_FPU_rounding<true> rounding;  // for the intervals of ray_meets
  std::uint32_t stamp = 0;
  for (const CubeFace& cube : cube_faces(*vp, meshes)) {
      const int k = cube.k;
      stop.check();
      Grid grid = grid_of(cube, *vp, meshes, options);
      // Regions: occluders wholly beyond this cube face, joined across edges run both ways.
      struct Region {
        std::uint32_t mesh;
        double deepest = -HUGE_VAL;
        std::vector<std::uint32_t> faces;
        std::vector<std::array<std::uint32_t, 2>> boundary;
      };
      std::vector<Region> regions;
      for (std::uint32_t m = 0; m < meshes.size(); ++m) {
        const Mesh& mesh = meshes[m];
        const MeshFacts& mf = facts[m];
        const std::size_t nf = mesh.faces.size();
        std::vector<bool> member(nf, false);
        for (std::uint32_t f = 0; f < nf; ++f) {
          if (!mf.occluder[f]) continue;
          bool beyond = true;
          for (std::uint32_t v : mesh.faces[f]) beyond = beyond && cube.beyond(mesh.vertices[v]);
          member[f] = beyond;
        }
        UnionFind joined(nf);
        for_each_edge(mf.uses, [&](EdgeUses first, EdgeUses last) {
          if (last - first != 2) return;
          const EdgeUse &a = first[0], &b = first[1];
          if (a.face != b.face && member[a.face] && member[b.face] && a.forward != b.forward &&
              mf.side[a.face] == mf.side[b.face])
            joined.join(a.face, b.face);
        });
        std::vector<std::int32_t> region_of(nf, -1);
        for (std::uint32_t f = 0; f < nf; ++f) {
          if (!member[f]) continue;
          const std::uint32_t root = joined.find(f);
          if (region_of[root] < 0) {
            region_of[root] = std::int32_t(regions.size());
            regions.push_back(Region{m});
          }
          Region& r = regions[region_of[root]];
          r.faces.push_back(f);
          for (std::uint32_t v : mesh.faces[f]) r.deepest = std::max(r.deepest, cube.depth(mesh.vertices[v]));
        }
        // Boundary edges: a member's edge that does not join it to another member.
        for_each_edge(mf.uses, [&](EdgeUses first, EdgeUses last) {
          const bool inner = last - first == 2 && first[0].face != first[1].face && member[first[0].face] &&
                             member[first[1].face] && joined.find(first[0].face) == joined.find(first[1].face) &&
                             first[0].forward != first[1].forward && mf.side[first[0].face] == mf.side[first[1].face];
          if (inner) return;
          for (EdgeUses u = first; u != last; ++u)
            if (member[u->face]) {
              regions[region_of[joined.find(u->face)]].boundary.push_back({edge_low(u->key), edge_high(u->key)});
            }
        });
      }
      out.regions += regions.size();
      std::sort(regions.begin(), regions.end(), [](const Region& a, const Region& b) { return a.deepest < b.deepest; });

      // The umbrae, nearest regions first.
      for (const Region& r : regions) {
        stop.check();
        const Mesh& mesh = meshes[r.mesh];
        ++stamp;
        for (const auto& [a, b] : r.boundary) {
          Extent e;
          e.add(cube, *vp, mesh.vertices[a]);
          e.add(cube, *vp, mesh.vertices[b]);
          const auto [a0, a1] = grid.span_u(e.u0, e.u1);
          const auto [b0, b1] = grid.span_w(e.w0, e.w1);
          for (long y = std::max(b0, 0L); y <= std::min(b1, long(grid.size()) - 1); ++y)
            for (long x = std::max(a0, 0L); x <= std::min(a1, long(grid.size()) - 1); ++x) grid.stamp(x, y) = stamp;
        }
        // Over each pixel, the largest depth of the region's faces whose fuzzy extent reaches it:
        // a line of the group through the pixel that meets the region meets one of them there, no
        // deeper (a region spanning a large range of depth, a ceiling joined to its walls, hides
        // by the depth of its nearby faces rather than by its deepest point).
        for (std::uint32_t f : r.faces) {
          Extent e;
          double deepest = -HUGE_VAL;
          for (std::uint32_t v : mesh.faces[f]) {
            e.add(cube, *vp, mesh.vertices[v]);
            deepest = std::max(deepest, cube.depth(mesh.vertices[v]));
          }
          const auto [a0, a1] = grid.span_u(e.u0, e.u1);
          const auto [b0, b1] = grid.span_w(e.w0, e.w1);
          for (long y = std::max(b0, 0L); y <= std::min(b1, long(grid.size()) - 1); ++y)
            for (long x = std::max(a0, 0L); x <= std::min(a1, long(grid.size()) - 1); ++x) {
              if (grid.local_stamp(x, y) != stamp) grid.local_stamp(x, y) = stamp, grid.local(x, y) = deepest;
              else grid.local(x, y) = std::max(grid.local(x, y), deepest);
            }
        }
        for (std::uint32_t f : r.faces)
          for_each_fan_triangle(mesh.faces[f], [&](std::uint32_t ia, std::uint32_t ib, std::uint32_t ic) {
            const Vec3 &pa = mesh.vertices[ia], &pb = mesh.vertices[ib], &pc = mesh.vertices[ic];
            // The triangle's image from v0 (parallel: the feet of its lines along q0), roughly:
            // which pixels to test.
            double u0 = HUGE_VAL, u1 = -HUGE_VAL, w0 = HUGE_VAL, w1 = -HUGE_VAL;
            for (const Vec3* p : {&pa, &pb, &pc}) {
              double u, w;
              if (vp->parallel) {
                const double t = cube.s * ((*p)[k] - cube.limit);
                u = (*p)[cube.i] - t * vp->q0[cube.i], w = (*p)[cube.j] - t * vp->q0[cube.j];
              } else {
                const double den = cube.s * ((*p)[k] - v0[k]);
                u = ((*p)[cube.i] - v0[cube.i]) / den, w = ((*p)[cube.j] - v0[cube.j]) / den;
              }
              u0 = std::min(u0, u), u1 = std::max(u1, u), w0 = std::min(w0, w), w1 = std::max(w1, w);
            }
            const auto [a0, a1] = grid.span_u(u0, u1);
            const auto [b0, b1] = grid.span_w(w0, w1);
            for (long y = std::max(b0, 0L); y <= std::min(b1, long(grid.size()) - 1); ++y)
              for (long x = std::max(a0, 0L); x <= std::min(a1, long(grid.size()) - 1); ++x) {
                if (grid.stamp(x, y) == stamp || grid.local_stamp(x, y) != stamp) continue;
                const double bound = grid.local(x, y);
                if (grid.depth(x, y) <= bound) continue;
                // Parallel: the line of direction q0 from the pixel's centre on the feet's plane.
                bool meets;
                if (vp->parallel) {
                  Vec3 foot{};
                  foot[cube.i] = grid.centre_u(x), foot[cube.j] = grid.centre_w(y), foot[k] = cube.limit;
                  meets = ray_meets(cube, foot, pa, pb, pc, vp->q0[cube.i], vp->q0[cube.j]);
                } else {
                  meets = ray_meets(cube, v0, pa, pb, pc, grid.centre_u(x), grid.centre_w(y));
                }
                if (meets) grid.depth(x, y) = bound;
              }
          });
      }

      // The faces behind them.
      for (std::uint32_t m = 0; m < meshes.size(); ++m) {
        const Mesh& mesh = meshes[m];
        for (std::uint32_t f = 0; f < mesh.faces.size(); ++f) {
          if (out.culled[m][f]) continue;
          bool beyond = true;
          double nearest = HUGE_VAL;
          Extent e;
          for (std::uint32_t v : mesh.faces[f]) {
            const Vec3& p = mesh.vertices[v];
            if (!cube.beyond(p)) {
              beyond = false;
              break;
            }
            nearest = std::min(nearest, cube.depth(p));
            e.add(cube, *vp, p);
          }
          if (!beyond) continue;
          const auto [a0, a1] = grid.span_u(e.u0, e.u1);
          const auto [b0, b1] = grid.span_w(e.w0, e.w1);
          if (a0 < 0 || b0 < 0 || a1 >= grid.size() || b1 >= grid.size()) continue;
          bool hidden = true;
          for (long y = b0; y <= b1 && hidden; ++y)
            for (long x = a0; x <= a1 && hidden; ++x) hidden = grid.depth(x, y) < nearest;
          if (hidden) {
            out.culled[m][f] = true;
            ++out.culled_faces;
            out.culled_back_faces += facts[m].back[f];
          }
        }
      }
    }
  out.seconds = seconds_since(start);
  return out;
}

}  // namespace hlr::hidden_line

namespace hlr::hidden_line {

Vec3 group_point(const View& view) {
  if (view.eye) return *view.eye;
  const Vec3& d = view.direction;
  const double n = std::hypot(d[0], d[1], d[2]);
  return {d[0] / n, d[1] / n, d[2] / n};
}

std::vector<ViewRun> group_views(const std::vector<View>& views, double extent) {
  std::vector<ViewRun> groups;
  Vec3 lo{}, hi{};
  for (std::size_t i = 0; i < views.size(); ++i) {
    const Vec3 e = group_point(views[i]);
    bool fits = !groups.empty() && bool(views[i].eye) == bool(views[groups.back().first].eye);
    if (fits)
      for (int k = 0; k < 3; ++k) fits = fits && std::max(hi[k], e[k]) - std::min(lo[k], e[k]) <= extent;
    if (!fits) {
      groups.push_back({i, 0});
      lo = hi = e;
    }
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], e[k]), hi[k] = std::max(hi[k], e[k]);
    ++groups.back().count;
  }
  return groups;
}

std::vector<CullPart> cull_parts(const std::vector<Mesh>& meshes, const std::vector<View>& views,
                                 std::vector<std::size_t> members, const FuzzyOptions& options, StopToken stop,
                                 CullPasses& passes) {
  // One pass over the views `ids`.
  auto pass = [&](const std::vector<std::size_t>& ids) {
    std::vector<View> group;
    for (std::size_t i : ids) group.push_back(views[i]);
    FuzzyCull cull = fuzzy_cull(meshes, group, options, stop);
    ++passes.passes;
    passes.seconds += cull.seconds;
    passes.patches = cull.patches;
    CullPart part{ids, cull.culled_faces, cull.culled_faces - cull.culled_back_faces, {}};
    if (cull.culled_faces > 0) part.faces = std::move(cull.culled);
    return part;
  };
  // The halves of `ids` on either side of the middle of their box's longest axis (both non-empty
  // unless every group point is the same).
  auto halves = [&](const std::vector<std::size_t>& ids) {
    Vec3 lo = group_point(views[ids.front()]), hi = lo;
    for (std::size_t i : ids) {
      const Vec3 p = group_point(views[i]);
      for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
    }
    int axis = 0;
    for (int k = 1; k < 3; ++k)
      if (hi[k] - lo[k] > hi[axis] - lo[axis]) axis = k;
    const double middle = lo[axis] + (hi[axis] - lo[axis]) / 2;
    std::array<std::vector<std::size_t>, 2> out;
    for (std::size_t i : ids) out[group_point(views[i])[axis] > middle].push_back(i);
    return out;
  };
  // Once: the passes cost about what a frame's area sort saves, and a scene where nothing is
  // hidden would pay one per eye for deeper splits (the rooms of BENCHMARKS.md: 7 passes for 5
  // eyes, 0.9 s against 0.1 s saved).
  std::vector<CullPart> parts;
  CullPart whole = pass(members);
  const auto [a, b] = whole.useful > 0 || members.size() < 2 ? std::array<std::vector<std::size_t>, 2>{} : halves(members);
  if (a.empty() || b.empty()) {
    parts.push_back(std::move(whole));
  } else {
    parts.push_back(pass(a));
    parts.push_back(pass(b));
  }
  std::sort(parts.begin(), parts.end(), [](const CullPart& x, const CullPart& y) { return x.views < y.views; });
  return parts;
}

}  // namespace hlr::hidden_line
