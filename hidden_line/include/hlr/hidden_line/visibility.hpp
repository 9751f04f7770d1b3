// hlr hidden_line: the hidden-surface solution of one view (Weiler–Atherton's area sort).
//
// build_sources turns the meshes of a scene into the polygons the area sort works on: faces are
// projected exactly (ViewFrame), back faces of closed, consistently oriented components are
// removed (a component wound inward is taken as turned outward, decided by the exact sign of its
// volume), faces seen edge-on are dropped (they cover no area), and connected, exactly coplanar
// faces are consolidated into one polygon with holes, so a tessellated planar face is one polygon.
//
// area_sort solves visibility: the nearest polygon clips the rest into inside and outside lists
// (clip_list); inside pieces behind it are hidden by it; pieces in front of it mean the rough
// depth order was wrong there: they hide that much of the front piece and are solved among
// themselves, recursively; a piece that is partly in front and partly behind (penetration) is
// split exactly along the line where the two planes meet. The result, a VisibilityMap, gives every source's visible pieces and
// its hidden pieces, each hidden piece tagged with the source that hides it.
//
// Depth is decided exactly from each source's plane (DESIGN.md rule 4). Where two sources lie in
// the same plane over an area, the one with the lower index wins (sources are ordered by mesh,
// then by first face), and the count of such areas is in the stats.
#pragma once

#include <hlr/clipper/clipper.hpp>
#include <hlr/kernel/errors.hpp>
#include <hlr/kernel/near_plane.hpp>
#include <hlr/kernel/scene.hpp>
#include <hlr/kernel/view.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace hlr::hidden_line {

// z = a x + b y + c in view coordinates (unnormalized frame).
template <class K>
struct DepthPlane {
  typename Geometry<K>::FT a, b, c;
};

// What a support line is.
struct LineOrigin {
  enum Kind { mesh_edge, intersection, auxiliary } kind = auxiliary;
  std::int32_t mesh = -1;                     // mesh_edge: the mesh and the edge's vertex indices,
  std::uint32_t v0 = 0, v1 = 0;               // v0 < v1
  std::int32_t source_a = -1, source_b = -1;  // intersection: the two sources whose planes meet
};

// One polygon of the area sort: consolidated faces of one mesh, in one plane.
template <class K>
struct SourcePolygon {
  clip::Polygon<K> polygon;  // projected, outer counter-clockwise
  std::optional<DepthPlane<K>> plane;  // none without SourceOptions::depth_planes
  // Three corners that span the plane, as indices into the mesh's view_points (in an
  // orthographic view, input vertices).
  std::array<std::uint32_t, 3> plane_points{};
  std::uint32_t mesh = 0;
  std::vector<std::uint32_t> faces;  // indices into the mesh's face list
};

struct SourceStats {
  std::size_t faces = 0;
  std::size_t back_faces_removed = 0;
  std::size_t edge_on_faces_removed = 0;
  std::size_t faces_behind_eye = 0;  // perspective: wholly behind the near plane
  std::size_t faces_consolidated = 0;  // faces merged into a polygon with other faces
  std::size_t sources = 0;
  std::size_t closed_components = 0, open_components = 0;
  std::size_t inward_components = 0;  // closed components whose faces face inward: culled as turned outward
  std::size_t faces_culled = 0;       // left out because they are in SourceOptions::culled
};

template <class K>
struct Sources {
  std::vector<SourcePolygon<K>> polygons;
  clip::LineTable<K> lines;
  std::vector<LineOrigin> line_origins;  // parallel to lines; empty without SourceOptions::line_origins
  // (mesh, v0, v1) of the edges of the faces dropped edge-on that can cover a line: each edge
  // once, and with `consolidate` not the edges between two of a region's coplanar triangles (the
  // region covers what its boundary covers). v0, v1 index view_points: in a perspective view an
  // end behind the near plane is replaced by the edge's crossing with it, and a clipped face's
  // cut is one more edge.
  std::vector<std::array<std::uint32_t, 3>> edge_on_edges;
  std::vector<std::vector<ViewPoint<K>>> view_points;        // per mesh, per input vertex
  std::vector<std::vector<typename Geometry<K>::Point>> image_points;  // the same, projected: the
                                                             // points every source corner shares
  // Per mesh: what the near plane clips (perspective; view_points then go on with the points where
  // edges cross it, and those behind it are unused).
  std::vector<NearCut<K>> near_cuts;
  // Per mesh, (edge_key(v0, v1), line) for every mesh edge's support line, sorted by key.
  std::vector<std::vector<std::pair<std::uint64_t, clip::LineId>>> edge_lines;
  SourceStats stats;
};

struct SourceOptions {
  bool remove_back_faces = true;
  bool consolidate = true;
  // Per mesh, per face: faces that nothing in the view can show (fuzzy_cull.hpp), or null. They
  // are left out of the sources as if they were not in the mesh (a coplanar group merges the
  // rest); what is seen, and every line's visibility, is the same.
  const std::vector<std::vector<bool>>* culled = nullptr;
  // Each source's DepthPlane: the area sort and the shadows need it; a line drawing in an
  // orthographic view on the exact kernel decides depths in model space instead (ModelPlane in
  // kernel/view_predicates.hpp) and is spared building them.
  bool depth_planes = true;
  // What each support line is (Sources::line_origins): the area sort and the shadows need it, a
  // line drawing does not (1.5M lines, 36 MB, at 1M faces).
  bool line_origins = true;
  StopToken stop;  // polled as the faces are projected
};

template <class K>
Sources<K> build_sources(const std::vector<Mesh>& meshes, const ViewFrame<K>& frame, const SourceOptions& options = {});

template <class K>
struct Fragment {
  clip::Polygon<K> polygon;
  std::uint32_t source = 0;
  std::int32_t occluder = -1;  // hidden fragments: the source strictly nearer over all of it
};

struct AreaSortStats {
  std::size_t clips = 0;             // clip_list calls
  std::size_t recursions = 0;        // sort errors resolved by recursion
  std::size_t penetration_splits = 0;
  std::size_t coplanar_ties = 0;     // areas where two sources coincide in space
};

template <class K>
struct VisibilityMap {
  std::vector<Fragment<K>> visible;
  std::vector<Fragment<K>> hidden;  // empty unless AreaSortOptions::keep_hidden
  AreaSortStats stats;
};

struct AreaSortOptions {
  // The hidden polygon set: `hlr surfaces` writes it; a line drawing needs only the visible one.
  bool keep_hidden = true;
  // Screen subdivision (exact kernel): the image is cut into vertical strips of about this many
  // sources each (at most 8), sorted in parallel; 0 never cuts it. Fragments that reach across a
  // strip border come out as one piece per strip. The strips do not depend on the thread count.
  std::size_t sources_per_strip = 256;
  StopToken stop;  // polled between front polygons
};

// Solves visibility for the sources; appends the lines of strip borders and penetration splits to
// sources.lines.
template <class K>
VisibilityMap<K> area_sort(Sources<K>& sources, const AreaSortOptions& options = {});

#define HLR_HIDDEN_LINE_DECLARE(K, EXTERN)                                                                 \
  EXTERN template Sources<K> build_sources<K>(const std::vector<Mesh>&, const ViewFrame<K>&, const SourceOptions&); \
  EXTERN template VisibilityMap<K> area_sort<K>(Sources<K>&, const AreaSortOptions&);

HLR_HIDDEN_LINE_DECLARE(ExactKernel, extern)
HLR_HIDDEN_LINE_DECLARE(EpickKernel, extern)
HLR_HIDDEN_LINE_DECLARE(DoubleKernel, extern)

}  // namespace hlr::hidden_line
