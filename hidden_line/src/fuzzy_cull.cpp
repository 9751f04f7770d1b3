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

namespace hlr::hidden_line {
namespace {

using IK = CGAL::Exact_predicates_inexact_constructions_kernel;
using Interval = CGAL::Interval_nt_advanced;  // needs the FPU rounding upward: Protect_FPU_rounding

struct Box {
  Vec3 lo, hi;
  Vec3 corner(int c) const { return {c & 1 ? hi[0] : lo[0], c & 2 ? hi[1] : lo[1], c & 4 ? hi[2] : lo[2]}; }
};

// A face of the fuzzy projection cube: directions whose component along `k` has sign `s`,
// sampled at (u, w) = (d_i, d_j) / (s d_k).
struct CubeFace {
  int k, i, j, s;
  double limit;  // B's extent along k on this side
  bool beyond(const Vec3& p) const { return s > 0 ? p[k] > limit : p[k] < limit; }
  double depth(const Vec3& p) const { return s * p[k]; }
};

// Widening of a computed direction coordinate: its few roundings err by far less.
double widen(double x) { return 1e-12 * (1 + std::abs(x)); }

class Grid {
 public:
  Grid(int resolution, double reach)
      : n_(resolution), reach_(reach), h_(2 * reach / resolution),
        depth_(std::size_t(resolution) * resolution, std::numeric_limits<double>::infinity()),
        stamp_(std::size_t(resolution) * resolution, 0) {}

  void reset() { std::fill(depth_.begin(), depth_.end(), std::numeric_limits<double>::infinity()); }
  int size() const { return n_; }
  // The pixels a coordinate range may reach, one more on each side (the floor of a computed
  // quotient may be off by one), unclamped; the range's ends are widened first.
  std::pair<long, long> span(double lo, double hi) const { return {index(lo - widen(lo)) - 1, index(hi + widen(hi)) + 1}; }
  double centre(long a) const { return -reach_ + (double(a) + 0.5) * h_; }
  double& depth(long a, long b) { return depth_[std::size_t(b) * n_ + a]; }
  std::uint32_t& stamp(long a, long b) { return stamp_[std::size_t(b) * n_ + a]; }

