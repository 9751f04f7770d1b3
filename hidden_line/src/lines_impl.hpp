// classify_lines and drawing_segments as templates over the kernel; included only by the
// instantiate_*.cpp files.
//
// A line is parametrized as a + t (b - a), t in [0, 1], and everything about it is decided on t:
//   - an occluder is a closed t-interval where something covers the line's image, with the depth
//     difference f(t) = z_occluder(t) - z_line(t), which is linear in t: a visible fragment's
//     plane over the intervals where the line runs in the fragment's closure, or an edge of a face
//     seen edge-on whose image runs along the line;
//   - the line is hidden at t when some occluder active at t has f(t) > 0.
// So the split points are the ends of occluder intervals (crossings with the support lines of
// fragment edges, and fragment corners on the line) and the zeros of f (where the line passes
// through an occluder's plane), and the class of each span between split points is read at its
// middle. Only the comparisons of exact numbers decide; nothing is rounded.
#pragma once

#include <hlr/hidden_line/lines.hpp>

#include "box_index.hpp"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace hlr::hidden_line {
namespace detail {

// A line's image a -> b in the view plane, and parameters along it.
template <class K>
struct ImageLine {
  using G = Geometry<K>;
  using FT = typename G::FT;
  using P = typename G::Point;
  P a, b;
  FT dx, dy;
  bool along_x;

  ImageLine(const P& pa, const P& pb)
      : a(pa), b(pb), dx(G::x(pb) - G::x(pa)), dy(G::y(pb) - G::y(pa)), along_x(G::compare_x(pa, pb) != 0) {}

  // The parameter of a point on the line.
  FT param(const P& q) const { return along_x ? (G::x(q) - G::x(a)) / dx : (G::y(q) - G::y(a)) / dy; }
  // The parameter where the line meets the line through c and d (not parallel to it).
  FT param_of_crossing(const P& c, const P& d) const {
    const FT ex = G::x(d) - G::x(c), ey = G::y(d) - G::y(c);
    const FT rx = G::x(c) - G::x(a), ry = G::y(c) - G::y(a);
    return (rx * ey - ry * ex) / (dx * ey - dy * ex);
  }
  P at(const FT& t) const { return G::point(G::x(a) + t * dx, G::y(a) + t * dy); }
  CGAL::Bbox_2 bbox() const { return G::bbox(a) + G::bbox(b); }
};

// Something that may cover a line over [lo, hi], f(t) = f0 + t (f1 - f0) nearer than the line.
template <class K>
struct Occluder {
  typename Geometry<K>::FT lo, hi, f0, f1;
};

template <class FT>
void sort_unique(std::vector<FT>& ts) {
  std::sort(ts.begin(), ts.end());
  ts.erase(std::unique(ts.begin(), ts.end()), ts.end());
}

// The t-intervals where the line runs inside the polygon: in its closure (`closed`) or in its
// interior, joined where they meet, and with `unit` only within [0, 1]. They are bounded by the
// polygon's corners on the line and by the line's crossings with the line each crossing edge lies
// on, which `edge_line(contour, i)` gives as two points (the support line, for rule 3).
template <class K, class EdgeLine>
std::vector<std::pair<typename Geometry<K>::FT, typename Geometry<K>::FT>> inside_intervals(
    const ImageLine<K>& line, const clip::Polygon<K>& polygon, EdgeLine&& edge_line, bool closed, bool unit) {
  using G = Geometry<K>;
  using FT = typename G::FT;
  std::vector<FT> ts;
  if (unit) ts = {FT(0), FT(1)};
  auto add = [&](const FT& t) {
    if (!unit || (FT(0) < t && t < FT(1))) ts.push_back(t);
  };
  // With `unit`, parameters outside (0, 1) are known from predicates before any is constructed: a
  // corner on the line lies strictly between a and b along the line's main axis, a crossing exactly
  // when a and b lie strictly on opposite sides of the crossing edge's support line.
  auto between = [&](const auto& p) {
    const int lo = line.along_x ? G::compare_x(line.a, p) : G::compare_y(line.a, p);
    const int hi = line.along_x ? G::compare_x(p, line.b) : G::compare_y(p, line.b);
    return lo != 0 && lo == hi;
  };
  std::vector<int> side;
  auto scan = [&](const clip::Contour<K>& c) {
    const std::size_t n = c.size();
    side.resize(n);
    for (std::size_t i = 0; i < n; ++i) side[i] = G::orientation(line.a, line.b, c.points[i]);
    for (std::size_t i = 0; i < n; ++i) {
      const int op = side[i], oq = side[(i + 1) % n];
      if (op == 0) {
        if (!unit || between(c.points[i])) add(line.param(c.points[i]));
      } else if (oq != 0 && op != oq) {
        const auto [c0, c1] = edge_line(c, i);
        if (!unit || G::orientation(c0, c1, line.a) * G::orientation(c0, c1, line.b) < 0)
          add(line.param_of_crossing(c0, c1));
      }
    }
  };
  scan(polygon.outer);
  for (const auto& h : polygon.holes) scan(h);
  sort_unique(ts);
  std::vector<std::pair<FT, FT>> out;
  for (std::size_t i = 0; i + 1 < ts.size(); ++i) {
    const int side = clip::side_of_polygon(polygon, line.at((ts[i] + ts[i + 1]) / 2));
    if (closed ? side < 0 : side <= 0) continue;
    if (!out.empty() && out.back().second == ts[i]) out.back().second = ts[i + 1];
    else out.emplace_back(ts[i], ts[i + 1]);
  }
  return out;
}

template <class K>
class Classifier {
  using G = Geometry<K>;
  using FT = typename G::FT;
  using P = typename G::Point;

