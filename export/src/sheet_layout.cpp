// The layout of a drawing sheet (hlr/export/sheet.hpp).
//
// Views sit in a grid of cells around the front view's, (row, column) = (0, 0), as ISO 5456-2
// places them; the other views (iso, a direction) take the grid's free corners, top right first,
// or a new column on the right. Each column is as wide as its widest view, each row as tall as
// its tallest, at one scale; the front view's column (front, top, bottom) is measured over the
// union of its views' x ranges, because they share their sheet x for a model point, and the
// front view's row (left, front, right, back) over the union of their y ranges. The scale is the
// largest of ISO 5455 at which the columns and rows, with view_gap_mm between them, fit the
// drawing area; the room left over is shared out evenly between the gaps and the margins.
//
// A view's extent depends a little on the scale (merging and circle recovery are decided at the
// sheet's resolution, and a true circle reaches beyond its polygon): the scale is chosen on the
// drawn segments' extents, then checked on the sheet lines made at it, and stepped down the
// series if they do not fit.
//
// Centre lines of cylinders seen from the side: a circle seen face-on in one view is the end of
// a cylinder when another view, looking across its axis, shows two lines parallel to the axis at
// the circle's radius on both sides of it (silhouettes of a tessellated cylinder lie between r cos
// (pi / 8) and r from the axis); the centre line runs along their common length and beyond.
#include <hlr/export/sheet.hpp>

#include "numbers.hpp"
#include "paint.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace hlr::exporter {
namespace {

constexpr double pi = 3.14159265358979323846;
constexpr double centre_overshoot_mm = 3;

struct Interval {
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  bool empty() const { return lo > hi; }
  double length() const { return empty() ? 0 : hi - lo; }
  void add(double lo_, double hi_) { lo = std::min(lo, lo_), hi = std::max(hi, hi_); }
};

struct Extent {
  Interval x, y;
};

Extent extent_of(const std::optional<Bounds>& b) {
  Extent e;
  if (b) e.x.add(b->x0, b->x1), e.y.add(b->y0, b->y1);
  return e;
}

// The drawn segments' extent: what the scale is first chosen on.
Extent segment_extent(const LineDrawing& d, const DrawingStyle& style) {
  Extent e;
  for (const auto& s : d.segments) {
    if (!s.visible && !style.hidden) continue;
    e.x.add(std::min(s.a[0], s.b[0]), std::max(s.a[0], s.b[0]));
    e.y.add(std::min(s.a[1], s.b[1]), std::max(s.a[1], s.b[1]));
  }
  return e;
}

struct Cell {
  int row = 0, column = 0;
  bool principal = false;
};

struct Grid {
  std::vector<int> rows, columns;  // the used ones, ascending
  std::map<int, double> width, height;  // model units
  Interval aligned_x, aligned_y;        // the front view's column and row
};

Grid grid_of(const std::vector<Cell>& cells, const std::vector<Extent>& extents) {
  Grid g;
  std::set<int> rows, columns;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const Cell& c = cells[i];
    rows.insert(c.row), columns.insert(c.column);
    if (c.principal && c.column == 0) g.aligned_x.add(extents[i].x.lo, extents[i].x.hi);
    if (c.principal && c.row == 0) g.aligned_y.add(extents[i].y.lo, extents[i].y.hi);
  }
  g.rows.assign(rows.begin(), rows.end());
  g.columns.assign(columns.begin(), columns.end());
  for (int r : g.rows) g.height[r] = 0;
  for (int c : g.columns) g.width[c] = 0;
  if (columns.count(0)) g.width[0] = g.aligned_x.length();
  if (rows.count(0)) g.height[0] = g.aligned_y.length();
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const Cell& c = cells[i];
    if (!(c.principal && c.column == 0)) g.width[c.column] = std::max(g.width[c.column], extents[i].x.length());
    if (!(c.principal && c.row == 0)) g.height[c.row] = std::max(g.height[c.row], extents[i].y.length());
  }
  return g;
}

double total(const std::map<int, double>& sizes) {
  double t = 0;
  for (const auto& [k, v] : sizes) t += v;
  return t;
}

// The grid's size on the sheet at `scale`, gaps included.
std::pair<double, double> sheet_size(const Grid& g, double scale) {
  return {scale * total(g.width) + view_gap_mm * double(g.columns.size() - 1),
          scale * total(g.height) + view_gap_mm * double(g.rows.size() - 1)};
}

