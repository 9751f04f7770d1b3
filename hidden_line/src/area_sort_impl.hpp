// area_sort as a template over the kernel; included only by the instantiate_*.cpp files.
//
// Weiler and Atherton clip by a copy of the front polygon's original outline and need a stack of
// clip polygons to stop on cyclic overlap. Here the clip polygon is the front piece itself, so
// every comparison is between two pieces that really overlap, depth is a strict pointwise order
// inside every recursion (penetrations having been split), and recursion cannot cycle.
#pragma once

#include <hlr/hidden_line/visibility.hpp>

#include "box_index.hpp"

#include <hlr/hidden_line/parallel.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <optional>

namespace hlr::hidden_line {
namespace detail {

// A piece of a source in a sort's list, with its box.
template <class K>
struct Item {
  clip::Polygon<K> polygon;
  std::uint32_t source;
  CGAL::Bbox_2 box;
};

// Rough depth order: the nearest corner of each source, in double (only a heuristic).
template <class K>
std::vector<double> rough_depths(const std::vector<SourcePolygon<K>>& polygons) {
  using G = Geometry<K>;
  std::vector<double> nearest(polygons.size());
  for (std::size_t s = 0; s < polygons.size(); ++s) {
    const auto& sp = polygons[s];
    const double a = G::rough_double(sp.plane->a), b = G::rough_double(sp.plane->b), c = G::rough_double(sp.plane->c);
    double z = -HUGE_VAL;
    for (const auto& p : sp.polygon.outer.points)
      z = std::max(z, a * G::rough_double(G::x(p)) + b * G::rough_double(G::y(p)) + c);
    nearest[s] = z;
  }
  return nearest;
}

// The support lines one tile's sort reads and appends its penetration cuts to. Alone, that is the
// sources' own table. Beside other tiles, which read the same table at the same time, it is a copy
// made at the first cut; the cuts go to the sources' table after all tiles, in tile order.
template <class K>
class TileLines {
 public:
  TileLines(clip::LineTable<K>& lines, std::vector<LineOrigin>& origins, bool alone)
      : shared_(lines), shared_origins_(origins), alone_(alone), base_(lines.size()) {}
  const clip::LineTable<K>& table() const { return copy_.empty() ? shared_ : copy_; }
  clip::LineId add(const clip::SupportLine<K>& line, const LineOrigin& origin) {
    if (alone_) {
      shared_.push_back(line);
      shared_origins_.push_back(origin);
      return static_cast<clip::LineId>(shared_.size() - 1);
    }
    if (copy_.empty()) copy_ = shared_;
    copy_.push_back(line);
    origins_.push_back(origin);
    return static_cast<clip::LineId>(copy_.size() - 1);
  }
  // Appends this tile's cuts to the sources' table; returns what to add to their ids.
  std::size_t append_to_shared() {
    const std::size_t offset = shared_.size() - base_;
    if (!copy_.empty()) shared_.insert(shared_.end(), copy_.begin() + std::ptrdiff_t(base_), copy_.end());
    shared_origins_.insert(shared_origins_.end(), origins_.begin(), origins_.end());
    return offset;
  }
  std::size_t base() const { return base_; }

 private:
  clip::LineTable<K>& shared_;
  std::vector<LineOrigin>& shared_origins_;
  bool alone_;
  std::size_t base_;
  clip::LineTable<K> copy_;
  std::vector<LineOrigin> origins_;
};

// The area sort of one list: sources, or their pieces within one tile, that nothing outside the
// list covers.
template <class K>
class AreaSort {
  using G = Geometry<K>;
  using FT = typename G::FT;
  using P = typename G::Point;
  using Polygon = clip::Polygon<K>;
  using Item = detail::Item<K>;
  enum class Relation { behind, ahead, coplanar, mixed };

 public:
  AreaSort(const std::vector<SourcePolygon<K>>& polygons, const std::vector<double>& nearest, TileLines<K>& lines,
           const AreaSortOptions& options)
      : polygons_(polygons), nearest_(nearest), lines_(lines), options_(options) {}

