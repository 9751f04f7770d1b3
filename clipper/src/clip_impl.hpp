// The Weiler–Atherton clipper, as a template over the kernel. Included only by the three
// instantiate_*.cpp files.
//
// Weiler and Atherton insert "false vertices" where the two boundaries meet, decide for every
// stretch of boundary between them whether it runs inside or outside the other polygon, and trace
// the output contours by turning at each intersection, traversing clip borders once forwards (inside
// list) and once backwards (outside list). This implementation does the same on an explicit planar
// graph, which makes every degeneracy an ordinary case:
//
//  1. overlay: all boundary edges of subject S and clip C are split at every point where they meet
//     (crossings, vertices on edges, collinear overlaps); coincident points are merged by exact
//     comparison, coincident pieces into one graph edge that remembers how many S and C edges run
//     along it, in which direction, and on which support lines.
//  2. classify: each graph edge learns on which of its sides S and C lie. Along an S edge the S side
//     is known from its direction. Elsewhere it comes from the exact angular order of the edges
//     around a vertex that S's boundary passes through, or, for a stretch that never meets S's
//     boundary, from one exact point-in-polygon test.
//  3. select and trace: an edge bounds the inside list where S∩C differs on its two sides, the
//     outside list where S−C does; it is directed with the result on its left. Cycles are traced
//     with the face rule (turn to the first edge clockwise) and split at repeated vertices so that
//     every contour is simple; counter-clockwise cycles are outer contours, clockwise ones holes,
//     each hole going to the innermost outer contour that contains it.
//
// All decisions are predicates of Geometry<K>; the only construction is the intersection of two
// support lines taken from the input.
#pragma once

#include <hlr/clipper/clipper.hpp>
#include <hlr/kernel/double_orientation.hpp>

#include <algorithm>
#include <numeric>

namespace hlr::clip {
namespace detail {

template <class K>
using Point = typename Geometry<K>::Point;

inline bool boxes_overlap(const CGAL::Bbox_2& a, const CGAL::Bbox_2& b) {
  return a.xmin() <= b.xmax() && b.xmin() <= a.xmax() && a.ymin() <= b.ymax() && b.ymin() <= a.ymax();
}

template <class K>
CGAL::Bbox_2 contour_box(const Contour<K>& c) {
  CGAL::Bbox_2 box;
  for (const auto& p : c.points) box += Geometry<K>::bbox(p);
  return box;
}

// q is collinear with a, b: is it strictly between them?
template <class K>
bool strictly_between(const Point<K>& a, const Point<K>& b, const Point<K>& q) {
  using G = Geometry<K>;
  return G::compare_xy(a, q) * G::compare_xy(q, b) > 0;
}

// +1 when q is inside the contour's bounded region, 0 on its boundary, -1 outside. With
// `on_line`, q lies on a line and on_line[i] is 0 where corner i does (side_of_polygon_on_line).
template <class K>
int side_of_contour(const Contour<K>& contour, const Point<K>& q, const int* on_line = nullptr) {
  using G = Geometry<K>;
  const auto& pts = contour.points;
  const std::size_t n = pts.size();
  bool inside = false;
  // Each corner's height against q, compared once: as the end of one edge, then the start of the next.
  const int y_first = G::compare_y(pts[0], q);
  int yb = y_first;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = i + 1 == n ? 0 : i + 1;
    const Point<K>& a = pts[i];
    const Point<K>& b = pts[j];
    const int ya = yb;
    yb = j == 0 ? y_first : G::compare_y(b, q);
    if (ya > 0 && yb > 0) continue;
    if (ya < 0 && yb < 0) continue;
    const bool along_line = G::exact_constructions && on_line && on_line[i] == 0 && on_line[j] == 0;
    const int o = along_line ? 0 : G::orientation(a, b, q);
    if (o == 0 && G::compare_xy(a, q) * G::compare_xy(q, b) >= 0) return 0;
    // Half-open rule: a vertex at q's height counts as below.
    if ((ya > 0) != (yb > 0)) {
      if (yb > 0 ? o > 0 : o < 0) inside = !inside;
    }
  }
  return inside ? 1 : -1;
}

}  // namespace detail

// +1 inside the polygon (inside the outer contour, outside every hole), 0 on its boundary, -1
// outside. Public (clipper.hpp); the overlay below uses it too.
template <class K>
int side_of_polygon(const Polygon<K>& polygon, const typename Geometry<K>::Point& q) {
  int s = detail::side_of_contour(polygon.outer, q);
  if (s <= 0) return s;
  for (const auto& hole : polygon.holes) {
    int h = detail::side_of_contour(hole, q);
    if (h == 0) return 0;
    if (h > 0) return -1;
  }
  return 1;
}

template <class K>
int side_of_polygon_on_line(const Contour<K>& outer, std::span<const Contour<K>* const> holes,
                            std::span<const int> corner_sides, const typename Geometry<K>::Point& q) {
  const int* sides = corner_sides.empty() ? nullptr : corner_sides.data();
  const int s = detail::side_of_contour(outer, q, sides);
  if (s <= 0) return s;
  if (sides) sides += outer.size();
  for (const Contour<K>* hole : holes) {
    const int h = detail::side_of_contour(*hole, q, sides);
    if (h == 0) return 0;
    if (h > 0) return -1;
    if (sides) sides += hole->size();
  }
  return 1;
}