bool fits(const Grid& g, double scale, const detail::Box& area) {
  const auto [w, h] = sheet_size(g, scale);
  return w <= area.width() * (1 + 1e-12) && h <= area.height() * (1 + 1e-12);
}

// The largest ISO 5455 ratio at which the grid fits, or nothing when not even the gaps do.
std::optional<double> fitting_ratio(const Grid& g, const detail::Box& area, double unit_mm) {
  const double room_w = area.width() - view_gap_mm * double(g.columns.size() - 1);
  const double room_h = area.height() - view_gap_mm * double(g.rows.size() - 1);
  if (room_w <= 0 || room_h <= 0) return std::nullopt;
  const double w = total(g.width), h = total(g.height);
  double largest = HUGE_VAL;
  if (w > 0) largest = std::min(largest, room_w / w);
  if (h > 0) largest = std::min(largest, room_h / h);
  if (!std::isfinite(largest)) return 1.0;  // nothing drawn
  double ratio = iso_scale_at_most(largest / unit_mm);
  while (!fits(g, ratio * unit_mm, area) && ratio > 1e-300) ratio = iso_scale_at_most(ratio * (1 - 1e-6));
  return ratio;
}

// The free cells for views that are not principal ones: the grid's corners, top right first, then
// a new column to the right (its top, then its bottom), and so on.
std::vector<Cell> place_free_views(std::vector<Cell> cells, const std::vector<bool>& free) {
  std::set<std::pair<int, int>> taken;
  for (std::size_t i = 0; i < cells.size(); ++i)
    if (!free[i]) taken.insert({cells[i].row, cells[i].column});
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (!free[i]) continue;
    int r0 = 0, r1 = 0, c0 = 0, c1 = 0;
    bool any = false;
    for (const auto& [r, c] : taken) {
      if (!any) r0 = r1 = r, c0 = c1 = c;
      any = true;
      r0 = std::min(r0, r), r1 = std::max(r1, r), c0 = std::min(c0, c), c1 = std::max(c1, c);
    }
    std::pair<int, int> cell{0, 0};
    if (any) {
      const std::pair<int, int> corners[] = {{r0, c1}, {r1, c1}, {r0, c0}, {r1, c0}};
      auto found = std::find_if(std::begin(corners), std::end(corners), [&](const auto& k) { return !taken.count(k); });
      cell = found != std::end(corners) ? *found : std::pair<int, int>{r0, c1 + 1};
    }
    taken.insert(cell);
    cells[i].row = cell.first, cells[i].column = cell.second;
  }
  return cells;
}

// --------------------------------------------------------------------------------------------
// Cylinder axes.

using Vec3 = std::array<double, 3>;
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 row_of(const ViewInfo& v, int r) { return {v.world_to_view[r][0], v.world_to_view[r][1], v.world_to_view[r][2]}; }

struct Axis {
  Point2 at, direction;  // in view B
  Interval extent;       // along direction, from `at`
};

