// What a sheet shows of one drawing (hlr/export/lines.hpp): line widths after ISO 128, scales
// after ISO 5455, the sheet's segments, chains, curves and centre marks, and their extent.
#include <hlr/export/lines.hpp>

#include "numbers.hpp"
#include "paint.hpp"
#include "source_curves.hpp"

#include <algorithm>
#include <cmath>

namespace hlr::exporter {
namespace {

constexpr double pi = 3.14159265358979323846;
// How far centre marks reach beyond their circle, on the sheet.
constexpr double centre_overshoot_mm = 3;

MergedSegments sheet_segments_at(const LineDrawing& drawing, const DrawingStyle& style, double scale) {
  std::vector<DrawingSegment> drawn;
  drawn.reserve(drawing.segments.size());
  std::size_t contact = 0;
  for (const auto& s : drawing.segments) {
    if (!s.visible && !style.hidden) continue;
    if (s.meeting_degrees < style.contact_degrees) ++contact;
    else drawn.push_back(s);
  }
  MergedSegments out = merge_segments(drawn, style.merge_distance / scale);
  out.contact = contact;
  return out;
}

// Bounding box of the drawn segments in view coordinates; nothing when none is drawn.
std::optional<Bounds> drawn_bounds(const LineDrawing& drawing, const DrawingStyle& style) {
  std::optional<Bounds> box;
  for (const auto& s : drawing.segments) {
    if (!s.visible && !style.hidden) continue;
    for (const Point2& p : {s.a, s.b}) {
      if (!box) box = Bounds{p[0], p[1], p[0], p[1]};
      box->x0 = std::min(box->x0, p[0]);
      box->y0 = std::min(box->y0, p[1]);
      box->x1 = std::max(box->x1, p[0]);
      box->y1 = std::max(box->y1, p[1]);
    }
  }
  return box;
}

// The largest ISO 5455 ratio at which w x h (mm of the part) fits into area_w x area_h (mm of
// the sheet). A ratio is kept as sheet:part, so that the test multiplies by whole numbers instead
// of dividing by rounded powers of ten.
double fitting_ratio(double w, double h, double area_w, double area_h) {
  double largest = HUGE_VAL;  // before rounding down to ISO 5455
  if (w > 0) largest = std::min(largest, area_w / w);
  if (h > 0) largest = std::min(largest, area_h / h);
  if (!std::isfinite(largest) || largest <= 0) return 1;  // a point, or an area too small to tell
  auto fits = [&](double on_sheet, double in_part) { return w * on_sheet <= area_w * in_part && h * on_sheet <= area_h * in_part; };
  const int top = std::clamp(static_cast<int>(std::floor(std::log10(largest))) + 1, -300, 300);
  for (int e = top; e >= -300; --e) {
    const double power = std::pow(10.0, std::abs(e));
    for (double m : {5.0, 2.0, 1.0}) {
      const double on_sheet = e >= 0 ? m * power : m, in_part = e >= 0 ? 1 : power;
      if (fits(on_sheet, in_part)) return on_sheet / in_part;
    }
  }
  return 1;
}

void include(Bounds& b, bool& any, double x, double y) {
  if (!any) b = {x, y, x, y};
  any = true;
  b.x0 = std::min(b.x0, x), b.y0 = std::min(b.y0, y), b.x1 = std::max(b.x1, x), b.y1 = std::max(b.y1, y);
}

}  // namespace

std::optional<LineWidths> line_widths(double line_group) {
  // ISO 128-20's line groups: wide and narrow widths.
  static const double groups[][2] = {{0.25, 0.13}, {0.35, 0.18}, {0.5, 0.25}, {0.7, 0.35}, {1.0, 0.5}};
  for (const auto& g : groups) {
    if (std::abs(g[0] - line_group) > 1e-9) continue;
    const double d = g[1];
    return LineWidths{g[0], d, {12 * d, 3 * d}, {24 * d, 3 * d, 0.5 * d, 3 * d}};
  }
  return std::nullopt;
}

double iso_scale_at_most(double ratio) {
  if (!(ratio > 0) || !std::isfinite(ratio)) return 1;
  const int top = static_cast<int>(std::floor(std::log10(ratio))) + 1;
  for (int e = top; e >= top - 2; --e)
    for (double m : {5.0, 2.0, 1.0}) {
      const double candidate = e >= 0 ? m * std::pow(10.0, e) : m / std::pow(10.0, -e);
      if (candidate <= ratio * (1 + 1e-9)) return candidate;
    }
  return ratio;
}

bool is_iso_scale(double ratio) {
  return ratio > 0 && std::isfinite(ratio) && std::abs(iso_scale_at_most(ratio) - ratio) <= 1e-9 * ratio;
}

std::string scale_label(double ratio) {
  using detail::fixed;
  return ratio >= 1 ? fixed(ratio, 4) + ":1" : "1:" + fixed(1 / ratio, 4);
}

std::string drawing_scale_label(const LineDrawing& drawing, double ratio) {
  // A perspective image has no one scale: its coordinates are at focal length 1, and sizes on the
  // sheet shrink with distance.
  return drawing.view.eye ? "NTS (perspective)" : scale_label(ratio);
}

double drawing_scale(const LineDrawing& drawing, const DrawingStyle& style) {
  if (style.scale) return *style.scale;
  const auto bounds = drawn_bounds(drawing, style);
  if (!bounds) return style.unit_mm;
  const detail::Box area = detail::frame_of(style.sheet, detail::draw_title_height).area;
  return style.unit_mm *
         fitting_ratio(bounds->width() * style.unit_mm, bounds->height() * style.unit_mm, area.width(), area.height());
}

double fitting_scale(const Bounds& bounds, const DrawingStyle& style) {
  const detail::Box area = detail::frame_of(style.sheet, detail::draw_title_height).area;
  return style.unit_mm *
         fitting_ratio(bounds.width() * style.unit_mm, bounds.height() * style.unit_mm, area.width(), area.height());
}

MergedSegments sheet_segments(const LineDrawing& drawing, const DrawingStyle& style) {
  return sheet_segments_at(drawing, style, drawing_scale(drawing, style));
}

void record_sheet_counts(LineDrawing& drawing, const MergedSegments& merged, const DrawingStyle& style) {
  drawing.merged_segments = merged.merged;
  drawing.merge_distance_mm = style.merge_distance;
  drawing.contact_segments = merged.contact;
  drawing.contact_degrees = style.contact_degrees;
}

SheetLines sheet_lines_at(const LineDrawing& drawing, const DrawingStyle& style, double scale) {
  SheetLines sheet;
  sheet.scale = scale;
  sheet.merged = sheet_segments_at(drawing, style, scale);
  // The source's own circles first (source_curves.hpp); what is left is chained, and its circles
  // recovered from the polylines.
  DrawingCurves source;
  const bool true_curves = style.circles && !drawing.source_curves.empty();
  std::vector<DrawingSegment> rest;
  if (true_curves) rest = detail::draw_source_curves(drawing, sheet.merged.segments, source);
  sheet.chains = chain_segments(true_curves ? rest : sheet.merged.segments);
  const double tolerance = style.merge_distance / scale;  // the drawing's resolution, in model units
  sheet.curves = recover_curves(sheet.chains, style.circles ? tolerance : 0);
  sheet.curves.paths.insert(sheet.curves.paths.end(), source.paths.begin(), source.paths.end());
  sheet.curves.circles.insert(sheet.curves.circles.end(), source.circles.begin(), source.circles.end());
  sheet.curves.ellipses = std::move(source.ellipses);
  sheet.curves.arcs += source.arcs;
  sheet.curves.from_source = {source.circles.size(), source.arcs};
  if (style.centre_lines) sheet.centre_lines = centre_marks(sheet.curves, tolerance, centre_overshoot_mm / scale);
  sheet.shadows = drawing.shadows;
  return sheet;
}

SheetLines sheet_lines(const LineDrawing& drawing, const DrawingStyle& style) {
  double scale = drawing_scale(drawing, style);
  const detail::Box area = detail::frame_of(style.sheet, detail::draw_title_height).area;
  // A circle reaches beyond its polygon by up to its sagitta: step down the series until the
  // recovered curves fit too (the tolerance grows as the scale falls, so this ends).
  for (int step = 0;; ++step) {
    SheetLines sheet = sheet_lines_at(drawing, style, scale);
    const auto b = sheet_bounds(sheet);
    if (style.scale || !b || step > 3) return sheet;
    if (b->width() * scale <= area.width() * (1 + 1e-12) && b->height() * scale <= area.height() * (1 + 1e-12)) return sheet;
    scale = style.unit_mm * iso_scale_at_most(scale / style.unit_mm * (1 - 1e-6));
  }
}

std::optional<Bounds> sheet_bounds(const SheetLines& sheet) {
  Bounds b;
  bool any = false;
  for (const auto& path : sheet.curves.paths) {
    include(b, any, path.start[0], path.start[1]);
    Point2 from = path.start;
    for (const auto& step : path.steps) {
      include(b, any, step.to[0], step.to[1]);
      if (step.arc) {
        // The arc's extreme points on the axes it passes.
        const double a0 = std::atan2(from[1] - step.centre[1], from[0] - step.centre[0]);
        const double a1 = std::atan2(step.to[1] - step.centre[1], step.to[0] - step.centre[0]);
        double sweep = step.ccw ? a1 - a0 : a0 - a1;
        while (sweep <= 0) sweep += 2 * pi;
        for (int k = 0; k < 4; ++k) {
          const double axis = k * pi / 2;
          double along = step.ccw ? axis - a0 : a0 - axis;
          while (along < 0) along += 2 * pi;
          while (along >= 2 * pi) along -= 2 * pi;
          if (along < sweep)
            include(b, any, step.centre[0] + step.radius * std::cos(axis), step.centre[1] + step.radius * std::sin(axis));
        }
      }
      from = step.to;
    }
  }
  for (const auto& c : sheet.curves.circles) {
    include(b, any, c.centre[0] - c.radius, c.centre[1] - c.radius);
    include(b, any, c.centre[0] + c.radius, c.centre[1] + c.radius);
  }
  for (const auto& e : sheet.curves.ellipses) {
    // Sampled finely enough for a scale's fit (extent only: 1 - cos(pi / 256) < 1e-4).
    constexpr int samples = 256;
    for (int k = 0; k <= samples; ++k) {
      const Point2 p = ellipse_point(e, e.t0 + (e.t1 - e.t0) * k / samples);
      include(b, any, p[0], p[1]);
    }
  }
  if (!any) return std::nullopt;
  return b;
}

std::optional<std::string> sheet_overflow(const SheetLines& sheet, const DrawingStyle& style) {
  const auto b = sheet_bounds(sheet);
  if (!b) return std::nullopt;
  const detail::Box area = detail::frame_of(style.sheet, detail::draw_title_height).area;
  const double w = b->width() * sheet.scale, h = b->height() * sheet.scale;
  if (w <= area.width() * (1 + 1e-12) && h <= area.height() * (1 + 1e-12)) return std::nullopt;
  using detail::fixed;
  return "the drawing needs " + fixed(w, 1) + " x " + fixed(h, 1) + " mm at " + scale_label(sheet.scale / style.unit_mm) +
         "; the drawing area of " + style.sheet.name + " is " + fixed(area.width(), 1) + " x " + fixed(area.height(), 1) +
         " mm";
}

}  // namespace hlr::exporter
