// Exact validity checks and helpers on Epeck. Only predicates here, plus midpoints for the
// side-of-contour tests; the Boolean operations live in oracle.cpp.
#include "exact_polygon.hpp"

#include <CGAL/Polygon_2_algorithms.h>

#include <algorithm>

namespace hlr::testing {

namespace {

using ET = EFT::Exact_type;

std::size_t next(std::size_t i, std::size_t n) { return i + 1 == n ? 0 : i + 1; }

CGAL::Bbox_2 box_of(const EContour& c) {
  CGAL::Bbox_2 b;
  for (const auto& p : c) b += p.bbox();
  return b;
}

bool boxes_overlap(const CGAL::Bbox_2& a, const CGAL::Bbox_2& b) {
  return a.xmin() <= b.xmax() && b.xmin() <= a.xmax() && a.ymin() <= b.ymax() && b.ymin() <= a.ymax();
}

// Collinear segments ab and cd: do they share a piece of positive length?
bool collinear_overlap(const EPoint& a, const EPoint& b, const EPoint& c, const EPoint& d) {
  const EPoint& lo1 = CGAL::compare_xy(a, b) < 0 ? a : b;
  const EPoint& hi1 = CGAL::compare_xy(a, b) < 0 ? b : a;
  const EPoint& lo2 = CGAL::compare_xy(c, d) < 0 ? c : d;
  const EPoint& hi2 = CGAL::compare_xy(c, d) < 0 ? d : c;
  const EPoint& lo = CGAL::compare_xy(lo1, lo2) < 0 ? lo2 : lo1;
  const EPoint& hi = CGAL::compare_xy(hi1, hi2) < 0 ? hi1 : hi2;
  return CGAL::compare_xy(lo, hi) < 0;
}

bool strictly_inside_segment(const EPoint& a, const EPoint& b, const EPoint& q) {
  return CGAL::collinear(a, b, q) && CGAL::collinear_are_strictly_ordered_along_line(a, q, b);
}

// Checks that the boundary of contour `a` lies strictly inside (want_inside) or strictly outside
// the region bounded by contour `b`, except at isolated touching points.
//
// Each edge of `a` is cut at the vertices of `b` on it; a proper crossing or a shared piece of
// edge is a defect at once. Between the points where `a` meets b's boundary, `a` stays on one
// side, so the side is tested (at a piece's midpoint) only after such a point.
std::optional<std::string> boundary_side(const EContour& a, const EContour& b, bool want_inside, const std::string& an,
                                         const std::string& bn) {
  const std::size_t n = a.size(), m = b.size();
  std::vector<CGAL::Bbox_2> b_boxes(m);
  for (std::size_t j = 0; j < m; ++j) b_boxes[j] = b[j].bbox() + b[next(j, m)].bbox();
  std::vector<EPoint> cuts;
  bool side_known = false;
  for (std::size_t i = 0; i < n; ++i) {
    const EPoint& a0 = a[i];
    const EPoint& a1 = a[next(i, n)];
    const CGAL::Bbox_2 a_box = a0.bbox() + a1.bbox();
    cuts.clear();
    bool a0_on_b = false;
    for (std::size_t j = 0; j < m; ++j) {
      if (!boxes_overlap(a_box, b_boxes[j])) continue;
      const EPoint& b0 = b[j];
      const EPoint& b1 = b[next(j, m)];
      const int o1 = CGAL::orientation(a0, a1, b0), o2 = CGAL::orientation(a0, a1, b1);
      if (o1 == 0 && o2 == 0) {
        if (collinear_overlap(a0, a1, b0, b1))
          return an + " edge " + std::to_string(i) + " overlaps " + bn + " edge " + std::to_string(j);
      } else if (o1 * o2 < 0) {
        const int o3 = CGAL::orientation(b0, b1, a0), o4 = CGAL::orientation(b0, b1, a1);
        if (o3 * o4 < 0)
          return an + " edge " + std::to_string(i) + " crosses " + bn + " edge " + std::to_string(j);
      }
      if (o1 == 0 && CGAL::collinear_are_strictly_ordered_along_line(a0, b0, a1)) cuts.push_back(b0);
      if (a0 == b0 || (CGAL::collinear(b0, b1, a0) && CGAL::collinear_are_ordered_along_line(b0, a0, b1))) a0_on_b = true;
    }
    if (a0_on_b) side_known = false;
    std::sort(cuts.begin(), cuts.end(), [&](const EPoint& p, const EPoint& q) {
      return CGAL::collinear_are_strictly_ordered_along_line(a0, p, q);
    });
    cuts.insert(cuts.begin(), a0);
    cuts.push_back(a1);
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
      if (k > 0) side_known = false;  // the piece starts on b's boundary
      if (side_known || cuts[k] == cuts[k + 1]) continue;
      const auto side = CGAL::bounded_side_2(b.begin(), b.end(), CGAL::midpoint(cuts[k], cuts[k + 1]), EK());
      if (side == CGAL::ON_BOUNDARY) return an + " edge " + std::to_string(i) + " runs along " + bn;
      if ((side == CGAL::ON_BOUNDED_SIDE) != want_inside)
        return an + " edge " + std::to_string(i) + (want_inside ? " leaves " : " enters ") + bn;
      side_known = true;
    }
  }
  return std::nullopt;
}

}  // namespace

