// A second exact oracle, independent of CGAL's Boolean_set_operations_2: the plane is cut into
// cells (the triangles of a constrained triangulation of every edge of the subject, the clip and
// the output pieces, with exact intersections), membership is constant inside each cell, and is
// compared on every cell at its centroid: inside pieces must cover exactly S ∩ C, outside pieces
// exactly S − C, each point at most once.
//
// Why a second oracle: CGAL 5.5.1's Boolean operations return wrong sets (silently, also with
// assertions on) when a polygon's hole touches its outer contour at a vertex that the other
// operand shares; see docs/STABILITY.md. This check has no such state: it is predicates on points.
#pragma once

#include "exact_polygon.hpp"

#include <optional>
#include <string>
#include <vector>

namespace hlr::testing {

struct CellCheck {
  bool ok = true;
  std::string message;                // the first wrong cell, when not ok
  bool overlap = false;               // some point covered by two pieces of one list
  EFT wrong_inside_twice_area = 0;    // twice the area where the inside list is wrong
  EFT wrong_outside_twice_area = 0;   // twice the area where the outside list is wrong
  std::size_t cells = 0;
};

CellCheck check_cells(const EPolygon& subject, const EPolygon& clip, const std::vector<EPolygon>& inside,
                      const std::vector<EPolygon>& outside);

// Do the two lists of pieces cover the same points, each point as often? Empty when they do,
// else where they differ.
std::optional<std::string> coverage_difference(const std::vector<EPolygon>& a, const std::vector<EPolygon>& b);

// Is the point strictly inside the polygon with holes (inside the outer contour, outside every
// hole)? Points on a boundary count as outside.
bool strictly_inside(const EPolygon& p, const EPoint& q);

}  // namespace hlr::testing
