// hlr hidden_line, shadows: which parts of every face a light reaches, exactly (Weiler and
// Atherton's "Shadowing"; DESIGN.md, "Shadows: hlr shadows and the contract hlr-shadows/1").
//
// cast_shadows solves the scene from each light on its own. For a directional light (a sun whose
// rays travel along d) the light view is the orthographic view looking along d (the exact,
// unnormalized ViewFrame of the exactness contract, up = +Z, or +Y when d is vertical); the area
// sort solves it (build_sources + area_sort, the hidden polygons kept), and every fragment is taken
// back onto its source's plane in model space by an exact rational map: a light-view point (x, y)
// on a source whose light-view plane is z = a x + b y + c is the model point
// p = x X/|X|² + y Y/|Y|² + z Z/|Z|² (X, Y, Z the orthogonal, unnormalized view axes).
// For a point light at e the light view is the perspective view from e (view.hpp): a light-view
// point (u, v) on a source whose light-view plane is s = a u + b v + c is the model point
// p = e + (u X/|X|² + v Y/|Y|² + d/|d|²) / s, rational again. One perspective view sees one half
// space: when every vertex of the scene lies strictly in front of a plane through the light
// (point_light_view chooses it) that view serves. A light among the geometry (a bulb in a room)
// is solved in the cube around it: six perspective views along ±X, ±Y, ±Z, each seeing only its
// pyramid (the points p with |(p − e)_b| ≤ s (p − e)_a for the other two coordinates b), which is
// the square [−1, 1]² of its image. Every view's sources are cut exactly to that square (its near
// plane lies before everything in the pyramid, so the cut is the pyramid's planes); rays from the
// light inside a pyramid meet only what lies inside it, so each pyramid is solved on its own and
// the pieces of a source from the six add up to it. A light on a face or inside a closed solid has
// no answer (point_light_defect).
//
//   lit     the visible fragments of sources that face the light, and the parts of hidden
//           fragments hidden only by a coplanar tie: where the visible fragment over them lies
//           exactly in their plane (nothing strictly nearer);
//   shadow  the other hidden fragments of those sources (cast shadow; `by` = the faces of the
//           visible fragments that overlap it in the light view with positive area: the faces
//           nearest to the light over it), and the whole of every source that faces away from
//           the light or is seen edge-on by it (attached shadow, `by` empty).
// So lit + shadow = source follows from the area sort's own identity (a source's visible and
// hidden fragments are exactly its projection); the tests check it exactly, on areas.
//
// Sources are light-independent: the maximal edge-connected, exactly coplanar face groups of one
// mesh with one front side, merged in model space exactly as build_sources merges them in a view
// (and kept face by face where that merge fails). The front side is the side a face's normal
// (its winding) points to; in a closed component wound inward it is the outside, as for back-face
// removal. Everything here runs on the exact kernel only; doubles appear where the result is
// rounded for output (the *_area doubles, LightView).
#pragma once

#include <hlr/hidden_line/fuzzy_cull.hpp>
#include <hlr/hidden_line/jobs.hpp>
#include <hlr/hidden_line/visibility.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace hlr::hidden_line {

struct Light {
  enum Kind { directional, point } kind = directional;
  Vec3 vector{0, 0, -1};  // directional: the direction the light travels; point: its position
};

// Why a light cannot be used, or nothing: a zero or non-finite direction, a non-finite position.
std::optional<std::string> light_defect(const Light& light);