// The axes of the cylinders whose ends view `a` shows face-on, in view `b` (orthogonal to it).
std::vector<Axis> cylinder_axes(const PlacedView& a, const PlacedView& b, double tol) {
  std::vector<Axis> out;
  const ViewInfo &va = a.drawing->view, &vb = b.drawing->view;
  const Vec3 axis = row_of(va, 2);  // towards a's viewer
  const Vec3 bx = row_of(vb, 0), by = row_of(vb, 1);
  const Point2 u{dot(bx, axis), dot(by, axis)};
  if (std::abs(std::hypot(u[0], u[1]) - 1) > 1e-9) return out;  // not looking across the axis
  const Point2 n{-u[1], u[0]};
  for (const auto& circle : face_on_circles(a.lines.curves, tol)) {
    // The circle's centre in model coordinates (a's frame is orthonormal: its transpose inverts it).
    Vec3 q{};
    const double v[3] = {circle.centre[0] - va.world_to_view[0][3], circle.centre[1] - va.world_to_view[1][3],
                         -va.world_to_view[2][3]};
    for (int r = 0; r < 3; ++r)
      for (int k = 0; k < 3; ++k) q[k] += v[r] * va.world_to_view[r][k];
    const Point2 at{dot(bx, q) + vb.world_to_view[0][3], dot(by, q) + vb.world_to_view[1][3]};
    Interval extent;
    for (double r : circle.radii) {
      Interval side[2];
      for (const auto& s : b.lines.merged.segments) {
        const double dx = s.b[0] - s.a[0], dy = s.b[1] - s.a[1], length = std::hypot(dx, dy);
        if (!(length > tol)) continue;
        if (std::abs(dx * u[1] - dy * u[0]) > length * std::sin(0.5 * pi / 180)) continue;  // not parallel
        const double off_a = n[0] * (s.a[0] - at[0]) + n[1] * (s.a[1] - at[1]);
        const double off_b = n[0] * (s.b[0] - at[0]) + n[1] * (s.b[1] - at[1]);
        const double off = (off_a + off_b) / 2;
        if (std::abs(off) > r + tol || std::abs(off) < r * std::cos(pi / 8) - tol) continue;
        const double t_a = u[0] * (s.a[0] - at[0]) + u[1] * (s.a[1] - at[1]);
        const double t_b = u[0] * (s.b[0] - at[0]) + u[1] * (s.b[1] - at[1]);
        side[off > 0 ? 0 : 1].add(std::min(t_a, t_b), std::max(t_a, t_b));
      }
      if (side[0].empty() || side[1].empty()) continue;
      if (std::min(side[0].hi, side[1].hi) - std::max(side[0].lo, side[1].lo) <= tol) continue;  // not side by side
      extent.add(std::min(side[0].lo, side[1].lo), std::max(side[0].hi, side[1].hi));
    }
    if (!extent.empty()) out.push_back({at, u, extent});
  }
  return out;
}

void add_cylinder_centre_lines(std::vector<PlacedView>& views, double scale, double tol_mm) {
  const double tol = tol_mm / scale, overshoot = centre_overshoot_mm / scale;
  std::vector<std::vector<Axis>> found(views.size());
  for (std::size_t a = 0; a < views.size(); ++a)
    for (std::size_t b = 0; b < views.size(); ++b) {
      if (a == b) continue;
      for (auto& axis : cylinder_axes(views[a], views[b], tol)) {
        // The same axis found from two views (top and bottom): one line over both extents.
        auto same = std::find_if(found[b].begin(), found[b].end(), [&](const Axis& o) {
          const double across = o.direction[1] * (axis.at[0] - o.at[0]) - o.direction[0] * (axis.at[1] - o.at[1]);
          return std::abs(o.direction[0] * axis.direction[1] - o.direction[1] * axis.direction[0]) < 1e-9 &&
                 std::abs(across) <= tol;
        });
        if (same == found[b].end()) {
          found[b].push_back(axis);
        } else {
          const double shift = same->direction[0] * (axis.at[0] - same->at[0]) + same->direction[1] * (axis.at[1] - same->at[1]);
          const double sign = same->direction[0] * axis.direction[0] + same->direction[1] * axis.direction[1] > 0 ? 1 : -1;
          const double lo = shift + sign * axis.extent.lo, hi = shift + sign * axis.extent.hi;
          same->extent.add(std::min(lo, hi), std::max(lo, hi));
        }
      }
    }
  for (std::size_t b = 0; b < views.size(); ++b)
    for (const Axis& axis : found[b]) {
      const double lo = axis.extent.lo - overshoot, hi = axis.extent.hi + overshoot;
      views[b].lines.centre_lines.push_back({{axis.at[0] + lo * axis.direction[0], axis.at[1] + lo * axis.direction[1]},
                                             {axis.at[0] + hi * axis.direction[0], axis.at[1] + hi * axis.direction[1]}});
    }
}

}  // namespace

std::optional<std::pair<int, int>> principal_cell(const std::string& view, Projection projection) {
  const int below = projection == Projection::third_angle ? 1 : -1;  // where the view from below goes
  const int right = projection == Projection::third_angle ? 1 : -1;  // where the view from the right goes
  if (view == "front") return std::pair{0, 0};
  if (view == "top") return std::pair{-below, 0};
  if (view == "bottom") return std::pair{below, 0};
  if (view == "right") return std::pair{0, right};
  if (view == "left") return std::pair{0, -right};
  if (view == "back") return std::pair{0, 2};  // beyond the side view on the right, in either method
  return std::nullopt;
}

