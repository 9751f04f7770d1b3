// The input families of the clipper property tests: a case is a subject and a clip polygon built
// deterministically from a small spec (shapes, relation, seed, sizes), so that RapidCheck can
// generate and shrink specs while the polygons come from the shared generators.
#pragma once

#include <polygon_generators.hpp>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace hlr::testing {

enum class Shape { star, comb, spiral, holes, grid, grid_holes };
inline constexpr Shape kAllShapes[] = {Shape::star, Shape::comb, Shape::spiral, Shape::holes, Shape::grid, Shape::grid_holes};

enum class Relation {
  independent,      // clip drawn on its own, in the same frame
  identity,         // clip == subject (possibly renumbered or reversed)
  shifted,          // clip is the subject shifted (by grid steps on grids)
  in_clip_hole,     // the subject lies in a hole of the clip (hole = subject, its box, or a larger box)
  subject_contour,  // the clip is one contour of the subject: its outer contour or one of its holes
  box_cut,          // the clip is the subject's bounding box, or a box cutting through it
};
inline constexpr Relation kAllRelations[] = {Relation::independent, Relation::identity, Relation::shifted,
                                             Relation::in_clip_hole, Relation::subject_contour, Relation::box_cut};

const char* shape_name(Shape s);
const char* relation_name(Relation r);
bool is_grid(Shape s);

struct CaseSpec {
  Shape subject = Shape::star;
  Shape clip = Shape::star;
  Relation relation = Relation::independent;
  std::uint64_t seed = 0;
  int subject_vertices = 8;
  int clip_vertices = 8;
  int holes = 1;  // for the shapes with holes
  int grid = 8;   // for the grid shapes: coordinates are integers in [0, grid]
};

struct ClipCase {
  RawPolygon subject, clip;
};

// Deterministic in the spec.
ClipCase make_case(const CaseSpec& spec);
// One polygon of a shape, in the common frame (roughly the box [0, 8]^2).
RawPolygon make_shape(Shape shape, Rng& rng, int vertices, int holes, int grid);
std::string describe(const CaseSpec& spec);

// The families of the stability run (stability_run.cpp), near-degenerate on purpose: random
// floats, grids, decimal grids, tiny rotations and shifts, nearly collinear edges, coordinates far
// from the origin, identity. The exact kernel must pass all of them; the property tests run them
// too.
struct Family {
  const char* name;
  const char* what;
  std::function<ClipCase(Rng&)> make;
};
std::vector<Family> stability_families();

}  // namespace hlr::testing
