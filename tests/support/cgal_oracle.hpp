// Direct CGAL conversions for tests that want CGAL's own types. Heavy header (Polygon_set_2):
// include it only where needed; oracle.hpp is the light way to the same oracle.
#pragma once

#include "clip_conversions.hpp"
#include "oracle.hpp"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_set_2.h>
#include <CGAL/Polygon_with_holes_2.h>

namespace hlr::testing {

using CgalPolygon = CGAL::Polygon_2<EK>;
using CgalPolygonWithHoles = CGAL::Polygon_with_holes_2<EK>;
using CgalPolygonSet = CGAL::Polygon_set_2<EK>;

struct ExactRegion::Impl {
  CgalPolygonSet set;
};

// An input polygon as CGAL's polygon with holes: outer counter-clockwise, holes clockwise, and
// every edge split at the vertices of other contours that touch it, so that contours meet only at
// shared vertices (what CGAL's validity asks of a polygon with holes). Same point set.
CgalPolygonWithHoles to_cgal_polygon(const RawPolygon& polygon);
CgalPolygonWithHoles to_cgal_polygon(const EPolygon& polygon);

// Regions as CGAL polygon sets (outer minus holes for each polygon, then the union).
CgalPolygonSet to_cgal_set(const RawPolygon& polygon);
CgalPolygonSet to_cgal_set(const EPolygon& polygon);
CgalPolygonSet to_cgal_set(const std::vector<EPolygon>& polygons);

// Clipper results as a CGAL polygon set; inexact kernels' coordinates go through to_double.
template <class K>
CgalPolygonSet to_cgal_set(const std::vector<clip::Polygon<K>>& polygons) {
  return to_cgal_set(to_exact<K>(polygons));
}

}  // namespace hlr::testing
