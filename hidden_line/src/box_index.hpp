// Internal to hlr_hidden_line: the candidate filters for boxes.
//
// overlapping_box_pairs: every pair of overlapping boxes of a fixed set, on all threads (the
// penetration search's faces, precedence's line keys).
//
// LooseGrid: for the area sort (whose pieces come and go), line classification and precedence.
// Queries do not change it, so threads may share it. A loose multi-level grid: level l splits the
// domain into 2^l x 2^l cells, and a box is filed once, at the finest level whose cells are at
// least as large as the box, in the cell of its centre; so inserting costs O(1) whatever the box's
// size, and a query looks at the cells of each level that can hold a box reaching into it (its
// own, widened by three quarters of a cell). Boxes are conservative (interval bounds of exact
// points) and the widening leaves room for rounding, so a query never misses a box that overlaps;
// it only filters, it decides nothing.
#pragma once

#include <hlr/clipper/clipper.hpp>
#include <hlr/hidden_line/parallel.hpp>

#include <CGAL/Bbox_2.h>
#include <CGAL/box_intersection_d.h>

#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <type_traits>
#include <vector>

namespace hlr::hidden_line::detail {

template <class K>
CGAL::Bbox_2 box_of(const clip::Contour<K>& c) {
  CGAL::Bbox_2 box;
  for (const auto& q : c.points) box += Geometry<K>::bbox(q);
  return box;
}

// A polygon's box: its outer contour's (the holes lie inside it).
template <class K>
CGAL::Bbox_2 box_of(const clip::Polygon<K>& p) {
  return box_of(p.outer);
}

// Calls visit(x, y) once for every pair of overlapping boxes (CGAL's box_self_intersection_d),
// from several threads where more than one is allowed. `boxes` is reordered.
//
// The segment tree scans lists of up to kCutoff boxes directly instead of splitting them further.
// Mesh faces' boxes overlap their neighbours' in every direction, and CGAL's default of 10 spends
// most of the search on splitting: with 1,000, finding the 538,234 overlapping pairs of
// refined_elephant takes 0.11 s instead of 0.32 s (docs/BENCHMARKS.md, "Eighth run").
//
// On several threads: slabs across `axis`, searched side by side. CGAL's Parallel_tag runs only
// the top of its tree in parallel (asm_1M: 4.3 s on one thread, 3.6 s on two). A box goes into
// every slab its extent meets, and a pair belongs to the slab that holds the larger of the two
// boxes' lower ends, which both reach: each pair is visited once. Slab bounds are quantiles of
// the lower ends, so that slabs hold about as many boxes.
template <class Box, class Visit>
void overlapping_box_pairs(std::vector<Box>& boxes, int axis, Visit&& visit) {
  constexpr std::ptrdiff_t kCutoff = 1000;
  const auto threads = tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism);
  if (threads <= 1) {
    CGAL::box_self_intersection_d<CGAL::Sequential_tag>(boxes.begin(), boxes.end(), visit, kCutoff);
    return;
  }
  const std::size_t slab_count = std::min<std::size_t>(4 * threads, boxes.size() / 4096 + 1);
  std::vector<double> lower_ends(boxes.size());
  for (std::size_t b = 0; b < boxes.size(); ++b) lower_ends[b] = boxes[b].min_coord(axis);
  std::sort(lower_ends.begin(), lower_ends.end());
  std::vector<double> bounds;  // slab s is [bounds[s - 1], bounds[s]), the first and last unbounded
  for (std::size_t s = 1; s < slab_count; ++s) bounds.push_back(lower_ends[s * lower_ends.size() / slab_count]);
  auto slab_of = [&](double x) { return std::size_t(std::upper_bound(bounds.begin(), bounds.end(), x) - bounds.begin()); };
  std::vector<std::vector<Box>> slabs(slab_count);
  for (const Box& b : boxes)
    for (std::size_t s = slab_of(b.min_coord(axis)), last = slab_of(b.max_coord(axis)); s <= last; ++s)
      slabs[s].push_back(b);
  parallel_chunks(slab_count, 1, [&](const auto& range) {
    for (std::size_t s = range.begin(); s != range.end(); ++s)
      CGAL::box_self_intersection_d<CGAL::Sequential_tag>(
          slabs[s].begin(), slabs[s].end(),
          [&](const Box& x, const Box& y) {
            if (slab_of(std::max(x.min_coord(axis), y.min_coord(axis))) == s) visit(x, y);
          },
          kCutoff);
  });
}

