// The cell oracle: a constrained Delaunay triangulation (exact intersections) of all edges, and
// point-in-polygon tests at the centroid of every triangle.
#include "cell_oracle.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Polygon_2_algorithms.h>

#include <sstream>

namespace hlr::testing {

namespace {

using Vb = CGAL::Triangulation_vertex_base_2<EK>;
using Fb = CGAL::Constrained_triangulation_face_base_2<EK>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<EK, Tds, CGAL::Exact_intersections_tag>;
using ET = EFT::Exact_type;

CGAL::Bbox_2 box_of(const EContour& c) {
  CGAL::Bbox_2 b;
  for (const auto& p : c) b += p.bbox();
  return b;
}

struct Located {
  const EPolygon* polygon;
  CGAL::Bbox_2 box;
};

std::vector<Located> locate(const std::vector<EPolygon>& ps) {
  std::vector<Located> v;
  for (const auto& p : ps) v.push_back({&p, box_of(p.outer)});
  return v;
}

bool in_box(const CGAL::Bbox_2& b, const CGAL::Bbox_2& q) {
  return b.xmin() <= q.xmax() && q.xmin() <= b.xmax() && b.ymin() <= q.ymax() && q.ymin() <= b.ymax();
}

int coverage(const std::vector<Located>& ps, const EPoint& q) {
  const CGAL::Bbox_2 qb = q.bbox();
  int n = 0;
  for (const auto& l : ps)
    if (in_box(l.box, qb) && strictly_inside(*l.polygon, q)) ++n;
  return n;
}

void insert_contour(Cdt& cdt, const EContour& c) {
  for (std::size_t i = 0, n = c.size(); i < n; ++i) {
    const EPoint& a = c[i];
    const EPoint& b = c[i + 1 == n ? 0 : i + 1];
    if (a != b) cdt.insert_constraint(a, b);
  }
}

void insert_polygon(Cdt& cdt, const EPolygon& p) {
  insert_contour(cdt, p.outer);
  for (const auto& h : p.holes) insert_contour(cdt, h);
}

}  // namespace

bool strictly_inside(const EPolygon& p, const EPoint& q) {
  if (CGAL::bounded_side_2(p.outer.begin(), p.outer.end(), q, EK()) != CGAL::ON_BOUNDED_SIDE) return false;
  for (const auto& h : p.holes)
    if (CGAL::bounded_side_2(h.begin(), h.end(), q, EK()) != CGAL::ON_UNBOUNDED_SIDE) return false;
  return true;
}

CellCheck check_cells(const EPolygon& subject, const EPolygon& clip, const std::vector<EPolygon>& inside,
                      const std::vector<EPolygon>& outside) {
  CellCheck r;
  Cdt cdt;
  insert_polygon(cdt, subject);
  insert_polygon(cdt, clip);
  for (const auto& p : inside) insert_polygon(cdt, p);
  for (const auto& p : outside) insert_polygon(cdt, p);
  const std::vector<Located> in = locate(inside), out = locate(outside);
  ET wrong_in = 0, wrong_out = 0;
  for (auto f : cdt.finite_face_handles()) {
    ++r.cells;
    const EPoint& a = f->vertex(0)->point();
    const EPoint& b = f->vertex(1)->point();
    const EPoint& c = f->vertex(2)->point();
    const EPoint m = CGAL::centroid(a, b, c);
    const bool s = strictly_inside(subject, m), k = strictly_inside(clip, m);
    const int ni = coverage(in, m), no = coverage(out, m);
    const bool want_in = s && k, want_out = s && !k;
    if (ni == int(want_in) && no == int(want_out)) continue;
    const ET area = CGAL::abs(CGAL::exact(CGAL::area(a, b, c))) * 2;
    if (ni != int(want_in)) wrong_in += area;
    if (no != int(want_out)) wrong_out += area;
    if (ni > 1 || no > 1) r.overlap = true;
    if (r.ok) {
      r.ok = false;
      std::ostringstream m_;
      m_ << "at (" << CGAL::to_double(m.x()) << ", " << CGAL::to_double(m.y()) << "), inside the cell with corners ("
         << exact_string(a.x()) << ", " << exact_string(a.y()) << "), (" << exact_string(b.x()) << ", "
         << exact_string(b.y()) << "), (" << exact_string(c.x()) << ", " << exact_string(c.y())
         << "): the point is " << (s ? "in" : "not in") << " the subject and " << (k ? "in" : "not in")
         << " the clip, but " << ni << " inside pieces and " << no << " outside pieces cover it";
      r.message = m_.str();
    }
  }
  r.wrong_inside_twice_area = EFT(wrong_in);
  r.wrong_outside_twice_area = EFT(wrong_out);
  return r;
}

std::optional<std::string> coverage_difference(const std::vector<EPolygon>& a, const std::vector<EPolygon>& b) {
  Cdt cdt;
  for (const auto& p : a) insert_polygon(cdt, p);
  for (const auto& p : b) insert_polygon(cdt, p);
  const std::vector<Located> la = locate(a), lb = locate(b);
  for (auto f : cdt.finite_face_handles()) {
    const EPoint m = CGAL::centroid(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point());
    const int na = coverage(la, m), nb = coverage(lb, m);
    if (na != nb) {
      std::ostringstream out;
      out << "at (" << CGAL::to_double(m.x()) << ", " << CGAL::to_double(m.y()) << "): covered " << na << " times by the first, "
          << nb << " times by the second";
      return out.str();
    }
  }
  return std::nullopt;
}

}  // namespace hlr::testing