namespace detail {

template <class K>
int contour_orientation(const std::vector<Point<K>>& pts) {
  using G = Geometry<K>;
  const std::size_t n = pts.size();
  std::size_t m = 0;
  for (std::size_t i = 1; i < n; ++i)
    if (G::compare_xy(pts[i], pts[m]) < 0) m = i;
  return G::orientation(pts[(m + n - 1) % n], pts[m], pts[(m + 1) % n]);
}

template <class K>
void reverse_contour(Contour<K>& c) {
  const std::size_t n = c.points.size();
  std::reverse(c.points.begin(), c.points.end());
  std::vector<LineId> lines(n);
  // The edge q[j] -> q[j+1] of the reversed contour is the input edge p[n-2-j] -> p[n-1-j].
  for (std::size_t j = 0; j < n; ++j) lines[j] = c.lines[(2 * n - 2 - j) % n];
  c.lines = std::move(lines);
}

// One boundary edge entering the overlay.
struct InputEdge {
  std::uint32_t a, b;  // raw point indices
  LineId line;
  std::uint8_t role;  // 0 subject, 1 clip
  std::uint32_t contour;
  CGAL::Bbox_2 box;
  LineId line_at_a = 0, line_at_b = 0;  // the lines of the contour's edges before and after this one
  // The ends' coordinates when both are doubles (exact kernel): the pair test's orientations are
  // then decided on these, without reading the points' intervals.
  bool doubles = false;
  double ax = 0, ay = 0, bx = 0, by = 0;
};

// An edge's box as the sweep reads it: the boxes sit side by side in x order, so the inner loop
// reads memory in sequence instead of following indices into the edges.
struct SweepBox {
  double xmin, xmax, ymin, ymax;
  std::uint32_t group;  // the edge's role and contour
  std::uint32_t index;  // into the edges
};

struct SweepBuffers {
  std::vector<SweepBox> boxes;
  std::vector<std::uint32_t> partners;
};

// Calls visit(i, j) for every pair of edges whose boxes overlap (sweep over x), in the order of
// their smaller x. With `across_contours_only`, pairs of edges of one contour are not visited.
template <bool across_contours_only, class Visit>
void for_each_overlapping_pair(const std::vector<InputEdge>& edges, SweepBuffers& buffers, Visit&& visit) {
  std::vector<SweepBox>& sweep = buffers.boxes;
  sweep.clear();
  sweep.reserve(edges.size());
  for (std::uint32_t i = 0; i < edges.size(); ++i) {
    const InputEdge& e = edges[i];
    sweep.push_back({e.box.xmin(), e.box.xmax(), e.box.ymin(), e.box.ymax(), (std::uint32_t(e.role) << 31) | e.contour, i});
  }
  std::sort(sweep.begin(), sweep.end(),
            [](const SweepBox& a, const SweepBox& b) { return a.xmin != b.xmin ? a.xmin < b.xmin : a.index < b.index; });
  // The partners of one box are gathered without branching on y (which overlaps unpredictably),
  // then visited.
  const std::size_t n = sweep.size();
  std::vector<std::uint32_t>& partners = buffers.partners;
  partners.resize(n);
  for (std::size_t s = 0; s < n; ++s) {
    const SweepBox& e = sweep[s];
    std::size_t found = 0;
    for (std::size_t t = s + 1; t < n; ++t) {
      const SweepBox& f = sweep[t];
      if (f.xmin > e.xmax) break;
      partners[found] = f.index;
      found += (f.ymin <= e.ymax) & (e.ymin <= f.ymax) & (!across_contours_only || f.group != e.group);
    }
    for (std::size_t k = 0; k < found; ++k) visit(e.index, partners[k]);
  }
}

// A raw point's intervals, as the exact kernel keeps them.
struct IntervalBox {
  CGAL::Interval_nt<false> x, y;
  std::uint32_t point;
};

// compare_xy on the intervals alone (the kernel's compare_intervals on x, then on y): -1 or +1
// where they decide, 0 when both are the same point of doubles, 2 when only the exact values can tell.
template <class G>
int compare_xy_intervals(const IntervalBox& a, const IntervalBox& b) {
  const int c = G::compare_intervals(a.x, b.x);
  return c != 0 ? c : G::compare_intervals(a.y, b.y);
}

// Puts `items` into `out` in order of key(item) < buckets, stably, by counting; the items of
// bucket b are out[start[b] .. start[b + 1]).
template <class T, class Key>
void bucket_by(const std::vector<T>& items, std::size_t buckets, Key key, std::vector<std::uint32_t>& start,
               std::vector<T>& out, std::vector<std::uint32_t>& fill) {
  start.assign(buckets + 1, 0);
  for (const T& item : items) ++start[key(item) + 1];
  for (std::size_t b = 0; b < buckets; ++b) start[b + 1] += start[b];
  fill.assign(start.begin(), start.end() - 1);
  out.resize(items.size());
  for (const T& item : items) out[fill[key(item)]++] = item;
}

// Union-find over graph edges.
struct Groups {
  std::vector<std::uint32_t> parent;
  void reset(std::size_t n) {
    parent.resize(n);
    std::iota(parent.begin(), parent.end(), 0u);
  }
  std::uint32_t find(std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void join(std::uint32_t a, std::uint32_t b) { parent[find(a)] = find(b); }
};

// An undirected edge of the overlay, stored from its lower vertex (lo) to its higher one (hi).
struct GraphEdge {
  std::uint32_t lo, hi;
  std::int32_t net[2];     // per role: edges running lo->hi minus edges running hi->lo
  bool has[2];             // per role: does any input edge run along it
  LineId line[2];          // per role: a support line it lies on
  std::int8_t left[2];     // per role: is the role's polygon on the left of lo->hi (-1 unknown)
  std::int8_t right[2];
};

template <class K>
class Overlay {
  using G = Geometry<K>;
  using P = Point<K>;

