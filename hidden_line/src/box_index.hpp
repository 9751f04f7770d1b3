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
// it only filters, it decides nothing. A grid that is only queried from some point on can be
// frozen: each level's cells packed into one array.
//
// bounds_of, bounds_at: a number's interval bounds, and a plane's depth over a point's bounds, in
// interval arithmetic (sound: a sign they give is the exact sign).
#pragma once

#include <hlr/clipper/clipper.hpp>
#include <hlr/hidden_line/parallel.hpp>

#include <CGAL/Bbox_2.h>
#include <CGAL/Interval_nt.h>

#include <tbb/global_control.h>
#include <tbb/parallel_reduce.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <stdexcept>
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

// A number's bounds (the interval Epeck keeps), for filters that must not build lazy nodes.
template <class K>
CGAL::Interval_nt<> bounds_of(const typename Geometry<K>::FT& v) {
  const auto [lo, hi] = Geometry<K>::interval(v);
  return CGAL::Interval_nt<>(lo, hi);
}
// The bounds of a x + b y + c over the bounds of p.
template <class K>
CGAL::Interval_nt<> bounds_at(const CGAL::Interval_nt<>& a, const CGAL::Interval_nt<>& b, const CGAL::Interval_nt<>& c,
                              const typename Geometry<K>::Point& p) {
  using I = CGAL::Interval_nt<>;
  const CGAL::Bbox_2 box = Geometry<K>::bbox(p);
  return a * I(box.xmin(), box.xmax()) + b * I(box.ymin(), box.ymax()) + c;
}

