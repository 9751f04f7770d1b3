// classify_lines and drawing_segments as templates over the kernel; included only by the
// instantiate_*.cpp files.
//
// A line is parametrized as a + t (b - a), t in [0, 1], and everything about it is decided on t:
//   - an occluder is a closed t-interval where something covers the line's image, with the depth
//     difference f(t) = z_occluder(t) - z_line(t), which is linear in t: a cover's plane (a
//     source's, or a visible fragment's) over the intervals where the line runs in the cover's
//     closure, or an edge of a face seen edge-on whose image runs along the line;
//   - the line is hidden at t when some occluder active at t has f(t) > 0.
// So the split points are the ends of occluder intervals (crossings with the support lines of
// cover edges, and cover corners on the line) and the zeros of f (where the line passes
// through an occluder's plane), and the class of each span between split points is read at its
// middle. Only the comparisons of exact numbers decide; nothing is rounded.
#pragma once

#include <hlr/hidden_line/lines.hpp>
#include <hlr/hidden_line/parallel.hpp>
#include <hlr/kernel/line_box.hpp>
#include <hlr/kernel/line_parameters.hpp>
#include <hlr/kernel/mesh_edges.hpp>
#include <hlr/kernel/view_predicates.hpp>

#include "box_index.hpp"

#include <CGAL/box_intersection_d.h>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <deque>
#include <limits>
#include <memory>
#include <numbers>
#include <numeric>
#include <optional>
#include <span>
#include <unordered_map>
#include <utility>

namespace hlr::hidden_line {
namespace detail {

// The line parameters 0 and 1, one number each per thread: on the exact kernel, the pieces that
// start or end at a line's end share them (most lines are one piece, hidden all along) instead of
// holding lazy numbers of their own.
template <class K>
const typename Geometry<K>::FT& parameter_zero() {
  static thread_local const typename Geometry<K>::FT zero(0);
  return zero;
}
template <class K>
const typename Geometry<K>::FT& parameter_one() {
  static thread_local const typename Geometry<K>::FT one(1);
  return one;
}

// A point's coordinates where both are doubles exactly (intervals of one value: input vertices in
// an axis view), on the exact kernel; else none. Points with the same are the same point.
template <class K>
std::optional<std::pair<double, double>> exact_doubles(const typename Geometry<K>::Point& p) {
  using G = Geometry<K>;
  if constexpr (!G::exact_constructions) return std::nullopt;
  const CGAL::Bbox_2 box = G::bbox(p);  // the approximation Epeck keeps, without a lazy node per coordinate
  if (box.xmin() != box.xmax() || box.ymin() != box.ymax()) return std::nullopt;
  return std::pair{box.xmin(), box.ymin()};
}

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
  // From the view points the image points were made of: their coordinates as they are, without a
  // lazy node to take each back out of its point.
  ImageLine(const P& pa, const P& pb, const ViewPoint<K>& va, const ViewPoint<K>& vb)
      : a(pa), b(pb), dx(vb.x - va.x), dy(vb.y - va.y), along_x(G::compare_x(pa, pb) != 0) {}

  // The parameter of a point on the line; the line's own ends (by identity, on the exact kernel)
  // are 0 and 1 exactly, not quotients equal to them that comparisons would evaluate exactly.
  std::optional<FT> end_param(const P& q) const {
    if (const std::uintptr_t id = G::identity(q); id != 0) {
      if (id == G::identity(a)) return parameter_zero<K>();
      if (id == G::identity(b)) return parameter_one<K>();
    }
    return std::nullopt;
  }
  FT param(const P& q) const {
    if (auto t = end_param(q)) return *t;
    return parameter_along<K>(a, b, q, along_x ? dx : dy, along_x);
  }
  // The same, with an end also known by its value where both are exact_doubles: the ends of
  // coincident lines, or vertices one behind the other in an axis view, are one point made twice.
  FT param_by_value(const P& q) const {
    if (auto t = end_param(q)) return *t;
    if (const auto key = exact_doubles<K>(q)) {
      if (key == exact_doubles<K>(a)) return parameter_zero<K>();
      if (key == exact_doubles<K>(b)) return parameter_one<K>();
    }
    return parameter_along<K>(a, b, q, along_x ? dx : dy, along_x);
  }
  // The parameter where the line meets the line through c and d (not parallel to it).
  FT param_of_crossing(const P& c, const P& d) const { return crossing_parameter<K>(a, b, dx, dy, c, d); }
  // On the exact kernel the line's own ends for t exactly 0 or 1, rather than constructions equal
  // to them.
  P at(const FT& t) const {
    if (const int end = exact_end(t); end >= 0) return end == 0 ? a : b;
    return G::point(G::x(a) + t * dx, G::y(a) + t * dy);
  }
  // 0 or 1 when t is known to be exactly that without arithmetic (exact kernel), else -1.
  static int exact_end(const FT& t) {
    if constexpr (G::exact_constructions) {
      const auto [lo, hi] = G::interval(t);
      if (lo == hi && (lo == 0 || lo == 1)) return lo == 0 ? 0 : 1;
    }
    return -1;
  }
  CGAL::Bbox_2 bbox() const { return G::bbox(a) + G::bbox(b); }
};

// Something that may cover a line over [lo, hi], with the depth difference f(t) = f0 + t (f1 - f0)
// (nearer than the line where positive), kept as the signs of f0 and f1 and, where they differ
// strictly, the zero t0 of f. Occluders of one plane share these.
template <class K>
struct Depth {
  int sign0 = 0, sign1 = 0;
  typename Geometry<K>::FT t0;  // only where sign0 * sign1 < 0
  bool crosses() const { return sign0 * sign1 < 0; }
  // Whether f > 0 at t in (0, 1), t != t0.
  bool nearer_at(const typename Geometry<K>::FT& t) const {
    if (!crosses()) return sign0 > 0 || sign1 > 0;
    return t < t0 ? sign0 > 0 : sign1 > 0;
  }
};
template <class K>
struct Occluder {
  typename Geometry<K>::FT lo, hi;
  const Depth<K>* depth;
};

// Empties a per-line lookup without clear()'s zeroing of every bucket, which a map grown once by a
// line with many covers would repeat for every line after it.
template <class Map>
void reset(Map& map) {
  if (map.empty()) return;
  if (map.bucket_count() > 64) map = Map();
  else map.clear();
}

template <class FT>
void sort_unique(std::vector<FT>& ts) {
  std::sort(ts.begin(), ts.end());
  ts.erase(std::unique(ts.begin(), ts.end()), ts.end());
}

// Parameters of points on a line, constructed plainly: a corner by its coordinate along the line,
// a crossing from the two points of the crossing edge's support line, which `edge_line(contour, i)`
// gives (rule 3: the support line, not the constructed edge).
template <class K, class EdgeLine>
struct PlainParams {
  using G = Geometry<K>;
  using FT = typename G::FT;
  const ImageLine<K>& line;
  EdgeLine edge_line;
  bool on_line(const clip::Contour<K>&, std::size_t) const { return false; }
  FT corner(const clip::Contour<K>& c, std::size_t i, std::span<const int>) { return line.param(c.points[i]); }
  FT crossing(const clip::Contour<K>& c, std::size_t i) {
    const auto [c0, c1] = edge_line(c, i);
    return line.param_of_crossing(c0, c1);
  }
};

// The segment a -> b of `line` against a polygon oriented as the clipper's (its region left of
// every edge) whose corners all lie strictly off the line (`sides`, contour after contour) and
// whose boundary the line crosses exactly twice: then the region meets the line in one chord,
// bounded by the two crossing edges. The segment lies in the region's interior when both its ends
// lie strictly inside both edges, and misses the region's closure when both lie strictly outside
// one of them (the chord begins beyond it). Nothing when neither holds, or the line crosses more
// edges or passes through a corner. Decided on the ends' sides of two edges, without constructing
// a crossing or locating the ends in the whole polygon.
template <class K>
std::optional<bool> segment_in_chord(const ImageLine<K>& line, const clip::Contour<K>& outer,
                                     std::span<const clip::Contour<K>* const> holes, std::span<const int> sides) {
  using G = Geometry<K>;
  std::array<std::pair<const clip::Contour<K>*, std::size_t>, 2> crossed;  // contour, edge
  int crossings = 0;
  std::size_t offset = 0;
  auto scan = [&](const clip::Contour<K>& c) {
    const std::size_t n = c.size();
    for (std::size_t i = 0; i < n; ++i) {
      const int here = sides[offset + i], next = sides[offset + (i + 1) % n];
      if (here == 0) return false;
      if (here != next) {
        if (crossings == 2) return false;
        crossed[crossings++] = {&c, i};
      }
    }
    offset += n;
    return true;
  };
  if (!scan(outer)) return std::nullopt;
  for (const clip::Contour<K>* h : holes)
    if (!scan(*h)) return std::nullopt;
  if (crossings != 2) return std::nullopt;
  bool inside = true;
  for (const auto& [c, i] : crossed) {
    const auto& p = c->points[i];
    const auto& q = c->points[(i + 1) % c->size()];
    const int sa = G::orientation(p, q, line.a), sb = G::orientation(p, q, line.b);
    if (sa < 0 && sb < 0) return false;
    inside = inside && sa > 0 && sb > 0;
  }
  if (inside) return true;
  return std::nullopt;
}

// The t-intervals where the line runs inside the polygon: in its closure (`closed`) or in its
// interior, joined where they meet, and with `unit` only within [0, 1]. They are bounded by the
// polygon's corners on the line and by the line's crossings with the line each crossing edge lies
// on; `params` constructs those parameters (PlainParams, or the classifier's shared ones) and may
// know corners on the line without arithmetic (`on_line`). `oriented`: the polygon is oriented as
// the clipper's output, which lets segment_in_chord settle most segments with `unit`.
// `hole_boxes`, the boxes of the polygon's holes (or none): with `unit`, a hole whose box misses
// the segment's box neither crosses nor holds it, and is not looked at.
// The order of the tests is the classifier's: most segments it asks about lie wholly off the
// polygon or wholly in it, and are told from their boxes and one end.
template <class K, class Params>
std::vector<std::pair<typename Geometry<K>::FT, typename Geometry<K>::FT>> inside_intervals(
    const ImageLine<K>& line, const clip::Polygon<K>& polygon, Params& params, bool closed, bool unit,
    bool oriented = false, std::span<const CGAL::Bbox_2> hole_boxes = {}) {
  using G = Geometry<K>;
  using FT = typename G::FT;
  const FT &zero = parameter_zero<K>(), &one = parameter_one<K>();
  // With `unit`, parameters outside (0, 1) are known from predicates before any is constructed: a
  // corner on the line lies strictly between a and b along the line's main axis, a crossing exactly
  // when a and b lie strictly on opposite sides of the crossing edge's support line.
  auto between = [&](const auto& p) {
    const int lo = line.along_x ? G::compare_x(line.a, p) : G::compare_y(line.a, p);
    const int hi = line.along_x ? G::compare_x(p, line.b) : G::compare_y(p, line.b);
    return lo != 0 && lo == hi;
  };
  const CGAL::Bbox_2 segment_box = unit ? line.bbox() : CGAL::Bbox_2();
  std::vector<const clip::Contour<K>*> holes;
  holes.reserve(polygon.holes.size());
  for (std::size_t h = 0; h < polygon.holes.size(); ++h)
    if (!unit || hole_boxes.empty() || CGAL::do_overlap(hole_boxes[h], segment_box)) holes.push_back(&polygon.holes[h]);
  if (unit) {
    // A segment whose box meets no edge's box lies wholly inside the polygon or wholly outside it,
    // where its end a lies (off the boundary).
    auto near = [&](const clip::Contour<K>* c) {
      CGAL::Bbox_2 previous = G::bbox(c->points.back());
      for (const auto& p : c->points) {
        const CGAL::Bbox_2 here = G::bbox(p);
        if (CGAL::do_overlap(previous + here, segment_box)) return true;
        previous = here;
      }
      return false;
    };
    if (!near(&polygon.outer) && std::none_of(holes.begin(), holes.end(), near)) {
      if (clip::side_of_polygon_on_line<K>(polygon.outer, holes, {}, line.a) > 0) return {{zero, one}};
      return {};
    }
  }
  // The side of the line each corner lies on, contour after contour (the outer one first).
  std::vector<int> sides;
  sides.reserve(polygon.outer.size());
  auto sides_of = [&](const clip::Contour<K>& c) {
    for (std::size_t i = 0; i < c.size(); ++i)
      sides.push_back(params.on_line(c, i) ? 0 : G::orientation(line.a, line.b, c.points[i]));
  };
  sides_of(polygon.outer);
  // An outer contour wholly on one side of the line (no corner on it) keeps the polygon off it.
  if (std::all_of(sides.begin(), sides.end(), [&](int s) { return s == sides[0] && s != 0; })) return {};
  for (const clip::Contour<K>* h : holes) sides_of(*h);
  if (unit && oriented)
    if (const auto inside = segment_in_chord<K>(line, polygon.outer, holes, sides)) {
      if (*inside) return {{zero, one}};
      return {};
    }
  // The parameters where the line may enter or leave the polygon (made only now: most segments the
  // classifier asks about are settled above).
  std::vector<FT> ts;
  if (unit) ts = {zero, one};
  std::size_t offset = 0;
  auto scan = [&](const clip::Contour<K>& c) {
    const std::size_t n = c.size();
    const std::span<const int> side(sides.data() + offset, n);
    offset += n;
    for (std::size_t i = 0; i < n; ++i) {
      const int op = side[i], oq = side[(i + 1) % n];
      if (op == 0) {
        if (!unit || between(c.points[i])) ts.push_back(params.corner(c, i, side));
      } else if (oq != 0 && op != oq) {
        const auto [c0, c1] = params.edge_line(c, i);
        if (!unit || G::orientation(c0, c1, line.a) * G::orientation(c0, c1, line.b) < 0)
          ts.push_back(params.crossing(c, i));
      }
    }
  };
  scan(polygon.outer);
  for (const clip::Contour<K>* h : holes) scan(*h);
  sort_unique(ts);
  std::vector<std::pair<FT, FT>> out;
  // A span that ends at the line's own end a (or b) meets no boundary inside, so it lies where
  // that end lies when the end is off the boundary: decided on the end itself, without making the
  // span's middle. Only an end on the boundary leaves it to the middle.
  auto end_side = [&](std::size_t i) {
    if (!unit) return 0;
    int side = 0;
    if (i == 0) side = clip::side_of_polygon_on_line<K>(polygon.outer, holes, sides, line.a);
    if (side == 0 && i + 2 == ts.size()) side = clip::side_of_polygon_on_line<K>(polygon.outer, holes, sides, line.b);
    return side;
  };
  for (std::size_t i = 0; i + 1 < ts.size(); ++i) {
    int side = end_side(i);
    if (side == 0)
      side = clip::side_of_polygon_on_line<K>(polygon.outer, holes, sides, line.at((ts[i] + ts[i + 1]) / 2));
    if (closed ? side < 0 : side <= 0) continue;
    if (!out.empty() && out.back().second == ts[i]) out.back().second = ts[i + 1];
    else out.emplace_back(ts[i], ts[i + 1]);
  }
  return out;
}

// A polygon that may hide lines: a visible fragment of the area sort, or a source itself.
template <class K>
struct Cover {
  const clip::Polygon<K>* polygon;
  std::uint32_t source;
};

template <class K>
class Classifier {
  using G = Geometry<K>;
  using FT = typename G::FT;
  using P = typename G::Point;

