// hlr kernel, feature edges: the mesh edges a drawing shows (DESIGN.md "Feature lines").
//
// An edge (two cyclically consecutive vertices of a face, unordered) is a feature edge when it is
//   - boundary: it has one face;
//   - crease: it has more than two faces (non-manifold), or two faces whose dihedral angle, the
//     angle between their normals once the two are oriented alike, is above the crease threshold;
//   - silhouette: it has two faces and one faces the viewer while the other does not (back-facing
//     or seen edge-on). In a closed solid the front side is the outside (mesh_edges.hpp
//     component_sides), whichever way it is wound; an open or inconsistently oriented mesh has two
//     alike sides: there the edge is a silhouette when one face is seen from one side and the
//     other from the other side or edge-on. So the feature set does not depend on the winding;
//   - group: two faces of different face groups (materials, OBJ groups, face colours);
//   - smooth (with smooth_edges): two faces that meet tangentially, as a fillet meets the flat
//     faces it blends (below). Drawn as `smooth` (thin) or, with SmoothEdges::full, as crease.
// An edge that is several of these takes the first in the order silhouette, crease, group, smooth.
// A face's normal follows its corner order (its vector area). Two faces that run their edge in the
// same direction are oriented alike by reversing the higher-numbered one.
// The internal edges of a tessellated planar face are none of these (their dihedral angle is 0).
// The internal edges of a non-planar face's fan (Mesh::fan_edges) are feature lines by the crease
// rule only (DESIGN.md "Feature lines").
//
// Smooth edges of a mesh, which has no B-rep to say where its surfaces meet tangentially: its
// planar surfaces are the coplanar groups (mesh_edges.hpp: edge-connected, exactly coplanar
// faces). A soft edge has two faces of different groups that meet at a dihedral angle above 0
// (not coplanar) and at most the crease threshold. A planar surface is a facet strip across the
// line L of one of its soft edges when it has another soft edge on a line L' parallel to L and
// every corner of it lies on L or L': the quad between two rulings of a tessellated cylinder or
// fillet. A soft edge is smooth when one of its surfaces is a facet strip across it and the other
// is flat across it: neither a strip across it nor a lone triangle (a facet of a tessellated
// sphere or cone). So a tessellated fillet's two tangent lines are smooth, and its inner edges,
// a cylinder's, a sphere's and a shallow bend between two flat faces are not. Fan edges inside a
// non-planar face are never smooth.
//
// A mesh whose source gives its feature edges (Mesh::source_edges, a CAD model's B-rep) has no
// crease, group or smooth rule: an edge of two faces is a silhouette as above, else a crease when
// it lies on a B-rep edge (whatever the dihedral angle), except that a tangent B-rep edge is a
// smooth edge (drawn only with smooth_edges), else nothing; the internal edges of a B-rep face's
// tessellation and its seams are never creases. Boundary and non-manifold edges are as above.
//
// Everything is decided exactly on the input doubles (CGAL Epeck), so the same edges are found
// on every kernel. The threshold is the one parameter taken as given: its cosine, rounded to
// double, is compared exactly with the cosine of each dihedral angle.
#pragma once

#include <hlr/kernel/scene.hpp>
#include <hlr/kernel/view.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace hlr {

enum class FeatureKind : std::uint8_t { silhouette, crease, boundary, intersection, group, smooth };
inline constexpr std::size_t kFeatureKinds = 6;

// The hlr-lines/1 name of a kind.
const char* feature_kind_name(FeatureKind kind);

struct FeatureEdge {
  std::uint32_t v0 = 0, v1 = 0;       // input vertex indices, v0 < v1
  FeatureKind kind = FeatureKind::boundary;
  std::vector<std::uint32_t> faces;   // the faces using the edge (indices into mesh.faces)
};

// Which smooth edges are feature edges (--smooth-edges): none, each as a `smooth` edge (drawn as
// a thin continuous line), or each as a crease (drawn as any other edge).
enum class SmoothEdges : std::uint8_t { off, thin, full };

struct FeatureOptions {
  double crease_degrees = 30;  // in [0, 180]
  SmoothEdges smooth_edges = SmoothEdges::off;
};

// The feature edges of one mesh seen along `view`, in order of (v0, v1).
std::vector<FeatureEdge> feature_edges(const Mesh& mesh, const View& view, const FeatureOptions& options = {});

}  // namespace hlr