// Calls visit(x, y) once for every pair of overlapping boxes (closed boxes: touching ones
// overlap, as in CGAL's box_intersection_d), from several threads where more than one is allowed.
// Box is a 3D box with min_coord(k) and max_coord(k), such as CGAL's Box_with_info_d.
//
// A sweep along `axis` within columns across the other two axes. A column is about as wide as
// the median box along each of those axes and holds the boxes that meet it, in the order of their
// lower ends along `axis`; there a box is tested against those after it until their lower ends
// pass its upper end. So a box meets a few boxes beside it rather than every box of its slice
// across the scene, and no tree is built (CGAL's box_self_intersection_d, which this replaced,
// spent most of its time splitting: refined_elephant's 538,234 pairs took 49 ms there, 21 ms
// here; docs/BENCHMARKS.md, "Fifteenth run"). A pair is visited in the column that holds the
// larger of the two boxes' lower corners, which both meet: once. Boxes that meet more than
// kWideColumns columns (long slivers) are swept apart, against every box. Columns are computed
// from the boxes' doubles by monotone arithmetic and the overlap test is on the doubles
// themselves, so no pair is missed or made up.
template <class Box, class Visit>
void overlapping_box_pairs(const std::vector<Box>& boxes, int axis, Visit&& visit) {
  constexpr std::size_t kWideColumns = 64;
  const std::size_t n = boxes.size();
  if (n < 2) return;
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  struct Swept {
    double lo, hi, ulo, uhi, vlo, vhi;  // along axis, u, v
    std::uint32_t box;
  };
  auto overlap = [](const Swept& a, const Swept& b) {
    return b.lo <= a.hi && a.lo <= b.hi && b.ulo <= a.uhi && a.ulo <= b.uhi && b.vlo <= a.vhi && a.vlo <= b.vhi;
  };
  constexpr std::size_t kGrain = 16384;
  // The set-up is on every thread too: at a million boxes its arrays' fresh pages and the sort
  // took as long as the sweep.
  std::vector<Swept> swept;
  resize_in_parallel(swept, n);
  parallel_chunks(n, kGrain, [&](const auto& range) {
    for (std::size_t i = range.begin(); i != range.end(); ++i) {
      const Box& b = boxes[i];
      swept[i] = {b.min_coord(axis), b.max_coord(axis), b.min_coord(u), b.max_coord(u), b.min_coord(v), b.max_coord(v),
                  std::uint32_t(i)};
    }
  });
  double umin = HUGE_VAL, umax = -HUGE_VAL, vmin = HUGE_VAL, vmax = -HUGE_VAL;
  for (const Swept& b : swept) {
    umin = std::min(umin, b.ulo), umax = std::max(umax, b.uhi);
    vmin = std::min(vmin, b.vlo), vmax = std::max(vmax, b.vhi);
  }
  // Square columns, measured in parts of each axis's range (the axes may be in different units,
  // as precedence's angles and offsets are), as wide as the median box, at most n of them; two,
  // four or eight times as wide where boxes would go into more than three columns on average, as
  // in assemblies of parts of many sizes (asm_300k: 760 ms as wide as the median, 220 ms at four
  // times).
  const double urange = umax - umin, vrange = vmax - vmin;
  const bool split_u = urange > 0 && std::isfinite(urange), split_v = vrange > 0 && std::isfinite(vrange);
  double median = 0;
  {
    std::vector<double> extent;
    resize_in_parallel(extent, n);
    parallel_chunks(n, kGrain, [&](const auto& range) {
      for (std::size_t i = range.begin(); i != range.end(); ++i)
        extent[i] = std::max(split_u ? (swept[i].uhi - swept[i].ulo) / urange : 0.0,
                             split_v ? (swept[i].vhi - swept[i].vlo) / vrange : 0.0);
    });
    std::nth_element(extent.begin(), extent.begin() + n / 2, extent.end());
    median = extent[n / 2];
  }
  auto cell = [](double x, double min, double scale, std::size_t count) -> std::size_t {
    const double c = (x - min) * scale;
    return c > 0 ? (c < double(count) ? std::size_t(c) : count - 1) : 0;
  };
  struct Cells {
    std::uint32_t u0, u1, v0, v1;
    std::size_t count() const { return std::size_t(u1 - u0 + 1) * (v1 - v0 + 1); }
  };
  std::size_t nu = 1, nv = 1;
  double su = 0, sv = 0;
  auto cells_of = [&](const Swept& b) {
    return Cells{std::uint32_t(cell(b.ulo, umin, su, nu)), std::uint32_t(cell(b.uhi, umin, su, nu)),
                 std::uint32_t(cell(b.vlo, vmin, sv, nv)), std::uint32_t(cell(b.vhi, vmin, sv, nv))};
  };
  // A total order (ties by box), so the parallel sort's result is the one order. A small set is
  // sorted and counted inline, as parallel_chunks runs a small range: starting the scheduler would
  // take longer.
  auto by_lower_end = [](const Swept& a, const Swept& b) { return a.lo < b.lo || (a.lo == b.lo && a.box < b.box); };
  if (n <= kGrain) std::sort(swept.begin(), swept.end(), by_lower_end);
  else tbb::parallel_sort(swept.begin(), swept.end(), by_lower_end);
  std::vector<Cells> cells;  // of swept[i], in the columns chosen
  resize_in_parallel(cells, n);
  for (double width = median;; width *= 2) {
    const std::size_t per_axis = width > 0 ? std::size_t(std::min(1 / width, double(n))) : n;
    nu = split_u ? std::max<std::size_t>(per_axis, 1) : 1;
    nv = split_v ? std::max<std::size_t>(per_axis, 1) : 1;
    while (nu * nv > n) (nu >= nv ? nu : nv) /= 2;
    su = nu > 1 ? double(nu) / urange : 0, sv = nv > 1 ? double(nv) / vrange : 0;
    auto count_entries = [&](const tbb::blocked_range<std::size_t>& range, std::size_t sum) {
      for (std::size_t i = range.begin(); i != range.end(); ++i)
        sum += std::min((cells[i] = cells_of(swept[i])).count(), kWideColumns);
      return sum;
    };
    const tbb::blocked_range<std::size_t> all(0, n, kGrain);
    const std::size_t entries = n <= kGrain ? count_entries(all, 0)
                                            : tbb::parallel_reduce(all, std::size_t(0), count_entries, std::plus<>());
    if (entries <= 3 * n || !(width > 0 && width < 8 * median) || nu * nv == 1) break;
  }

  // Each column's boxes, in sweep order (a counting sort), and the wide boxes apart.
  std::vector<std::uint32_t> start(nu * nv + 1, 0), wide;
  std::vector<char> is_wide(n, 0);
  for (std::uint32_t i = 0; i < n; ++i) {
    const Cells& c = cells[i];
    if (c.count() > kWideColumns) {
      wide.push_back(i);
      is_wide[i] = 1;
      continue;
    }
    for (std::size_t cu = c.u0; cu <= c.u1; ++cu)
      for (std::size_t cv = c.v0; cv <= c.v1; ++cv) ++start[cu * nv + cv + 1];
  }
  for (std::size_t k = 1; k < start.size(); ++k) start[k] += start[k - 1];
  std::vector<std::uint32_t> members(start.back());
  {
    std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
    for (std::uint32_t i = 0; i < n; ++i) {
      if (is_wide[i]) continue;
      const Cells& c = cells[i];
      for (std::size_t cu = c.u0; cu <= c.u1; ++cu)
        for (std::size_t cv = c.v0; cv <= c.v1; ++cv) members[next[cu * nv + cv]++] = i;
    }
  }
  auto visit_pair = [&](const Swept& a, const Swept& b) { visit(boxes[a.box], boxes[b.box]); };
  // Each column's boxes are copied side by side before its sweep, which reads each of them again
  // for every box before it in reach: then from one array, in order.
  struct Entry {
    Swept box;
    std::uint32_t u0, v0;  // its first column across
  };
  auto sweep_columns = [&](std::size_t first, std::size_t last) {
    std::vector<Entry> column;
    for (std::size_t col = first; col != last; ++col) {
      const std::size_t cu = col / nv, cv = col % nv;
      column.clear();
      for (std::uint32_t k = start[col]; k < start[col + 1]; ++k)
        column.push_back({swept[members[k]], cells[members[k]].u0, cells[members[k]].v0});
      for (std::size_t k = 0; k < column.size(); ++k) {
        const Entry& a = column[k];
        for (std::size_t l = k + 1; l < column.size(); ++l) {
          const Entry& b = column[l];
          if (b.box.lo > a.box.hi) break;
          if (!overlap(a.box, b.box)) continue;
          if (std::max(a.u0, b.u0) == cu && std::max(a.v0, b.v0) == cv) visit_pair(a.box, b.box);
        }
      }
    }
  };
  // The wide boxes against each other and against every other box, in sweep order: the box that
  // begins first meets those that begin before it ends.
  auto sweep_wide = [&] {
    for (std::size_t k = 0; k < wide.size(); ++k)
      for (std::size_t l = k + 1; l < wide.size() && swept[wide[l]].lo <= swept[wide[k]].hi; ++l)
        if (overlap(swept[wide[k]], swept[wide[l]])) visit_pair(swept[wide[k]], swept[wide[l]]);
    std::size_t w = 0, i = 0;
    while (w < wide.size() && i < n) {
      if (is_wide[i]) {
        ++i;
        continue;
      }
      const Swept& a = swept[wide[w]];
      const Swept& b = swept[i];
      if (wide[w] < i) {  // the wide box begins first
        for (std::size_t j = i; j < n && swept[j].lo <= a.hi; ++j)
          if (!is_wide[j] && overlap(a, swept[j])) visit_pair(a, swept[j]);
        ++w;
      } else {
        for (std::size_t l = w; l < wide.size() && swept[wide[l]].lo <= b.hi; ++l)
          if (overlap(b, swept[wide[l]])) visit_pair(b, swept[wide[l]]);
        ++i;
      }
    }
  };
  const auto threads = tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism);
  const std::size_t column_count = nu * nv;
  if (threads <= 1 || n < 4096) {
    sweep_columns(0, column_count);
  } else {
    parallel_chunks(column_count, std::max<std::size_t>(1, column_count / (16 * threads)),
                    [&](const auto& range) { sweep_columns(range.begin(), range.end()); });
  }
  sweep_wide();
}