 public:
  Classifier(const std::vector<Mesh>& meshes, const ViewFrame<K>& frame, const Sources<K>& sources,
             std::vector<Cover<K>> covers)
      : meshes_(meshes), sources_(sources), covers_(std::move(covers)), view_points_(sources.view_points),
        grid_(filed(covers_)),
        edge_on_grid_(grid_.domain(), std::max<std::size_t>(sources.edge_on_edges.size(), 1)) {
    source_of_face_.resize(meshes.size());
    for (std::size_t m = 0; m < meshes.size(); ++m) source_of_face_[m].assign(meshes[m].faces.size(), -1);
    parallel_chunks(sources.polygons.size(), 4096, [&](const auto& range) {  // each face has one source
      for (std::size_t s = range.begin(); s != range.end(); ++s)
        for (std::uint32_t f : sources.polygons[s].faces) source_of_face_[sources.polygons[s].mesh][f] = std::int32_t(s);
    });
    // The sources through each mesh vertex: their planes contain it exactly. Counted, placed by a
    // scan and filled on every thread, each list then sorted. Each thread remembers the last
    // source it met at each vertex (`mark`), so that a vertex of several faces of one source
    // counts once: the counting marks s, the filling -2 - s (-1 is none).
    vertex_sources_.resize(meshes.size());
    tbb::enumerable_thread_specific<std::vector<std::vector<std::int32_t>>> last;
    auto each_vertex_source = [&](auto mark, auto visit) {  // visit(mesh, vertex, source), each triple once
      parallel_chunks(sources.polygons.size(), 1024, [&](const auto& range) {
        auto& seen = last.local();
        if (seen.empty())
          for (const Mesh& mesh : meshes) seen.emplace_back(mesh.vertices.size(), -1);
        for (std::size_t s = range.begin(); s != range.end(); ++s) {
          const auto& sp = sources.polygons[s];
          const std::int32_t m = mark(std::int32_t(s));
          for (std::uint32_t f : sp.faces)
            for (std::uint32_t v : meshes[sp.mesh].faces[f])
              if (seen[sp.mesh][v] != m) {
                seen[sp.mesh][v] = m;
                visit(sp.mesh, v, std::int32_t(s));
              }
        }
      });
    };
    for (std::size_t m = 0; m < meshes.size(); ++m) vertex_sources_[m].start.assign(meshes[m].vertices.size() + 1, 0);
    each_vertex_source([](std::int32_t s) { return s; }, [&](std::uint32_t m, std::uint32_t v, std::int32_t) {
      std::atomic_ref(vertex_sources_[m].start[v + 1]).fetch_add(1, std::memory_order_relaxed);
    });
    std::vector<std::vector<std::uint32_t>> next(meshes.size());
    for (std::size_t m = 0; m < meshes.size(); ++m) {
      auto& vs = vertex_sources_[m];
      std::partial_sum(vs.start.begin(), vs.start.end(), vs.start.begin());
      vs.sources.resize(vs.start.back());
      next[m].assign(vs.start.begin(), vs.start.end() - 1);
    }
    each_vertex_source([](std::int32_t s) { return -2 - s; }, [&](std::uint32_t m, std::uint32_t v, std::int32_t s) {
      vertex_sources_[m].sources[std::atomic_ref(next[m][v]).fetch_add(1, std::memory_order_relaxed)] = s;
    });
    for (auto& vs : vertex_sources_)
      parallel_chunks(vs.start.size() - 1, 16384, [&](const auto& range) {
        for (std::size_t v = range.begin(); v != range.end(); ++v)
          std::sort(vs.sources.begin() + vs.start[v], vs.sources.begin() + vs.start[v + 1]);
      });
    hole_box_start_.assign(covers_.size() + 1, 0);
    for (std::uint32_t i = 0; i < covers_.size(); ++i)
      hole_box_start_[i + 1] = hole_box_start_[i] + std::uint32_t(covers_[i].polygon->holes.size());
    hole_boxes_.resize(hole_box_start_.back());
    parallel_chunks(covers_.size(), 4096, [&](const auto& range) {
      for (std::size_t i = range.begin(); i != range.end(); ++i) {
        const auto& holes = covers_[i].polygon->holes;
        for (std::size_t h = 0; h < holes.size(); ++h) hole_boxes_[hole_box_start_[i] + h] = box_of(holes[h]);
      }
    });
    // Orthographic views on the exact kernel decide depths in model space, on the input doubles.
    if constexpr (G::exact_constructions)
      if (!frame.perspective()) {
        model_turns_.resize(sources.polygons.size());
        parallel_chunks(sources.polygons.size(), 4096, [&](const auto& range) {
          for (std::size_t s = range.begin(); s != range.end(); ++s) {
            const auto& sp = sources.polygons[s];
            const auto& v = meshes[sp.mesh].vertices;
            const ModelPlane plane(v[sp.plane_points[0]], v[sp.plane_points[1]], v[sp.plane_points[2]], frame.view().direction);
            model_turns_[s] = static_cast<std::int8_t>(plane.turn());
          }
        });
      }
    nearest_.resize(covers_.size());
    parallel_chunks(covers_.size(), 4096, [&](const auto& range) {
      for (std::size_t i = range.begin(); i != range.end(); ++i) {
        const SourcePolygon<K>& source = sources.polygons[covers_[i].source];
        nearest_[i] = source.plane ? nearest_depth(*covers_[i].polygon, *source.plane) : nearest_vertex(source);
      }
    });
    for (std::uint32_t i = 0; i < sources.edge_on_edges.size(); ++i) {
      const auto [m, v0, v1] = sources.edge_on_edges[i];
      edge_on_grid_.insert(i, G::bbox(image(m, v0)) + G::bbox(image(m, v1)));
    }
    edge_on_grid_.freeze();
  }

