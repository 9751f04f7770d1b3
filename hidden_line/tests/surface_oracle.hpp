// The independent oracle of the hidden-surface tests. It shares no code with hidden_line/src: it
// takes the meshes as read and the exact view frame (kernel/view.hpp), and answers, by brute force
// over every face of every mesh, in exact arithmetic (CGAL Epeck):
//   - which faces are seen edge-on, front or back, and which lie in closed, consistently oriented
//     components and which way those face (so which faces the hidden-surface solution must keep:
//     an inward component's back faces are the ones wound toward the viewer);
//   - which faces contain a point of the view plane (faces are closed sets), and the largest exact
//     depth z among them (a larger z is nearer to the viewer);
//   - an exact interior point of a polygon with holes.
// Face planes come from Newell's formula over all corners (exact for planar faces), not from three
// chosen corners as the engine does, so a shared mistake is unlikely.
#pragma once

#include <hlr/kernel/kernel.hpp>
#include <hlr/kernel/scene.hpp>
#include <hlr/kernel/view.hpp>

#include <CGAL/Bbox_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace hlr::hltest {

using EK = ExactKernel;
using FT = EK::FT;
using P2 = EK::Point_2;
using P3 = EK::Point_3;

// z = a x + b y + c in the exact, unnormalized view frame.
struct Plane {
  FT a, b, c;
  FT at(const P2& q) const { return a * q.x() + b * q.y() + c; }
};
bool same_plane(const Plane& p, const Plane& q);

struct FaceRef {
  std::uint32_t mesh = 0, face = 0;
  bool operator==(const FaceRef&) const = default;
  auto operator<=>(const FaceRef&) const = default;
};

// Exact point-in-polygon for a closed contour (any orientation): +1 strictly inside, 0 on the
// boundary, -1 outside. The contour may be any closed polyline; inside means non-zero winding.
int locate(const std::vector<P2>& contour, const P2& q);

// Per face: +1 or -1 in a closed, consistently oriented component whose faces face outward or
// inward (the sign of the volume they enclose), 0 elsewhere.
std::vector<int> closed_sides(const Mesh& mesh);

// An exact point strictly inside a polygon with holes (outer and holes in any orientation): a line
// y = y* strictly between two consecutive distinct vertex ordinates (the widest gap) meets the
// edges; the midpoint of the first interval between sorted crossings. Nothing when the polygon has
// no two distinct ordinates or the line meets fewer than two edges.
std::optional<P2> interior_point(const std::vector<P2>& outer, const std::vector<std::vector<P2>>& holes);

// Strictly inside outer and strictly outside every hole?
bool strictly_inside(const std::vector<P2>& outer, const std::vector<std::vector<P2>>& holes, const P2& q);

// The near plane of a perspective view, as DESIGN.md defines it, for the oracles: depth
// d.(p - e), nu = (1/1000 or the view's fraction) x the largest depth of a vertex, and faces and
// segments clipped to depth >= nu with CGAL's own plane intersections (the engine interpolates).
// For an orthographic view nothing is clipped.
class NearPlane {
 public:
  NearPlane(const std::vector<Mesh>& meshes, const View& view);
  bool perspective() const { return eye_.has_value(); }
  bool in_front(const P3& p) const { return !eye_ || depth(p) >= nu_; }
  // Sutherland-Hodgman on the face's corners (they are convex or cut at most twice in the tests);
  // empty when fewer than three corners remain.
  std::vector<P3> clip(const std::vector<P3>& polygon) const;
  // A segment's part in front; nothing when no more than a point of it is.
  std::optional<std::pair<P3, P3>> clip(const P3& a, const P3& b) const;

 private:
  FT depth(const P3& p) const { return (p - *eye_) * d_; }
  P3 crossing(const P3& a, const P3& b) const;
  std::optional<P3> eye_;
  EK::Vector_3 d_;
  FT nu_;
};

class SceneOracle {
 public:
  SceneOracle(const std::vector<Mesh>& meshes, const View& view);

  struct Face {
    std::vector<P2> points;  // projected corners, in the face's order
    Plane plane;             // only when facing != 0
    int facing = 0;          // sign of the projected area: +1 toward the viewer, -1 away, 0 edge-on
    bool behind = false;     // perspective: wholly behind the near plane (then facing is 0, no points)
    FT twice_projected_area;  // signed
    bool closed = false;      // in a closed, consistently oriented component that encloses volume
    int side = 0;             // closed: +1 outward, -1 inward (its back faces are the front-wound ones)
    CGAL::Bbox_2 box;         // conservative (interval) bounds of the projection
  };
  const Face& face(FaceRef f) const { return meshes_[f.mesh][f.face]; }
  std::size_t mesh_count() const { return meshes_.size(); }
  std::size_t face_count(std::uint32_t mesh) const { return meshes_[mesh].size(); }

  // Should the engine keep this face as (part of) a source? Not edge-on, and, when back faces are
  // removed, not a back face of a closed, consistently oriented component.
  bool kept(FaceRef f, bool remove_back_faces) const;

  // Does the (closed) projection of the face contain q? Edge-on faces never do.
  bool contains(FaceRef f, const P2& q) const;

  // All faces that are not edge-on and contain q, and the largest depth among them.
  struct Probe {
    std::vector<FaceRef> faces;
    std::optional<FT> max_z;
  };
  Probe probe(const P2& q) const;

 private:
  std::vector<std::vector<Face>> meshes_;
  // A uniform grid over the projected bounding boxes of the faces that are not edge-on.
  CGAL::Bbox_2 extent_;
  int nx_ = 1, ny_ = 1;
  std::vector<std::vector<FaceRef>> cells_;
  void cell_range(const CGAL::Bbox_2& b, int& x0, int& x1, int& y0, int& y1) const;
};

// Exact signed area of a contour, doubled (positive when counter-clockwise).
FT twice_signed_area(const std::vector<P2>& contour);

}  // namespace hlr::hltest