class LooseGrid {
 public:
  LooseGrid(const CGAL::Bbox_2& domain, std::size_t expected) : domain_(domain) {
    if (!(domain_.xmin() <= domain_.xmax() && domain_.ymin() <= domain_.ymax())) domain_ = CGAL::Bbox_2(0, 0, 1, 1);
    width_ = std::max(domain_.xmax() - domain_.xmin(), 1e-300);
    height_ = std::max(domain_.ymax() - domain_.ymin(), 1e-300);
    // About one finest cell per box, at most 2^10 x 2^10.
    while (levels_ < 11 && (std::size_t(1) << (2 * (levels_ - 1))) < expected) ++levels_;
    cells_.resize(std::size_t(levels_));  // a level's cells are made when a box is first filed there
    filed_.assign(std::size_t(levels_), 0);
    boxes_.reserve(expected);
    // A few ulps of the domain's coordinates: what rounding may move a box's centre by.
    slack_x_ = 1e-15 * (std::abs(domain_.xmin()) + std::abs(domain_.xmax()));
    slack_y_ = 1e-15 * (std::abs(domain_.ymin()) + std::abs(domain_.ymax()));
  }

  // A frozen grid of boxes[id] for every id, filed at once: the grid that inserting each in turn
  // and freezing makes, made without a vector per cell (and where threads are allowed, placed on
  // all of them).
  LooseGrid(const CGAL::Bbox_2& domain, std::vector<CGAL::Bbox_2> boxes) : LooseGrid(domain, boxes.size()) {
    boxes_ = std::move(boxes);
    // Where each box is filed: its level in the top byte, its cell below (levels_ <= 11, so
    // fewer than 2^20 cells a level).
    std::vector<std::uint32_t> where(boxes_.size());
    parallel_chunks(boxes_.size(), 4096, [&](const auto& range) {
      for (std::size_t id = range.begin(); id != range.end(); ++id) {
        const int l = level_of(boxes_[id]);
        where[id] = std::uint32_t(l) << 24 | std::uint32_t(cell_index(boxes_[id], l));
      }
    });
    frozen_.resize(std::size_t(levels_));
    for (const std::uint32_t w : where) ++filed_[w >> 24];
    for (int l = 0; l < levels_; ++l)
      if (filed_[l] > 0) frozen_[l].start.assign((std::size_t(1) << (2 * l)) + 1, 0);
    for (const std::uint32_t w : where) ++frozen_[w >> 24].start[(w & 0xffffff) + 1];
    std::vector<std::vector<std::uint32_t>> next(static_cast<std::size_t>(levels_));  // per level, per cell
    for (int l = 0; l < levels_; ++l) {
      if (filed_[l] == 0) continue;
      auto& start = frozen_[l].start;
      for (std::size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
      frozen_[l].ids.resize(filed_[l]);
      next[l].assign(start.begin(), start.end() - 1);
    }
    for (std::uint32_t id = 0; id < where.size(); ++id) {
      const std::uint32_t l = where[id] >> 24, c = where[id] & 0xffffff;
      frozen_[l].ids[next[l][c]++] = id;
    }
  }

  const CGAL::Bbox_2& domain() const { return domain_; }
  const CGAL::Bbox_2& box(std::uint32_t id) const { return boxes_[id]; }

  // Files the box (cell_index).
  void insert(std::uint32_t id, const CGAL::Bbox_2& box) {
    if (!frozen_.empty()) throw std::logic_error("LooseGrid: insert after freeze");
    if (id >= boxes_.size()) boxes_.resize(id + 1);
    boxes_[id] = box;
    const int l = level_of(box);
    if (cells_[l].empty()) cells_[l].resize(std::size_t(1) << (2 * l));
    cells_[l][cell_index(box, l)].push_back(id);
    ++filed_[l];
  }

  // Takes an inserted id out, so that queries no longer look at it (the area sort's pieces that a
  // clip replaced). The order of ids in a cell changes; queries promise no order.
  void remove(std::uint32_t id) {
    if (!frozen_.empty()) throw std::logic_error("LooseGrid: remove after freeze");
    const int l = level_of(boxes_[id]);
    if (cells_[l].empty()) return;
    auto& ids = cells_[l][cell_index(boxes_[id], l)];
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
        for (long x = x0; x <= x1; ++x) {
          const std::size_t c = index(l, x, y);
          const std::uint32_t* first = frozen_.empty() ? cells_[l][c].data() : frozen_[l].ids.data() + frozen_[l].start[c];
          const std::uint32_t* last = frozen_.empty() ? first + cells_[l][c].size() : frozen_[l].ids.data() + frozen_[l].start[c + 1];
          for (const std::uint32_t* id = first; id != last; ++id)
            if (CGAL::do_overlap(boxes_[*id], box)) {
              if constexpr (std::is_same_v<decltype(visit(*id)), bool>) {
                if (visit(*id)) return;
              } else {
                visit(*id);
              }
            }
        }
    }
  }