EContour to_exact(const RawContour& c) {
  EContour e;
  e.reserve(c.size());
  for (const auto& p : c) e.emplace_back(p[0], p[1]);
  return e;
}

EPolygon to_exact(const RawPolygon& p) {
  EPolygon e;
  e.outer = to_exact(p.outer);
  for (const auto& h : p.holes) e.holes.push_back(to_exact(h));
  return e;
}

EFT twice_signed_area(const EContour& c) {
  ET sum = 0;
  for (std::size_t i = 0, n = c.size(); i < n; ++i) {
    const EPoint& p = c[i];
    const EPoint& q = c[next(i, n)];
    sum += CGAL::exact(p.x()) * CGAL::exact(q.y()) - CGAL::exact(q.x()) * CGAL::exact(p.y());
  }
  return EFT(sum);
}

EFT twice_area(const EPolygon& p) {
  ET sum = CGAL::abs(CGAL::exact(twice_signed_area(p.outer)));
  for (const auto& h : p.holes) sum -= CGAL::abs(CGAL::exact(twice_signed_area(h)));
  return EFT(sum);
}

EFT twice_area(const std::vector<EPolygon>& ps) {
  ET sum = 0;
  for (const auto& p : ps) sum += CGAL::exact(twice_area(p));
  return EFT(sum);
}

std::optional<std::string> contour_defect(const EContour& c) {
  const std::size_t n = c.size();
  if (n < 3) return "has " + std::to_string(n) + " vertices";
  for (std::size_t i = 0; i < n; ++i)
    if (c[i] == c[next(i, n)]) return "has a zero-length edge at vertex " + std::to_string(i);
  {
    std::vector<std::size_t> order(n);
    for (std::size_t i = 0; i < n; ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return CGAL::compare_xy(c[i], c[j]) < 0; });
    for (std::size_t k = 0; k + 1 < n; ++k)
      if (c[order[k]] == c[order[k + 1]])
        return "repeats a vertex (indices " + std::to_string(order[k]) + " and " + std::to_string(order[k + 1]) + ")";
  }
  for (std::size_t i = 0; i < n; ++i) {
    const EPoint& p = c[i];
    const EPoint& s = c[next(i, n)];
    const EPoint& q = c[next(next(i, n), n)];
    if (CGAL::collinear(p, s, q) && !CGAL::collinear_are_strictly_ordered_along_line(p, s, q))
      return "folds back at vertex " + std::to_string(next(i, n));
  }
  if (!CGAL::is_simple_2(c.begin(), c.end(), EK())) return "is not simple";
  if (CGAL::is_zero(twice_signed_area(c))) return "has zero area";
  return std::nullopt;
}

std::optional<std::string> polygon_defect(const EPolygon& p, bool oriented) {
  if (auto d = contour_defect(p.outer)) return "outer contour " + *d;
  for (std::size_t h = 0; h < p.holes.size(); ++h)
    if (auto d = contour_defect(p.holes[h])) return "hole " + std::to_string(h) + " " + *d;
  if (oriented) {
    if (CGAL::orientation_2(p.outer.begin(), p.outer.end(), EK()) != CGAL::COUNTERCLOCKWISE)
      return std::string("outer contour is not counter-clockwise");
    for (std::size_t h = 0; h < p.holes.size(); ++h)
      if (CGAL::orientation_2(p.holes[h].begin(), p.holes[h].end(), EK()) != CGAL::CLOCKWISE)
        return "hole " + std::to_string(h) + " is not clockwise";
  }
  // bounded_side_2 and the midpoint logic need a consistent orientation only implicitly: they do
  // not depend on it.
  const CGAL::Bbox_2 ob = box_of(p.outer);
  std::vector<CGAL::Bbox_2> hb;
  for (const auto& h : p.holes) hb.push_back(box_of(h));
  for (std::size_t h = 0; h < p.holes.size(); ++h) {
    const std::string name = "hole " + std::to_string(h);
    if (!boxes_overlap(hb[h], ob)) return name + " lies outside the outer contour";
    if (auto d = boundary_side(p.holes[h], p.outer, true, name, "the outer contour")) return d;
  }
  for (std::size_t h = 0; h < p.holes.size(); ++h)
    for (std::size_t g = h + 1; g < p.holes.size(); ++g) {
      if (!boxes_overlap(hb[h], hb[g])) continue;
      const std::string hn = "hole " + std::to_string(h), gn = "hole " + std::to_string(g);
      if (auto d = boundary_side(p.holes[h], p.holes[g], false, hn, gn)) return d;
      if (auto d = boundary_side(p.holes[g], p.holes[h], false, gn, hn)) return d;
    }
  if (!CGAL::is_positive(twice_area(p))) return std::string("has no positive area");
  return std::nullopt;
}