 public:
  ClipResult<K> run(const Polygon<K>& subject, const ClipRegion<K>& clip);
  std::vector<Polygon<K>> merge(std::span<const Contour<K>> pieces, const LineTable<K>& lines);
  // Lets go of the points of the last run; the buffers keep their capacity unless it grew large.
  void release();

 private:
  void add_polygon(const Polygon<K>& polygon, std::uint8_t role, const CGAL::Bbox_2* filter);
  void add_contour(const Contour<K>& contour, std::uint8_t role, std::uint32_t contour_id,
                   const CGAL::Bbox_2* filter);
  void intersect_edges();
  void test_pair(std::uint32_t i, std::uint32_t j);
  void build_graph();
  void sort_rings();
  void classify(int role, const Polygon<K>& polygon);
  std::vector<Polygon<K>> trace(std::uint8_t list_bit);

  int net_out(std::uint32_t he, int role) const {
    const GraphEdge& e = graph_[he >> 1];
    return (he & 1) ? -e.net[role] : e.net[role];
  }
  std::uint32_t origin(std::uint32_t he) const { return (he & 1) ? graph_[he >> 1].hi : graph_[he >> 1].lo; }
  std::uint32_t target(std::uint32_t he) const { return (he & 1) ? graph_[he >> 1].lo : graph_[he >> 1].hi; }