SheetLayout lay_out_sheet(const std::vector<SheetViewInput>& inputs, const SheetSpec& spec) {
  const DrawingStyle& style = spec.style;
  if (inputs.empty()) throw SheetError("--views: no view to draw");
  const detail::Box area = detail::frame_of(style.sheet, detail::sheet_title_height).area;

  std::vector<Cell> cells(inputs.size());
  std::vector<bool> free(inputs.size());
  std::set<std::string> names;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    if (!names.insert(inputs[i].name).second) throw SheetError("--views: view " + inputs[i].name + " is listed twice");
    const auto cell = principal_cell(inputs[i].name, spec.projection);
    free[i] = !cell;
    if (cell) cells[i] = {cell->first, cell->second, true};
  }
  cells = place_free_views(cells, free);

  // The scale: on the segments' extents first, then on the sheet lines made at it.
  std::vector<Extent> extents;
  for (const auto& v : inputs) extents.push_back(segment_extent(*v.drawing, style));
  double ratio = 1;
  if (style.scale) {
    ratio = *style.scale / style.unit_mm;
  } else {
    const auto r = fitting_ratio(grid_of(cells, extents), area, style.unit_mm);
    if (!r) throw SheetError("--sheet " + style.sheet.name + ": " + std::to_string(cells.size()) + " views do not fit on it");
    ratio = *r;
  }
  SheetLayout layout;
  std::vector<PlacedView>& views = layout.views;
  Grid grid;
  for (int attempt = 0;; ++attempt) {
    const double scale = ratio * style.unit_mm;
    views.clear();
    extents.clear();
    for (std::size_t i = 0; i < inputs.size(); ++i) {
      PlacedView v;
      v.name = inputs[i].name;
      v.drawing = inputs[i].drawing;
      v.lines = sheet_lines_at(*v.drawing, style, scale);
      v.row = cells[i].row, v.column = cells[i].column;
      extents.push_back(extent_of(sheet_bounds(v.lines)));
      views.push_back(std::move(v));
    }
    grid = grid_of(cells, extents);
    if (fits(grid, scale, area)) break;
    if (style.scale) {
      const auto [w, h] = sheet_size(grid, scale);
      using detail::fixed;
      throw SheetError("--scale " + scale_label(ratio) + ": the views need " + fixed(w, 1) + " x " + fixed(h, 1) +
                       " mm at this scale (" + fixed(view_gap_mm, 0) + " mm between them); the drawing area of " +
                       style.sheet.name + " is " + fixed(area.width(), 1) + " x " + fixed(area.height(), 1) + " mm");
    }
    if (attempt > 3) throw SheetError("--sheet " + style.sheet.name + ": the views do not fit on it");
    ratio = iso_scale_at_most(ratio * (1 - 1e-6));
  }
  layout.ratio = ratio;
  layout.scale = ratio * style.unit_mm;
  const double s = layout.scale;

  // Share out the room left over between the gaps and the margins, evenly.
  const auto [used_w, used_h] = sheet_size(grid, s);
  const double extra_x = (area.width() - used_w) / double(grid.columns.size() + 1);
  const double extra_y = (area.height() - used_h) / double(grid.rows.size() + 1);
  std::map<int, double> left, top;
  double x = area.x0 + extra_x;
  for (int c : grid.columns) left[c] = x, x += s * grid.width[c] + view_gap_mm + extra_x;
  double y = area.y0 + extra_y;
  for (int r : grid.rows) top[r] = y, y += s * grid.height[r] + view_gap_mm + extra_y;
  for (std::size_t i = 0; i < views.size(); ++i) {
    PlacedView& v = views[i];
    const Cell& c = cells[i];
    const Extent& e = extents[i];
    const bool aligned_x = c.principal && c.column == 0, aligned_y = c.principal && c.row == 0;
    const Interval& xs = aligned_x ? grid.aligned_x : e.x;
    const Interval& ys = aligned_y ? grid.aligned_y : e.y;
    const double x_lo = xs.empty() ? 0 : xs.lo, y_hi = ys.empty() ? 0 : ys.hi;
    v.ox = left[c.column] + s * (grid.width[c.column] - xs.length()) / 2 - s * x_lo;
    v.oy = top[c.row] + s * (grid.height[c.row] - ys.length()) / 2 + s * y_hi;
  }

  if (style.centre_lines) add_cylinder_centre_lines(views, s, style.merge_distance);
  for (const auto& v : views) {
    layout.circles += v.lines.curves.circles.size();
    layout.arcs += v.lines.curves.arcs;
    layout.centre_lines += v.lines.centre_lines.size();
  }
  return layout;
}

}  // namespace hlr::exporter