 public:
  Classifier(const std::vector<Mesh>& meshes, const Sources<K>& sources, const VisibilityMap<K>& map)
      : meshes_(meshes), sources_(sources), map_(map), view_points_(sources.view_points),
        grid_(domain(map), map.visible.size()),
        edge_on_grid_(domain(map), std::max<std::size_t>(sources.edge_on_faces.size(), 1)) {
    source_of_face_.resize(meshes.size());
    for (std::size_t m = 0; m < meshes.size(); ++m) source_of_face_[m].assign(meshes[m].faces.size(), -1);
    for (std::size_t s = 0; s < sources.polygons.size(); ++s)
      for (std::uint32_t f : sources.polygons[s].faces) source_of_face_[sources.polygons[s].mesh][f] = std::int32_t(s);
    for (std::uint32_t i = 0; i < map.visible.size(); ++i) grid_.insert(i, polygon_bbox(map.visible[i].polygon));
    for (std::uint32_t i = 0; i < sources.edge_on_faces.size(); ++i) {
      const auto [m, f] = sources.edge_on_faces[i];
      CGAL::Bbox_2 box;
      for (std::uint32_t v : meshes[m].faces[f]) box += G::bbox(image(m, v));
      edge_on_grid_.insert(i, box);
    }
  }

  const ViewPoint<K>& view_point(std::uint32_t mesh, std::uint32_t v) const { return view_points_[mesh][v]; }
  std::int32_t source_of_face(std::uint32_t mesh, std::uint32_t face) const { return source_of_face_[mesh][face]; }

  // What one thread needs to classify lines; the classifier itself is shared and read only.
  struct Scratch {
    std::vector<Occluder<K>> occluders;
  };