  const LineTable<K>* lines_ = nullptr;
  CrossingCache<K>* crossings_ = nullptr;
  std::vector<P> raw_;                 // input vertices, then constructed intersections
  std::vector<InputEdge> edges_;
  struct Split {
    std::uint32_t edge, point;  // a raw point on the edge's interior
  };
  std::vector<Split> splits_, sorted_splits_;
  std::vector<std::uint32_t> split_start_;  // per edge, into sorted_splits_
  SweepBuffers sweep_;
  std::vector<std::uint32_t> order_;   // raw points in xy order (inexact kernels)
  std::vector<IntervalBox> approx_;    // the same on the exact kernel
  std::vector<std::uint32_t> canon_;   // raw point -> vertex
  std::vector<P> vertices_;
  struct Piece {
    std::uint32_t lo, hi;
    std::int8_t dir;  // +1 when the input edge runs lo->hi
    std::uint8_t role;
    LineId line;
  };
  std::vector<Piece> pieces_, sorted_pieces_;
  std::vector<std::uint32_t> piece_start_;  // per vertex, into sorted_pieces_ (by lo)
  std::vector<GraphEdge> graph_;
  std::vector<std::uint32_t> ring_start_, ring_, pos_;  // half-edges around each vertex, CCW
  std::vector<std::uint8_t> upper_;                    // per half-edge: points into the upper half-plane
  std::vector<std::uint8_t> result_;   // per half-edge: bit 0 inside list, bit 1 outside list
  // Working memory of single steps, kept for its capacity.
  std::vector<std::uint32_t> scratch_;
  Groups groups_;
  std::vector<std::int8_t> group_value_;
  std::vector<std::int32_t> on_path_;
  std::vector<std::uint8_t> used_;
};

template <class K>
void Overlay<K>::add_contour(const Contour<K>& c, std::uint8_t role, std::uint32_t contour_id,
                             const CGAL::Bbox_2* filter) {
  const std::uint32_t base = static_cast<std::uint32_t>(raw_.size());
  const std::uint32_t n = static_cast<std::uint32_t>(c.points.size());
  for (const auto& p : c.points) raw_.push_back(p);
  const CGAL::Bbox_2 first_box = G::bbox(c.points[0]);
  CGAL::Bbox_2 box_a = first_box;
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t j = i + 1 == n ? 0 : i + 1;
    const CGAL::Bbox_2 box_b = j == 0 ? first_box : G::bbox(c.points[j]);
    const CGAL::Bbox_2 box = box_a + box_b;
    box_a = box_b;
    // A clip edge that cannot reach the subject's box can neither cut it nor bound a result.
    if (filter && !boxes_overlap(box, *filter)) continue;
    InputEdge& e = edges_.emplace_back(
        InputEdge{base + i, base + j, c.lines[i], role, contour_id, box, c.lines[i == 0 ? n - 1 : i - 1], c.lines[j]});
    if constexpr (G::exact_constructions) {
      const auto &a = CGAL::approx(c.points[i]), &b = CGAL::approx(c.points[j]);
      if (G::is_double(a) && G::is_double(b)) {
        e.doubles = true;
        e.ax = a.x().inf(), e.ay = a.y().inf(), e.bx = b.x().inf(), e.by = b.y().inf();
      }
    }
  }
}

template <class K>
void Overlay<K>::add_polygon(const Polygon<K>& polygon, std::uint8_t role, const CGAL::Bbox_2* filter) {
  add_contour(polygon.outer, role, 0, filter);
  for (std::size_t h = 0; h < polygon.holes.size(); ++h)
    add_contour(polygon.holes[h], role, static_cast<std::uint32_t>(h + 1), filter);
}

template <class K>
void Overlay<K>::test_pair(std::uint32_t i, std::uint32_t j) {
  const InputEdge& e = edges_[i];
  const InputEdge& f = edges_[j];
  const P& p1 = raw_[e.a];
  const P& p2 = raw_[e.b];
  const P& q1 = raw_[f.a];
  const P& q2 = raw_[f.b];
  // The orientation of `other`'s end (a or b) seen from `edge`. An endpoint lies on its own edge's
  // line and on the line of the edge that meets it there (corner_on_line); on the exact kernel
  // those orientations are 0 without arithmetic.
  auto orientation = [](const InputEdge& edge, const P& a, const P& b, const InputEdge& other, bool at_b, const P& q) {
    if constexpr (G::exact_constructions) {
      if (other.line == edge.line || (at_b ? other.line_at_b : other.line_at_a) == edge.line) return 0;
      if (edge.doubles && other.doubles) {
        const int o = orientation_of_doubles(edge.ax, edge.ay, edge.bx, edge.by, at_b ? other.bx : other.ax,
                                             at_b ? other.by : other.ay);
        if (o != 2) {
          PredicateStats::add(PredicateFamily::orientation, DecidedBy::interval);
          return o;
        }
      }
    }
    return G::orientation(a, b, q);
  };
  const int o1 = orientation(e, p1, p2, f, false, q1);
  const int o2 = orientation(e, p1, p2, f, true, q2);
  if (o1 * o2 > 0) return;
  const int o3 = orientation(f, q1, q2, e, false, p1);
  const int o4 = orientation(f, q1, q2, e, true, p2);
  if (o3 * o4 > 0) return;
  if (o1 != 0 && o2 != 0 && o3 != 0 && o4 != 0) {
    if (e.role == f.role) throw ClipError("contours of one polygon cross each other");
    const SupportLine<K>& l1 = (*lines_)[e.line];
    const SupportLine<K>& l2 = (*lines_)[f.line];
    const std::uint32_t x = static_cast<std::uint32_t>(raw_.size());
    try {
      raw_.push_back(crossings_ ? crossings_->crossing(e.line, f.line, *lines_)
                                : G::line_intersection(l1.a, l1.b, l2.a, l2.b));
    } catch (const std::runtime_error&) {
      // Exact predicates never call parallel lines crossing; rounded constructions can.
      throw ClipError("crossing edges lie on parallel lines");
    }
    splits_.push_back({i, x});
    splits_.push_back({j, x});
    return;
  }
  // Touching or collinear: every endpoint lying strictly inside the other edge splits it.
  if (o1 == 0 && strictly_between<K>(p1, p2, q1)) splits_.push_back({i, f.a});
  if (o2 == 0 && strictly_between<K>(p1, p2, q2)) splits_.push_back({i, f.b});
  if (o3 == 0 && strictly_between<K>(q1, q2, p1)) splits_.push_back({j, e.a});
  if (o4 == 0 && strictly_between<K>(q1, q2, p2)) splits_.push_back({j, e.b});
}

template <class K>
void Overlay<K>::intersect_edges() {
  // A valid contour is simple: its own edges meet only at shared vertices.
  for_each_overlapping_pair<true>(edges_, sweep_, [&](std::uint32_t i, std::uint32_t j) { test_pair(i, j); });
}

// Merges coincident points, cuts every edge at its split points and merges coincident pieces.
template <class K>
void Overlay<K>::build_graph() {
  // 1. vertices: raw points up to exact equality.
  canon_.assign(raw_.size(), 0);
  vertices_.clear();
  if constexpr (G::exact_constructions) {
    // Sorted on the points' intervals side by side rather than through each point's handle; the
    // kernel is asked only where they cannot decide.
    approx_.resize(raw_.size());
    for (std::uint32_t i = 0; i < raw_.size(); ++i) {
      const auto& a = CGAL::approx(raw_[i]);
      approx_[i] = {a.x(), a.y(), i};
    }
    auto compare = [&](const IntervalBox& a, const IntervalBox& b) {
      const int c = compare_xy_intervals<G>(a, b);
      if (c != 2) {
        PredicateStats::add(PredicateFamily::comparison, DecidedBy::interval);
        return c;
      }
      return G::compare_xy(raw_[a.point], raw_[b.point]);
    };
    std::sort(approx_.begin(), approx_.end(), [&](const IntervalBox& a, const IntervalBox& b) { return compare(a, b) < 0; });
    for (std::size_t k = 0; k < approx_.size(); ++k) {
      if (k == 0 || compare(approx_[k - 1], approx_[k]) != 0) vertices_.push_back(raw_[approx_[k].point]);
      canon_[approx_[k].point] = static_cast<std::uint32_t>(vertices_.size() - 1);
    }
  } else {
    order_.resize(raw_.size());
    std::iota(order_.begin(), order_.end(), 0u);
    std::sort(order_.begin(), order_.end(),
              [&](std::uint32_t a, std::uint32_t b) { return G::compare_xy(raw_[a], raw_[b]) < 0; });
    for (std::size_t k = 0; k < order_.size(); ++k) {
      if (k == 0 || !G::equal(raw_[order_[k]], vertices_.back())) vertices_.push_back(raw_[order_[k]]);
      canon_[order_[k]] = static_cast<std::uint32_t>(vertices_.size() - 1);
    }
  }
  // Vertex ids follow xy order, so comparing ids compares points.

  // 2. pieces: each edge cut at its split points, in order along the edge.
  bucket_by(splits_, edges_.size(), [](const Split& s) { return s.edge; }, split_start_, sorted_splits_, scratch_);
  pieces_.clear();
  std::vector<std::uint32_t>& cuts = scratch_;
  for (std::uint32_t i = 0; i < edges_.size(); ++i) {
    const InputEdge& e = edges_[i];
    cuts.clear();
    cuts.push_back(canon_[e.a]);
    for (std::uint32_t k = split_start_[i]; k < split_start_[i + 1]; ++k) cuts.push_back(canon_[sorted_splits_[k].point]);
    cuts.push_back(canon_[e.b]);
    const bool ascending = cuts.front() < cuts.back();
    if (ascending) std::sort(cuts.begin(), cuts.end());
    else std::sort(cuts.begin(), cuts.end(), std::greater<>());
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
      const std::uint32_t u = cuts[k], v = cuts[k + 1];
      pieces_.push_back({std::min(u, v), std::max(u, v), static_cast<std::int8_t>(u < v ? 1 : -1), e.role, e.line});
    }
  }