  const ViewPoint<K>& view_point(std::uint32_t mesh, std::uint32_t v) const { return view_points_[mesh][v]; }
  std::int32_t source_of_face(std::uint32_t mesh, std::uint32_t face) const { return source_of_face_[mesh][face]; }
  // The support line of a mesh edge, or kNoLine when no source has it.
  clip::LineId line_of_edge(std::uint32_t mesh, std::uint32_t v0, std::uint32_t v1) const {
    const auto& lines = sources_.edge_lines[mesh];
    const std::uint64_t key = edge_key(v0, v1);
    auto it = std::lower_bound(lines.begin(), lines.end(), key, [](const auto& e, std::uint64_t k) { return e.first < k; });
    return it != lines.end() && it->first == key ? it->second : kNoLine;
  }

  static constexpr clip::LineId kNoLine = ~clip::LineId(0);
  static constexpr std::uint32_t kNoVertex = ~std::uint32_t(0);

  // The line to classify: its ends in view coordinates and projected, and what is known of it
  // without arithmetic: the support line it is (a mesh edge's), and its ends' mesh vertices.
  // Its ends in model space where depths are decided there: input vertices, or exact points.
  struct Query {
    const ViewPoint<K>&a, &b;
    P pa, pb;
    clip::LineId line = kNoLine;
    std::uint32_t mesh = 0, v0 = kNoVertex, v1 = kNoVertex;
    const Vec3 *model_a = nullptr, *model_b = nullptr;
    const ModelPlane::Point3 *exact_a = nullptr, *exact_b = nullptr;
  };
  // A mesh edge's ends in front of the near plane (NearCut::edge_ends): an end replaced by the
  // edge's crossing with it is no mesh vertex.
  Query mesh_edge(std::uint32_t mesh, std::uint32_t v0, std::uint32_t v1) const {
    const auto& images = sources_.image_points[mesh];
    const auto [i0, i1] = *sources_.near_cuts[mesh].edge_ends(v0, v1);
    Query q{view_points_[mesh][i0], view_points_[mesh][i1], images[i0], images[i1], line_of_edge(mesh, v0, v1), mesh,
            i0 == v0 ? v0 : kNoVertex, i1 == v1 ? v1 : kNoVertex};
    if (!model_turns_.empty()) {  // orthographic: the ends are input vertices
      q.model_a = &meshes_[mesh].vertices[i0];
      q.model_b = &meshes_[mesh].vertices[i1];
    }
    return q;
  }
  // A line between constructed points: `model` are its ends in model space (orthographic views).
  static Query constructed(const ViewPoint<K>& a, const ViewPoint<K>& b,
                           std::pair<const ModelPlane::Point3*, const ModelPlane::Point3*> model = {}) {
    Query q{a, b, G::point(a.x, a.y), G::point(b.x, b.y)};
    std::tie(q.exact_a, q.exact_b) = model;
    return q;
  }

  // Parameters along the line being classified, one per support line it crosses: the fragments
  // that share an edge or a corner on that support line get the same number, so the exact ties
  // between them are decided by identity, not by exact arithmetic.
  struct SharedParams {
    const ImageLine<K>* line = nullptr;
    const clip::LineTable<K>* lines = nullptr;
    clip::LineId own = kNoLine;
    std::unordered_map<clip::LineId, FT> by_line;
    std::unordered_map<std::uintptr_t, FT> by_point;  // by G::identity of corners on the line
    // By exact_doubles of points on the line: in an axis view the images of vertices one behind
    // the other are one point, met through edge-on faces' edges all along a line, and equal
    // parameters made apart would be compared exactly when the split points are sorted.
    struct DoublesHash {
      std::size_t operator()(const std::pair<double, double>& p) const noexcept {
        return std::hash<double>()(p.first) * 31 + std::hash<double>()(p.second);
      }
    };
    std::unordered_map<std::pair<double, double>, FT, DoublesHash> by_value;

    bool on_line(const clip::Contour<K>& c, std::size_t i) const {
      if constexpr (G::exact_constructions) return own != kNoLine && clip::corner_on_line(c, i, own);
      else return false;
    }
    std::pair<const P&, const P&> edge_line(const clip::Contour<K>& c, std::size_t i) const {
      const auto& l = (*lines)[c.lines[i]];
      return {l.a, l.b};
    }
    FT crossing(const clip::Contour<K>& c, std::size_t i) { return crossing_of(c.lines[i]); }
    // A corner on the line where an edge from a corner off the line arrives or leaves is where
    // that edge's support line crosses the line (rule 3: the corner lies on it).
    // One corner shared by several fragments (a mesh vertex on the line) is reached by different
    // edges in each, so it is also looked up by identity.
    FT corner(const clip::Contour<K>& c, std::size_t i, std::span<const int> side) {
      if constexpr (!G::exact_constructions) return line->param(c.points[i]);  // rounded points: as they are
      const std::uintptr_t id = G::identity(c.points[i]);
      // The line's own end (a corner it starts from) is 0 or 1, not a crossing equal to it.
      if (auto t = line->end_param(c.points[i])) return *t;
      if (id != 0)
        if (auto it = by_point.find(id); it != by_point.end()) return it->second;
      const std::size_t n = c.size(), prev = i == 0 ? n - 1 : i - 1, next = i + 1 == n ? 0 : i + 1;
      const FT t = side[prev] != 0 ? crossing_of(c.lines[prev])
                   : side[next] != 0 ? crossing_of(c.lines[i])
                                     : line->param(c.points[i]);
      if (id != 0) by_point.emplace(id, t);
      return t;
    }
    // The parameter of any point on the line: the line's own ends are 0 and 1 exactly.
    FT at_point(const P& p) {
      if (auto t = line->end_param(p)) return *t;
      if (G::identity(p) != 0) {
        auto [it, added] = by_point.try_emplace(G::identity(p));
        if (added) it->second = of_value(p);
        return it->second;
      }
      return of_value(p);
    }
    // A point's parameter, made once for all points of the same exact_doubles.
    FT of_value(const P& p) {
      const auto key = exact_doubles<K>(p);
      if (!key) return line->param(p);
      auto [it, added] = by_value.try_emplace(*key);
      if (added) it->second = line->param_by_value(p);
      return it->second;
    }
    FT crossing_of(clip::LineId id) {
      auto [it, added] = by_line.try_emplace(id);
      if (added) {
        const auto& l = (*lines)[id];
        it->second = line->param_of_crossing(l.a, l.b);
      }
      return it->second;
    }
  };

  // What one thread needs to classify lines; the classifier itself is shared and read only.
  struct Scratch {
    std::vector<Occluder<K>> occluders;
    std::vector<std::pair<FT, FT>> whole;
    SharedParams params;
    std::unordered_map<std::uint32_t, Depth<K>> by_source;  // the line against each source's plane
    std::deque<Depth<K>> edge_on;                           // against faces seen edge-on
    // The covers that last completed the cover of a line all along, the latest first (kNoCover:
    // none yet). classify asks them first.
    std::array<std::uint32_t, 2> recent_hiders{kNoCover, kNoCover};
    // The line inside each recent hider, as asked (kept for the grid, which gives it again).
    std::array<std::vector<std::pair<FT, FT>>, 2> recent_inside;
  };
  static constexpr std::uint32_t kNoCover = ~std::uint32_t(0);

