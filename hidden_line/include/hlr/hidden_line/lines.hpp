// hlr hidden_line, lines: the feature lines of a view split into visible and hidden pieces.
//
// intersection_lines finds where faces penetrate each other, in model space and exactly: the
// segments along which the relative interiors of two faces in different planes cross (pieces over
// the faces of one coplanar group are joined). They do not depend on the view.
//
// classify_lines splits every feature edge (kernel/features.hpp) and every intersection segment
// into visible and hidden pieces, against the VisibilityMap or against the sources themselves (the
// same pieces, without the sort). A point of a line is hidden when a face is strictly nearer at its
// image position (DESIGN.md "What is visible"; faces are closed sets, and faces seen edge-on count
// too). Split points are the line's crossings with the support lines of the occluding polygons'
// edges, and the points where the line passes through an occluder's plane:
// each is constructed from input data only (DESIGN.md rule 3). The pieces of a line cover it
// exactly once, and consecutive pieces differ in visibility.
//
// drawing_segments applies ISO 128 precedence for drawings: where pieces coincide in the image,
// the visible one is drawn and a hidden one is not; coincident pieces of one class are drawn once,
// for the mesh whose line comes first. Smooth lines (FeatureKind::smooth) are thin continuous
// lines (ISO 128 type 01.1): their visible pieces come last in precedence, after hidden ones (a
// narrow continuous line gives way to a hidden edge), and their hidden pieces are not drawn
// (drafters leave hidden tangent edges out).
#pragma once

#include <hlr/hidden_line/visibility.hpp>
#include <hlr/kernel/exact_output.hpp>
#include <hlr/kernel/features.hpp>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace hlr::hidden_line {

// A penetration segment in model space, exact.
struct IntersectionSegment {
  using Point3 = CGAL::Exact_predicates_exact_constructions_kernel::Point_3;
  Point3 a, b;
  std::uint32_t mesh_a = 0, mesh_b = 0;
  std::vector<std::uint32_t> faces_a, faces_b;  // the faces of each side the segment crosses
  // The angle between the two planes in degrees, in (0, 90], rounded: not a decision of the exact
  // path, but what drawings use to leave out the contact lines of nearly tangent surfaces.
  double meeting_degrees = 90;
  // How a and b were built from the input, for their rounding in output, is kept in the points
  // themselves (recipe_of, kernel/exact_output.hpp).
};

// Throws Cancelled when `stop` asks (polled between candidate face pairs).
std::vector<IntersectionSegment> intersection_lines(const std::vector<Mesh>& meshes, StopToken stop = {});

template <class K>
struct LinePiece {
  typename Geometry<K>::FT t0, t1;  // along the line: a + t (b - a), 0 <= t0 < t1 <= 1
  bool visible = true;
};

// One feature edge or intersection segment, with its pieces.
template <class K>
struct FeatureLine {
  ViewPoint<K> a, b;  // view coordinates, unnormalized frame (exact on ExactKernel)
  std::vector<LinePiece<K>> pieces;  // empty when the line projects to a point
  double meeting_degrees = 90;       // intersections: IntersectionSegment::meeting_degrees
  std::uint32_t mesh = 0;
  std::uint32_t v0 = 0, v1 = 0;  // the mesh edge's input vertices; unused for intersections
  // Intersections in orthographic views on the exact kernel: the index of their ends' rounding in
  // LineSet::rounded_ends.
  static constexpr std::uint32_t kNotRounded = UINT32_MAX;
  std::uint32_t rounded_ends = kNotRounded;
  FeatureKind kind = FeatureKind::boundary;
  // Mesh edges whose ends are the input vertices v0 and v1 (LineSet::model_end), for predicates
  // decided on their input coordinates (view_predicates.hpp); not where the near plane of a
  // perspective view cuts the edge (an end is then constructed).
  bool has_model_ends = false;
};

struct LineStats {
  std::size_t lines = 0;                 // feature edges plus intersection segments
  std::size_t by_kind[kFeatureKinds] = {};  // indexed by FeatureKind
  std::size_t point_in_view = 0;         // lines seen end-on (no pieces)
  std::size_t visible_pieces = 0, hidden_pieces = 0;
};

