// The independent oracle of the clipper tests: CGAL's Boolean_set_operations_2 on Epeck, behind a
// small value type so that only oracle.cpp pays for the CGAL headers.
#pragma once

#include "exact_polygon.hpp"

#include <memory>
#include <vector>

namespace hlr::testing {

// A regularized point set: a CGAL::Polygon_set_2<Epeck>. Copies share the (immutable) set.
class ExactRegion {
 public:
  ExactRegion();  // the empty set

  // The region of an input polygon (any orientation): outer contour minus its holes.
  static ExactRegion from(const RawPolygon& polygon);
  // The region of one polygon with holes: outer contour minus its holes (each contour must be
  // simple; holes may touch the outer contour and each other anywhere).
  static ExactRegion from(const EPolygon& polygon);
  // The union of several such polygons.
  static ExactRegion from(const std::vector<EPolygon>& polygons);

  ExactRegion intersection(const ExactRegion& other) const;
  ExactRegion difference(const ExactRegion& other) const;
  ExactRegion join(const ExactRegion& other) const;
  ExactRegion symmetric_difference(const ExactRegion& other) const;

  bool empty() const;
  EFT twice_area() const;
  std::size_t polygon_count() const;
  std::vector<EPolygon> polygons() const;  // outer counter-clockwise, holes clockwise

  struct Impl;
  const Impl& impl() const { return *impl_; }
  explicit ExactRegion(std::shared_ptr<const Impl> impl);

 private:
  std::shared_ptr<const Impl> impl_;
};

// Same point set (symmetric difference empty)?
bool same_region(const ExactRegion& a, const ExactRegion& b);

}  // namespace hlr::testing