  VisibilityMap<K> run(std::vector<Item> list) {
    resolve(list);
    return std::move(map_);
  }

 private:
  // Whether the line through an edge of one outer contour has that contour on its closed left
  // side and the other outer contour on its closed right side: then the polygons' interiors are
  // disjoint, and clipping one by the other would cut nothing. Mesh neighbours, whose boxes always
  // overlap, are told apart this way with a few filtered orientation tests. Exact; a false "no"
  // only costs a clip. Long contours are left to the clipper.
  static bool separated(const clip::Contour<K>& a, const clip::Contour<K>& b) {
    constexpr std::size_t kMaxCorners = 16;
    if (a.size() > kMaxCorners || b.size() > kMaxCorners) return false;
    // Two triangles with an edge each on one support line, run in opposite directions (mesh
    // neighbours): each lies on its own closed side of the line, without an orientation test. On
    // the exact kernel only, where corners lie on their support lines exactly.
    if constexpr (G::exact_constructions)
      if (a.size() == 3 && b.size() == 3)
        for (std::size_t i = 0; i < 3; ++i)
          for (std::size_t j = 0; j < 3; ++j)
            if (a.lines[i] == b.lines[j] &&
                G::compare_xy(a.points[i], a.points[(i + 1) % 3]) == -G::compare_xy(b.points[j], b.points[(j + 1) % 3]))
              return true;
    auto separates = [](const clip::Contour<K>& own, const clip::Contour<K>& other) {
      for (std::size_t i = 0; i < own.size(); ++i)
        if ((exact_triangle(own) || on_closed_side(own, i, own, 1)) && on_closed_side(own, i, other, -1)) return true;
      return false;
    };
    return separates(a, b) || separates(b, a);
  }

  // An outer contour of three corners on the exact kernel: counter-clockwise with a positive area
  // (sources and clip results both are), so each corner lies strictly left of the opposite edge and
  // the triangle is convex, without an orientation test.
  static bool exact_triangle(const clip::Contour<K>& c) { return G::exact_constructions && c.size() == 3; }

  // Whether every corner of c lies on the closed left (side 1) or right (side -1) of the line
  // through edge i of `own`. Exact.
  static bool on_closed_side(const clip::Contour<K>& own, std::size_t i, const clip::Contour<K>& c, int side) {
    const P &p = own.points[i], &q = own.points[(i + 1) % own.size()];
    for (std::size_t k = 0; k < c.size(); ++k) {
      if constexpr (G::exact_constructions)
        if (clip::corner_on_line(c, k, own.lines[i])) continue;  // on the line: orientation 0
      if (G::orientation(p, q, c.points[k]) == -side) return false;
    }
    return true;
  }

  // Whether a front piece is a strictly convex polygon without holes of a few corners: then a
  // piece lies in its closure when every corner of the piece does (covered, below).
  static bool small_convex(const Polygon& front) {
    constexpr std::size_t kMaxCorners = 16;
    const auto& c = front.outer;
    if (!front.holes.empty() || c.size() > kMaxCorners) return false;
    if (exact_triangle(c)) return true;
    for (std::size_t i = 0; i < c.size(); ++i)
      if (G::orientation(c.points[i], c.points[(i + 1) % c.size()], c.points[(i + 2) % c.size()]) <= 0) return false;
    return true;
  }
  static bool covered(const clip::Contour<K>& convex_front, const clip::Contour<K>& piece) {
    for (std::size_t i = 0; i < convex_front.size(); ++i)
      if (!on_closed_side(convex_front, i, piece, 1)) return false;
    return true;
  }

  // Nearer first; ties by source index, so the order is deterministic.
  bool nearer(const Item& x, const Item& y) const {
    const double zx = nearest_[x.source], zy = nearest_[y.source];
    return zx != zy ? zx > zy : x.source < y.source;
  }