template <class K>
struct LineSet {
  std::vector<FeatureLine<K>> lines;
  LineStats stats;
  Vec3 view_direction{0, 0, -1};  // of the view the lines were classified in
  std::optional<Vec3> view_eye;   // and its eye, when it is a perspective view
  // See FeatureLine::rounded_ends: the nearest doubles to the ends' view coordinates, worked out
  // from their recipes (RecipeRounding), or nothing where the general path must round them.
  std::vector<std::array<std::optional<std::array<double, 3>>, 2>> rounded_ends;
  // Per mesh, its input vertices, where lines with FeatureLine::has_model_ends end (kept once here
  // rather than twice in every line).
  std::vector<std::vector<Vec3>> model_vertices;
  const Vec3& model_end(const FeatureLine<K>& line, int end) const {
    return model_vertices[line.mesh][end == 0 ? line.v0 : line.v1];
  }
};

struct LineOptions {
  FeatureOptions features;
  bool intersections = true;
  StopToken stop;  // polled every so many lines
  bool free_at_exit = false;  // a stopped classification leaves its lines to the process's exit
};

// `sources` and `map` must come from build_sources and area_sort of the same meshes and frame,
// with back faces removed or not (either is correct).
template <class K>
LineSet<K> classify_lines(const std::vector<Mesh>& meshes, const ViewFrame<K>& frame, const Sources<K>& sources,
                          const VisibilityMap<K>& map, const std::vector<IntersectionSegment>& intersections,
                          const LineOptions& options = {});

// The same pieces without the area sort: the sources themselves are the occluders. A point is
// hidden when some face is strictly nearer there, and wherever one is, the visible fragment there
// is nearer still (and conversely each fragment lies in its source), so both give the same lines;
// what the sources add are split points inside runs of one class, which are joined. It costs more
// per line where the scene is deep (a line behind k faces meets all k), far less than the sort.
template <class K>
LineSet<K> classify_lines(const std::vector<Mesh>& meshes, const ViewFrame<K>& frame, const Sources<K>& sources,
                          const std::vector<IntersectionSegment>& intersections, const LineOptions& options = {});

// A segment of the drawing in the image plane (unnormalized view frame). `mesh` is the part it
// is drawn for: its line's mesh (for an intersection line the lower of the two meshes); where
// lines of several meshes coincide, the one that comes first in the LineSet is drawn.
template <class K>
struct DrawnSegment {
  typename Geometry<K>::Point a, b;
  bool visible = true;
  std::uint32_t mesh = 0;
  double meeting_degrees = 90;  // of its line
  std::uint32_t line = 0;       // its line's index in the LineSet
  bool thin = false;            // a visible piece of a smooth line: thin continuous
  typename Geometry<K>::FT t0, t1;  // where a and b lie along the line (FeatureLine's a + t (b - a))
};

// `vertex_images`: the mesh vertices' image points (Sources::image_points of the same view), which
// the drawing then shares instead of making its own.
template <class K>
std::vector<DrawnSegment<K>> drawing_segments(const LineSet<K>& lines, StopToken stop = {},
                                              const std::vector<std::vector<typename Geometry<K>::Point>>* vertex_images = nullptr);

#define HLR_HIDDEN_LINE_LINES_DECLARE(K, EXTERN)                                                         \
  EXTERN template LineSet<K> classify_lines<K>(const std::vector<Mesh>&, const ViewFrame<K>&, const Sources<K>&, \
                                              const VisibilityMap<K>&, const std::vector<IntersectionSegment>&, \
                                              const LineOptions&);                                           \
  EXTERN template LineSet<K> classify_lines<K>(const std::vector<Mesh>&, const ViewFrame<K>&, const Sources<K>&, \
                                              const std::vector<IntersectionSegment>&, const LineOptions&);     \
  EXTERN template std::vector<DrawnSegment<K>> drawing_segments<K>(                                    \
      const LineSet<K>&, StopToken, const std::vector<std::vector<Geometry<K>::Point>>*);

HLR_HIDDEN_LINE_LINES_DECLARE(ExactKernel, extern)
HLR_HIDDEN_LINE_LINES_DECLARE(EpickKernel, extern)
HLR_HIDDEN_LINE_LINES_DECLARE(DoubleKernel, extern)

}  // namespace hlr::hidden_line