  // 3. graph edges: coincident pieces merged. Pieces are put in order of lo by counting, then each
  // vertex's few in order of hi.
  bucket_by(pieces_, vertices_.size(), [](const Piece& p) { return p.lo; }, piece_start_, sorted_pieces_, scratch_);
  for (std::size_t v = 0; v + 1 < piece_start_.size(); ++v)
    if (piece_start_[v + 1] - piece_start_[v] > 1)
      std::sort(sorted_pieces_.begin() + piece_start_[v], sorted_pieces_.begin() + piece_start_[v + 1],
                [](const Piece& a, const Piece& b) { return a.hi < b.hi; });
  graph_.clear();
  for (const Piece& p : sorted_pieces_) {
    if (graph_.empty() || graph_.back().lo != p.lo || graph_.back().hi != p.hi)
      graph_.push_back({p.lo, p.hi, {0, 0}, {false, false}, {0, 0}, {-1, -1}, {-1, -1}});
    GraphEdge& g = graph_.back();
    if (!g.has[p.role]) g.line[p.role] = p.line;
    g.has[p.role] = true;
    g.net[p.role] += p.dir;
  }
}

// Sorts the half-edges around every vertex counter-clockwise, starting from the direction +x.
template <class K>
void Overlay<K>::sort_rings() {
  const std::uint32_t nv = static_cast<std::uint32_t>(vertices_.size());
  ring_start_.assign(nv + 1, 0);
  for (const GraphEdge& e : graph_) {
    ++ring_start_[e.lo + 1];
    ++ring_start_[e.hi + 1];
  }
  for (std::uint32_t v = 0; v < nv; ++v) ring_start_[v + 1] += ring_start_[v];
  ring_.resize(2 * graph_.size());
  std::vector<std::uint32_t>& fill = scratch_;
  fill.assign(ring_start_.begin(), ring_start_.end() - 1);
  for (std::uint32_t he = 0; he < 2 * graph_.size(); ++he) ring_[fill[origin(he)]++] = he;

  pos_.resize(2 * graph_.size());
  upper_.resize(2 * graph_.size());
  for (std::uint32_t v = 0; v < nv; ++v) {
    auto first = ring_.begin() + ring_start_[v], last = ring_.begin() + ring_start_[v + 1];
    // Two edges are in cyclic order whichever comes first.
    if (last - first > 2) {
      const P& o = vertices_[v];
      // Upper half-plane: angle in [0, pi). Within a half, by orientation. Vertex ids follow xy
      // order, so a target with a higher id lies in the upper half exactly when it is not level.
      for (auto it = first; it != last; ++it) {
        const std::uint32_t t = target(*it);
        const int cy = G::compare_y(vertices_[t], o);
        upper_[*it] = cy > 0 || (cy == 0 && t > v);
      }
      std::sort(first, last, [&](std::uint32_t h1, std::uint32_t h2) {
        if (upper_[h1] != upper_[h2]) return upper_[h1] > upper_[h2];
        return G::orientation(o, vertices_[target(h1)], vertices_[target(h2)]) > 0;
      });
    }
    for (std::uint32_t k = ring_start_[v]; k < ring_start_[v + 1]; ++k) pos_[ring_[k]] = k;
  }
}

