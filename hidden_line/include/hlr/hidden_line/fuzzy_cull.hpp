// hlr hidden_line, fuzzy culling: the faces of a scene that no eye of a group of perspective views
// can see, found once for the group (after Lim, "Toward a fuzzy hidden surface algorithm",
// ../shared/seeds/000_2ecfc050513bde2d.txt), so that every view of the group leaves them out of its
// area sort.
//
// The eyes are replaced by their bounding box B. Directions from B are sampled on the six faces of
// a fuzzy projection cube: on the face (k, s) (axis k, sign s) a direction is (u, w) = the other two
// components divided by s times the k component, and only faces whose vertices all lie strictly
// beyond B along s·k take part there, so that every ray from B towards them runs along s·k. Each
// face of the cube is a grid of pixels over |u|, |w| <= reach.
//   - Occluders are the faces that every view from B keeps in its area sort and that face B
//     strictly, with one side for all of B (exact orientation tests on the input doubles): not seen
//     edge-on, never back faces of a closed component, and not cut by the near plane of any of the
//     group's views (every vertex deeper than its near plane, with a margin). Occluders joined
//     across edges they run in opposite directions, with the same side towards B, form regions;
//     any other edge of an occluder is a boundary edge of its region.
//   - A region cannot fold over as seen from B, so the number of times a ray from B meets it
//     changes only where the ray crosses a boundary edge. A pixel that no boundary edge's fuzzy
//     extent reaches (the rectangle of the directions from B's corners to the edge's ends, which
//     holds every direction from B to the edge, widened and rounded outward to whole pixels, one
//     more pixel around) and whose centre direction from one eye meets the region (an interval
//     test that says yes only when certain) is therefore met from every point of B, in every one of
//     its directions: it is in the region's umbra. Such a ray meets the region in one of its faces
//     whose fuzzy extent reaches the pixel, so no deeper than the largest depth (s times the k
//     coordinate) of those faces; the pixel keeps the smallest such bound of the regions whose
//     umbra it is in (a region spanning a large range of depth, a ceiling joined to its walls,
//     hides by the depth of its faces over the pixel rather than by its deepest point).
//   - A face whose fuzzy extent lies within the grid, on pixels that each keep a depth strictly
//     below its own smallest depth, is hidden from every point of B: along every ray from B to it,
//     an occluder comes strictly first (depth grows along the ray). It is culled.
// A group of directions (orthographic views, the light views of a sun study) is the same with the
// viewer at infinity: the box is one of directions (their ratios to the component along the axis k
// where they all run one way), the cube has that one face, and a pixel is a set of parallel lines
// of the group, by where they meet a plane x_k = const before the scene; extents are the feet of
// a point's lines over the box of directions (linear in the ratios: its corners), sides are decided
// against the box's corner directions, and every argument above holds line by line.
// Doubles only, and every rounding goes the safe way: the result is conservative by construction,
// never exact in the sense of the area sort (it culls less than it could, never more).
//
// What the views do with it (SourceOptions::culled): a culled face is left out of the sources
// before its facing is computed, as if it were not in the mesh (a coplanar group merges the rest).
// It covers no point that its occluders do not cover strictly nearer (and an occluder that is
// culled itself has one nearer still), so the visible polygons are the same sets and every line is
// classified the same way.
#pragma once

#include <hlr/kernel/errors.hpp>
#include <hlr/kernel/scene.hpp>
#include <hlr/kernel/view.hpp>

#include <cstddef>
#include <vector>

namespace hlr::hidden_line {

struct FuzzyOptions {
  int resolution = 400;  // pixels along each side of a fuzzy projection face (Lim: 400)
  double reach = 2;      // a face of the cube holds the directions with |u|, |w| <= reach
};

struct FuzzyCull {
  std::vector<std::vector<bool>> culled;  // per mesh, per face: hidden from every eye of the group
  std::size_t patches = 0;                // faces of the scene
  std::size_t culled_faces = 0;
  // Of those, the back faces of closed components (as seen from all of B): every view removes
  // them anyway (but one whose near plane cuts their component), so culling them saves nothing.
  std::size_t culled_back_faces = 0;
  std::size_t occluders = 0, regions = 0;  // faces and regions that went into the depth buffer
  double seconds = 0;
};

// The faces of `meshes` that no eye in the bounding box of the views' eyes can see. Every view
// must be a perspective view (View::eye) that can be drawn of the scene (perspective_defect);
// the near planes are those of the views given. Or every view is orthographic (the light views of
// a sun study): then the viewpoints are directions, the viewer at infinity against each, and the
// box is that of the directions' ratios d / |d_k| on the axis k where all of them run one way
// (the one where they run most steeply); the cube has that one face, its pixels the feet of the
// group's parallel lines on a plane before the scene, and the same argument holds line by line
// (Lim's parallel case): a face is culled when along every line of every direction of the box
// an occluder region lies strictly nearer to the viewer. Nothing is culled for directions that
// share no such axis. Throws Cancelled when `stop` asks, std::invalid_argument for a mix of views.
FuzzyCull fuzzy_cull(const std::vector<Mesh>& meshes, const std::vector<View>& views, const FuzzyOptions& options = {},
                     StopToken stop = {});

// Groups of viewpoints (hlr frames' eyes, a sun study's light directions).
//
// The point a view stands for in a group: its eye, or (orthographic) its unit direction.
Vec3 group_point(const View& view);
// Runs of consecutive views whose group points fit in a box no longer than `extent` along any axis.
struct ViewRun {
  std::size_t first = 0, count = 0;
};
std::vector<ViewRun> group_views(const std::vector<View>& views, double extent);

// The views of a group that one fuzzy pass culls for (cull_parts).
struct CullPart {
  std::vector<std::size_t> views;        // ascending
  std::size_t culled = 0;                // faces culled for these views
  std::size_t useful = 0;                // of those, the ones a view would keep (not back faces)
  std::vector<std::vector<bool>> faces;  // per mesh, per face: culled (empty when none is)
};
struct CullPasses {
  std::size_t passes = 0;   // those that culled nothing and were split included
  std::size_t patches = 0;  // faces of the scene
  double seconds = 0;       // all passes
};
// The fuzzy culling of the views `members` of `views`: one pass over their box; when it culls
// nothing useful (no face but back faces, which every view removes anyway) and there are two
// views or more, they are split once, at the middle of the box of their group points' longest
// axis, and each half is culled alone (at most three passes). Every pass goes to `passes`.
std::vector<CullPart> cull_parts(const std::vector<Mesh>& meshes, const std::vector<View>& views,
                                 std::vector<std::size_t> members, const FuzzyOptions& options, StopToken stop,
                                 CullPasses& passes);

}  // namespace hlr::hidden_line