std::optional<std::string> last_hole_defect(const EPolygon& p) {
  if (p.holes.empty()) return std::nullopt;
  const std::size_t h = p.holes.size() - 1;
  const std::string name = "hole " + std::to_string(h);
  if (auto d = contour_defect(p.holes[h])) return name + " " + *d;
  const CGAL::Bbox_2 hb = box_of(p.holes[h]);
  if (!boxes_overlap(hb, box_of(p.outer))) return name + " lies outside the outer contour";
  if (auto d = boundary_side(p.holes[h], p.outer, true, name, "the outer contour")) return d;
  for (std::size_t g = 0; g < h; ++g) {
    if (!boxes_overlap(hb, box_of(p.holes[g]))) continue;
    const std::string gn = "hole " + std::to_string(g);
    if (auto d = boundary_side(p.holes[h], p.holes[g], false, name, gn)) return d;
    if (auto d = boundary_side(p.holes[g], p.holes[h], false, gn, name)) return d;
  }
  return std::nullopt;
}

bool segment_within(const EPoint& a, const EPoint& b, const EPoint& p, const EPoint& q) {
  if (!CGAL::collinear(a, b, p) || !CGAL::collinear(a, b, q)) return false;
  return CGAL::collinear_are_ordered_along_line(a, p, b) && CGAL::collinear_are_ordered_along_line(a, q, b);
}

Degeneracies find_degeneracies(const RawPolygon& ra, const RawPolygon& rb) {
  Degeneracies d;
  const EPolygon a = to_exact(ra), b = to_exact(rb);
  std::vector<const EContour*> ca{&a.outer}, cb{&b.outer};
  for (const auto& h : a.holes) ca.push_back(&h);
  for (const auto& h : b.holes) cb.push_back(&h);
  for (const EContour* x : ca)
    for (const EContour* y : cb) {
      const std::size_t n = x->size(), m = y->size();
      for (std::size_t i = 0; i < n; ++i) {
        const EPoint& a0 = (*x)[i];
        const EPoint& a1 = (*x)[next(i, n)];
        for (std::size_t j = 0; j < m; ++j) {
          const EPoint& b0 = (*y)[j];
          const EPoint& b1 = (*y)[next(j, m)];
          if (a0 == b0) d.shared_vertex = true;
          if (strictly_inside_segment(a0, a1, b0) || strictly_inside_segment(b0, b1, a0)) d.vertex_on_edge = true;
          if (CGAL::collinear(a0, a1, b0) && CGAL::collinear(a0, a1, b1) && collinear_overlap(a0, a1, b0, b1))
            d.collinear_overlap = true;
        }
      }
    }
  return d;
}

std::string exact_string(const EFT& v) { return Geometry<EK>::exact_string(v); }

namespace {
std::string contour_json(const EContour& c) {
  std::string s = "[";
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (i) s += ", ";
    s += "[\"" + exact_string(c[i].x()) + "\", \"" + exact_string(c[i].y()) + "\"]";
  }
  return s + "]";
}
}  // namespace

std::string to_exact_json(const EPolygon& p) {
  std::string s = "{\"outer\": " + contour_json(p.outer) + ", \"holes\": [";
  for (std::size_t h = 0; h < p.holes.size(); ++h) {
    if (h) s += ", ";
    s += contour_json(p.holes[h]);
  }
  return s + "]}";
}

std::string to_exact_json(const std::vector<EPolygon>& ps) {
  std::string s = "[";
  for (std::size_t k = 0; k < ps.size(); ++k) {
    if (k) s += ", ";
    s += to_exact_json(ps[k]);
  }
  return s + "]";
}

}  // namespace hlr::testing

namespace hlr::testing {
std::string last_hole_defect(const RawPolygon& polygon) {
  auto d = last_hole_defect(to_exact(polygon));
  return d ? *d : std::string();
}

std::string validity_defect(const RawPolygon& polygon) {
  auto d = polygon_defect(to_exact(polygon), false);
  return d ? *d : std::string();
}
}  // namespace hlr::testing