  // Splits the line into pieces; `own` are the sources whose plane contains the line (they never
  // lie strictly nearer), sorted.
  std::vector<LinePiece<K>> classify(const Query& q, std::span<const std::int32_t> own, Scratch& scratch) const {
    const ViewPoint<K>&a = q.a, &b = q.b;
    const P &pa = q.pa, &pb = q.pb;
    if (G::equal(pa, pb)) return {};
    const ImageLine<K> line(pa, pb, a, b);
    auto& occluders_ = scratch.occluders;
    occluders_.clear();
    auto& params = scratch.params;
    params.line = &line;
    params.lines = &sources_.lines;
    params.own = q.line;
    reset(params.by_line);
    reset(params.by_point);
    reset(params.by_value);
    reset(scratch.by_source);
    scratch.edge_on.clear();
    // A mesh vertex lies exactly in the plane of every source through it.
    auto in_plane = [&](std::uint32_t v, std::int32_t source) {
      if (v == kNoVertex) return false;
      const VertexSources& vs = vertex_sources_[q.mesh];
      return std::binary_search(vs.sources.begin() + vs.start[v], vs.sources.begin() + vs.start[v + 1], source);
    };
    // The line against the plane of a source, once per source.
    auto depth_of_source = [&](std::uint32_t source) -> const Depth<K>& {
      auto [it, added] = scratch.by_source.try_emplace(source);
      if (!added) return it->second;
      if constexpr (G::exact_constructions)
        if (!model_turns_.empty()) {
          const ModelPlane plane = model_plane(source);
          Depth<K>& d = it->second;
          // The ends as input vertices or as exact points (a constructed line has no vertex).
          auto against = [&](const auto& pa, const auto& pb) {
            d.sign0 = in_plane(q.v0, std::int32_t(source)) ? 0 : plane.nearer_than(pa);
            d.sign1 = in_plane(q.v1, std::int32_t(source)) ? 0 : plane.nearer_than(pb);
            if (d.crosses()) d.t0 = plane.crossing(pa, pb);
          };
          if (q.model_a) against(*q.model_a, *q.model_b);
          else against(*q.exact_a, *q.exact_b);
          return d;
        }
      const DepthPlane<K>& plane = *sources_.polygons[source].plane;
      auto f = [&](const ViewPoint<K>& p) { return plane.a * p.x + plane.b * p.y + plane.c - p.z; };
      Depth<K>& d = it->second;
      d.sign0 = in_plane(q.v0, std::int32_t(source)) ? 0 : G::sign_above(plane.a, plane.b, plane.c, a.x, a.y, a.z);
      d.sign1 = in_plane(q.v1, std::int32_t(source)) ? 0 : G::sign_above(plane.a, plane.b, plane.c, b.x, b.y, b.z);
      if (d.crosses()) {
        const FT f0 = f(a), f1 = f(b);
        d.t0 = f0 / (f0 - f1);
      }
      return d;
    };

    // A cover's depth against the line where the cover may lie nearer than the line somewhere
    // along it, and its box meets the line; else null.
    const double line_depth = std::min(G::interval(a.z).first, G::interval(b.z).first);
    auto nearer_cover = [&](std::uint32_t i) -> const Depth<K>* {
      // Wholly behind the nearest point of the line: on interval bounds, so it decides nothing
      // the exact test below would not.
      if (nearest_[i] < line_depth) return nullptr;
      const Cover<K>& cover = covers_[i];
      if (std::binary_search(own.begin(), own.end(), std::int32_t(cover.source))) return nullptr;
      const Depth<K>& depth = depth_of_source(cover.source);
      // Never strictly nearer along the line (the depth difference is linear in t).
      if (depth.sign0 <= 0 && depth.sign1 <= 0) return nullptr;
      // A line across the box's corner: the boxes overlap, the cover lies off the line.
      if (line_misses_box<K>(line.a, line.b, grid_.box(i))) return nullptr;
      return &depth;
    };
    auto inside = [&](std::uint32_t i) {
      const std::span<const CGAL::Bbox_2> hole_boxes(hole_boxes_.data() + hole_box_start_[i],
                                                     hole_box_start_[i + 1] - hole_box_start_[i]);
      return inside_intervals(line, *covers_[i].polygon, params, true, true, true, hole_boxes);
    };
    const FT &zero = parameter_zero<K>(), &one = parameter_one<K>();
    auto& whole = scratch.whole;
    auto& recent = scratch.recent_hiders;
    auto remember = [&](std::uint32_t i) {  // in front, once
      const auto at = std::find(recent.begin(), recent.end() - 1, i);
      std::rotate(recent.begin(), at, at + 1);
      recent[0] = i;
    };
    // Lines side by side are mostly hidden by the same cover: those that last completed the cover
    // of a line all along are asked first, each alone. When one hides this line all along, so would
    // the covers the grid gives (it is one of them): the answer is the same.
    std::array<std::uint32_t, 2> asked{kNoCover, kNoCover};  // the recent hiders whose inside is known
    for (std::size_t k = 0; k < recent.size() && recent[k] != kNoCover; ++k) {
      const Depth<K>* depth = nearer_cover(recent[k]);
      if (!depth || depth->sign0 <= 0 || depth->sign1 <= 0) continue;
      auto& in = scratch.recent_inside[k];
      in = inside(recent[k]);
      asked[k] = recent[k];
      whole.assign(in.begin(), in.end());  // covers_unit sorts its intervals; `in` keeps their order
      if (!whole.empty() && covers_unit(whole)) {
        remember(recent[k]);
        return {{zero, one, false}};
      }
    }

    // Where covers nearer than the line all along it (`whole`) cover all of it, the line is hidden
    // all along: every span lies in one of them, whatever the other occluders do.
    whole.clear();
    bool hidden_all_along = false;
    grid_.query(line.bbox(), [&](std::uint32_t i) {
      const Depth<K>* depth = nearer_cover(i);
      if (!depth) return false;
      const bool nearer_all_along = depth->sign0 > 0 && depth->sign1 > 0;
      const std::size_t before = whole.size();
      std::vector<std::pair<FT, FT>> fresh;
      const auto* in = i == asked[0] ? &scratch.recent_inside[0] : i == asked[1] ? &scratch.recent_inside[1] : nullptr;
      if (!in) in = &(fresh = inside(i));
      for (const auto& [lo, hi] : *in) {
        occluders_.push_back({lo, hi, depth});
        if (nearer_all_along) whole.emplace_back(lo, hi);
      }
      if (whole.size() == before) return false;
      hidden_all_along = covers_unit(whole);
      if (hidden_all_along) remember(i);
      return hidden_all_along;
    });
    if (hidden_all_along) return {{zero, one, false}};

    // Faces seen edge-on cover the line where their edges' images run along it.
    edge_on_grid_.query(line.bbox(), [&](std::uint32_t i) {
      const auto [m, vu, vw] = sources_.edge_on_edges[i];
      const ViewPoint<K>&u = view_points_[m][vu], &w = view_points_[m][vw];
      const P &pu = image(m, vu), &pw = image(m, vw);
      if (G::equal(pu, pw)) return;  // an edge along the view direction covers one point
      if (G::orientation(pa, pb, pu) != 0 || G::orientation(pa, pb, pw) != 0) return;
      const FT tu = params.at_point(pu), tw = params.at_point(pw);
      FT lo = std::min(tu, tw), hi = std::max(tu, tw);
      if (hi <= zero || lo >= one) return;
      lo = std::max(lo, zero);
      hi = std::min(hi, one);
      // The edge's depth at line parameter t: u.z + (t - tu) / (tw - tu) (w.z - u.z).
      const FT slope = (w.z - u.z) / (tw - tu);
      const FT f0 = u.z - tu * slope - a.z;
      const FT f1 = u.z + (one - tu) * slope - b.z;
      Depth<K>& d = scratch.edge_on.emplace_back();
      d.sign0 = G::sign(f0);
      d.sign1 = G::sign(f1);
      if (d.crosses()) d.t0 = f0 / (f0 - f1);
      occluders_.push_back({lo, hi, &d});
    });

    // Split points: occluder ends and the zeros of f inside each occluder.
    std::vector<FT> ts{zero, one};
    for (const auto& o : occluders_) {
      ts.push_back(o.lo);
      ts.push_back(o.hi);
      if (o.depth->crosses() && o.lo < o.depth->t0 && o.depth->t0 < o.hi) ts.push_back(o.depth->t0);
    }
    sort_unique(ts);
    std::vector<LinePiece<K>> pieces;
    for (std::size_t i = 0; i + 1 < ts.size(); ++i) {
      const FT mid = (ts[i] + ts[i + 1]) / 2;
      bool hidden = false;
      for (const auto& o : occluders_)
        if (o.lo < mid && mid < o.hi && o.depth->nearer_at(mid)) {
          hidden = true;
          break;
        }
      if (!pieces.empty() && pieces.back().visible == !hidden) pieces.back().t1 = ts[i + 1];
      else pieces.push_back({ts[i], ts[i + 1], !hidden});
    }
    return pieces;
  }

 private:
  // The covers' polygons' boxes in a grid over all of them.
  static LooseGrid filed(const std::vector<Cover<K>>& covers) {
    std::vector<CGAL::Bbox_2> boxes(covers.size());
    parallel_chunks(covers.size(), 4096, [&](const auto& range) {
      for (std::size_t i = range.begin(); i != range.end(); ++i) boxes[i] = box_of(*covers[i].polygon);
    });
    CGAL::Bbox_2 domain;
    for (const auto& box : boxes) domain += box;
    return LooseGrid(domain, std::move(boxes));
  }
  const P& image(std::uint32_t mesh, std::uint32_t v) const { return sources_.image_points[mesh][v]; }
  // An upper bound of the depth over a source: at its faces' corners (z is linear over each face).
  double nearest_vertex(const SourcePolygon<K>& source) const {
    double z = -std::numeric_limits<double>::infinity();
    for (std::uint32_t f : source.faces)
      for (std::uint32_t v : meshes_[source.mesh].faces[f]) z = std::max(z, G::interval(view_points_[source.mesh][v].z).second);
    return z;
  }
  // An upper bound of the depth z = a x + b y + c over the polygon (at its outer corners: the
  // polygon lies in their hull), in interval arithmetic on the numbers' bounds.
  static double nearest_depth(const clip::Polygon<K>& polygon, const DepthPlane<K>& plane) {
    const auto pa = bounds_of<K>(plane.a), pb = bounds_of<K>(plane.b), pc = bounds_of<K>(plane.c);
    double z = -std::numeric_limits<double>::infinity();
    for (const P& p : polygon.outer.points) z = std::max(z, bounds_at<K>(pa, pb, pc, p).sup());
    return z;
  }
  // Whether closed intervals in [0, 1] cover all of it.
  static bool covers_unit(std::vector<std::pair<FT, FT>>& intervals) {
    std::sort(intervals.begin(), intervals.end());
    FT reach = parameter_zero<K>();  // the shared constants: FT(0) and FT(1) would each be a new node
    for (const auto& [lo, hi] : intervals) {
      if (reach < lo) return false;
      if (reach < hi) reach = hi;
    }
    return !(reach < parameter_one<K>());
  }