  // Splits the line into pieces; `own` are the sources whose plane contains the line (they never
  // lie strictly nearer), sorted.
  std::vector<LinePiece<K>> classify(const ViewPoint<K>& a, const ViewPoint<K>& b, const std::vector<std::int32_t>& own,
                                     Scratch& scratch) const {
    const P pa = G::point(a.x, a.y), pb = G::point(b.x, b.y);
    if (G::equal(pa, pb)) return {};
    const ImageLine<K> line(pa, pb);
    auto& occluders_ = scratch.occluders;
    occluders_.clear();

    grid_.query(line.bbox(), [&](std::uint32_t i) {
      const Fragment<K>& frag = map_.visible[i];
      if (std::binary_search(own.begin(), own.end(), std::int32_t(frag.source))) return;
      const DepthPlane<K>& plane = sources_.polygons[frag.source].plane;
      // Never strictly nearer along the line (the depth difference is linear in t).
      if (G::sign_above(plane.a, plane.b, plane.c, a.x, a.y, a.z) <= 0 &&
          G::sign_above(plane.a, plane.b, plane.c, b.x, b.y, b.z) <= 0)
        return;
      const FT f0 = plane.a * G::x(pa) + plane.b * G::y(pa) + plane.c - a.z;
      const FT f1 = plane.a * G::x(pb) + plane.b * G::y(pb) + plane.c - b.z;
      for (const auto& [lo, hi] : closure_intervals(line, frag.polygon)) occluders_.push_back({lo, hi, f0, f1});
    });

    edge_on_grid_.query(line.bbox(), [&](std::uint32_t i) {
      const auto [m, f] = sources_.edge_on_faces[i];
      const auto& face = meshes_[m].faces[f];
      for (std::uint32_t v : face)
        if (G::orientation(pa, pb, image(m, v)) != 0) return;  // meets the line in one point at most
      for (std::size_t k = 0; k < face.size(); ++k) {
        const ViewPoint<K>&u = view_points_[m][face[k]], &w = view_points_[m][face[(k + 1) % face.size()]];
        const P pu = G::point(u.x, u.y), pw = G::point(w.x, w.y);
        if (G::equal(pu, pw)) continue;  // an edge along the view direction covers one point
        const FT tu = line.param(pu), tw = line.param(pw);
        FT lo = std::min(tu, tw), hi = std::max(tu, tw);
        if (hi <= FT(0) || lo >= FT(1)) continue;
        lo = std::max(lo, FT(0));
        hi = std::min(hi, FT(1));
        // The edge's depth at line parameter t: u.z + (t - tu) / (tw - tu) (w.z - u.z).
        const FT slope = (w.z - u.z) / (tw - tu);
        const FT f0 = u.z - tu * slope - a.z;
        const FT f1 = u.z + (FT(1) - tu) * slope - b.z;
        occluders_.push_back({lo, hi, f0, f1});
      }
    });

    // Split points: occluder ends and the zeros of f inside each occluder.
    std::vector<FT> ts{FT(0), FT(1)};
    for (const auto& o : occluders_) {
      ts.push_back(o.lo);
      ts.push_back(o.hi);
      if (G::sign(o.f0) * G::sign(o.f1) < 0) {
        const FT t = o.f0 / (o.f0 - o.f1);
        if (o.lo < t && t < o.hi) ts.push_back(t);
      }
    }
    sort_unique(ts);
    std::vector<LinePiece<K>> pieces;
    for (std::size_t i = 0; i + 1 < ts.size(); ++i) {
      const FT mid = (ts[i] + ts[i + 1]) / 2;
      bool hidden = false;
      for (const auto& o : occluders_)
        if (o.lo < mid && mid < o.hi && G::sign(o.f0 + mid * (o.f1 - o.f0)) > 0) {
          hidden = true;
          break;
        }
      if (!pieces.empty() && pieces.back().visible == !hidden) pieces.back().t1 = ts[i + 1];
      else pieces.push_back({ts[i], ts[i + 1], !hidden});
    }
    return pieces;
  }

 private:
  static CGAL::Bbox_2 polygon_bbox(const clip::Polygon<K>& polygon) {
    CGAL::Bbox_2 box;
    for (const auto& p : polygon.outer.points) box += G::bbox(p);
    return box;
  }
  static CGAL::Bbox_2 domain(const VisibilityMap<K>& map) {
    CGAL::Bbox_2 box;
    for (const auto& frag : map.visible) box += polygon_bbox(frag.polygon);
    return box;
  }
  P image(std::uint32_t mesh, std::uint32_t v) const {
    const auto& q = view_points_[mesh][v];
    return G::point(q.x, q.y);
  }

  // The closed t-intervals, within [0, 1], where the line runs in the closure of the polygon.
  std::vector<std::pair<FT, FT>> closure_intervals(const ImageLine<K>& line, const clip::Polygon<K>& polygon) const {
    auto support = [&](const clip::Contour<K>& c, std::size_t i) {
      const auto& l = sources_.lines[c.lines[i]];  // rule 3: the support line, not the constructed edge
      return std::pair<const P&, const P&>(l.a, l.b);
    };
    return inside_intervals(line, polygon, support, true, true);
  }

  const std::vector<Mesh>& meshes_;
  const Sources<K>& sources_;
  const VisibilityMap<K>& map_;
  const std::vector<std::vector<ViewPoint<K>>>& view_points_;
  std::vector<std::vector<std::int32_t>> source_of_face_;
  LooseGrid grid_, edge_on_grid_;
};

}  // namespace detail

