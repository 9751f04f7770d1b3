// The independent oracle of the hidden-line tests, and the checks of a LineSet against it.
//
// Like the surface oracle (surface_oracle.hpp), it shares no code with hidden_line/src or
// kernel/src/features.cpp: it takes the meshes as read and the view, and answers by brute force in
// exact arithmetic (CGAL Epeck):
//   - feature edges: its own edge map over the faces, face normals from Newell's formula over all
//     corners (the engine takes three corners), kinds as kernel/features.hpp defines them;
//   - the exact view transform of any model point (X = d x up, Y = X x d, Z = -d, as
//     kernel/view.hpp documents), for points that are not input doubles (penetration midpoints);
//   - visibility of a point (DESIGN.md "What is visible"): hidden iff some face of some mesh (all
//     faces: front, back and edge-on) contains its image position in its closed projection and
//     reaches a depth strictly greater there. For a face seen edge-on the depth it reaches at (x, y)
//     is the largest depth of its boundary edges whose projection contains (x, y). The part over
//     faces that are not edge-on is the surface oracle's probe;
//   - visibility along a whole segment: the set of parameters t in (0, 1) where a + t (b - a) is
//     hidden, up to finitely many points, as disjoint open intervals. Per face it is the closed set
//     where the segment's image lies in the face's projection (split at every crossing with the
//     projected boundary, each part tested at its midpoint) intersected with the open set where
//     the face is strictly nearer (a linear function of t); an edge-on face hides a stretch only
//     where the segment's image runs along one of its projected edges. Isolated hidden points (an
//     edge-on face crossing the segment's image, a vertex touching it) are dropped, because no
//     piece of positive length can show them;
//   - the faces whose closed point set contains a point in 3D, and whether two faces are coplanar;
//   - penetrations, for the completeness of intersection lines: every pair of triangles (polygon
//     faces are cut into triangles by exact ear clipping; a face where that fails, not being
//     simple, is skipped and counted) of the same or different meshes, with a 3D box prefilter, whose CGAL::intersection is a segment of
//     positive length with its midpoint in the relative interior of both triangles. Two filters
//     that cannot lose such a pair run first: triangles of one mesh sharing an edge (two vertex
//     indices) cannot have one, and neither can a pair where one triangle lacks corners strictly
//     on both sides of the other's plane (line_oracle.cpp says why).
//
// check_lines compares a LineSet<ExactKernel> (hidden_line/lines.hpp) with the oracle:
//   (a) coverage: the pieces of every line start at t = 0, end at t = 1, are non-empty and
//       consecutive without gap or overlap (exactly), and consecutive pieces differ in visibility;
//       a line that projects to a point has no pieces, any other line has some;
//   (b) visibility: every piece agrees with the oracle's hidden intervals over all of it (up to
//       finitely many points); in addition the point oracle is asked at t = 1/4, 1/2, 3/4 of every
//       piece, and a disagreement there that the interval check explains (an isolated point) is a
//       note, not a failure;
//   (c) feature set: the (mesh, v0, v1, kind) of the lines that are not intersections are exactly
//       the oracle's feature edges, once each, and each line's endpoints are the exact view
//       coordinates of its two vertices;
//   (d) intersection lines: every checked point of an intersection line (its ends, its midpoint,
//       the sample points of its pieces) lies on two faces in different planes (soundness); every
//       penetration midpoint lies on an intersection line (completeness: exactly collinear with the
//       line's ends and between them, in view space);
//   stats: the LineSet's counts match its lines.
// Failures are counted by kind (the strings above, e.g. "(c) missing edge") and the first few are
// described with exact numbers, enough to reproduce them.
#pragma once

#include "surface_checks.hpp"
#include "surface_oracle.hpp"

#include <hlr/hidden_line/lines.hpp>

