// Feature-edge extraction (hlr/kernel/features.hpp), exact on the input doubles.
#include <hlr/kernel/features.hpp>
#include <hlr/kernel/mesh_edges.hpp>
#include <hlr/kernel/parallel.hpp>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Mpzf.h>

#include <unordered_map>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>

namespace hlr {
namespace {

// A face's normal, oriented by its corner order: twice its vector area, the sum of the fan
// triangles' cross products from the first corner. Right for any planar simple polygon, convex or
// not (three corners alone give the wrong side at a reflex corner). Over NT: intervals (under
// CGAL::Protect_FPU_rounding) to filter, CGAL::Mpzf (exact sums and products of doubles) to
// decide what they cannot.
template <class NT>
std::array<NT, 3> face_normal(const Mesh& mesh, const std::vector<std::uint32_t>& face) {
  using V = std::array<NT, 3>;
  auto sub = [&](std::uint32_t a, std::uint32_t b) -> V {
    const auto &p = mesh.vertices[a], &q = mesh.vertices[b];
    return V{NT(p[0]) - NT(q[0]), NT(p[1]) - NT(q[1]), NT(p[2]) - NT(q[2])};
  };
  V sum{NT(0), NT(0), NT(0)};
  for (std::size_t k = 2; k < face.size(); ++k) {
    const V u = sub(face[k - 1], face[0]), w = sub(face[k], face[0]);
    sum = V{sum[0] + (u[1] * w[2] - u[2] * w[1]), sum[1] + (u[2] * w[0] - u[0] * w[2]), sum[2] + (u[0] * w[1] - u[1] * w[0])};
  }
  return sum;
}

template <class NT>
NT dot(const std::array<NT, 3>& a, const std::array<NT, 3>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// n1·n2 < c |n1| |n2|, squared with the signs taken care of: exact over CGAL::Mpzf, possibly
// uncertain over intervals.
template <class NT>
auto angle_above(const std::array<NT, 3>& n1, const std::array<NT, 3>& n2, double cos_threshold) {
  const NT s = dot(n1, n2);
  const NT c(cos_threshold);
  const NT q = c * c * dot(n1, n1) * dot(n2, n2);
  if (cos_threshold >= 0) return CGAL::is_negative(s) | (s * s < q);
  return CGAL::is_negative(s) & (s * s > q);
}

// Normals of every face, decided in interval arithmetic and, where the intervals cannot tell,
// exactly: the facing signs, and the crease test between two faces.
class FaceNormals {
 public:
  using IA = CGAL::Interval_nt<false>;
  // Not a lazy number: edge-on faces leave many faces to the exact stage, and a lazy number's first
  // exact evaluation costs a std::call_once per node.
  using FT = CGAL::Mpzf;

  // Facing: the sign of n·t with t toward the viewer: −d in an orthographic view; in a
  // perspective one e − p for a corner p, so that the face faces the viewer exactly when the eye
  // lies on its front side. Faces in parallel chunks, each on its own.
  FaceNormals(const Mesh& mesh, const View& view)
      : mesh_(mesh), approx_((mesh.faces.size() + kBlock - 1) / kBlock), facing_(mesh.faces.size()) {
    const double toward_viewer[3] = {-view.direction[0], -view.direction[1], -view.direction[2]};
    auto toward = [&]<class NT>(std::size_t f, NT) -> std::array<NT, 3> {
      if (!view.eye) return {NT(toward_viewer[0]), NT(toward_viewer[1]), NT(toward_viewer[2])};
      const auto& p = mesh.vertices[mesh.faces[f][0]];
      const Vec3& e = *view.eye;
      return {NT(e[0]) - NT(p[0]), NT(e[1]) - NT(p[1]), NT(e[2]) - NT(p[2])};
    };
    aligned_chunks(mesh.faces.size(), kBlock, [&](std::size_t begin, std::size_t end) {
      std::vector<std::size_t> undecided;
      {
        CGAL::Protect_FPU_rounding<true> protect;
        auto& block = approx_[begin / kBlock];
        block.reserve(end - begin);
        for (std::size_t f = begin; f < end; ++f) {
          block.push_back(face_normal<IA>(mesh, mesh.faces[f]));
          const CGAL::Uncertain<CGAL::Sign> sign = CGAL::sign(dot(block.back(), toward(f, IA())));
          if (CGAL::is_certain(sign)) facing_[f] = CGAL::get_certain(sign);
          else undecided.push_back(f);
        }
      }
      for (std::size_t f : undecided) facing_[f] = CGAL::sign(dot(exact(f), toward(f, FT())));
    });
  }

  int facing(std::size_t f) const { return facing_[f]; }

  // Whether faces f and g (g's normal times `flip`) meet at more than the crease angle. From any
  // thread: the exact normals it may need are made for the call (it needs them only where the
  // angle is the crease angle, up to rounding).
  bool crease(std::size_t f, std::size_t g, int flip, double cos_threshold) const {
    {
      CGAL::Protect_FPU_rounding<true> protect;
      std::array<IA, 3> ng = approx(g);
      if (flip < 0) ng = {-ng[0], -ng[1], -ng[2]};
      const CGAL::Uncertain<bool> above = angle_above(approx(f), ng, cos_threshold);
      if (CGAL::is_certain(above)) return CGAL::get_certain(above);
    }
    std::array<FT, 3> ng = exact(g);
    if (flip < 0) ng = {-ng[0], -ng[1], -ng[2]};
    return angle_above(exact(f), ng, cos_threshold);
  }

 private:
  std::array<FT, 3> exact(std::size_t f) const { return face_normal<FT>(mesh_, mesh_.faces[f]); }

  const std::array<IA, 3>& approx(std::size_t f) const { return approx_[f / kBlock][f % kBlock]; }

  // The normals in intervals, in blocks of kBlock faces, each made by the thread that fills it: a
  // large mesh's (48 MB at 1M faces) would otherwise be made on one thread before the rest.
  static constexpr std::size_t kBlock = 4096;
  const Mesh& mesh_;
  std::vector<std::vector<std::array<IA, 3>>> approx_;
  std::vector<int> facing_;
};


// The smooth-edge rule of meshes (features.hpp), on the coplanar groups: which soft edges lie
// where a facet strip meets a flat surface. Exact on the input doubles: collinearity by Epick's
// predicates, parallel directions by a cross product in intervals and, where they cannot tell,
// in rationals.
class SmoothSurfaces {
 public:
  struct Soft {
    std::uint32_t v0, v1, f, g;
  };

  SmoothSurfaces(const Mesh& mesh, const CoplanarGroups& groups) : mesh_(mesh), groups_(groups) {}

  std::uint32_t group(std::uint32_t f) const { return groups_.group[f]; }

  // Whether faces f and g (of different groups, sharing an edge) lie in one plane.
  bool coplanar(std::uint32_t f, std::uint32_t g) const {
    const auto& pv = groups_.plane_vertices[f];
    const IK::Point_3 a = point(pv[0]), b = point(pv[1]), c = point(pv[2]);
    for (std::uint32_t v : mesh_.faces[g])
      if (!CGAL::coplanar(a, b, c, point(v))) return false;
    return true;
  }

  // Called for every soft edge before smooth() is asked.
  void add_soft(const Soft& e) {
    soft_by_group_[group(e.f)].push_back(soft_.size());
    soft_by_group_[group(e.g)].push_back(soft_.size());
    soft_.push_back(e);
  }

  // Whether soft edge e (as given to add_soft) is a smooth edge.
  bool smooth(const Soft& e) {
    if (members_.empty()) gather_members();
    const std::uint32_t rf = group(e.f), rg = group(e.g);
    const bool strip_f = strip_across(rf, e), strip_g = strip_across(rg, e);
    return (strip_f && !strip_g && !lone_triangle(rg)) || (strip_g && !strip_f && !lone_triangle(rf));
  }

 private:
  using IK = CGAL::Exact_predicates_inexact_constructions_kernel;
  IK::Point_3 point(std::uint32_t v) const {
    const auto& p = mesh_.vertices[v];
    return IK::Point_3(p[0], p[1], p[2]);
  }

  // Whether q - p is parallel to b - a (or zero): their cross product vanishes.
  bool parallel(std::uint32_t a, std::uint32_t b, std::uint32_t p, std::uint32_t q) const {
    auto cross_zero = [&](auto zero) -> CGAL::Uncertain<bool> {
      using NT = decltype(zero);
      auto d = [&](std::uint32_t u, std::uint32_t w, int axis) -> NT {
        return NT(mesh_.vertices[w][axis]) - NT(mesh_.vertices[u][axis]);
      };
      const NT ux = d(a, b, 0), uy = d(a, b, 1), uz = d(a, b, 2), wx = d(p, q, 0), wy = d(p, q, 1), wz = d(p, q, 2);
      return CGAL::is_zero(uy * wz - uz * wy) & CGAL::is_zero(uz * wx - ux * wz) & CGAL::is_zero(ux * wy - uy * wx);
    };
    {
      CGAL::Protect_FPU_rounding<true> protect;
      const CGAL::Uncertain<bool> approx = cross_zero(CGAL::Interval_nt<false>(0));
      if (CGAL::is_certain(approx)) return CGAL::get_certain(approx);
    }
    return CGAL::get_certain(cross_zero(CGAL::Mpzf(0)));
  }

  bool collinear(std::uint32_t a, std::uint32_t b, std::uint32_t p) const {
    return p == a || p == b || CGAL::collinear(point(a), point(b), point(p));
  }

  // The corners of each group that has soft edges, each once.
  void gather_members() {
    for (const auto& [root, edges] : soft_by_group_) members_[root];
    for (std::uint32_t f = 0; f < mesh_.faces.size(); ++f) {
      const auto it = members_.find(group(f));
      if (it == members_.end()) continue;
      ++face_counts_[group(f)];
      for (std::uint32_t v : mesh_.faces[f]) it->second.push_back(v);
    }
    for (auto& [root, corners] : members_) {
      std::sort(corners.begin(), corners.end());
      corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
    }
  }

  bool lone_triangle(std::uint32_t root) const {
    return face_counts_.at(root) == 1 && mesh_.faces[root].size() == 3;
  }

  // Whether group `root` is a facet strip across the line of soft edge e: every corner on that
  // line L or on one parallel line L', and a soft edge of the group on L'.
  bool strip_across(std::uint32_t root, const Soft& e) const {
    const std::uint32_t a = e.v0, b = e.v1;
    std::optional<std::uint32_t> other;  // a corner on L', off L
    for (std::uint32_t v : members_.at(root)) {
      if (collinear(a, b, v)) continue;
      if (!other) other = v;
      else if (!parallel(a, b, *other, v)) return false;
    }
    if (!other) return false;
    const std::uint32_t p = *other;
    auto on_far_line = [&](std::uint32_t v) { return v == p || (!collinear(a, b, v) && parallel(a, b, p, v)); };
    for (std::size_t k : soft_by_group_.at(root)) {
      const Soft& s = soft_[k];
      if (on_far_line(s.v0) && on_far_line(s.v1)) return true;
    }
    return false;
  }

  const Mesh& mesh_;
  const CoplanarGroups& groups_;
  std::vector<Soft> soft_;
  std::unordered_map<std::uint32_t, std::vector<std::size_t>> soft_by_group_;  // group -> soft edges
  std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> members_;      // group -> corners
  std::unordered_map<std::uint32_t, std::size_t> face_counts_;                 // group -> faces
};

}  // namespace

const char* feature_kind_name(FeatureKind kind) {
  switch (kind) {
    case FeatureKind::silhouette: return "silhouette";
    case FeatureKind::crease: return "crease";
    case FeatureKind::boundary: return "boundary";
    case FeatureKind::intersection: return "intersection";
    case FeatureKind::group: return "group";
    case FeatureKind::smooth: return "smooth";
  }
  return "?";
}

std::vector<FeatureEdge> feature_edges(const Mesh& mesh, const View& view, const FeatureOptions& options) {
  const double cos_threshold = std::cos(options.crease_degrees * std::numbers::pi / 180.0);
  FaceNormals normals(mesh, view);
  // How a smooth edge is drawn, if at all.
  const std::optional<FeatureKind> smooth_kind =
      options.smooth_edges == SmoothEdges::off    ? std::nullopt
      : options.smooth_edges == SmoothEdges::thin ? std::optional(FeatureKind::smooth)
                                                  : std::optional(FeatureKind::crease);

  const std::shared_ptr<const MeshTopology> topology = topology_of(mesh);
  const std::vector<EdgeUse>& uses = topology->uses;
  const ComponentSides& sides = topology->sides;
  // Meshes' smooth edges need every soft edge known first (a strip is known by its soft edges).
  std::optional<SmoothSurfaces> surfaces;
  auto soft_edge = [&](EdgeUses first) -> std::optional<SmoothSurfaces::Soft> {
    const std::uint32_t f = first[0].face, g = first[1].face;
    if ((first[0].fan && first[1].fan) || surfaces->group(f) == surfaces->group(g)) return std::nullopt;
    const int flip = first[0].forward == first[1].forward ? -1 : 1;
    if (normals.crease(f, g, flip, cos_threshold) || surfaces->coplanar(f, g)) return std::nullopt;
    return SmoothSurfaces::Soft{edge_low(first->key), edge_high(first->key), f, g};
  };
  if (smooth_kind && mesh.source_edges.empty()) {
    surfaces.emplace(mesh, topology->groups);
    for_each_edge(uses, [&](EdgeUses first, EdgeUses last) {
      if (last - first != 2) return;
      if (const auto soft = soft_edge(first)) surfaces->add_soft(*soft);
    });
  }

  // An edge's feature, if it is one.
  auto feature = [&](EdgeUses first, EdgeUses last) -> std::optional<FeatureEdge> {
    FeatureEdge edge;
    edge.v0 = edge_low(first->key);
    edge.v1 = edge_high(first->key);
    for (EdgeUses u = first; u != last; ++u) edge.faces.push_back(u->face);
    const std::size_t n = edge.faces.size();
    if (n == 1) {
      edge.kind = FeatureKind::boundary;
    } else if (n > 2) {
      edge.kind = FeatureKind::crease;  // non-manifold
    } else {
      // Orient the two faces alike: faces that run the edge the same way disagree in orientation.
      const std::uint32_t f = first[0].face, g = first[1].face;
      const int flip = first[0].forward == first[1].forward ? -1 : 1;
      // A closed solid's front side is its outside, whichever way it is wound; an open or
      // inconsistent mesh has two alike sides, so the edge turns wherever the facings differ.
      const int side = sides.outward[f];
      const int f_sign = normals.facing(f), g_sign = flip * normals.facing(g);
      const bool turns = side != 0 ? (f_sign * side > 0) != (g_sign * side > 0) : f_sign != g_sign;
      const bool fan = first[0].fan && first[1].fan;  // inside one non-planar face: crease rule only
      if (turns && !fan) {
        edge.kind = FeatureKind::silhouette;
      } else if (!mesh.source_edges.empty()) {
        // Features from the B-rep: its edges, not the crease rule (features.hpp).
        const std::uint8_t source = first[0].source | first[1].source;
        if (!(source & 1u)) return std::nullopt;
        if (source & 2u) {
          if (!smooth_kind) return std::nullopt;
          edge.kind = *smooth_kind;
        } else {
          edge.kind = FeatureKind::crease;
        }
      } else if (normals.crease(f, g, flip, cos_threshold)) {
        edge.kind = FeatureKind::crease;
      } else if (!mesh.face_group.empty() && mesh.face_group[f] != mesh.face_group[g]) {
        edge.kind = FeatureKind::group;
      } else if (surfaces) {
        const auto soft = soft_edge(first);
        if (!soft || !surfaces->smooth(*soft)) return std::nullopt;
        edge.kind = *smooth_kind;
      } else {
        return std::nullopt;
      }
    }
    return edge;
  };
  std::vector<FeatureEdge> out;
  if (surfaces) {  // SmoothSurfaces learns as it is asked: one thread
    for_each_edge(uses, [&](EdgeUses first, EdgeUses last) {
      if (auto edge = feature(first, last)) out.push_back(std::move(*edge));
    });
    return out;
  }
  // Chunks of uses on every thread, each with the edges whose first use it holds, joined in order.
  constexpr std::size_t kUses = 16384;
  std::vector<std::vector<FeatureEdge>> found((uses.size() + kUses - 1) / kUses);
  auto edge_start = [&](std::size_t u) {  // the first use at or after u that starts an edge
    while (u > 0 && u < uses.size() && uses[u].key == uses[u - 1].key) ++u;
    return uses.begin() + std::ptrdiff_t(std::min(u, uses.size()));
  };
  aligned_chunks(uses.size(), kUses, [&](std::size_t begin, std::size_t end) {
    for_each_edge(edge_start(begin), edge_start(end), [&](EdgeUses first, EdgeUses last) {
      if (auto edge = feature(first, last)) found[begin / kUses].push_back(std::move(*edge));
    });
  });
  // Joined where each chunk's edges begin, on every thread: a large mesh has a million edges to move.
  std::vector<std::size_t> at(found.size() + 1, 0);
  for (std::size_t k = 0; k < found.size(); ++k) at[k + 1] = at[k] + found[k].size();
  out.resize(at.back());
  aligned_chunks(found.size(), 1, [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) {
      std::move(found[k].begin(), found[k].end(), out.begin() + std::ptrdiff_t(at[k]));
      std::vector<FeatureEdge>().swap(found[k]);
    }
  });
  return out;
}

}  // namespace hlr