  // Where piece (of source s) lies relative to the plane of source f, over all of the piece.
  Relation relation(const Polygon& piece, std::uint32_t s, std::uint32_t f) const {
    const auto& ps = *polygons_[s].plane;
    const auto& pf = *polygons_[f].plane;
    // The sign at a corner is first taken from the numbers' bounds (the intervals Epeck keeps),
    // which decide most corners without a lazy node; the difference of the planes is made only
    // for a corner they leave open.
    using I = CGAL::Interval_nt<>;
    const I ia = bounds_of<K>(ps.a) - bounds_of<K>(pf.a), ib = bounds_of<K>(ps.b) - bounds_of<K>(pf.b),
            ic = bounds_of<K>(ps.c) - bounds_of<K>(pf.c);
    std::optional<std::array<FT, 3>> difference;
    bool nearer_somewhere = false, farther_somewhere = false;
    // The depth difference is linear: its extremes are at corners of the outer contour.
    for (const P& p : piece.outer.points) {
      const I v = bounds_at<K>(ia, ib, ic, p);
      int sign = v.inf() > 0 ? 1 : v.sup() < 0 ? -1 : 2;
      if (sign != 2) {
        PredicateStats::add(PredicateFamily::sign, DecidedBy::interval);
      } else {
        if (!difference) difference = std::array<FT, 3>{ps.a - pf.a, ps.b - pf.b, ps.c - pf.c};
        const auto& [da, db, dc] = *difference;
        sign = G::sign_above(da, db, dc, G::x(p), G::y(p), FT(0));
      }
      nearer_somewhere |= sign > 0;
      farther_somewhere |= sign < 0;
      if (nearer_somewhere && farther_somewhere) return Relation::mixed;
    }
    if (nearer_somewhere) return Relation::ahead;
    if (farther_somewhere) return Relation::behind;
    return Relation::coplanar;
  }

  clip::LineId add_line(const P& a, const P& b, LineOrigin origin) { return lines_.add({a, b}, origin); }