  const std::vector<Mesh>& meshes_;
  const Sources<K>& sources_;
  std::vector<Cover<K>> covers_;
  // Per source, in orthographic views on the exact kernel: its plane's turn (ModelPlane::turn), the
  // plane made again from it where needed (one byte kept per source instead of three points).
  std::vector<std::int8_t> model_turns_;
  ModelPlane model_plane(std::uint32_t source) const {
    const auto& sp = sources_.polygons[source];
    const auto& v = meshes_[sp.mesh].vertices;
    return ModelPlane::with_turn(v[sp.plane_points[0]], v[sp.plane_points[1]], v[sp.plane_points[2]], model_turns_[source]);
  }
  const std::vector<std::vector<ViewPoint<K>>>& view_points_;
  std::vector<std::vector<std::int32_t>> source_of_face_;
  // Per mesh: vertex v's sources are sources[start[v] .. start[v + 1]), sorted.
  struct VertexSources {
    std::vector<std::uint32_t> start;
    std::vector<std::int32_t> sources;
  };
  std::vector<VertexSources> vertex_sources_;
  // The boxes of cover i's holes are hole_boxes_[hole_box_start_[i] .. hole_box_start_[i + 1]).
  std::vector<CGAL::Bbox_2> hole_boxes_;
  std::vector<std::uint32_t> hole_box_start_;
  std::vector<double> nearest_;      // nearest_depth of covers_' polygons
  LooseGrid grid_;  // of covers_' polygons
  LooseGrid edge_on_grid_;
};

// Sorts (key, item) pairs and calls run(items) once for each run of one key, with the items of
// the run, in parallel chunks of `grain` runs: how the ends that are one point are found, to be
// made, viewed or rounded once.
template <class Key, class Run>
void for_each_run_of_one_key(std::vector<std::pair<Key, std::uint32_t>>& keyed, std::size_t grain, const StopToken& stop,
                             const Run& run) {
  tbb::parallel_sort(keyed.begin(), keyed.end());
  std::vector<std::size_t> firsts;  // where each run starts in `keyed`
  for (std::size_t k = 0; k < keyed.size(); ++k)
    if (k == 0 || keyed[k].first != keyed[k - 1].first) firsts.push_back(k);
  firsts.push_back(keyed.size());
  parallel_chunks(firsts.size() - 1, grain, [&](const auto& range) {
    stop.check();
    for (std::size_t r = range.begin(); r != range.end(); ++r)
      run(std::span(keyed.data() + firsts[r], keyed.data() + firsts[r + 1]));
  });
}

// (point id, 2 i + e) for end e of segment i: the segments' ends keyed by their lazy point, for
// for_each_run_of_one_key.
inline std::vector<std::pair<std::size_t, std::uint32_t>> ends_by_point(const std::vector<IntersectionSegment>& segments) {
  std::vector<std::pair<std::size_t, std::uint32_t>> ends(2 * segments.size());
  parallel_chunks(segments.size(), 4096, [&](const auto& range) {
    for (std::size_t i = range.begin(); i != range.end(); ++i) {
      ends[2 * i] = {segments[i].a.id(), std::uint32_t(2 * i)};
      ends[2 * i + 1] = {segments[i].b.id(), std::uint32_t(2 * i + 1)};
    }
  });
  return ends;
}

// The segments' ends in an orthographic view: end(2 i + e, point, rounded) for end e of segment i,
// from every thread, with its view point and on the exact kernel the nearest doubles to it (from
// its recipe). Ends that are one lazy point (the same id) share one view point, rounded once.
template <class K, class End>
void for_each_view_end(const ViewFrame<K>& frame, const std::vector<IntersectionSegment>& segments,
                       const StopToken& stop, const End& end) {
  auto ends = ends_by_point(segments);
  const RecipeRounding rounding(frame.view());
  for_each_run_of_one_key(ends, 1024, stop, [&](auto run) {
    const std::uint32_t first = run.front().second;
    const IntersectionSegment& s = segments[first / 2];
    const ViewPoint<K> point = frame.to_view(first % 2 == 0 ? s.a : s.b);
    std::optional<std::array<double, 3>> rounded;
    if constexpr (Geometry<K>::exact_constructions) rounded = rounding.nearest(recipe_of(first % 2 == 0 ? s.a : s.b));
    for (const auto& [id, e] : run) end(e, point, rounded);
  });
}

template <class K>
LineSet<K> classify_against(const std::vector<Mesh>& meshes, const ViewFrame<K>& frame, const Sources<K>& sources,
                          std::vector<Cover<K>> covers, const std::vector<IntersectionSegment>& intersections,
                          const LineOptions& options) {
  std::optional<Classifier<K>> classifier;
  // The lines first, each with the sources it lies in (`own`, sorted); then their pieces, in
  // parallel over chunks of lines: each line is classified on its own, so the result does not
  // depend on the number of threads.
  LineSet<K> out;
  // Line i's own sources are own[own_start[i] .. own_start[i + 1]), sorted: one array for all.
  std::vector<std::int32_t> own;
  std::vector<std::uint32_t> own_start{0};
  using Sides = std::initializer_list<std::pair<std::uint32_t, const std::vector<std::uint32_t>*>>;
  // Calls use(source) for each source of the faces on the line's sides.
  auto for_each_own_source = [&](Sides sides, auto&& use) {
    for (const auto& [mesh, faces] : sides)
      for (std::uint32_t f : *faces)
        if (const std::int32_t s = classifier->source_of_face(mesh, f); s >= 0) use(s);
  };

  tbb::enumerable_thread_specific<typename Classifier<K>::Scratch> scratch;
  try {
    // Every line's room taken at once: a vector grown by doubling keeps up to half of it unused
    // until the drawing is made, where the run's memory peaks.
    std::vector<std::vector<FeatureEdge>> edges;
    std::size_t line_count = options.intersections ? intersections.size() : 0;
    for (const Mesh& mesh : meshes) line_count += edges.emplace_back(feature_edges(mesh, frame.view(), options.features)).size();
    out.lines.reserve(line_count);
    own_start.reserve(line_count + 1);
    // The classifier after the lines' room: the stage's largest allocation (120 MB at 1M faces)
    // then finds a run of free pages before the classifier's arrays split them, instead of
    // growing the heap by its size (1M faces on 2 threads: 58 MB less peak).
    classifier.emplace(meshes, frame, sources, std::move(covers));
    // Each mesh's edges made lines in place on every thread: where each goes (an edge wholly
    // behind the near plane, in perspective, is not drawn) and how many own sources it has,
    // counted, then placed by a scan.
    for (std::uint32_t m = 0; m < meshes.size(); ++m) {
      const NearCut<K>& cut = sources.near_cuts[m];
      const std::vector<FeatureEdge>& mesh_edges = edges[m];
      const std::size_t count = mesh_edges.size();
      std::vector<std::uint32_t> line_at(count + 1), own_at(count + 1);  // counts, then places
      parallel_chunks(count, 4096, [&](const auto& range) {
        options.stop.check();
        for (std::size_t i = range.begin(); i != range.end(); ++i) {
          line_at[i] = cut.edge_ends(mesh_edges[i].v0, mesh_edges[i].v1) ? 1 : 0;
          own_at[i] = 0;
          if (line_at[i]) for_each_own_source({{m, &mesh_edges[i].faces}}, [&](std::int32_t) { ++own_at[i]; });
        }
      });
      std::exclusive_scan(line_at.begin(), line_at.end(), line_at.begin(), std::uint32_t(out.lines.size()));
      std::exclusive_scan(own_at.begin(), own_at.end(), own_at.begin(), std::uint32_t(own.size()));
      resize_in_parallel(out.lines, line_at[count]);
      own.resize(own_at[count]);
      own_start.resize(line_at[count] + 1);
      parallel_chunks(count, 4096, [&](const auto& range) {
        for (std::size_t i = range.begin(); i != range.end(); ++i) {
          if (line_at[i + 1] == line_at[i]) continue;
          const FeatureEdge& edge = mesh_edges[i];
          // In perspective, the part in front of the near plane.
          const auto ends = *cut.edge_ends(edge.v0, edge.v1);
          FeatureLine<K>& line = out.lines[line_at[i]];
          line.a = classifier->view_point(m, ends[0]);
          line.b = classifier->view_point(m, ends[1]);
          line.kind = edge.kind;
          line.mesh = m;
          line.v0 = edge.v0;
          line.v1 = edge.v1;
          line.has_model_ends = ends[0] == edge.v0 && ends[1] == edge.v1;
          auto at = own.begin() + own_at[i];
          for_each_own_source({{m, &edge.faces}}, [&](std::int32_t s) { *at++ = s; });
          std::sort(own.begin() + own_at[i], at);
          own_start[line_at[i] + 1] = own_at[i + 1];
        }
      });
    }
    std::vector<std::vector<FeatureEdge>>().swap(edges);  // each is its line now
    const std::size_t first_intersection = out.lines.size();
    if (options.intersections) {
      // The segments' lines made in place, in parallel, then in perspective those wholly behind
      // the near plane taken out: no copy of their ends is held beside the lines, where the run's
      // memory peaks. Their own sources are counted first, then written in place.
      const std::size_t n = intersections.size();
      resize_in_parallel(out.lines, first_intersection + n);
      own_start.resize(first_intersection + n + 1);
      const bool rounds = !frame.perspective() && Geometry<K>::exact_constructions;
      if (rounds) resize_in_parallel(out.rounded_ends, n);
      // Perspective: per segment, whether it is wholly behind the near plane (bytes, not bits: the
      // chunks write it side by side).
      std::vector<std::uint8_t> behind;
      if (frame.perspective()) behind.resize(n);
      parallel_chunks(n, 1024, [&](const auto& range) {
        options.stop.check();
        for (std::size_t i = range.begin(); i != range.end(); ++i) {
          const IntersectionSegment& s = intersections[i];
          FeatureLine<K>& line = out.lines[first_intersection + i];
          line.kind = FeatureKind::intersection;
          line.mesh = s.mesh_a;
          line.meeting_degrees = s.meeting_degrees;
          if (rounds) line.rounded_ends = std::uint32_t(i);
          std::uint32_t count = 0;
          if (frame.perspective()) {
            const auto ends = frame.to_view_clipped(s.a, s.b);
            if (ends) {
              line.a = ends->first;
              line.b = ends->second;
            }
            behind[i] = !ends;
          }
          if (behind.empty() || !behind[i]) for_each_own_source({{s.mesh_a, &s.faces_a}, {s.mesh_b, &s.faces_b}}, [&](std::int32_t) { ++count; });
          own_start[first_intersection + i + 1] = count;
        }
      });
      for (std::size_t i = first_intersection; i < first_intersection + n; ++i) own_start[i + 1] += own_start[i];
      own.resize(own_start.back());
      parallel_chunks(n, 1024, [&](const auto& range) {
        options.stop.check();
        for (std::size_t i = range.begin(); i != range.end(); ++i) {
          if (!behind.empty() && behind[i]) continue;
          const IntersectionSegment& s = intersections[i];
          const auto begin = own.begin() + own_start[first_intersection + i];
          auto at = begin;
          for_each_own_source({{s.mesh_a, &s.faces_a}, {s.mesh_b, &s.faces_b}}, [&](std::int32_t source) { *at++ = source; });
          std::sort(begin, at);
        }
      });
      if (frame.perspective()) {
        // A line behind the near plane has no own sources: taking out its start keeps the others'.
        std::size_t kept = first_intersection;
        for (std::size_t i = 0; i < n; ++i) {
          if (behind[i]) continue;
          if (kept != first_intersection + i) {
            out.lines[kept] = std::move(out.lines[first_intersection + i]);
            own_start[kept] = own_start[first_intersection + i];
          }
          ++kept;
        }
        out.lines.resize(kept);
        own_start[kept] = std::uint32_t(own.size());
        own_start.resize(kept + 1);
      } else {
        // Most crossings end two segments as one lazy point: its view point is made once.
        for_each_view_end(frame, intersections, options.stop,
                          [&](std::uint32_t end, const ViewPoint<K>& point, const std::optional<std::array<double, 3>>& rounded) {
                            FeatureLine<K>& line = out.lines[first_intersection + end / 2];
                            (end % 2 == 0 ? line.a : line.b) = point;
                            if (rounds) out.rounded_ends[end / 2][end % 2] = rounded;
                          });
      }
    }

    parallel_chunks(out.lines.size(), 16, [&](const auto& range) {
      options.stop.check();
      auto& mine = scratch.local();
      for (std::size_t i = range.begin(); i != range.end(); ++i) {
        FeatureLine<K>& line = out.lines[i];
        // Orthographic: an intersection line's ends are its segment's, uncut.
        const IntersectionSegment* s =
            frame.perspective() || i < first_intersection ? nullptr : &intersections[i - first_intersection];
        const auto query = line.kind == FeatureKind::intersection
                               ? classifier->constructed(line.a, line.b, {s ? &s->a : nullptr, s ? &s->b : nullptr})
                               : classifier->mesh_edge(line.mesh, line.v0, line.v1);
        line.pieces = classifier->classify(query, std::span(own).subspan(own_start[i], own_start[i + 1] - own_start[i]), mine);
      }
    });
  } catch (const Cancelled&) {
    // Freeing millions of lazy exact numbers one by one would delay the stop by about a second at
    // 1M faces: a run that ends at once leaves them to the operating system.
    if (options.free_at_exit) (void)new LineSet<K>(std::move(out));
    throw;
  }
  // What only the classification reads is freed first: the copy would add to the run's peak.
  classifier.reset();
  scratch.clear();
  std::vector<std::int32_t>().swap(own);
  std::vector<std::uint32_t>().swap(own_start);
  for (const Mesh& mesh : meshes) out.model_vertices.push_back(mesh.vertices);
  for (const auto& line : out.lines) {
    ++out.stats.by_kind[static_cast<int>(line.kind)];
    if (line.pieces.empty()) ++out.stats.point_in_view;
    for (const auto& p : line.pieces) ++(p.visible ? out.stats.visible_pieces : out.stats.hidden_pieces);
  }
  out.stats.lines = out.lines.size();
  out.view_direction = frame.view().direction;
  out.view_eye = frame.view().eye;
  return out;
}

}  // namespace detail

