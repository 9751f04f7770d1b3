// Conversions between the generators' raw polygons, the clipper's polygons and exact polygons.
// Header-only templates over the kernel; the clipper library holds the algorithm's instantiations.
#pragma once

#include "exact_polygon.hpp"

#include <hlr/clipper/clipper.hpp>

#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace hlr::testing {

// A raw polygon as the clipper's polygon: each contour through make_contour (every edge a new line
// of `lines`, so line k of the table is exactly one input edge), then normalize_polygon. Returns
// normalize_polygon's defect message, if any.
template <class K>
std::optional<std::string> to_clip_polygon(const RawPolygon& raw, clip::LineTable<K>& lines, clip::Polygon<K>& out) {
  using G = Geometry<K>;
  auto points = [](const RawContour& c) {
    std::vector<typename G::Point> v;
    v.reserve(c.size());
    for (const auto& p : c) v.push_back(G::point(p[0], p[1]));
    return v;
  };
  out = clip::Polygon<K>{};
  out.outer = clip::make_contour<K>(points(raw.outer), lines);
  for (const auto& h : raw.holes) out.holes.push_back(clip::make_contour<K>(points(h), lines));
  return clip::normalize_polygon<K>(out);
}

// A point of kernel K as an exact point: exact points as they are, others through to_double
// (exactly the double the inexact kernel computed).
template <class K>
EPoint to_exact_point(const typename Geometry<K>::Point& p) {
  if constexpr (std::is_same_v<K, ExactKernel>) {
    return p;
  } else {
    using G = Geometry<K>;
    return EPoint(G::to_double(G::x(p)), G::to_double(G::y(p)));
  }
}

template <class K>
EContour to_exact(const clip::Contour<K>& c) {
  EContour e;
  e.reserve(c.points.size());
  for (const auto& p : c.points) e.push_back(to_exact_point<K>(p));
  return e;
}

template <class K>
EPolygon to_exact(const clip::Polygon<K>& p) {
  EPolygon e;
  e.outer = to_exact<K>(p.outer);
  for (const auto& h : p.holes) e.holes.push_back(to_exact<K>(h));
  return e;
}

template <class K>
std::vector<EPolygon> to_exact(const std::vector<clip::Polygon<K>>& ps) {
  std::vector<EPolygon> e;
  e.reserve(ps.size());
  for (const auto& p : ps) e.push_back(to_exact<K>(p));
  return e;
}

}  // namespace hlr::testing
