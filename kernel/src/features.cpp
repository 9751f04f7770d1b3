// Feature-edge extraction (hlr/kernel/features.hpp), exact on the input doubles.
#include <hlr/kernel/features.hpp>
#include <hlr/kernel/mesh_edges.hpp>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <cmath>
#include <numbers>

namespace hlr {
namespace {

using EK = CGAL::Exact_predicates_exact_constructions_kernel;

// A face's normal, oriented by its corner order: twice its vector area, the sum of the fan
// triangles' cross products from the first corner. Right for any planar simple polygon, convex or
// not (three corners alone give the wrong side at a reflex corner).
EK::Vector_3 face_normal(const Mesh& mesh, const std::vector<std::uint32_t>& face) {
  auto point = [&](std::uint32_t v) {
    const auto& p = mesh.vertices[v];
    return EK::Point_3(p[0], p[1], p[2]);
  };
  const EK::Point_3 origin = point(face[0]);
  EK::Vector_3 sum = CGAL::cross_product(point(face[1]) - origin, point(face[2]) - origin);
  for (std::size_t k = 3; k < face.size(); ++k)
    sum = sum + CGAL::cross_product(point(face[k - 1]) - origin, point(face[k]) - origin);
  return sum;
}

// n1·n2 < c |n1| |n2|, decided exactly by squaring with the signs taken care of.
bool angle_above(const EK::Vector_3& n1, const EK::Vector_3& n2, double cos_threshold) {
  const EK::FT s = n1 * n2;
  const EK::FT c(cos_threshold);
  const EK::FT q = c * c * n1.squared_length() * n2.squared_length();
  if (cos_threshold >= 0) return CGAL::is_negative(s) || s * s < q;
  return CGAL::is_negative(s) && s * s > q;
}

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
  const EK::Vector_3 toward_viewer(-view.direction[0], -view.direction[1], -view.direction[2]);

  std::vector<EK::Vector_3> normal(mesh.faces.size());
  std::vector<int> facing(mesh.faces.size());
  for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
    normal[f] = face_normal(mesh, mesh.faces[f]);
    facing[f] = CGAL::sign(normal[f] * toward_viewer);
  }

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
      const int f_sign = facing[f], g_sign = flip * facing[g];
      const bool turns = side != 0 ? (f_sign * side > 0) != (g_sign * side > 0) : f_sign != g_sign;
      const bool fan = first[0].fan && first[1].fan;  // inside one non-planar face: crease rule only
      if (turns && !fan) {
        edge.kind = FeatureKind::silhouette;
      } else if (angle_above(normal[f], flip > 0 ? normal[g] : -normal[g], cos_threshold)) {
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