class LooseGrid {
 public:
  LooseGrid(const CGAL::Bbox_2& domain, std::size_t expected) : domain_(domain) {
    if (!(domain_.xmin() <= domain_.xmax() && domain_.ymin() <= domain_.ymax())) domain_ = CGAL::Bbox_2(0, 0, 1, 1);
    width_ = std::max(domain_.xmax() - domain_.xmin(), 1e-300);
    height_ = std::max(domain_.ymax() - domain_.ymin(), 1e-300);
    // About one finest cell per box, at most 2^10 x 2^10.
    while (levels_ < 11 && (std::size_t(1) << (2 * (levels_ - 1))) < expected) ++levels_;
    for (int l = 0; l < levels_; ++l) cells_.emplace_back(std::size_t(1) << (2 * l));
    filed_.assign(std::size_t(levels_), 0);
    boxes_.reserve(expected);
    // A few ulps of the domain's coordinates: what rounding may move a box's centre by.
    slack_x_ = 1e-15 * (std::abs(domain_.xmin()) + std::abs(domain_.xmax()));
    slack_y_ = 1e-15 * (std::abs(domain_.ymin()) + std::abs(domain_.ymax()));
  }

  // Files the box (cell_of).
  void insert(std::uint32_t id, const CGAL::Bbox_2& box) {
    if (id >= boxes_.size()) boxes_.resize(id + 1);
    boxes_[id] = box;
    const int l = level_of(box);
    cell_of(box, l).push_back(id);
    ++filed_[l];
  }

  // Takes an inserted id out, so that queries no longer look at it (the area sort's pieces that a
  // clip replaced). The order of ids in a cell changes; queries promise no order.
  void remove(std::uint32_t id) {
    const int l = level_of(boxes_[id]);
    auto& ids = cell_of(boxes_[id], l);
    const auto it = std::find(ids.begin(), ids.end(), id);
    if (it == ids.end()) return;
    *it = ids.back();
    ids.pop_back();
    --filed_[l];
  }

  // Calls visit(id) for every inserted id whose box overlaps `box` (each id once), larger boxes
  // first; a visit that returns true ends the query.
  template <class Visit>
  void query(const CGAL::Bbox_2& box, Visit&& visit) const {
    for (int l = 0; l < levels_; ++l) {
      if (filed_[l] == 0) continue;  // boxes of like sizes fill one or two levels of the eleven
      // A box filed at level l that overlaps `box` is at most a cell wide and high, so its centre
      // lies within half a cell of `box`; the cells within three quarters of one (and the slack)
      // hold every such box, whatever the rounding of widths and centres.
      const double w = cell_w(l), h = cell_h(l), mx = 0.75 * w + slack_x_, my = 0.75 * h + slack_y_;
      const long x0 = cell(box.xmin() - mx, domain_.xmin(), w, l), x1 = cell(box.xmax() + mx, domain_.xmin(), w, l);
      const long y0 = cell(box.ymin() - my, domain_.ymin(), h, l), y1 = cell(box.ymax() + my, domain_.ymin(), h, l);
      for (long y = y0; y <= y1; ++y)
        for (long x = x0; x <= x1; ++x)
          for (std::uint32_t id : cells_[l][index(l, x, y)])
            if (CGAL::do_overlap(boxes_[id], box)) {
              if constexpr (std::is_same_v<decltype(visit(id)), bool>) {
                if (visit(id)) return;
              } else {
                visit(id);
              }
            }
    }
  }

 private:
  double cell_w(int l) const { return width_ / double(1L << l); }
  double cell_h(int l) const { return height_ / double(1L << l); }
  static long cell(double v, double lo, double size, int l) {
    const double q = std::floor((v - lo) / size);
    const long n = 1L << l;
    return q >= double(n - 1) ? n - 1 : q >= 0 ? long(q) : 0;  // clamped: monotone, so nothing is missed
  }
  // The cell a box is filed in: at the finest level whose cells are as wide and as high as it,
  // the cell of its centre.
  int level_of(const CGAL::Bbox_2& box) const {
    int l = levels_ - 1;
    while (l > 0 && (box.xmax() - box.xmin() > cell_w(l) || box.ymax() - box.ymin() > cell_h(l))) --l;
    return l;
  }
  std::vector<std::uint32_t>& cell_of(const CGAL::Bbox_2& box, int l) {
    const double cx = box.xmin() + (box.xmax() - box.xmin()) / 2, cy = box.ymin() + (box.ymax() - box.ymin()) / 2;
    return cells_[l][index(l, cell(cx, domain_.xmin(), cell_w(l), l), cell(cy, domain_.ymin(), cell_h(l), l))];
  }
  static std::size_t index(int l, long x, long y) { return std::size_t(y) * (std::size_t(1) << l) + std::size_t(x); }

  CGAL::Bbox_2 domain_;
  double width_ = 1, height_ = 1, slack_x_ = 0, slack_y_ = 0;
  int levels_ = 1;
  std::vector<std::vector<std::vector<std::uint32_t>>> cells_;  // per level, per cell
  std::vector<std::size_t> filed_;                               // per level: boxes filed there
  std::vector<CGAL::Bbox_2> boxes_;
};

}  // namespace hlr::hidden_line::detail