// Decides, for every graph edge, whether `polygon` (the one of `role`) lies on its left and right.
template <class K>
void Overlay<K>::classify(int role, const Polygon<K>& polygon) {
  const std::uint32_t nv = static_cast<std::uint32_t>(vertices_.size());
  // Along the polygon's own boundary the direction says it.
  for (GraphEdge& e : graph_) {
    if (e.net[role] == 0) continue;
    if (e.net[role] > 1 || e.net[role] < -1) throw ClipError("boundary edges of one polygon overlap");
    e.left[role] = e.net[role] > 0;
    e.right[role] = e.net[role] < 0;
  }
  // Around a vertex on the polygon's boundary, membership changes only across its boundary edges:
  // the sector counter-clockwise of an outgoing boundary edge is inside.
  Groups& groups = groups_;
  groups.reset(graph_.size());
  for (std::uint32_t v = 0; v < nv; ++v) {
    const std::uint32_t first = ring_start_[v], last = ring_start_[v + 1], deg = last - first;
    bool touched = false, needed = false;
    std::uint32_t start = deg;
    for (std::uint32_t k = 0; k < deg; ++k) {
      const std::uint32_t he = ring_[first + k];
      touched |= graph_[he >> 1].has[role];
      needed |= graph_[he >> 1].net[role] == 0;
      if (start == deg && net_out(he, role) != 0) start = k;
    }
    if (!touched) {
      // Membership is the same all around v: one group.
      for (std::uint32_t k = 1; k < deg; ++k) groups.join(ring_[first] >> 1, ring_[first + k] >> 1);
      continue;
    }
    // Only edges off the boundary need the walk. Where there are none, v may lie outside the
    // subject's box, where clip edges were left out and the ring is incomplete.
    if (!needed) continue;
    // Boundary edges that cancel (a hole touching the outer along an edge) leave the polygon outside.
    int w = start == deg ? 0 : (net_out(ring_[first + start], role) > 0 ? 1 : 0);
    if (start == deg) start = 0;
    for (std::uint32_t j = 1; j < deg; ++j) {
      const std::uint32_t he = ring_[first + (start + j) % deg];
      GraphEdge& e = graph_[he >> 1];
      if (e.net[role] == 0) {
        e.left[role] = e.right[role] = static_cast<std::int8_t>(w);
      } else {
        w += net_out(he, role);
        if (w < 0 || w > 1) throw ClipError("inconsistent boundary orientation around a vertex");
      }
    }
  }
  // Edges that never meet the boundary: one group shares one answer.
  std::vector<std::int8_t>& group_value = group_value_;
  group_value.assign(graph_.size(), -1);
  for (std::uint32_t k = 0; k < graph_.size(); ++k)
    if (graph_[k].left[role] >= 0 && graph_[k].net[role] == 0) group_value[groups.find(k)] = graph_[k].left[role];
  for (std::uint32_t k = 0; k < graph_.size(); ++k) {
    GraphEdge& e = graph_[k];
    if (e.left[role] >= 0) continue;
    std::int8_t& value = group_value[groups.find(k)];
    if (value < 0) {
      int side = side_of_polygon(polygon, vertices_[e.lo]);
      if (side == 0) side = side_of_polygon(polygon, vertices_[e.hi]);
      if (side == 0) side = side_of_polygon(polygon, G::midpoint(vertices_[e.lo], vertices_[e.hi]));
      if (side == 0) throw ClipError("cannot place an edge inside or outside the other polygon");
      value = side > 0;
    }
    e.left[role] = e.right[role] = value;
  }
}