// The light view of a point light: the perspective view from it, looking along the first of these
// directions (doubles, taken as exact) that has every vertex of the scene strictly in front of the
// light, decided exactly: toward the centre of the scene's bounding box, then -Z, +Z, -X, +X, -Y,
// +Y, then from the light toward the nearest point of the vertices' convex hull (searched in
// double, up to 64 Frank-Wolfe steps, each candidate tested exactly). Its near plane lies at or
// before the nearest vertex, so nothing is clipped. Nothing when no direction qualifies (the light
// inside the convex hull, on a face, or outside it by too little for the search); cast_shadows
// then solves the light in its cube of views.
std::optional<View> point_light_view(const std::vector<Mesh>& meshes, const Light& light);
// Why cast_shadows cannot solve this light, or nothing: light_defect, or a point light without a
// point_light_view that lies on a face (in its plane, inside it or on its boundary) or inside a
// closed solid (odd crossings of a ray from it with a closed component), both decided exactly.
std::optional<std::string> point_light_defect(const std::vector<Mesh>& meshes, const Light& light);
// The view from any light: a directional light's orthographic view looking along its direction
// (up +Z, or +Y when it is vertical), a point light's point_light_view (nothing when it has none:
// the light is among the geometry). cast_shadows solves the scene in it; the raster shadow map
// (raster_shadows.hpp) renders it.
std::optional<View> light_view(const std::vector<Mesh>& meshes, const Light& light);

using ShadowFT = ExactKernel::FT;
struct ShadowPoint {
  ShadowFT x, y, z;  // model coordinates, exact
};
// A planar polygon in model space, oriented as seen from its source's front side: outer
// counter-clockwise, holes clockwise.
struct ShadowPolygon {
  std::vector<ShadowPoint> outer;
  std::vector<std::vector<ShadowPoint>> holes;
};

enum class Facing { toward, away, edge_on };
const char* facing_name(Facing facing);  // "toward", "away", "edge-on"

struct CastShadow {
  ShadowPolygon polygon;
  std::vector<std::array<std::uint32_t, 2>> by;  // (mesh, face), sorted; empty for attached shadow
};

// One source under one light.
struct SourceLight {
  Facing facing = Facing::toward;
  std::vector<ShadowPolygon> lit;  // do not overlap
  std::vector<CastShadow> shadow;
  ShadowFT lit_area2 = 0;          // exact: twice the lit area projected along the source's axis
  double lit_area = 0;             // model units: the lit polygons' areas, each rounded once, summed
};

struct ShadowSource {
  std::uint32_t mesh = 0;
  std::vector<std::uint32_t> faces;       // indices into the mesh's face list
  std::array<ShadowFT, 3> normal;         // toward the front side (Newell's normal of the first face)
  ShadowFT offset = 0;                    // normal · p + offset = 0 on the plane
  int axis = 2;                           // the coordinate with the largest |normal|: areas are
                                          // measured exactly in the plane of the other two
  std::vector<ShadowPolygon> polygons;    // the source itself (several where it touches itself)
  ShadowFT area2 = 0;                     // exact: twice the area projected along `axis`
  double area = 0;                        // model units
  std::vector<SourceLight> lights;        // per light
};

// The light view as a picture ("the view from the sun"): its visible fragments in the
// orthonormal light frame, rounded once; `lit` when the fragment's source faces the light.
struct LightViewPolygon {
  std::vector<std::array<double, 2>> outer;
  std::vector<std::vector<std::array<double, 2>>> holes;
  bool lit = false;
  std::uint32_t source = 0;  // index into ShadowResult::sources
};
// A point light solved in its cube: `pyramids` holds the views of the pyramids that see something
// (`view` and world_to_view are the first's), and `polygons` their squares side by side, pyramid
// i of +X, −X, +Y, −Y, +Z, −Z shifted by (2.5 (i mod 3), −2.5 floor(i / 3)).
struct LightView {
  View view;
  std::array<std::array<double, 4>, 4> world_to_view{};
  std::vector<LightViewPolygon> polygons;
  std::vector<View> pyramids;  // empty: one view
};

struct ShadowTimes {
  double sources = 0;   // the light-independent sources
  double views = 0;     // the light views' polygons (build_sources), all lights
  double sort = 0;      // the area sorts, all lights
  double map_back = 0;  // fragments to model space, `by`, per-face areas, all lights
  double unions = 0;    // ShadowOptions::union_shadows
  double total = 0;
};

// How a point light is solved: its one view where the scene lies on one side of a plane through
// it, else the cube (automatic); or the cube always (the same lit and shadow areas: tests and
// benchmarks compare them).
enum class PointLightViews { automatic, cube };

