// Exact polygons (CGAL Epeck) for test oracles: validity, areas, degeneracy classification.
// Light header: the heavy CGAL code (Boolean operations) is behind oracle.hpp.
#pragma once

#include "polygon_generators.hpp"

#include <hlr/kernel/kernel.hpp>

#include <optional>
#include <string>
#include <vector>

namespace hlr::testing {

using EK = hlr::ExactKernel;
using EPoint = EK::Point_2;
using EFT = EK::FT;
using EContour = std::vector<EPoint>;

struct EPolygon {
  EContour outer;
  std::vector<EContour> holes;
};

EContour to_exact(const RawContour& c);
EPolygon to_exact(const RawPolygon& p);

// Twice the signed area, summed in the exact number type (positive when counter-clockwise).
EFT twice_signed_area(const EContour& c);
// Twice the area of outer minus holes, whatever the orientations.
EFT twice_area(const EPolygon& p);
EFT twice_area(const std::vector<EPolygon>& ps);

// The first defect of a contour: fewer than 3 vertices, a zero-length edge, a repeated vertex,
// adjacent edges folding back, not simple (CGAL::is_simple_2), zero area.
std::optional<std::string> contour_defect(const EContour& c);

// The first defect of a polygon with holes, exactly: every contour as above; holes strictly
// inside the outer contour and pairwise apart, except at touching points (a vertex on a vertex or
// on an edge); no two contours share a piece of an edge. With `oriented`, the outer contour must
// also be counter-clockwise and every hole clockwise.
std::optional<std::string> polygon_defect(const EPolygon& p, bool oriented);

// Like polygon_defect (unoriented), for a polygon known to be valid without its last hole: checks
// only the last hole against the outer contour and the other holes. For adding holes one by one.
std::optional<std::string> last_hole_defect(const EPolygon& p);

// Is the segment pq contained in the closed segment ab (collinear, both ends within)? Exact.
bool segment_within(const EPoint& a, const EPoint& b, const EPoint& p, const EPoint& q);

// Degeneracies between two polygons' boundaries, found exactly.
struct Degeneracies {
  bool shared_vertex = false;      // a vertex of one equals a vertex of the other
  bool vertex_on_edge = false;     // a vertex of one lies inside an edge of the other
  bool collinear_overlap = false;  // two edges share a piece of positive length
  bool any() const { return shared_vertex || vertex_on_edge || collinear_overlap; }
};
Degeneracies find_degeneracies(const RawPolygon& a, const RawPolygon& b);

// Exact rationals: "p/q" or "p".
std::string exact_string(const EFT& v);
// {"outer": [["p/q", "p/q"], ...], "holes": [...]}, coordinates as exact rationals.
std::string to_exact_json(const EPolygon& p);
std::string to_exact_json(const std::vector<EPolygon>& ps);

}  // namespace hlr::testing