  // Splits a piece of source s along the line where its plane meets the plane of f: returns the
  // part nearer than f and the part farther. The cut is an exact half-plane clip whose only edge
  // that can reach the piece lies on that line.
  std::pair<std::vector<Polygon>, std::vector<Polygon>> split(const Polygon& piece, std::uint32_t s, std::uint32_t f) {
    ++map_.stats.penetration_splits;
    const auto& ps = *polygons_[s].plane;
    const auto& pf = *polygons_[f].plane;
    const FT da = ps.a - pf.a, db = ps.b - pf.b, dc = ps.c - pf.c;  // nearer where da x + db y + dc > 0
    const CGAL::Bbox_2 box = box_of(piece);
    auto widen = [](double v, double dir) { return v + dir * (1 + 1e-6 * std::abs(v)); };
    LineOrigin cut;
    cut.kind = LineOrigin::intersection;
    cut.source_a = static_cast<std::int32_t>(std::min(s, f));
    cut.source_b = static_cast<std::int32_t>(std::max(s, f));
    const LineOrigin aux;
    std::vector<P> corners;
    // Decided exactly: on rough doubles a near tie would go by what the run had evaluated before.
    const bool by_x = G::sign(db) != 0 && (G::sign(da) == 0 || CGAL::compare(CGAL::abs(db), CGAL::abs(da)) != CGAL::SMALLER);
    if (by_x) {
      // The line crosses the verticals x = x0 and x = x1 at y = -(da x + dc) / db.
      const double x0 = widen(box.xmin(), -1), x1 = widen(box.xmax(), 1);
      const FT y0 = -(da * FT(x0) + dc) / db, y1 = -(da * FT(x1) + dc) / db;
      const P l0 = G::point(FT(x0), y0), l1 = G::point(FT(x1), y1);
      const double lo = widen(std::min({box.ymin(), G::rough_double(y0), G::rough_double(y1)}), -1);
      const double hi = widen(std::max({box.ymax(), G::rough_double(y0), G::rough_double(y1)}), 1);
      if (G::sign(db) > 0) corners = {l0, l1, G::point(x1, hi), G::point(x0, hi)};  // nearer above
      else corners = {l0, G::point(x0, lo), G::point(x1, lo), l1};                   // nearer below
    } else {
      // The line crosses the horizontals y = y0 and y = y1 at x = -(db y + dc) / da.
      const double y0 = widen(box.ymin(), -1), y1 = widen(box.ymax(), 1);
      const FT x0 = -(db * FT(y0) + dc) / da, x1 = -(db * FT(y1) + dc) / da;
      const P l0 = G::point(x0, FT(y0)), l1 = G::point(x1, FT(y1));
      const double lo = widen(std::min({box.xmin(), G::rough_double(x0), G::rough_double(x1)}), -1);
      const double hi = widen(std::max({box.xmax(), G::rough_double(x0), G::rough_double(x1)}), 1);
      if (G::sign(da) > 0) corners = {l0, G::point(hi, y0), G::point(hi, y1), l1};  // nearer right
      else corners = {l0, l1, G::point(lo, y1), G::point(lo, y0)};                   // nearer left
    }
    // The edge from l0 to l1 (or l1 to l0) lies on the cut; the others stay clear of the piece.
    clip::Contour<K> half;
    for (std::size_t i = 0; i < corners.size(); ++i) {
      const P& a = corners[i];
      const P& b = corners[(i + 1) % corners.size()];
      const bool on_cut = (i == 0 && by_x && G::sign(db) > 0) || (i == 3 && by_x && G::sign(db) < 0) ||
                          (i == 3 && !by_x && G::sign(da) > 0) || (i == 0 && !by_x && G::sign(da) < 0);
      half.points.push_back(a);
      half.lines.push_back(add_line(a, b, on_cut ? cut : aux));
    }
    clip::Polygon<K> half_plane{std::move(half), {}};
    if (G::sign(clip::twice_signed_area(half_plane.outer)) <= 0)
      throw clip::ClipError("penetration cut is not a proper half-plane");
    clip::ClipRegion<K> region(std::move(half_plane), lines_.table(), crossings());
    auto parts = clip::clip_polygon(piece, region);
    return {std::move(parts.inside), std::move(parts.outside)};
  }

  // One point per crossing of two support lines, whichever clip finds it (exact kernel only: on
  // the others a rounded crossing would depend on which clip came first).
  clip::CrossingCache<K>* crossings() {
    if constexpr (G::exact_constructions) return &crossings_;
    else return nullptr;
  }

  void hide(Polygon piece, std::uint32_t s, std::uint32_t by) {
    if (options_.keep_hidden) map_.hidden.push_back({std::move(piece), s, static_cast<std::int32_t>(by)});
  }

  // Places one inside piece of source s, found within the front piece of source f.
  void place(Polygon piece, std::uint32_t s, std::uint32_t f, std::vector<Item>& ahead) {
    // Pieces of one source never overlap; only an inconsistent inexact kernel gets here.
    if (s == f) throw clip::ClipError("a source overlaps itself");
    Relation r = relation(piece, s, f);
    if (r == Relation::coplanar) {
      ++map_.stats.coplanar_ties;
      r = s < f ? Relation::ahead : Relation::behind;  // the lower source wins a tie
    }
    if (r == Relation::behind) {
      hide(std::move(piece), s, f);
    } else if (r == Relation::ahead) {
      CGAL::Bbox_2 box = box_of(piece);
      ahead.push_back({std::move(piece), s, box});
    } else {
      auto [nearer, farther] = split(piece, s, f);
      for (auto& part : nearer) {
        if (relation(part, s, f) != Relation::ahead) throw clip::ClipError("penetration split left a mixed piece");
        CGAL::Bbox_2 box = box_of(part);
        ahead.push_back({std::move(part), s, box});
      }
      for (auto& part : farther) {
        if (relation(part, s, f) != Relation::behind) throw clip::ClipError("penetration split left a mixed piece");
        hide(std::move(part), s, f);
      }
    }
  }