template <class K>
LineSet<K> classify_lines(const std::vector<Mesh>& meshes, const ViewFrame<K>& frame, const Sources<K>& sources,
                          const VisibilityMap<K>& map, const std::vector<IntersectionSegment>& intersections,
                          const LineOptions& options) {
  std::vector<detail::Cover<K>> covers;
  covers.reserve(map.visible.size());
  for (const auto& f : map.visible) covers.push_back({&f.polygon, f.source});
  return detail::classify_against(meshes, frame, sources, std::move(covers), intersections, options);
}

template <class K>
LineSet<K> classify_lines(const std::vector<Mesh>& meshes, const ViewFrame<K>& frame, const Sources<K>& sources,
                          const std::vector<IntersectionSegment>& intersections, const LineOptions& options) {
  std::vector<detail::Cover<K>> covers;
  covers.reserve(sources.polygons.size());
  for (std::uint32_t s = 0; s < sources.polygons.size(); ++s) covers.push_back({&sources.polygons[s].polygon, s});
  return detail::classify_against(meshes, frame, sources, std::move(covers), intersections, options);
}

template <class K>
std::vector<DrawnSegment<K>> drawing_segments(const LineSet<K>& lines, StopToken stop,
                                              const std::vector<std::vector<typename Geometry<K>::Point>>* vertex_images) {
  using G = Geometry<K>;
  using FT = typename G::FT;
  // A piece of a line in precedence order (its parameters read where they are: no lazy numbers
  // copied, and the spans made on every thread).
  struct Span {
    std::uint32_t line;
    const LinePiece<K>* piece;
    bool visible;
    bool thin;
    const FT& t0() const { return piece->t0; }
    const FT& t1() const { return piece->t1; }
  };
  // Each line's image ends; its parameters (detail::ImageLine) are made only for the lines that
  // need them: a large drawing's lines are nearly all drawn whole, alone on their image line.
  struct ImageEnds {
    typename G::Point a, b;
    CGAL::Bbox_2 bbox() const { return G::bbox(a) + G::bbox(b); }
  };
  const std::size_t n = lines.lines.size();
  std::vector<ImageEnds> images(n);
  // One image point per mesh vertex: collinear lines that meet at a vertex then meet at one point
  // (G::identity), and the spans' overlaps there need no exact comparison (ImageLine::param).
  // The sources' points (`vertex_images`), or without them made here, once per vertex.
  std::vector<std::vector<typename G::Point>> own_images;
  if (!vertex_images) {
    std::vector<std::vector<char>> made;
    for (const auto& l : lines.lines) {
      if (!l.has_model_ends) continue;
      if (own_images.size() <= l.mesh) own_images.resize(l.mesh + 1), made.resize(l.mesh + 1);
      auto &points = own_images[l.mesh], &done = made[l.mesh];
      if (points.size() <= std::max(l.v0, l.v1)) points.resize(std::max(l.v0, l.v1) + 1), done.resize(points.size());
      for (const auto& [v, p] : {std::pair{l.v0, &l.a}, std::pair{l.v1, &l.b}})
        if (!done[v]) points[v] = G::point(p->x, p->y), done[v] = 1;
    }
    vertex_images = &own_images;
  }
  parallel_chunks(n, 4096, [&](const auto& range) {
    for (std::size_t i = range.begin(); i != range.end(); ++i) {
      const FeatureLine<K>& l = lines.lines[i];
      if (l.has_model_ends) {
        const auto& points = (*vertex_images)[l.mesh];
        images[i] = {points[l.v0], points[l.v1]};
      } else if constexpr (!G::exact_constructions) {
        images[i] = {G::point(l.a.x, l.a.y), G::point(l.b.x, l.b.y)};
      }
    }
  });
  // The other lines' ends: on the exact kernel, one image point per view point (an intersection
  // line's ends are shared along its curve, classify_lines), which halves them in a large drawing.
  if constexpr (G::exact_constructions) {
    // Each line's place counted, then the ends written there, on every thread.
    std::vector<std::uint32_t> place(n + 1, 0);  // and their count at place[n]
    parallel_chunks(n, 4096, [&](const auto& range) {
      for (std::size_t i = range.begin(); i != range.end(); ++i) place[i] = lines.lines[i].has_model_ends ? 0 : 2;
    });
    std::exclusive_scan(place.begin(), place.end(), place.begin(), 0u);
    std::vector<std::pair<std::array<std::uintptr_t, 2>, std::uint32_t>> shared_ends;  // ((x, y) reps, 2 line + end)
    resize_in_parallel(shared_ends, place[n]);
    parallel_chunks(n, 4096, [&](const auto& range) {
      for (std::size_t i = range.begin(); i != range.end(); ++i) {
        const FeatureLine<K>& l = lines.lines[i];
        if (l.has_model_ends) continue;
        shared_ends[place[i]] = {{std::uintptr_t(l.a.x.id()), std::uintptr_t(l.a.y.id())}, std::uint32_t(2 * i)};
        shared_ends[place[i] + 1] = {{std::uintptr_t(l.b.x.id()), std::uintptr_t(l.b.y.id())}, std::uint32_t(2 * i + 1)};
      }
    });
    detail::for_each_run_of_one_key(shared_ends, 4096, stop, [&](auto run) {
      const std::uint32_t first = run.front().second;
      const ViewPoint<K>& v = first % 2 == 0 ? lines.lines[first / 2].a : lines.lines[first / 2].b;
      const typename G::Point point = G::point(v.x, v.y);
      for (const auto& [xy, end] : run) (end % 2 == 0 ? images[end / 2].a : images[end / 2].b) = point;
    });
  }
  // Whether two lines' images are collinear, decided on their own ends: on the input coordinates
  // where both are mesh edges (exact zeros there are common, and cheap), else on the images.
  auto collinear_lines = [&](std::uint32_t i, std::uint32_t j) {
    const FeatureLine<K>&li = lines.lines[i], &lj = lines.lines[j];
    if (li.has_model_ends && lj.has_model_ends) {
      const Vec3 &ia = lines.model_end(li, 0), &ib = lines.model_end(li, 1);
      const Vec3 &ja = lines.model_end(lj, 0), &jb = lines.model_end(lj, 1);
      if (const auto& e = lines.view_eye) return collinear_seen_from(ia, ib, ja, *e) && collinear_seen_from(ia, ib, jb, *e);
      const Vec3& d = lines.view_direction;
      return collinear_in_view(ia, ib, ja, d) && collinear_in_view(ia, ib, jb, d);
    }
    const ImageEnds &a = images[i], &b = images[j];
    return G::orientation(a.a, a.b, b.a) == 0 && G::orientation(a.a, a.b, b.b) == 0;
  };

  // Spans in precedence order; each loses what earlier, collinear spans already draw.
  // Pieces of one line never overlap. Only spans of collinear lines whose boxes overlap interact,
  // and lines joined by such pairs all lie on one image line (collinearity is exact, so
  // transitive): each such group is solved on its own, in parallel, and the segments gathered in
  // span order are those of one pass over all spans, for any number of threads.
  // A candidate filter in double (it decides nothing): each line's unit direction from the
  // centres of its ends' interval boxes, and a bound on that direction's error. Two lines whose
  // directions' cross product exceeds both bounds are certainly not parallel, so not collinear.
  // A line without one (error HUGE_VAL) goes by its box.
  struct Direction {
    double x, y, error;
  };
  // The large arrays below are made untouched and filled in parallel (or room is kept for them):
  // a large drawing's fresh pages are much of this stage's time, and so are faulted in on every
  // thread. Keys are boxes, whose default constructor writes nothing.
  auto directions = std::make_unique_for_overwrite<Direction[]>(n);
  // Lines are filed by where they lie, not by their boxes, which overlap a great many others in
  // a large drawing: by their angle in (-pi/2, pi/2], their offset from the origin along the
  // normal, and where they lie along their direction, each with a bound on its error, so that
  // collinear lines whose images meet have overlapping keys (a line near the ends of the angle
  // range also at the other end, with the offset and the position negated: the same line seen the
  // other way). The position matters where thousands of lines share one image line, as the hole
  // rims of a plate seen edge-on do: angle and offset alone would pair each with all the others.
  // Lines whose direction is too uncertain go by their boxes.
  using Key = CGAL::Box_intersection_d::Box_with_info_d<double, 3, std::uint32_t, CGAL::Box_intersection_d::ID_NONE>;
  std::vector<Key> keys;
  keys.reserve(2 * std::size_t(n));  // with their mirrors (below), at most one per line
  keys.resize(n);
  std::vector<char> is_uncertain(n, 0);
  constexpr double kHalfTurn = std::numbers::pi;
  auto file = [&](std::uint32_t i) {
    directions[i] = {0, 0, HUGE_VAL};
    if (lines.lines[i].pieces.empty()) return;
    const CGAL::Bbox_2 a = G::bbox(images[i].a), b = G::bbox(images[i].b);
    const double dx = (b.xmin() + b.xmax() - a.xmin() - a.xmax()) / 2, dy = (b.ymin() + b.ymax() - a.ymin() - a.ymax()) / 2;
    const double length = std::hypot(dx, dy);
    // The boxes' widths, and the rounding of the sums above (a few ulps of the coordinates).
    const double magnitude = std::abs(a.xmin()) + std::abs(a.xmax()) + std::abs(b.xmin()) + std::abs(b.xmax()) +
                             std::abs(a.ymin()) + std::abs(a.ymax()) + std::abs(b.ymin()) + std::abs(b.ymax());
    const double spread = (a.xmax() - a.xmin()) + (a.ymax() - a.ymin()) + (b.xmax() - b.xmin()) + (b.ymax() - b.ymin()) +
                          1e-15 * magnitude;
    if (!(length > 0 && std::isfinite(length) && spread < 1e-3 * length)) {
      is_uncertain[i] = 1;
      return;
    }
    const Direction& u = directions[i] = {dx / length, dy / length, 4 * spread / length + 1e-12};
    // The direction within `error` of the true one turns by less than twice that; the offset
    // n·a and the positions u·a, u·b are off by the direction's error times the point's size,
    // the boxes, and rounding.
    const double sign = u.x < 0 || (u.x == 0 && u.y < 0) ? -1 : 1;
    const double px = (a.xmin() + a.xmax()) / 2, py = (a.ymin() + a.ymax()) / 2, size = std::abs(px) + std::abs(py);
    const double qx = (b.xmin() + b.xmax()) / 2, qy = (b.ymin() + b.ymax()) / 2;
    const double size_b = std::abs(qx) + std::abs(qy), size_ab = std::max(size, size_b);
    const double angle = std::atan2(sign * u.y, sign * u.x), offset = sign * (u.x * py - u.y * px);
    const double at_a = sign * (u.x * px + u.y * py), at_b = sign * (u.x * qx + u.y * qy);
    const double angle_error = 2 * u.error, offset_error = 2 * (u.error * size + spread) + 1e-14 * size;
    const double position_error = 2 * (u.error * size_ab + spread) + 1e-14 * size_ab;
    double lo[3] = {angle - angle_error, offset - offset_error, std::min(at_a, at_b) - position_error};
    double hi[3] = {angle + angle_error, offset + offset_error, std::max(at_a, at_b) + position_error};
    keys[i] = Key(lo, hi, i);
  };
  parallel_chunks(n, 4096, [&](const auto& range) {
    for (std::size_t i = range.begin(); i != range.end(); ++i) file(std::uint32_t(i));
  });
  // The keys of lines with a certain direction, moved to the front of `keys`, then their mirrors.
  std::vector<std::uint32_t> uncertain;
  CGAL::Bbox_2 box_domain;
  std::vector<Key> mirrored;
  mirrored.reserve(n);
  std::size_t filed = 0;
  for (std::uint32_t i = 0; i < n; ++i) {
    if (is_uncertain[i]) {
      uncertain.push_back(i);
      box_domain += images[i].bbox();
    } else if (directions[i].error != HUGE_VAL) {
      const Key k = keys[filed++] = keys[i];
      if (k.max_coord(0) >= kHalfTurn / 2 || k.min_coord(0) <= -kHalfTurn / 2) {
        // The same line seen the other way: the angle a half turn on, offset and position negated.
        const double shift = k.max_coord(0) > kHalfTurn / 2 ? -kHalfTurn : kHalfTurn;
        double lo[3] = {k.min_coord(0) + shift, -k.max_coord(1), -k.max_coord(2)};
        double hi[3] = {k.max_coord(0) + shift, -k.min_coord(1), -k.min_coord(2)};
        mirrored.push_back(Key(lo, hi, i));
      }
    }
  }
  keys.resize(filed);
  keys.insert(keys.end(), mirrored.begin(), mirrored.end());
  std::vector<Key>().swap(mirrored);
  // The uncertain lines' boxes filed at once (id k: the line uncertain[k]).
  std::vector<CGAL::Bbox_2> uncertain_boxes(uncertain.size());
  parallel_chunks(uncertain.size(), 4096, [&](const auto& range) {
    for (std::size_t k = range.begin(); k != range.end(); ++k) uncertain_boxes[k] = images[uncertain[k]].bbox();
  });
  const detail::LooseGrid box_grid(box_domain, std::move(uncertain_boxes));
  auto maybe_collinear = [&](std::uint32_t i, std::uint32_t j) {
    const Direction &u = directions[i], &v = directions[j];
    return !(std::abs(u.x * v.y - u.y * v.x) > u.error + v.error) && collinear_lines(i, j);
  };
  // Only lines whose boxes overlap are joined (their spans may interact); every line is asked
  // against the uncertain lines whose boxes overlap its own. The groups are the components of
  // that relation, so a pair already in one group needs no test: thousands of lines on one image
  // line are then joined by about as many tests, not by all their pairs. Each thread keeps its
  // own groups, and the pairs it joined; those pairs then make the groups.
  struct Joined {
    std::optional<UnionFind> groups;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
    std::size_t polls = 0;
  };
  // Looked up per pair: a key of its own makes that a native TLS read.
  tbb::enumerable_thread_specific<Joined, tbb::cache_aligned_allocator<Joined>, tbb::ets_key_per_instance> joined;
  // The double kernel's orientation is not transitive, nor symmetric in the two lines: there every
  // candidate pair is tested, in one order, so that the groups do not depend on which thread
  // meets which pair first.
  constexpr bool transitive = !std::is_same_v<K, DoubleKernel>;
  auto join_if_collinear = [&](Joined& mine, std::uint32_t a, std::uint32_t b) {
    stop.check_every(mine.polls, 4096);
    if (!mine.groups) mine.groups.emplace(n);
    const std::uint32_t i = std::min(a, b), j = std::max(a, b);
    if (i != j && (!transitive || mine.groups->find(i) != mine.groups->find(j)) &&
        CGAL::do_overlap(images[i].bbox(), images[j].bbox()) && maybe_collinear(i, j)) {
      mine.groups->join(i, j);
      mine.pairs.emplace_back(i, j);
    }
  };
  detail::overlapping_box_pairs(keys, 2, [&](const Key& x, const Key& y) {
    join_if_collinear(joined.local(), x.info(), y.info());
  });
  std::vector<Key>().swap(keys);
  if (!uncertain.empty())
    parallel_chunks(n, 4096, [&](const auto& range) {
      Joined& mine = joined.local();
      for (std::uint32_t i = std::uint32_t(range.begin()); i != range.end(); ++i)
        if (!lines.lines[i].pieces.empty())
          box_grid.query(images[i].bbox(), [&](std::uint32_t k) { join_if_collinear(mine, i, uncertain[k]); });
    });
  UnionFind groups(n);
  for (const Joined& mine : joined)
    for (const auto& [i, j] : mine.pairs) groups.join(i, j);
  // What only the joining needed is freed before the spans are listed.
  joined.clear();
  directions.reset();
  std::vector<char>().swap(is_uncertain);

  // ISO 128-20's precedence: visible lines, then hidden ones, then thin continuous ones (the
  // visible pieces of smooth lines); hidden pieces of smooth lines are not drawn (lines.hpp).
  // Spans by pass, then line, then piece: each line's spans of each pass counted, then written
  // in place, on every thread.
  auto pass_of = [](const FeatureLine<K>& l, const LinePiece<K>& p) {
    if (l.kind != FeatureKind::smooth) return p.visible ? 0 : 1;
    return p.visible ? 2 : -1;
  };
  std::vector<std::uint32_t> place(3 * std::size_t(n));  // line i's first span of pass k: place[k n + i]
  parallel_chunks(n, 4096, [&](const auto& range) {
    for (std::size_t i = range.begin(); i != range.end(); ++i) {
      std::uint32_t count[3] = {0, 0, 0};
      for (const auto& p : lines.lines[i].pieces)
        if (const int k = pass_of(lines.lines[i], p); k >= 0) ++count[k];
      for (int k = 0; k < 3; ++k) place[k * n + i] = count[k];
    }
  });
  std::uint32_t span_count = 0;
  for (std::uint32_t& at : place) span_count += std::exchange(at, span_count);
  std::vector<Span> spans;
  resize_in_parallel(spans, span_count);
  parallel_chunks(n, 4096, [&](const auto& range) {
    for (std::size_t i = range.begin(); i != range.end(); ++i) {
      const FeatureLine<K>& l = lines.lines[i];
      std::uint32_t next[3] = {place[i], place[n + i], place[2 * n + i]};
      for (const auto& p : l.pieces)
        if (const int k = pass_of(l, p); k >= 0) spans[next[k]++] = {std::uint32_t(i), &p, p.visible, k == 2};
    }
  });
  std::vector<std::uint32_t>().swap(place);

  // The spans of each group, in span order (group_members from group_start[g]): a counting sort.
  std::vector<std::uint32_t> span_group(spans.size());
  std::uint32_t group_count = 0;
  {
    std::vector<std::int32_t> group_of_root(n, -1);
    for (std::uint32_t s = 0; s < spans.size(); ++s) {
      std::int32_t& g = group_of_root[groups.find(spans[s].line)];
      if (g < 0) g = std::int32_t(group_count++);
      span_group[s] = std::uint32_t(g);
    }
  }
  std::vector<std::uint32_t> group_start(group_count + 1, 0), group_members(spans.size());
  for (std::uint32_t g : span_group) ++group_start[g + 1];
  for (std::uint32_t g = 0; g < group_count; ++g) group_start[g + 1] += group_start[g];
  {
    std::vector<std::uint32_t> next(group_start.begin(), group_start.end() - 1);
    for (std::uint32_t s = 0; s < spans.size(); ++s) group_members[next[span_group[s]]++] = s;
  }
  // A group whose spans all lie on one line draws each of them whole: nearly every group of a large
  // drawing. Its segments go straight to their places; only the other groups are solved apart.
  std::vector<char> group_alone(group_count, 1);
  for (std::uint32_t g = 0; g < group_count; ++g)
    for (std::uint32_t k = group_start[g] + 1; k < group_start[g + 1]; ++k)
      if (spans[group_members[k]].line != spans[group_members[group_start[g]]].line) group_alone[g] = 0;

  // A span of a group whose spans all lie on one line: drawn whole.
  auto whole = [&](std::uint32_t s) {
    const Span& span = spans[s];
    const ImageEnds& ends = images[span.line];
    const FeatureLine<K>& line = lines.lines[span.line];
    const int end0 = detail::ImageLine<K>::exact_end(span.t0()), end1 = detail::ImageLine<K>::exact_end(span.t1());
    std::optional<detail::ImageLine<K>> image;
    if (end0 != 0 || end1 != 1) image.emplace(ends.a, ends.b, line.a, line.b);
    return DrawnSegment<K>{end0 == 0 ? ends.a : image->at(span.t0()), end1 == 1 ? ends.b : image->at(span.t1()),
                           span.visible, line.mesh, line.meeting_degrees, span.line, span.thin, span.t0(), span.t1()};
  };
  // One group of several lines' spans, in order: what each adds to the drawing, with its span index.
  auto solve_group = [&](std::span<const std::uint32_t> members,
                         std::vector<std::pair<std::uint32_t, DrawnSegment<K>>>& emitted) {
    std::vector<DrawnSegment<K>> out;
    std::vector<std::uint32_t> drawn_line;  // parallel to out
    CGAL::Bbox_2 group_domain;
    for (std::uint32_t s : members) group_domain += images[spans[s].line].bbox();
    detail::LooseGrid grid(group_domain, members.size());
    for (std::uint32_t s : members) {
      const Span& span = spans[s];
      const ImageEnds& ends = images[span.line];
      const FeatureLine<K>& line = lines.lines[span.line];
      const int end0 = detail::ImageLine<K>::exact_end(span.t0()), end1 = detail::ImageLine<K>::exact_end(span.t1());
      const detail::ImageLine<K> image(ends.a, ends.b, line.a, line.b);
      const auto a = end0 == 0 ? ends.a : image.at(span.t0()), b = end1 == 1 ? ends.b : image.at(span.t1());
      std::vector<std::pair<FT, FT>> covered;
      grid.query(G::bbox(a) + G::bbox(b), [&](std::uint32_t i) {
        if (drawn_line[i] == span.line) return;
        // On the inexact kernels collinearity need not be transitive (the double kernel decides it
        // in floating point): each pair is asked again.
        if constexpr (!G::exact_constructions)
          if (!collinear_lines(span.line, drawn_line[i])) return;
        FT lo = image.param_by_value(out[i].a), hi = image.param_by_value(out[i].b);
        if (hi < lo) std::swap(lo, hi);
        lo = std::max(lo, span.t0());
        hi = std::min(hi, span.t1());
        if (lo < hi) covered.emplace_back(lo, hi);
      });
      std::sort(covered.begin(), covered.end());
      FT from = span.t0();
      bool at_start = true;  // from is span.t0(), whose point is a
      auto emit = [&](const FT& t0, const FT& t1, bool to_end) {
        const DrawnSegment<K> d{at_start ? a : image.at(t0), to_end ? b : image.at(t1), span.visible, line.mesh,
                                line.meeting_degrees, span.line, span.thin, t0, t1};
        grid.insert(std::uint32_t(out.size()), G::bbox(d.a) + G::bbox(d.b));
        out.push_back(d);
        drawn_line.push_back(span.line);
        emitted.emplace_back(s, d);
      };
      for (const auto& [lo, hi] : covered) {
        if (from < lo) emit(from, lo, false);
        from = std::max(from, hi);
        at_start = false;
      }
      if (from < span.t1()) emit(from, span.t1(), true);
    }
  };
  std::vector<std::uint32_t> shared;  // the groups of more than one line
  for (std::uint32_t g = 0; g < group_count; ++g)
    if (!group_alone[g]) shared.push_back(g);
  std::vector<std::vector<std::pair<std::uint32_t, DrawnSegment<K>>>> emitted(shared.size());
  parallel_chunks(shared.size(), 256, [&](const auto& range) {
    stop.check();
    for (std::size_t k = range.begin(); k != range.end(); ++k) {
      const std::uint32_t g = shared[k];
      solve_group({group_members.data() + group_start[g], group_members.data() + group_start[g + 1]}, emitted[k]);
    }
  });
  // Gathered in span order; a span's segments come from one group, in the order it emitted them.
  std::vector<std::size_t> first(spans.size() + 1, 0);
  for (std::uint32_t s = 0; s < spans.size(); ++s)
    if (group_alone[span_group[s]]) first[s + 1] = 1;
  for (const auto& list : emitted)
    for (const auto& e : list) ++first[e.first + 1];
  for (std::size_t s = 0; s < spans.size(); ++s) first[s + 1] += first[s];
  std::vector<DrawnSegment<K>> out;
  resize_in_parallel(out, first.back());
  parallel_chunks(spans.size(), 4096, [&](const auto& range) {
    stop.check();
    for (std::size_t s = range.begin(); s != range.end(); ++s)
      if (group_alone[span_group[s]]) out[first[s]] = whole(std::uint32_t(s));
  });
  for (auto& list : emitted)
    for (auto& [s, d] : list) out[first[s]++] = std::move(d);
  return out;
}

}  // namespace hlr::hidden_line