#include <CGAL/Bbox_2.h>

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace hlr::hltest {

using P3 = EK::Point_3;
using VP = ViewPoint<EK>;

// The oracle's name of a feature kind (hlr-lines/1 spelling).
const char* kind_text(FeatureKind kind);

// The exact, unnormalized view basis: X = d x up, Y = X x d, Z = -d; view coordinates (X.p, Y.p, Z.p).
// A perspective view from e: q = p - e, w = d.q, view coordinates (X.q / w, Y.q / w, 1 / w).
class ExactViewBasis {
 public:
  explicit ExactViewBasis(const View& view);
  VP to_view(const P3& p) const;
  VP to_view(const std::array<double, 3>& p) const;
  // Toward the viewer from a model point p: Z = -d, or e - p in a perspective view.
  EK::Vector_3 toward_viewer(const P3& p) const;

 private:
  FT x_[3], y_[3], z_[3];
  std::optional<P3> eye_;
};

// ---------------------------------------------------------------------------------------------
// Feature edges.

struct OracleFeature {
  std::uint32_t mesh = 0, v0 = 0, v1 = 0;  // v0 < v1
  FeatureKind kind = FeatureKind::boundary;
  std::vector<std::uint32_t> faces;  // ascending
};

// Every feature edge of every mesh, ordered by (mesh, v0, v1). With two faces that run the edge in
// the same direction (inconsistent orientation), the face with the lower index keeps its
// orientation and the other is flipped; this matters only for the silhouette test when one of the
// two faces is seen edge-on (features.hpp does not say which face is flipped).
// Smooth edges (features.hpp) as `smooth_edges` says: off, as kind smooth (thin) or as crease (full).
std::vector<OracleFeature> oracle_features(const std::vector<Mesh>& meshes, const View& view, double crease_degrees,
                                           SmoothEdges smooth_edges = SmoothEdges::off);

// ---------------------------------------------------------------------------------------------
// Penetrations (view-independent; compute once per scene).

struct Penetration {
  P3 midpoint;  // model space
  FaceRef f, g;
};
struct PenetrationSearch {
  std::vector<Penetration> found;
  std::size_t triangles = 0;       // after ear clipping
  std::size_t pairs_tested = 0;    // box-overlapping pairs given to CGAL::intersection
  std::size_t faces_skipped = 0;   // polygon faces that could not be cut into triangles, not searched
};
PenetrationSearch find_penetrations(const std::vector<Mesh>& meshes);

// ---------------------------------------------------------------------------------------------
// Visibility.

// An open interval (lo, hi) of parameters, lo < hi.
struct Interval {
  FT lo, hi;
};

class LineOracle {
 public:
  // Keeps a pointer to `meshes`: they must outlive the oracle.
  LineOracle(const std::vector<Mesh>& meshes, const View& view);

  const std::vector<Mesh>& meshes() const { return *meshes_; }
  const View& view() const { return view_; }
  const SceneOracle& surfaces() const { return surfaces_; }
  const ExactViewBasis& basis() const { return basis_; }
  const VP& vertex(std::uint32_t mesh, std::uint32_t v) const { return vertices_[mesh][v]; }
  const NearPlane& near() const { return near_; }
  // The ends of a mesh edge's part in front of the near plane, in view coordinates (the vertices'
  // where nothing is clipped); nothing when it lies wholly behind.
  std::optional<std::pair<VP, VP>> edge_ends(std::uint32_t mesh, std::uint32_t v0, std::uint32_t v1) const;
  std::size_t non_planar_faces() const { return non_planar_; }

  // The point oracle: a face that hides p (strictly nearer at p's image position), if any.
  std::optional<FaceRef> hiding_face(const VP& p) const;
  bool hidden(const VP& p) const { return hiding_face(p).has_value(); }

  // The interval oracle: where a + t (b - a), t in (0, 1), is hidden, as sorted, disjoint open
  // intervals (intervals that touch are merged: the point between them is not distinguished).
  // Empty when a and b have the same image.
  std::vector<Interval> hidden_intervals(const VP& a, const VP& b) const;

  // The faces whose closed point set (in 3D) contains p.
  std::vector<FaceRef> faces_through(const VP& p) const;
  bool coplanar(FaceRef f, FaceRef g) const;

 private:
  struct FaceData {
    FaceRef ref;
    std::vector<VP> corners;  // view coordinates
    FT nx, ny, nz, d;         // Newell plane nx x + ny y + nz z = d in view coordinates
  };
  const FaceData& data(FaceRef f) const { return faces_[first_[f.mesh] + f.face]; }
  void face_intervals(const FaceData& face, const VP& a, const VP& b, std::vector<Interval>& out) const;
  void edge_on_intervals(const FaceData& face, const VP& a, const VP& b, std::vector<Interval>& out) const;
  std::vector<std::uint32_t> candidates(const CGAL::Bbox_2& box) const;

  const std::vector<Mesh>* meshes_;
  View view_;
  SceneOracle surfaces_;
  ExactViewBasis basis_;
  NearPlane near_;
  std::vector<std::vector<VP>> vertices_;
  std::vector<FaceData> faces_;
  std::vector<std::size_t> first_;  // per mesh: index of its first face in faces_
  std::size_t non_planar_ = 0;
  // Uniform grid over the projected boxes of all faces (edge-on ones included).
  CGAL::Bbox_2 extent_;
  int nx_ = 1, ny_ = 1;
  std::vector<std::vector<std::uint32_t>> cells_;
};

// ---------------------------------------------------------------------------------------------
// Checks.

struct LineCheckOptions {
  double crease_degrees = 30;  // as given to classify_lines
  SmoothEdges smooth_edges = SmoothEdges::off;  // likewise (smooth edges)
  bool intersections = true;   // as given to classify_lines; false: no intersection line may appear
  bool completeness = true;    // (d) completeness (needs find_penetrations)
  std::size_t max_messages = 12;
};

struct LineReport {
  std::map<std::string, std::size_t> failures;
  std::map<std::string, std::size_t> notes;
  std::vector<std::string> messages;
  std::size_t lines = 0, pieces = 0, samples = 0;   // (a), (b)
  std::size_t intersection_points = 0;               // (d) soundness
  std::size_t penetrations = 0;                      // (d) completeness
  bool ok() const { return failures.empty(); }
  std::string summary() const;
};

// `penetrations`: find_penetrations(oracle.meshes()), or nothing to have it computed here.
LineReport check_lines(const LineOracle& oracle, const hidden_line::LineSet<ExactKernel>& set,
                       const LineCheckOptions& options, const PenetrationSearch* penetrations = nullptr);

}  // namespace hlr::hltest
