// perspective_defect (hlr/kernel/near_plane.hpp): decided exactly on the input doubles, with
// Epick's predicates (exact on them) and Epeck's numbers for the depths.
#include <hlr/kernel/near_plane.hpp>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

namespace hlr {
namespace {

using IK = CGAL::Exact_predicates_inexact_constructions_kernel;

// The face's corners and the eye dropped to the coordinate plane where the face's projection is
// not degenerate (the eye lies in the face's plane).
std::vector<IK::Point_2> dropped(const Mesh& mesh, const std::vector<std::uint32_t>& face, int axis) {
  std::vector<IK::Point_2> out;
  for (std::uint32_t v : face) {
    const auto& p = mesh.vertices[v];
    out.emplace_back(p[(axis + 1) % 3], p[(axis + 2) % 3]);
  }
  return out;
}

// Whether q lies in the closed polygon (any orientation): on an edge, or odd crossings of the
// ray to +x (the half-open rule counts a vertex once).
bool in_closed_polygon(const std::vector<IK::Point_2>& c, const IK::Point_2& q) {
  bool inside = false;
  for (std::size_t i = 0; i < c.size(); ++i) {
    const IK::Point_2 &a = c[i], &b = c[(i + 1) % c.size()];
    if (CGAL::collinear(a, b, q) && CGAL::collinear_are_ordered_along_line(a, q, b)) return true;
    const bool a_above = CGAL::compare_y(a, q) > 0, b_above = CGAL::compare_y(b, q) > 0;
    if (a_above == b_above) continue;
    // The edge crosses the horizontal through q: to its right when q is on the left of a→b going up.
    const CGAL::Orientation o = CGAL::orientation(a, b, q);
    if (b_above ? o == CGAL::LEFT_TURN : o == CGAL::RIGHT_TURN) inside = !inside;
  }
  return inside;
}

bool eye_on_face(const Mesh& mesh, const std::vector<std::uint32_t>& face, const IK::Point_3& eye) {
  auto point = [&](std::uint32_t v) {
    const auto& p = mesh.vertices[v];
    return IK::Point_3(p[0], p[1], p[2]);
  };
  // Three corners not on a line span the face's plane (import keeps only planar faces).
  for (std::size_t k = 2; k < face.size(); ++k) {
    const IK::Point_3 a = point(face[0]), b = point(face[1]), c = point(face[k]);
    if (CGAL::collinear(a, b, c)) continue;
    if (!CGAL::coplanar(a, b, c, eye)) return false;
    for (int axis = 0; axis < 3; ++axis) {
      auto drop = [&](const IK::Point_3& p) { return IK::Point_2(p[(axis + 1) % 3], p[(axis + 2) % 3]); };
      if (CGAL::collinear(drop(a), drop(b), drop(c))) continue;
      return in_closed_polygon(dropped(mesh, face, axis), drop(eye));
    }
  }
  return false;
}

}  // namespace

std::optional<std::string> perspective_defect(const std::vector<Mesh>& meshes, const View& view) {
  if (!view.eye) return std::nullopt;
  using FT = CGAL::Exact_predicates_exact_constructions_kernel::FT;
  const Vec3& e = *view.eye;
  const Vec3& d = view.direction;
  bool in_front = false;
  for (const Mesh& mesh : meshes)
    for (const Vec3& p : mesh.vertices)
      if (!in_front && CGAL::is_positive(FT(d[0]) * (FT(p[0]) - FT(e[0])) + FT(d[1]) * (FT(p[1]) - FT(e[1])) +
                                         FT(d[2]) * (FT(p[2]) - FT(e[2]))))
        in_front = true;
  if (!in_front) return "the whole scene is behind the eye";
  const IK::Point_3 eye(e[0], e[1], e[2]);
  for (const Mesh& mesh : meshes)
    for (std::size_t f = 0; f < mesh.faces.size(); ++f)
      if (eye_on_face(mesh, mesh.faces[f], eye))
        return "the eye lies on face " + std::to_string(mesh.face_index[f]) + " of " + mesh.file;
  return std::nullopt;
}

}  // namespace hlr
