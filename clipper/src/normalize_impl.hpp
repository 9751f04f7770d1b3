// Validation and orientation of input polygons, as a template over the kernel. Included only by
// the instantiate_*.cpp files, after clip_impl.hpp.
#pragma once

#include "clip_impl.hpp"

#include <string>

namespace hlr::clip {
namespace detail {

inline std::string contour_name(std::size_t c) {
  return c == 0 ? std::string("outer contour") : "hole " + std::to_string(c - 1);
}

// Drops repeated consecutive points; original[k] is the input index of the edge that starts at the
// k-th kept point, so that messages name edges as the user numbered them.
template <class K>
void drop_repeated_points(Contour<K>& c, std::vector<std::size_t>& original) {
  using G = Geometry<K>;
  Contour<K> kept;
  original.clear();
  for (std::size_t i = 0; i < c.points.size(); ++i) {
    if (!kept.points.empty() && G::equal(c.points[i], kept.points.back())) {
      kept.lines.back() = c.lines[i];  // the zero-length edge gives way to the next one
      original.back() = i;
      continue;
    }
    kept.points.push_back(c.points[i]);
    kept.lines.push_back(c.lines[i]);
    original.push_back(i);
  }
  while (kept.points.size() > 1 && G::equal(kept.points.back(), kept.points.front())) {
    kept.points.pop_back();
    kept.lines.pop_back();
    original.pop_back();
  }
  c = std::move(kept);
}

// Do the closed segments ab and cd share a point?
template <class K>
bool segments_meet(const Point<K>& a, const Point<K>& b, const Point<K>& c, const Point<K>& d) {
  using G = Geometry<K>;
  const int o1 = G::orientation(a, b, c), o2 = G::orientation(a, b, d);
  if (o1 * o2 > 0) return false;
  const int o3 = G::orientation(c, d, a), o4 = G::orientation(c, d, b);
  if (o3 * o4 > 0) return false;
  if (o1 != 0 || o2 != 0) return true;
  // Collinear: do their extents along the line overlap?
  auto lo = [](const Point<K>& p, const Point<K>& q) { return G::compare_xy(p, q) < 0 ? p : q; };
  auto hi = [](const Point<K>& p, const Point<K>& q) { return G::compare_xy(p, q) < 0 ? q : p; };
  return G::compare_xy(lo(a, b), hi(c, d)) <= 0 && G::compare_xy(lo(c, d), hi(a, b)) <= 0;
}

// Do the collinear-or-not segments ab and cd overlap along a piece of positive length?
template <class K>
bool segments_overlap(const Point<K>& a, const Point<K>& b, const Point<K>& c, const Point<K>& d) {
  using G = Geometry<K>;
  if (G::orientation(a, b, c) != 0 || G::orientation(a, b, d) != 0) return false;
  auto lo = [](const Point<K>& p, const Point<K>& q) { return G::compare_xy(p, q) < 0 ? p : q; };
  auto hi = [](const Point<K>& p, const Point<K>& q) { return G::compare_xy(p, q) < 0 ? q : p; };
  return G::compare_xy(lo(a, b), hi(c, d)) < 0 && G::compare_xy(lo(c, d), hi(a, b)) < 0;
}

// Do ab and cd cross at one point interior to both?
template <class K>
bool segments_cross(const Point<K>& a, const Point<K>& b, const Point<K>& c, const Point<K>& d) {
  using G = Geometry<K>;
  return G::orientation(a, b, c) * G::orientation(a, b, d) < 0 && G::orientation(c, d, a) * G::orientation(c, d, b) < 0;
}

// Where the contour `inner` lies relative to `outer`: +1 inside, -1 outside, judged on its vertices
// and, for edges whose ends both lie on `outer`, their midpoints. Returns 0 when it is on both sides.
template <class K>
int place_contour(const Contour<K>& inner, const Contour<K>& outer) {
  using G = Geometry<K>;
  bool in = false, out = false;
  const std::size_t n = inner.points.size();
  std::vector<int> sides(n);
  for (std::size_t i = 0; i < n; ++i) {
    sides[i] = side_of_contour(outer, inner.points[i]);
    in |= sides[i] > 0;
    out |= sides[i] < 0;
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (sides[i] != 0 || sides[(i + 1) % n] != 0) continue;
    const int s = side_of_contour(outer, G::midpoint(inner.points[i], inner.points[(i + 1) % n]));
    in |= s > 0;
    out |= s < 0;
  }
  if (in && out) return 0;
  return out ? -1 : 1;  // all on the boundary counts as inside; the overlap check catches that
}

}  // namespace detail

template <class K>
std::optional<std::string> normalize_polygon(Polygon<K>& polygon) {
  using G = Geometry<K>;
  using P = detail::Point<K>;
  using detail::contour_name;
  std::vector<Contour<K>*> contours{&polygon.outer};
  for (auto& h : polygon.holes) contours.push_back(&h);

  std::vector<std::vector<std::size_t>> original(contours.size());
  for (std::size_t c = 0; c < contours.size(); ++c) {
    detail::drop_repeated_points(*contours[c], original[c]);
    if (contours[c]->size() < 3)
      return contour_name(c) + " has " + std::to_string(contours[c]->size()) +
             " distinct vertices, at least 3 are needed";
  }

  // One sweep over all edges finds self-intersections and contours that cross or overlap.
  std::vector<detail::InputEdge> edges;
  std::vector<P> pts;
  for (std::size_t c = 0; c < contours.size(); ++c) {
    const auto& cp = contours[c]->points;
    const std::uint32_t base = static_cast<std::uint32_t>(pts.size()), n = static_cast<std::uint32_t>(cp.size());
    pts.insert(pts.end(), cp.begin(), cp.end());
    for (std::uint32_t i = 0; i < n; ++i) {
      const std::uint32_t j = i + 1 == n ? 0 : i + 1;
      // Here `line` holds the edge index within its contour.
      edges.push_back({base + i, base + j, i, 0, static_cast<std::uint32_t>(c), G::bbox(cp[i]) + G::bbox(cp[j])});
    }
  }
  std::optional<std::string> defect;
  auto edge_name = [&](const detail::InputEdge& e) { return std::to_string(original[e.contour][e.line]); };
  detail::SweepBuffers sweep;
  detail::for_each_overlapping_pair<false>(edges, sweep, [&](std::uint32_t i, std::uint32_t j) {
    if (defect) return;
    const detail::InputEdge& e = edges[i];
    const detail::InputEdge& f = edges[j];
    const P&a = pts[e.a], &b = pts[e.b], &c = pts[f.a], &d = pts[f.b];
    if (e.contour == f.contour) {
      const std::string name = contour_name(e.contour) + " edges " + edge_name(e) + " and " + edge_name(f);
      if (e.b == f.a || f.b == e.a) {
        // Adjacent edges share one vertex; they must not fold back over each other.
        const P& s = e.b == f.a ? b : a;
        const P& p = e.b == f.a ? a : b;
        const P& q = e.b == f.a ? d : c;
        if (G::orientation(p, s, q) == 0 && G::compare_xy(p, s) == G::compare_xy(q, s))
          defect = name + " fold back over each other";
      } else if (detail::segments_meet<K>(a, b, c, d)) {
        defect = name + " intersect (the contour is not simple)";
      }
    } else if (detail::segments_cross<K>(a, b, c, d)) {
      defect = contour_name(e.contour) + " edge " + edge_name(e) + " crosses " + contour_name(f.contour) + " edge " +
               edge_name(f);
    } else if (detail::segments_overlap<K>(a, b, c, d)) {
      defect = contour_name(e.contour) + " edge " + edge_name(e) + " overlaps " + contour_name(f.contour) +
               " edge " + edge_name(f);
    }
  });
  if (defect) return defect;

  // Contours are simple now, so orientation is well defined.
  for (std::size_t c = 0; c < contours.size(); ++c) {
    const int o = detail::contour_orientation<K>(contours[c]->points);
    if ((c == 0) != (o > 0)) detail::reverse_contour(*contours[c]);
  }
  for (std::size_t h = 0; h < polygon.holes.size(); ++h) {
    const int place = detail::place_contour(polygon.holes[h], polygon.outer);
    if (place < 0) return contour_name(h + 1) + " lies outside the outer contour";
    if (place == 0) return contour_name(h + 1) + " crosses the outer contour at a vertex";
    const CGAL::Bbox_2 hb = detail::contour_box(polygon.holes[h]);
    for (std::size_t g = 0; g < polygon.holes.size(); ++g) {
      if (g == h || !detail::boxes_overlap(hb, detail::contour_box(polygon.holes[g]))) continue;
      const int inner = detail::place_contour(polygon.holes[h], polygon.holes[g]);
      if (inner > 0) return contour_name(h + 1) + " lies inside " + contour_name(g + 1);
      if (inner == 0) return contour_name(h + 1) + " crosses " + contour_name(g + 1) + " at a vertex";
    }
  }
  return std::nullopt;
}

}  // namespace hlr::clip