// Traces the contours of one result list and assembles polygons with holes.
template <class K>
std::vector<Polygon<K>> Overlay<K>::trace(std::uint8_t bit) {
  std::vector<Polygon<K>> polygons;  // an outer contour each, holes added at the end
  std::vector<Contour<K>> holes;
  std::vector<std::int32_t>& on_path = on_path_;
  on_path.assign(vertices_.size(), -1);
  std::vector<std::uint32_t>& path = scratch_;  // half-edges of the walk so far
  std::vector<std::uint8_t>& used = used_;
  used.assign(result_.size(), 0);

  auto emit = [&](std::size_t from) {
    Contour<K> c;
    c.points.reserve(path.size() - from);
    c.lines.reserve(path.size() - from);
    for (std::size_t k = from; k < path.size(); ++k) {
      const std::uint32_t he = path[k];
      const GraphEdge& e = graph_[he >> 1];
      const LineId line = e.has[0] ? e.line[0] : e.line[1];
      // A vertex where the contour runs on along the same line is no corner.
      if (!c.lines.empty() && c.lines.back() == line) continue;
      c.points.push_back(vertices_[origin(he)]);
      c.lines.push_back(line);
    }
    for (std::size_t k = from; k < path.size(); ++k) on_path[origin(path[k])] = -1;
    path.resize(from);
    if (c.points.size() > 1 && c.lines.front() == c.lines.back()) {
      c.points.erase(c.points.begin());
      c.lines.erase(c.lines.begin());
    }
    if (c.points.size() < 3) throw ClipError("traced a degenerate contour");
    if (contour_orientation<K>(c.points) > 0) polygons.emplace_back().outer = std::move(c);
    else holes.push_back(std::move(c));
  };

  for (std::uint32_t start = 0; start < result_.size(); ++start) {
    if (!(result_[start] & bit) || used[start]) continue;
    std::uint32_t he = start;
    path.clear();
    while (true) {
      used[he] = 1;
      on_path[origin(he)] = static_cast<std::int32_t>(path.size());
      path.push_back(he);
      const std::uint32_t v = target(he);
      // Face rule: the next edge is the first result edge clockwise from the way back.
      const std::uint32_t first = ring_start_[v], deg = ring_start_[v + 1] - first;
      const std::uint32_t back = pos_[he ^ 1] - first;
      std::uint32_t next = UINT32_MAX;
      for (std::uint32_t step = 1, k = back; step < deg; ++step) {
        k = k == 0 ? deg - 1 : k - 1;
        const std::uint32_t cand = ring_[first + k];
        if (result_[cand] & bit) {
          next = cand;
          break;
        }
      }
      if (next == UINT32_MAX) throw ClipError("result boundary is not closed");
      // Back at a vertex of the walk: what lies between is a simple cycle of its own.
      if (on_path[v] >= 0) emit(static_cast<std::size_t>(on_path[v]));
      if (used[next]) {
        if (next != start || !path.empty()) throw ClipError("result boundary is inconsistent");
        break;
      }
      he = next;
    }
  }

  // Holes go to the innermost outer contour that contains them. Result contours never cross, so
  // of two outer contours that both contain a hole, one lies inside the other.
  // The outer contours' boxes are needed only to choose among several for a hole.
  std::vector<CGAL::Bbox_2> boxes(holes.empty() || polygons.size() < 2 ? 0 : polygons.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) boxes[i] = contour_box(polygons[i].outer);
  // Where `inner` lies relative to `outer`, judged on its first vertex off that contour; the
  // midpoint of an edge if all its vertices are on it.
  auto contains = [&](const Contour<K>& outer, const Contour<K>& inner) {
    int side = 0;
    for (std::size_t k = 0; k < inner.points.size() && side == 0; ++k) side = side_of_contour(outer, inner.points[k]);
    for (std::size_t k = 0; k < inner.points.size() && side == 0; ++k)
      side = side_of_contour(outer, G::midpoint(inner.points[k], inner.points[(k + 1) % inner.points.size()]));
    return side > 0;
  };
  auto box_inside = [](const CGAL::Bbox_2& in, const CGAL::Bbox_2& out) {
    return in.xmin() >= out.xmin() && in.xmax() <= out.xmax() && in.ymin() >= out.ymin() && in.ymax() <= out.ymax();
  };
  for (Contour<K>& hole : holes) {
    std::size_t best = polygons.size() == 1 ? 0 : SIZE_MAX;
    if (best == SIZE_MAX) {
      const CGAL::Bbox_2 hb = contour_box(hole);
      for (std::size_t i = 0; i < polygons.size(); ++i) {
        if (!box_inside(hb, boxes[i]) || !contains(polygons[i].outer, hole)) continue;
        if (best == SIZE_MAX || (box_inside(boxes[i], boxes[best]) && contains(polygons[best].outer, polygons[i].outer)))
          best = i;
      }
    }
    if (best == SIZE_MAX) throw ClipError("a hole of the result lies in no outer contour");
    polygons[best].holes.push_back(std::move(hole));
  }
  return polygons;
}

template <class K>
ClipResult<K> Overlay<K>::run(const Polygon<K>& subject, const ClipRegion<K>& clip) {
  const auto& prepared = clip.prepared();
  const Polygon<K>& clip_polygon = clip.polygon();
  lines_ = prepared.lines;
  crossings_ = prepared.crossings;
  ClipResult<K> result;

  const CGAL::Bbox_2 subject_box = contour_box(subject.outer);
  if (!boxes_overlap(subject_box, prepared.box)) {
    result.outside.push_back(subject);
    return result;
  }
  raw_.clear();
  edges_.clear();
  splits_.clear();
  add_polygon(subject, 0, nullptr);
  const std::size_t subject_edges = edges_.size();
  add_polygon(clip_polygon, 1, &subject_box);
  if (edges_.size() == subject_edges) {
    // The clip boundary stays away from the subject: it is wholly inside or wholly outside.
    const int side = side_of_polygon(clip_polygon, subject.outer.points.front());
    (side > 0 ? result.inside : result.outside).push_back(subject);
    return result;
  }

  intersect_edges();
  build_graph();
  sort_rings();
  classify(0, subject);
  classify(1, clip_polygon);

  result_.assign(2 * graph_.size(), 0);
  for (std::uint32_t k = 0; k < graph_.size(); ++k) {
    const GraphEdge& e = graph_[k];
    const bool in_l = e.left[0] && e.left[1], in_r = e.right[0] && e.right[1];
    const bool out_l = e.left[0] && !e.left[1], out_r = e.right[0] && !e.right[1];
    if (in_l != in_r) result_[in_l ? 2 * k : 2 * k + 1] |= 1;
    if (out_l != out_r) result_[out_l ? 2 * k : 2 * k + 1] |= 2;
  }
  result.inside = trace(1);
  result.outside = trace(2);
  return result;
}