  // Solves visibility within `list`: the pieces of one region, which nothing outside the list
  // covers. Along a chain of recursive calls every front lies strictly nearer than the one before
  // it at every point of the inner call's region, so no source appears twice on the chain.
  //
  // Items are taken nearest first (by rough depth); the pieces a front cuts off an item stay in
  // that item's place in the order (its slot). A loose grid of the live pieces' boxes gives each
  // front the pieces it can cut, so no front scans the whole list.
  void resolve(std::vector<Item>& list) {
    if (++depth_ > polygons_.size() + 1) throw clip::ClipError("area sort recursion does not converge");
    std::stable_sort(list.begin(), list.end(), [&](const Item& x, const Item& y) { return nearer(x, y); });

    CGAL::Bbox_2 domain;
    for (const Item& item : list) domain += item.box;
    detail::LooseGrid grid(domain, list.size());
    std::vector<Item> pieces = std::move(list);
    std::vector<std::uint32_t> slot_of(pieces.size());
    std::vector<std::vector<std::uint32_t>> slots(pieces.size());
    for (std::uint32_t i = 0; i < pieces.size(); ++i) {
      slot_of[i] = i;
      slots[i] = {i};
      grid.insert(i, pieces[i].box);
    }

    std::vector<std::uint32_t> cut;
    std::vector<Polygon> subjects;
    for (std::size_t slot = 0; slot < slots.size(); ++slot) {
      while (!slots[slot].empty()) {
        options_.stop.check_every(fronts_, 64);
        const std::uint32_t id = slots[slot].back();
        slots[slot].pop_back();
        grid.remove(id);
        Item front = std::move(pieces[id]);
        // Pieces of the front's own source never overlap it.
        cut.clear();
        grid.query(front.box, [&](std::uint32_t other) {
          if (pieces[other].source != front.source &&
              !separated(front.polygon.outer, pieces[other].polygon.outer))
            cut.push_back(other);
        });
        std::sort(cut.begin(), cut.end());
        // When no output asks for hidden pieces, a piece that a convex front covers and lies
        // behind is dropped without clipping: its clip would give the piece itself, hidden.
        if (!options_.keep_hidden && !cut.empty() && small_convex(front.polygon)) {
          std::erase_if(cut, [&](std::uint32_t other) {
            const Item& item = pieces[other];
            if (!covered(front.polygon.outer, item.polygon.outer) ||
                relation(item.polygon, item.source, front.source) != Relation::behind)
              return false;
            grid.remove(other);
            auto& kept = slots[slot_of[other]];
            kept.erase(std::find(kept.begin(), kept.end(), other));
            return true;
          });
        }
        std::vector<Item> ahead;
        if (!cut.empty()) {
          ++map_.stats.clips;
          subjects.clear();
          for (std::uint32_t other : cut) subjects.push_back(std::move(pieces[other].polygon));
          clip::ClipRegion<K> region(front.polygon, lines_.table(), crossings());
          auto results = clip::clip_list<K>(subjects, region);
          for (std::size_t i = 0; i < cut.size(); ++i) {
            const std::uint32_t other = cut[i], source = pieces[other].source, home = slot_of[other];
            grid.remove(other);
            auto& kept = slots[home];
            kept.erase(std::find(kept.begin(), kept.end(), other));
            for (auto& piece : results[i].outside) {
              const auto pid = static_cast<std::uint32_t>(pieces.size());
              const CGAL::Bbox_2 box = box_of(piece);
              pieces.push_back({std::move(piece), source, box});
              slot_of.push_back(home);
              kept.push_back(pid);
              grid.insert(pid, box);
            }
            for (auto& piece : results[i].inside) place(std::move(piece), source, front.source, ahead);
          }
        }
        if (ahead.empty()) {
          map_.visible.push_back({std::move(front.polygon), front.source, -1});
          continue;
        }
        // The rough order was wrong here: what lies ahead hides that much of the front piece, and
        // is solved among itself (it lies within the front piece, apart from the rest of the list).
        ++map_.stats.recursions;
        std::vector<Polygon> remaining{std::move(front.polygon)};
        for (const Item& a : ahead) {
          clip::ClipRegion<K> region(a.polygon, lines_.table(), crossings());
          std::vector<Polygon> outside;
          for (auto& r : clip::clip_list<K>(remaining, region)) {
            for (auto& piece : r.inside) hide(std::move(piece), front.source, a.source);
            for (auto& piece : r.outside) outside.push_back(std::move(piece));
          }
          remaining.swap(outside);
          if (remaining.empty()) break;
        }
        for (auto& piece : remaining) map_.visible.push_back({std::move(piece), front.source, -1});
        resolve(ahead);
      }
    }
    --depth_;
  }