struct ShadowOptions {
  AreaSortOptions sort;
  PointLightViews point_light_views = PointLightViews::automatic;
  bool light_views = true;     // fill ShadowResult::views
  // Also the union of every face's shadows over all lights (a sun study's "shadow over the day"):
  // ShadowResult::face_union_shadow_area.
  bool union_shadows = false;
  // A stage line per light ("light 2 of 7: sorting 1200 polygons"); cancellation is checked
  // between the stages of every light (throws hlr::Cancelled).
  Progress progress;
  // Sun studies (after Lim): consecutive directional lights whose unit directions fit in a box no
  // longer than `cull_extent` along any axis form a group (group_views); with `cull`, the faces
  // that no direction of a group's box can light (fuzzy_cull of its orthographic light views,
  // split once by cull_parts where it culls nothing) are left out of the sources of its light
  // views. A culled face is hidden strictly behind faces the views keep, so every face's lit area
  // (face_lit_area, face_lit_area2, the union) is the same, exactly; the polygons are not: the
  // area sort's fragments (ShadowSource::lights, LightView) depend on every polygon it sorts
  // (strip borders, the order of its fronts), and a culled face has none (docs/FORMATS.md).
  bool cull = false;
  FuzzyOptions fuzzy;
  double cull_extent = 0.25;  // about 14 degrees between the group's directions
};

// A group of consecutive directional lights (ShadowOptions::cull).
struct ShadowCullGroup {
  std::size_t first = 0, count = 0;  // lights first .. first + count - 1
  std::size_t patches = 0;
  std::size_t culled = 0;            // the most faces culled for one of its parts
  std::size_t parts = 1, fuzzy_passes = 0;
  double fuzzy_seconds = 0;          // all its fuzzy passes
  double solve_seconds = 0;          // its lights' views, sorts and map back
};

struct ShadowResult {
  std::vector<ShadowSource> sources;  // ordered by mesh, then first face
  // Per mesh, per face: the source it belongs to and its area (model units).
  std::vector<std::vector<std::uint32_t>> face_source;
  std::vector<std::vector<double>> face_area;
  std::vector<std::vector<ShadowFT>> face_area2;  // exact, along the source's axis, twice
  // Per light, per mesh, per face: the lit area (model units, the exact area rounded once) and
  // its exact projected double area.
  std::vector<std::vector<std::vector<double>>> face_lit_area;
  std::vector<std::vector<std::vector<ShadowFT>>> face_lit_area2;
  // With union_shadows: per mesh, per face, the area in shadow under at least one light.
  std::vector<std::vector<double>> face_union_shadow_area;
  std::vector<std::vector<ShadowFT>> face_union_shadow_area2;
  std::vector<LightView> views;  // per light, with ShadowOptions::light_views
  // The groups of the directional lights (every one is in one; with ShadowOptions::cull their
  // counts), and per light the faces culled from its light view (none: empty).
  std::vector<ShadowCullGroup> cull_groups;
  std::vector<std::size_t> culled_faces;
  ShadowTimes times;
};

// The library's entry point for shadows (as hidden_line/jobs.hpp's for a view): solves every
// light on its own. Throws std::invalid_argument for a light with a defect (light_defect,
// point_light_defect), and Cancelled.
ShadowResult cast_shadows(const Scene& scene, const std::vector<Light>& lights, const ShadowOptions& options = {});
ShadowResult cast_shadows(const std::vector<Mesh>& meshes, const std::vector<Light>& lights,
                          const ShadowOptions& options = {});

// Shadows as surface detail of a view (hlr draw --sun; after Weiler and Atherton, "a normal hidden
// surface removed view can be taken from any viewpoint to create a correctly shadowed scene"): the
// shadow polygons of `shadows` (solved for the scene `sources` was built from) projected exactly
// into the view and clipped exactly to the visible polygons of their sources there. Their support
// lines are appended to sources.lines (auxiliary lines, which no later stage reads).
std::vector<clip::Polygon<ExactKernel>> shadows_in_view(const ShadowResult& shadows, const ViewFrame<ExactKernel>& frame,
                                                        Sources<ExactKernel>& sources,
                                                        const VisibilityMap<ExactKernel>& map);

}  // namespace hlr::hidden_line
