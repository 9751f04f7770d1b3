// Feature-edge extraction (hlr/kernel/features.hpp), exact on the input doubles.
#include <hlr/kernel/features.hpp>
#include <hlr/kernel/mesh_edges.hpp>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Interval_nt.h>

#include <array>
#include <cmath>
#include <numbers>
#include <optional>

namespace hlr {
namespace {

using EK = CGAL::Exact_predicates_exact_constructions_kernel;

// A face's normal, oriented by its corner order: twice its vector area, the sum of the fan
// triangles' cross products from the first corner. Right for any planar simple polygon, convex or
// not (three corners alone give the wrong side at a reflex corner). Over NT: intervals (under
// CGAL::Protect_FPU_rounding) to filter, EK::FT to decide what they cannot.
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

// n1·n2 < c |n1| |n2|, squared with the signs taken care of: exact over EK::FT, possibly
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
  using FT = EK::FT;

  // Facing: the sign of n·t with t toward the viewer: −d in an orthographic view; in a
  // perspective one e − p for a corner p, so that the face faces the viewer exactly when the eye
  // lies on its front side.
  FaceNormals(const Mesh& mesh, const View& view) : mesh_(mesh), approx_(mesh.faces.size()), exact_(mesh.faces.size()) {
    facing_.resize(mesh.faces.size());
    const double toward_viewer[3] = {-view.direction[0], -view.direction[1], -view.direction[2]};
    auto toward = [&]<class NT>(std::size_t f, NT) -> std::array<NT, 3> {
      if (!view.eye) return {NT(toward_viewer[0]), NT(toward_viewer[1]), NT(toward_viewer[2])};
      const auto& p = mesh.vertices[mesh.faces[f][0]];
      const Vec3& e = *view.eye;
      return {NT(e[0]) - NT(p[0]), NT(e[1]) - NT(p[1]), NT(e[2]) - NT(p[2])};
    };
    std::vector<std::size_t> undecided;
    {
      CGAL::Protect_FPU_rounding<true> protect;
      for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        approx_[f] = face_normal<IA>(mesh, mesh.faces[f]);
        const CGAL::Uncertain<CGAL::Sign> sign = CGAL::sign(dot(approx_[f], toward(f, IA())));
        if (CGAL::is_certain(sign)) facing_[f] = CGAL::get_certain(sign);
        else undecided.push_back(f);
      }
    }
    for (std::size_t f : undecided) facing_[f] = CGAL::sign(dot(exact(f), toward(f, FT())));
  }

  int facing(std::size_t f) const { return facing_[f]; }

  // Whether faces f and g (g's normal times `flip`) meet at more than the crease angle.
  bool crease(std::size_t f, std::size_t g, int flip, double cos_threshold) {
    {
      CGAL::Protect_FPU_rounding<true> protect;
      std::array<IA, 3> ng = approx_[g];
      if (flip < 0) ng = {-ng[0], -ng[1], -ng[2]};
      const CGAL::Uncertain<bool> above = angle_above(approx_[f], ng, cos_threshold);
      if (CGAL::is_certain(above)) return CGAL::get_certain(above);
    }
    std::array<FT, 3> ng = exact(g);
    if (flip < 0) ng = {-ng[0], -ng[1], -ng[2]};
    return angle_above(exact(f), ng, cos_threshold);
  }

 private:
  const std::array<FT, 3>& exact(std::size_t f) {
    if (!exact_[f]) exact_[f] = face_normal<FT>(mesh_, mesh_.faces[f]);
    return *exact_[f];
  }

  const Mesh& mesh_;
  std::vector<std::array<IA, 3>> approx_;
  std::vector<std::optional<std::array<FT, 3>>> exact_;
  std::vector<int> facing_;
};

}  // namespace

const char* feature_kind_name(FeatureKind kind) {
  switch (kind) {
    case FeatureKind::silhouette: return "silhouette";
    case FeatureKind::crease: return "crease";
    case FeatureKind::boundary: return "boundary";
    case FeatureKind::intersection: return "intersection";
    case FeatureKind::group: return "group";
  }
  return "?";
}

std::vector<FeatureEdge> feature_edges(const Mesh& mesh, const View& view, const FeatureOptions& options) {
  const double cos_threshold = std::cos(options.crease_degrees * std::numbers::pi / 180.0);
  FaceNormals normals(mesh, view);

  const std::vector<EdgeUse> uses = edge_uses(mesh);
  const ComponentSides sides = component_sides(mesh, uses);
  std::vector<FeatureEdge> out;
  for_each_edge(uses, [&](EdgeUses first, EdgeUses last) {
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
        if (!(source & 1u) || ((source & 2u) && !options.smooth_edges)) return;
        edge.kind = FeatureKind::crease;
      } else if (normals.crease(f, g, flip, cos_threshold)) {
        edge.kind = FeatureKind::crease;
      } else if (!mesh.face_group.empty() && mesh.face_group[f] != mesh.face_group[g]) {
        edge.kind = FeatureKind::group;
      } else {
        return;
      }
    }
    out.push_back(std::move(edge));
  });
  return out;
}

}  // namespace hlr