  // For a grid only queried from here on: each level's ids in one array, cell after cell in the
  // order they were filed (queries visit them as before), without a vector per cell (24 bytes
  // each, a million cells at the finest level). No insert or remove after.
  void freeze() {
    if (!frozen_.empty()) return;
    frozen_.resize(std::size_t(levels_));
    for (int l = 0; l < levels_; ++l) {
      if (filed_[l] == 0) continue;  // never queried
      Packed& packed = frozen_[l];
      packed.ids.reserve(filed_[l]);
      packed.start.reserve(cells_[l].size() + 1);
      packed.start.push_back(0);
      for (const auto& ids : cells_[l]) {
        packed.ids.insert(packed.ids.end(), ids.begin(), ids.end());
        packed.start.push_back(std::uint32_t(packed.ids.size()));
      }
      std::vector<std::vector<std::uint32_t>>().swap(cells_[l]);
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
  std::size_t cell_index(const CGAL::Bbox_2& box, int l) const {
    const double cx = box.xmin() + (box.xmax() - box.xmin()) / 2, cy = box.ymin() + (box.ymax() - box.ymin()) / 2;
    return index(l, cell(cx, domain_.xmin(), cell_w(l), l), cell(cy, domain_.ymin(), cell_h(l), l));
  }
  static std::size_t index(int l, long x, long y) { return std::size_t(y) * (std::size_t(1) << l) + std::size_t(x); }

  CGAL::Bbox_2 domain_;
  double width_ = 1, height_ = 1, slack_x_ = 0, slack_y_ = 0;
  int levels_ = 1;
  std::vector<std::vector<std::vector<std::uint32_t>>> cells_;  // per level, per cell (until frozen)
  // Once frozen, per level: the ids of cell c are ids[start[c] .. start[c + 1]).
  struct Packed {
    std::vector<std::uint32_t> start, ids;
  };
  std::vector<Packed> frozen_;
  std::vector<std::size_t> filed_;                               // per level: boxes filed there
  std::vector<CGAL::Bbox_2> boxes_;
};

}  // namespace hlr::hidden_line::detail