  const std::vector<SourcePolygon<K>>& polygons_;
  const std::vector<double>& nearest_;
  TileLines<K>& lines_;
  AreaSortOptions options_;
  clip::CrossingCache<K> crossings_;
  std::size_t depth_ = 0;
  std::size_t fronts_ = 0;  // front polygons taken, for polling options_.stop
  VisibilityMap<K> map_;
};

// Screen subdivision (Weiler and Atherton): vertical strips at exact abscissas, each sorted on its
// own, in parallel. Pieces in different strips have disjoint images, so no piece of one can hide a
// piece of another; a source across a border is clipped exactly into one piece per strip. The
// strips depend on the sources only, never on the number of threads, so neither does the result.
// On the exact kernel only: elsewhere the border clips would round.
template <class K>
std::vector<std::vector<Item<K>>> strips(Sources<K>& sources, std::size_t sources_per_strip) {
  using G = Geometry<K>;
  using FT = typename G::FT;
  constexpr std::size_t kMaxStrips = 8;
  const std::size_t n = sources.polygons.size();
  std::vector<Item<K>> items;
  items.reserve(n);
  for (std::uint32_t s = 0; s < n; ++s)
    items.push_back({sources.polygons[s].polygon, s, box_of(sources.polygons[s].polygon)});
  const std::size_t count = sources_per_strip == 0 ? 1 : std::min(kMaxStrips, n / sources_per_strip);
  if (!G::exact_constructions || count < 2) return {std::move(items)};

  // Borders at quantiles of the boxes' centres, so that strips hold about as many sources.
  std::vector<double> centres;
  CGAL::Bbox_2 domain;
  for (const auto& item : items) {
    centres.push_back((item.box.xmin() + item.box.xmax()) / 2);
    domain += item.box;
  }
  std::sort(centres.begin(), centres.end());
  std::vector<double> borders;  // strip j is [borders[j - 1], borders[j]], unbounded at the ends
  for (std::size_t j = 1; j < count; ++j) {
    const double x = centres[j * n / count];
    if (borders.empty() || x > borders.back()) borders.push_back(x);
  }
  auto widen = [](double v, double dir) { return v + dir * (1 + 1e-6 * std::abs(v)); };
  const double x_lo = widen(std::min(domain.xmin(), borders.front()), -1);
  const double x_hi = widen(std::max(domain.xmax(), borders.back()), 1);
  const double y_lo = widen(domain.ymin(), -1), y_hi = widen(domain.ymax(), 1);
  std::vector<double> xs{x_lo};
  xs.insert(xs.end(), borders.begin(), borders.end());
  xs.push_back(x_hi);
  auto add_line = [&](double ax, double ay, double bx, double by) {
    sources.lines.push_back({G::point(FT(ax), FT(ay)), G::point(FT(bx), FT(by))});
    sources.line_origins.push_back({});
    return static_cast<clip::LineId>(sources.lines.size() - 1);
  };
  const clip::LineId bottom = add_line(x_lo, y_lo, x_hi, y_lo), top = add_line(x_hi, y_hi, x_lo, y_hi);
  std::vector<clip::LineId> verticals;
  for (double x : xs) verticals.push_back(add_line(x, y_lo, x, y_hi));
  // One point per crossing of a border with a support line, whichever source's clip finds it: the
  // pieces on both sides of a border, and neighbours across it, share their corners there.
  clip::CrossingCache<K> crossings;
  std::vector<clip::ClipRegion<K>> regions;
  for (std::size_t j = 0; j + 1 < xs.size(); ++j) {
    clip::Contour<K> rect;
    rect.points = {G::point(FT(xs[j]), FT(y_lo)), G::point(FT(xs[j + 1]), FT(y_lo)),
                   G::point(FT(xs[j + 1]), FT(y_hi)), G::point(FT(xs[j]), FT(y_hi))};
    rect.lines = {bottom, verticals[j + 1], top, verticals[j]};
    regions.emplace_back(clip::Polygon<K>{std::move(rect), {}}, sources.lines, &crossings);
  }

  std::vector<std::vector<Item<K>>> out(regions.size());
  for (auto& item : items) {
    // The strips the box reaches; a box within one strip's closure needs no clip.
    const std::size_t first = std::size_t(std::upper_bound(borders.begin(), borders.end(), item.box.xmin()) - borders.begin());
    const std::size_t last = std::size_t(std::lower_bound(borders.begin(), borders.end(), item.box.xmax()) - borders.begin());
    if (first >= last) {
      out[std::min(first, last)].push_back(std::move(item));
      continue;
    }
    for (std::size_t j = first; j <= last; ++j)
      for (auto& piece : clip::clip_polygon(item.polygon, regions[j]).inside) {
        const CGAL::Bbox_2 box = box_of(piece);
        out[j].push_back({std::move(piece), item.source, box});
      }
  }
  return out;
}

}  // namespace detail

template <class K>
VisibilityMap<K> area_sort(Sources<K>& sources, const AreaSortOptions& options) {
  using namespace detail;
  const std::vector<double> nearest = rough_depths(sources.polygons);
  std::vector<std::vector<Item<K>>> lists = strips(sources, options.sources_per_strip);
  if (lists.size() == 1) {
    TileLines<K> lines(sources.lines, sources.line_origins, true);
    return AreaSort<K>(sources.polygons, nearest, lines, options).run(std::move(lists.front()));
  }
  std::vector<VisibilityMap<K>> maps(lists.size());
  std::vector<std::unique_ptr<TileLines<K>>> lines(lists.size());
  for (auto& l : lines) l = std::make_unique<TileLines<K>>(sources.lines, sources.line_origins, false);
  parallel_chunks(lists.size(), 1, [&](const auto& range) {
    for (std::size_t j = range.begin(); j != range.end(); ++j)
      maps[j] = AreaSort<K>(sources.polygons, nearest, *lines[j], options).run(std::move(lists[j]));
  });
  // In strip order: each strip's cuts get the ids after the strips before it.
  VisibilityMap<K> out;
  for (std::size_t j = 0; j < maps.size(); ++j) {
    const std::size_t base = lines[j]->base(), offset = lines[j]->append_to_shared();
    auto renumber = [&](std::vector<Fragment<K>>& fragments) {
      for (auto& f : fragments) {
        auto fix = [&](clip::Contour<K>& c) {
          for (auto& id : c.lines)
            if (id >= base) id = static_cast<clip::LineId>(id + offset);
        };
        fix(f.polygon.outer);
        for (auto& h : f.polygon.holes) fix(h);
      }
    };
    if (offset > 0) {
      renumber(maps[j].visible);
      renumber(maps[j].hidden);
    }
    auto& m = maps[j];
    out.visible.insert(out.visible.end(), std::make_move_iterator(m.visible.begin()), std::make_move_iterator(m.visible.end()));
    out.hidden.insert(out.hidden.end(), std::make_move_iterator(m.hidden.begin()), std::make_move_iterator(m.hidden.end()));
    out.stats.clips += m.stats.clips;
    out.stats.recursions += m.stats.recursions;
    out.stats.penetration_splits += m.stats.penetration_splits;
    out.stats.coplanar_ties += m.stats.coplanar_ties;
  }
  return out;
}

}  // namespace hlr::hidden_line