template <class K>
LineSet<K> classify_lines(const std::vector<Mesh>& meshes, const ViewFrame<K>& frame, const Sources<K>& sources,
                          const VisibilityMap<K>& map, const std::vector<IntersectionSegment>& intersections,
                          const LineOptions& options) {
  using FT = typename Geometry<K>::FT;
  detail::Classifier<K> classifier(meshes, sources, map);
  // The lines first, each with the sources it lies in (`own`, sorted); then their pieces, in
  // parallel over chunks of lines: each line is classified on its own, so the result does not
  // depend on the number of threads.
  LineSet<K> out;
  std::vector<std::vector<std::int32_t>> owns;
  auto add = [&](FeatureLine<K> line, std::initializer_list<std::pair<std::uint32_t, const std::vector<std::uint32_t>*>> sides) {
    std::vector<std::int32_t> own;
    for (const auto& [mesh, faces] : sides)
      for (std::uint32_t f : *faces)
        if (const std::int32_t s = classifier.source_of_face(mesh, f); s >= 0) own.push_back(s);
    std::sort(own.begin(), own.end());
    out.lines.push_back(std::move(line));
    owns.push_back(std::move(own));
  };

  for (std::uint32_t m = 0; m < meshes.size(); ++m) {
    for (const FeatureEdge& edge : feature_edges(meshes[m], frame.view(), options.features)) {
      FeatureLine<K> line;
      line.a = classifier.view_point(m, edge.v0);
      line.b = classifier.view_point(m, edge.v1);
      line.kind = edge.kind;
      line.mesh = m;
      line.v0 = edge.v0;
      line.v1 = edge.v1;
      add(std::move(line), {{m, &edge.faces}});
    }
  }
  if (options.intersections) {
    auto to_view = [&](const IntersectionSegment::Point3& p) {
      if constexpr (std::is_same_v<FT, CGAL::Epeck::FT>) return frame.to_view(p.x(), p.y(), p.z());
      else return frame.to_view(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    };
    for (const IntersectionSegment& s : intersections) {
      FeatureLine<K> line;
      line.a = to_view(s.a);
      line.b = to_view(s.b);
      line.kind = FeatureKind::intersection;
      line.mesh = s.mesh_a;
      line.meeting_degrees = s.meeting_degrees;
      add(std::move(line), {{s.mesh_a, &s.faces_a}, {s.mesh_b, &s.faces_b}});
    }
  }

  tbb::enumerable_thread_specific<typename detail::Classifier<K>::Scratch> scratch;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, out.lines.size(), 16), [&](const auto& range) {
    auto& mine = scratch.local();
    for (std::size_t i = range.begin(); i != range.end(); ++i) {
      FeatureLine<K>& line = out.lines[i];
      line.pieces = classifier.classify(line.a, line.b, owns[i], mine);
    }
  });
  for (const auto& line : out.lines) {
    ++out.stats.by_kind[static_cast<int>(line.kind)];
    if (line.pieces.empty()) ++out.stats.point_in_view;
    for (const auto& p : line.pieces) ++(p.visible ? out.stats.visible_pieces : out.stats.hidden_pieces);
  }
  out.stats.lines = out.lines.size();
  return out;
}

template <class K>
std::vector<DrawnSegment<K>> drawing_segments(const LineSet<K>& lines) {
  using G = Geometry<K>;
  using FT = typename G::FT;
  using P = typename G::Point;
  struct Span {
    detail::ImageLine<K> line;
    FT t0, t1;
    bool visible;
    std::uint32_t mesh;
    double meeting_degrees;
  };
  std::vector<Span> spans;
  CGAL::Bbox_2 domain;
  for (bool visible : {true, false})
    for (const auto& l : lines.lines) {
      if (l.pieces.empty()) continue;
      const detail::ImageLine<K> image(G::point(l.a.x, l.a.y), G::point(l.b.x, l.b.y));
      domain += image.bbox();
      for (const auto& p : l.pieces)
        if (p.visible == visible) spans.push_back({image, p.t0, p.t1, visible, l.mesh, l.meeting_degrees});
    }

  // Visible spans first, then hidden ones; each loses what earlier, collinear spans already draw.
  std::vector<DrawnSegment<K>> out;
  detail::LooseGrid grid(domain, spans.size());
  for (const Span& span : spans) {
    const P a = span.line.at(span.t0), b = span.line.at(span.t1);
    const CGAL::Bbox_2 box = G::bbox(a) + G::bbox(b);
    std::vector<std::pair<FT, FT>> covered;
    grid.query(box, [&](std::uint32_t i) {
      const DrawnSegment<K>& d = out[i];
      if (G::orientation(a, b, d.a) != 0 || G::orientation(a, b, d.b) != 0) return;
      FT lo = span.line.param(d.a), hi = span.line.param(d.b);
      if (hi < lo) std::swap(lo, hi);
      lo = std::max(lo, span.t0);
      hi = std::min(hi, span.t1);
      if (lo < hi) covered.emplace_back(lo, hi);
    });
    std::sort(covered.begin(), covered.end());
    FT from = span.t0;
    auto emit = [&](const FT& t0, const FT& t1) {
      const DrawnSegment<K> d{span.line.at(t0), span.line.at(t1), span.visible, span.mesh, span.meeting_degrees};
      grid.insert(std::uint32_t(out.size()), G::bbox(d.a) + G::bbox(d.b));
      out.push_back(d);
    };
    for (const auto& [lo, hi] : covered) {
      if (from < lo) emit(from, lo);
      from = std::max(from, hi);
    }
    if (from < span.t1) emit(from, span.t1);
  }
  return out;
}

}  // namespace hlr::hidden_line