 private:
  long index(double x) const {
    const double q = std::floor((x + reach_) / h_);
    if (!(q > -2)) return -2;  // also NaN
    if (q > n_ + 1) return n_ + 1;
    return long(q);
  }
  int n_;
  double reach_, h_;
  std::vector<double> depth_;
  std::vector<std::uint32_t> stamp_;
};

// The rectangle of directions from the corners of B to the points (all beyond the cube face).
struct Extent {
  double u0 = HUGE_VAL, u1 = -HUGE_VAL, w0 = HUGE_VAL, w1 = -HUGE_VAL;
  void add(const CubeFace& f, const Box& box, const Vec3& p) {
    for (int c = 0; c < 8; ++c) {
      const Vec3 v = box.corner(c);
      const double den = f.s * (p[f.k] - v[f.k]);  // > 0: p is beyond B, and distinct doubles differ
      const double u = (p[f.i] - v[f.i]) / den, w = (p[f.j] - v[f.j]) / den;
      u0 = std::min(u0, u), u1 = std::max(u1, u), w0 = std::min(w0, w), w1 = std::max(w1, w);
    }
  }
};

// Whether the ray from v along the cube direction (cu, cw) certainly meets the closed triangle
// a, b, c (all beyond the cube face): the direction lies in the cone the triangle spans from v,
// by the signs of three determinants, each certain on intervals.
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

MeshFacts mesh_facts(const Mesh& mesh, const Box& box, const std::vector<bool>& deep_vertex) {
  MeshFacts facts;
  facts.uses = edge_uses(mesh);
  const ComponentSides sides = component_sides(mesh, facts.uses);
  const std::size_t nf = mesh.faces.size();
  facts.side.assign(nf, 0);
  facts.occluder.assign(nf, false);
  facts.back.assign(nf, false);
  auto point = [&](std::uint32_t v) { return IK::Point_3(mesh.vertices[v][0], mesh.vertices[v][1], mesh.vertices[v][2]); };
  std::array<IK::Point_3, 8> corners;
  for (int c = 0; c < 8; ++c) {
    const Vec3 p = box.corner(c);
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
      const IK::Point_3 pa = point(a), pb = point(b), pc = point(c);
      for (const auto& corner : corners) {
        const int o = CGAL::orientation(pa, pb, pc, corner);
        if (o == 0 || (side != 0 && o != side)) {
          one_side = false;
          return;
        }
        side = o;
      }
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
  for (const View& v : views)
    if (!v.eye) throw std::invalid_argument("fuzzy culling needs perspective views");
  Box box{*views.front().eye, *views.front().eye};
  for (const View& v : views)
    for (int k = 0; k < 3; ++k) box.lo[k] = std::min(box.lo[k], (*v.eye)[k]), box.hi[k] = std::max(box.hi[k], (*v.eye)[k]);
  const Vec3 v0 = *views.front().eye;  // the umbrae's one viewpoint, in B

  const auto deep = deep_vertices(meshes, views);
  std::vector<MeshFacts> facts;
  for (std::size_t m = 0; m < meshes.size(); ++m) {
    stop.check();
    facts.push_back(mesh_facts(meshes[m], box, deep[m]));
    out.occluders += std::count(facts.back().occluder.begin(), facts.back().occluder.end(), true);
  }

  CGAL::Protect_FPU_rounding<true> rounding;  // for the intervals of ray_meets
  Grid grid(options.resolution, options.reach);
  std::uint32_t stamp = 0;
  for (int k = 0; k < 3; ++k)
    for (int s : {1, -1}) {
      stop.check();
      const CubeFace cube{k, (k + 1) % 3, (k + 2) % 3, s, s > 0 ? box.hi[k] : box.lo[k]};
      grid.reset();
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
          e.add(cube, box, mesh.vertices[a]);
          e.add(cube, box, mesh.vertices[b]);
          const auto [a0, a1] = grid.span(e.u0, e.u1);
          const auto [b0, b1] = grid.span(e.w0, e.w1);
          for (long y = std::max(b0, 0L); y <= std::min(b1, long(grid.size()) - 1); ++y)
            for (long x = std::max(a0, 0L); x <= std::min(a1, long(grid.size()) - 1); ++x) grid.stamp(x, y) = stamp;
        }
        for (std::uint32_t f : r.faces)
          for_each_fan_triangle(mesh.faces[f], [&](std::uint32_t ia, std::uint32_t ib, std::uint32_t ic) {
            const Vec3 &pa = mesh.vertices[ia], &pb = mesh.vertices[ib], &pc = mesh.vertices[ic];
            // The triangle's image from v0, roughly: which pixels to test.
            double u0 = HUGE_VAL, u1 = -HUGE_VAL, w0 = HUGE_VAL, w1 = -HUGE_VAL;
            for (const Vec3* p : {&pa, &pb, &pc}) {
              const double den = cube.s * ((*p)[k] - v0[k]);
              const double u = ((*p)[cube.i] - v0[cube.i]) / den, w = ((*p)[cube.j] - v0[cube.j]) / den;
              u0 = std::min(u0, u), u1 = std::max(u1, u), w0 = std::min(w0, w), w1 = std::max(w1, w);
            }
            const auto [a0, a1] = grid.span(u0, u1);
            const auto [b0, b1] = grid.span(w0, w1);
            for (long y = std::max(b0, 0L); y <= std::min(b1, long(grid.size()) - 1); ++y)
              for (long x = std::max(a0, 0L); x <= std::min(a1, long(grid.size()) - 1); ++x) {
                if (grid.stamp(x, y) == stamp || grid.depth(x, y) <= r.deepest) continue;
                if (ray_meets(cube, v0, pa, pb, pc, grid.centre(x), grid.centre(y))) grid.depth(x, y) = r.deepest;
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
            e.add(cube, box, p);
          }
          if (!beyond) continue;
          const auto [a0, a1] = grid.span(e.u0, e.u1);
          const auto [b0, b1] = grid.span(e.w0, e.w1);
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
