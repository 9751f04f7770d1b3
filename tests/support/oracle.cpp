// CGAL Boolean_set_operations_2 on Epeck: the only translation unit of the support library that
// instantiates the Boolean operations.
#include "cgal_oracle.hpp"

#include <algorithm>

namespace hlr::testing {

namespace {

CgalPolygon counter_clockwise(const EContour& c) {
  CgalPolygon p(c.begin(), c.end());
  if (p.orientation() == CGAL::CLOCKWISE) p.reverse_orientation();
  return p;
}

EContour contour_of(const CgalPolygon& p) { return EContour(p.vertices_begin(), p.vertices_end()); }

// Every edge of `c` split at the points of `others` lying strictly inside it.
EContour split_at(const EContour& c, const std::vector<const EContour*>& others) {
  EContour out;
  std::vector<EPoint> cuts;
  for (std::size_t i = 0, n = c.size(); i < n; ++i) {
    const EPoint& a = c[i];
    const EPoint& b = c[i + 1 == n ? 0 : i + 1];
    cuts.clear();
    for (const EContour* o : others)
      for (const EPoint& q : *o)
        if (CGAL::collinear(a, b, q) && CGAL::collinear_are_strictly_ordered_along_line(a, q, b)) cuts.push_back(q);
    std::sort(cuts.begin(), cuts.end(),
              [&](const EPoint& p, const EPoint& q) { return CGAL::collinear_are_strictly_ordered_along_line(a, p, q); });
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
    out.push_back(a);
    out.insert(out.end(), cuts.begin(), cuts.end());
  }
  return out;
}

}  // namespace

CgalPolygonWithHoles to_cgal_polygon(const EPolygon& polygon) {
  std::vector<const EContour*> all{&polygon.outer};
  for (const auto& h : polygon.holes) all.push_back(&h);
  auto others = [&](std::size_t k) {
    std::vector<const EContour*> o;
    for (std::size_t j = 0; j < all.size(); ++j)
      if (j != k) o.push_back(all[j]);
    return o;
  };
  CgalPolygonWithHoles result(counter_clockwise(split_at(polygon.outer, others(0))));
  for (std::size_t h = 0; h < polygon.holes.size(); ++h) {
    CgalPolygon hole = counter_clockwise(split_at(polygon.holes[h], others(h + 1)));
    hole.reverse_orientation();
    result.add_hole(std::move(hole));
  }
  return result;
}

CgalPolygonWithHoles to_cgal_polygon(const RawPolygon& polygon) { return to_cgal_polygon(to_exact(polygon)); }

CgalPolygonSet to_cgal_set(const EPolygon& polygon) {
  CgalPolygonSet set(counter_clockwise(polygon.outer));
  if (!polygon.holes.empty()) {
    std::vector<CgalPolygon> holes;
    for (const auto& h : polygon.holes) holes.push_back(counter_clockwise(h));
    CgalPolygonSet hole_set;
    hole_set.join(holes.begin(), holes.end());
    set.difference(hole_set);
  }
  return set;
}

CgalPolygonSet to_cgal_set(const RawPolygon& polygon) { return to_cgal_set(to_exact(polygon)); }

CgalPolygonSet to_cgal_set(const std::vector<EPolygon>& polygons) {
  std::vector<CgalPolygon> plain;
  std::vector<CgalPolygonWithHoles> with_holes;
  for (const auto& p : polygons) {
    if (p.holes.empty()) {
      plain.push_back(counter_clockwise(p.outer));
    } else {
      to_cgal_set(p).polygons_with_holes(std::back_inserter(with_holes));
    }
  }
  CgalPolygonSet set;
  if (plain.empty() && with_holes.empty()) return set;
  if (with_holes.empty()) set.join(plain.begin(), plain.end());
  else if (plain.empty()) set.join(with_holes.begin(), with_holes.end());
  else set.join(plain.begin(), plain.end(), with_holes.begin(), with_holes.end());
  return set;
}

// ---- ExactRegion ----

ExactRegion::ExactRegion() : impl_(std::make_shared<const Impl>()) {}
ExactRegion::ExactRegion(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}

namespace {
ExactRegion wrap(CgalPolygonSet&& set) {
  return ExactRegion(std::make_shared<const ExactRegion::Impl>(ExactRegion::Impl{std::move(set)}));
}
}  // namespace

ExactRegion ExactRegion::from(const RawPolygon& polygon) { return wrap(to_cgal_set(polygon)); }
ExactRegion ExactRegion::from(const EPolygon& polygon) { return wrap(to_cgal_set(polygon)); }
ExactRegion ExactRegion::from(const std::vector<EPolygon>& polygons) { return wrap(to_cgal_set(polygons)); }

ExactRegion ExactRegion::intersection(const ExactRegion& other) const {
  CgalPolygonSet s = impl_->set;
  s.intersection(other.impl_->set);
  return wrap(std::move(s));
}
ExactRegion ExactRegion::difference(const ExactRegion& other) const {
  CgalPolygonSet s = impl_->set;
  s.difference(other.impl_->set);
  return wrap(std::move(s));
}
ExactRegion ExactRegion::join(const ExactRegion& other) const {
  CgalPolygonSet s = impl_->set;
  s.join(other.impl_->set);
  return wrap(std::move(s));
}
ExactRegion ExactRegion::symmetric_difference(const ExactRegion& other) const {
  CgalPolygonSet s = impl_->set;
  s.symmetric_difference(other.impl_->set);
  return wrap(std::move(s));
}

bool ExactRegion::empty() const { return impl_->set.is_empty(); }
std::size_t ExactRegion::polygon_count() const { return impl_->set.number_of_polygons_with_holes(); }

std::vector<EPolygon> ExactRegion::polygons() const {
  std::vector<CgalPolygonWithHoles> pwhs;
  impl_->set.polygons_with_holes(std::back_inserter(pwhs));
  std::vector<EPolygon> out;
  for (const auto& pwh : pwhs) {
    EPolygon p;
    p.outer = contour_of(pwh.outer_boundary());
    for (auto h = pwh.holes_begin(); h != pwh.holes_end(); ++h) p.holes.push_back(contour_of(*h));
    out.push_back(std::move(p));
  }
  return out;
}

EFT ExactRegion::twice_area() const { return hlr::testing::twice_area(polygons()); }

bool same_region(const ExactRegion& a, const ExactRegion& b) { return a.symmetric_difference(b).empty(); }

}  // namespace hlr::testing