// The union of a tessellation: an edge bounds it where the pieces along it do not cancel out.
template <class K>
std::vector<Polygon<K>> Overlay<K>::merge(std::span<const Contour<K>> pieces, const LineTable<K>& lines) {
  lines_ = &lines;
  raw_.clear();
  edges_.clear();
  splits_.clear();
  for (std::size_t i = 0; i < pieces.size(); ++i) add_contour(pieces[i], 0, static_cast<std::uint32_t>(i), nullptr);
  intersect_edges();
  build_graph();
  sort_rings();
  result_.assign(2 * graph_.size(), 0);
  for (std::uint32_t k = 0; k < graph_.size(); ++k) {
    const int net = graph_[k].net[0];
    if (net > 1 || net < -1) throw ClipError("pieces of a tessellation overlap");
    if (net != 0) result_[net > 0 ? 2 * k : 2 * k + 1] = 1;
  }
  return trace(1);
}

template <class K>
void Overlay<K>::release() {
  // Past this many input points a buffer is returned rather than kept for the next call.
  constexpr std::size_t kept_points = std::size_t{1} << 16;
  if (raw_.capacity() > kept_points) {
    *this = Overlay();
    return;
  }
  raw_.clear();
  vertices_.clear();
}

// Calls use(overlay) with this thread's overlay. Its buffers outlive the call, so a clip allocates
// little more than its result: small clips (the area sort's triangles) would otherwise spend a
// third of their time in malloc and free.
template <class K, class Use>
decltype(auto) with_overlay(Use&& use) {
  thread_local Overlay<K> overlay;
  struct Release {
    Overlay<K>& overlay;
    ~Release() { overlay.release(); }
  } release{overlay};
  return use(overlay);
}

}  // namespace detail

template <class K>
std::vector<Polygon<K>> merge_polygons(std::span<const Contour<K>> pieces, const LineTable<K>& lines) {
  return detail::with_overlay<K>([&](detail::Overlay<K>& overlay) { return overlay.merge(pieces, lines); });
}

template <class K>
struct ClipRegion<K>::Prepared {
  Polygon<K> polygon;
  const LineTable<K>* lines;
  CrossingCache<K>* crossings;
  CGAL::Bbox_2 box;
};

template <class K>
ClipRegion<K>::ClipRegion(Polygon<K> polygon, const LineTable<K>& lines, CrossingCache<K>* crossings)
    : prepared_(std::make_unique<Prepared>()) {
  prepared_->box = detail::contour_box(polygon.outer);
  prepared_->polygon = std::move(polygon);
  prepared_->lines = &lines;
  prepared_->crossings = crossings;
}
template <class K>
ClipRegion<K>::~ClipRegion() = default;
template <class K>
ClipRegion<K>::ClipRegion(ClipRegion&&) noexcept = default;
template <class K>
ClipRegion<K>& ClipRegion<K>::operator=(ClipRegion&&) noexcept = default;
template <class K>
const Polygon<K>& ClipRegion<K>::polygon() const {
  return prepared_->polygon;
}

template <class K>
ClipResult<K> clip_polygon(const Polygon<K>& subject, const ClipRegion<K>& clip) {
  return detail::with_overlay<K>([&](detail::Overlay<K>& overlay) { return overlay.run(subject, clip); });
}

template <class K>
std::vector<ClipResult<K>> clip_list(std::span<const Polygon<K>> subjects, const ClipRegion<K>& clip) {
  return detail::with_overlay<K>([&](detail::Overlay<K>& overlay) {
    std::vector<ClipResult<K>> results;
    results.reserve(subjects.size());
    for (const Polygon<K>& s : subjects) results.push_back(overlay.run(s, clip));
    return results;
  });
}

template <class K>
Contour<K> make_contour(std::vector<typename Geometry<K>::Point> points, LineTable<K>& lines) {
  Contour<K> c;
  c.points = std::move(points);
  const std::size_t n = c.points.size();
  c.lines.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    c.lines.push_back(static_cast<LineId>(lines.size()));
    lines.push_back({c.points[i], c.points[(i + 1) % n]});
  }
  return c;
}

template <class K>
typename Geometry<K>::FT twice_signed_area(const Contour<K>& contour) {
  using G = Geometry<K>;
  const auto& pts = contour.points;
  const std::size_t n = pts.size();
  // Summed in G::Exact: a lazy sum over many terms would build a deep DAG.
  typename G::Exact sum = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const auto& p = pts[i];
    const auto& q = pts[(i + 1) % n];
    sum += G::exact(G::x(p)) * G::exact(G::y(q)) - G::exact(G::x(q)) * G::exact(G::y(p));
  }
  return typename G::FT(sum);
}

template <class K>
typename Geometry<K>::FT twice_area(const Polygon<K>& polygon) {
  auto a = twice_signed_area(polygon.outer);
  for (const auto& h : polygon.holes) a += twice_signed_area(h);  // holes are clockwise: negative
  return a;
}

}  // namespace hlr::clip
