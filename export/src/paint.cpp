// The sheet painter (paint.hpp).
//
// Lettering after ISO 3098: 2.5 mm labels over 3.5 mm values (the title 5 mm); a character is
// about 0.6 h wide, which is how values are shortened to their cells.
#include "paint.hpp"

#include "numbers.hpp"
#include "text.hpp"

#include <algorithm>
#include <cmath>

namespace hlr::exporter::detail {
namespace {

constexpr double pi = 3.14159265358979323846;
constexpr double area_clearance = 5;
constexpr double max_title_width = 180;

// A label and its value in a cell whose top left corner is (x, y).
void cell(Canvas& c, double x, double y, double width, const std::string& label, const std::string& value,
          double value_size = 3.5, double row = 10) {
  const auto fit = static_cast<std::size_t>(std::max(1.0, (width - 4) / (0.6 * value_size)));
  c.text(x + 2, y + 3.5, 2.5, label);
  if (!value.empty()) c.text(x + 2, y + row - 1.5, value_size, shorten(value, fit));
}

// The part of a turn from a0 to a1 going one way (ccw: angles growing), in (0, 2 pi].
double sweep_of(double a0, double a1, bool ccw) {
  double s = ccw ? a1 - a0 : a0 - a1;
  while (s <= 0) s += 2 * pi;
  while (s > 2 * pi) s -= 2 * pi;
  return s;
}

// A drawing path on the sheet. View angles t become sheet angles -t (y is flipped), so a
// counter-clockwise arc of the view is one of falling angle on the sheet. Arcs are split into
// pieces of at most 3/4 of a half turn (canvas.hpp).
SheetPath sheet_path(const DrawingPath& p, const Placement& at) {
  SheetPath out;
  out.move(at.x(p.start[0]), at.y(p.start[1]));
  Point2 from = p.start;
  for (const auto& step : p.steps) {
    if (!step.arc) {
      out.line(at.x(step.to[0]), at.y(step.to[1]));
    } else {
      const double a0 = std::atan2(from[1] - step.centre[1], from[0] - step.centre[0]);
      const double a1 = std::atan2(step.to[1] - step.centre[1], step.to[0] - step.centre[0]);
      const double sweep = sweep_of(a0, a1, step.ccw);
      const int pieces = std::max(1, int(std::ceil(sweep / (0.75 * pi))));
      const double cx = at.x(step.centre[0]), cy = at.y(step.centre[1]), r = at.scale * step.radius;
      for (int k = 1; k <= pieces; ++k) {
        const double t0 = a0 + (step.ccw ? 1 : -1) * sweep * (k - 1) / pieces;
        const double t1 = a0 + (step.ccw ? 1 : -1) * sweep * k / pieces;
        const double ex = k == pieces ? at.x(step.to[0]) : cx + r * std::cos(t1);
        const double ey = k == pieces ? at.y(step.to[1]) : cy - r * std::sin(t1);
        out.arc(ex, ey, cx, cy, r, -t0, -t1, !step.ccw);
      }
    }
    from = step.to;
  }
  if (p.closed) out.close();
  return out;
}

// An ellipse of the view on the sheet: its axes flipped with y, its parameters t become -t (as
// angles do), split into arcs as circles are.
SheetPath sheet_ellipse(const DrawingEllipse& e, const Placement& at) {
  const double mx = at.scale * e.major[0], my = -at.scale * e.major[1];
  const double rx = std::hypot(mx, my), ry = e.ratio * rx, rotation = std::atan2(my, mx);
  const double cx = at.x(e.centre[0]), cy = at.y(e.centre[1]);
  auto point = [&](double t) {
    const Point2 p = ellipse_point(e, t);
    return std::array<double, 2>{at.x(p[0]), at.y(p[1])};
  };
  SheetPath out;
  const auto start = point(e.t0);
  out.move(start[0], start[1]);
  const double sweep = e.t1 - e.t0;
  const int pieces = std::max(1, int(std::ceil(sweep / (0.75 * pi))));
  for (int k = 1; k <= pieces; ++k) {
    const double t0 = e.t0 + sweep * (k - 1) / pieces, t1 = e.t0 + sweep * k / pieces;
    const auto end = point(t1);
    out.ellipse(end[0], end[1], cx, cy, rx, ry, rotation, -t0, -t1, false);
  }
  if (e.closed) out.close();
  return out;
}

Pen pen_of(double width, const std::vector<double>& dashes = {}) { return Pen{width, dashes}; }

}  // namespace

SheetFrame frame_of(const Sheet& sheet, double title_height) {
  constexpr double frame_left = 20, frame_margin = 10;
  SheetFrame l;
  l.frame = {frame_left, frame_margin, sheet.width_mm - frame_margin, sheet.height_mm - frame_margin};
  l.title = {l.frame.x1 - std::min(max_title_width, l.frame.width()), l.frame.y1 - title_height, l.frame.x1, l.frame.y1};
  l.area = {l.frame.x0 + area_clearance, l.frame.y0 + area_clearance, l.frame.x1 - area_clearance,
            l.title.y0 - area_clearance};
  return l;
}

// The ISO 5457 frame and centring marks (from the sheet edge to 5 mm inside the frame; the bottom
// one stops at the frame where the title block lies under it).
void paint_frame(Canvas& c, const Sheet& sheet, const SheetFrame& l) {
  const Box& f = l.frame;
  const double mx = sheet.width_mm / 2, my = sheet.height_mm / 2;
  const double bottom_mark_end = mx >= l.title.x0 ? f.y1 : f.y1 - 5;
  c.begin({"frame", "", pen_of(frame_width)});
  c.rect(f.x0, f.y0, f.width(), f.height());
  SheetPath marks;
  marks.move(mx, 0);
  marks.vertical(f.y0 + 5);
  marks.move(mx, sheet.height_mm);
  marks.vertical(bottom_mark_end);
  marks.move(0, my);
  marks.horizontal(f.x0 + 5);
  marks.move(sheet.width_mm, my);
  marks.horizontal(f.x1 - 5);
  c.path(marks);
  c.end();
}

void paint_draw_title(Canvas& c, const LineDrawing& drawing, const SheetFrame& l, double ratio) {
  const Box& t = l.title;
  const double view_width = 70, scale_width = 50;  // the bottom row's cells; "hlr" takes the rest
  const double row = 10;
  c.begin({"title-block", "", pen_of(ruling_width)});
  SheetPath rulings;
  rulings.move(t.x0, t.y0 + row);
  rulings.horizontal(t.x1);
  rulings.move(t.x0 + view_width, t.y0 + row);
  rulings.vertical(t.y1);
  rulings.move(t.x0 + view_width + scale_width, t.y0 + row);
  rulings.vertical(t.y1);
  c.path(rulings);
  c.rect(t.x0, t.y0, t.width(), t.height(), frame_width);
  c.end();

  std::string files;
  std::string last;  // a CAD model's solids are meshes of one file: named once
  for (const auto& f : drawing.input.files)
    if (f != last) files += (files.empty() ? "" : ", ") + base_name(last = f);
  std::string view = drawing.view.name.empty() ? "custom" : drawing.view.name;
  if (const auto& e = drawing.view.eye) {
    view = "perspective from (" + fixed((*e)[0], 6) + ", " + fixed((*e)[1], 6) + ", " + fixed((*e)[2], 6) + ")";
  } else if (view == "custom") {
    const auto& d = drawing.view.direction;
    view += " (" + fixed(d[0], 6) + ", " + fixed(d[1], 6) + ", " + fixed(d[2], 6) + ")";
  }
  GroupStyle text = GroupStyle::named("title-text");
  text.lettering = true;
  c.begin(text);
  cell(c, t.x0, t.y0, t.width(), "Files", files);
  cell(c, t.x0, t.y0 + row, view_width, "View", view);
  cell(c, t.x0 + view_width, t.y0 + row, scale_width, "Scale", drawing_scale_label(drawing, ratio));
  cell(c, t.x0 + view_width + scale_width, t.y0 + row, t.width() - view_width - scale_width, "Drawn by",
       drawing.raster ? "hlr, raster " + std::to_string(drawing.raster->resolution) + " px" : std::string("hlr"));
  c.end();
}

// ISO 7200: title and projection symbol over drawing number, revision, scale and sheet, over
// creator, date, units and projection method.
//
//   | Title                               | symbol      |   12 mm
//   | Drawing number | Rev. | Scale       | Sheet       |   10 mm
//   | Created by     | Date       | Units | Projection  |   10 mm
//     70               25/35  35/25         50
void paint_sheet_title(Canvas& c, const SheetFields& fields, const Sheet& sheet, const SheetFrame& l,
                       Projection projection, double ratio, const std::string& units) {
  const Box& t = l.title;
  const double top = 12, row = 10;
  const double y1 = t.y0 + top, y2 = y1 + row;
  const double wide = t.width() - 50;  // title cell; the symbol's and the sheet's cells are 50 wide
  const double x_number = t.x0, x_revision = t.x0 + 70, x_scale = t.x0 + 95, x_right = t.x0 + wide;
  const double x_date = t.x0 + 70, x_units = t.x0 + 105;
  c.begin({"title-block", "", pen_of(ruling_width)});
  SheetPath r;
  r.move(t.x0, y1);
  r.horizontal(t.x1);
  r.move(t.x0, y2);
  r.horizontal(t.x1);
  r.move(x_right, t.y0);
  r.vertical(t.y1);
  r.move(x_revision, y1);
  r.vertical(t.y1);
  r.move(x_scale, y1);
  r.vertical(y2);
  r.move(x_units, y2);
  r.vertical(t.y1);
  c.path(r);
  c.rect(t.x0, t.y0, t.width(), t.height(), frame_width);
  c.end();

  GroupStyle text = GroupStyle::named("title-text");
  text.lettering = true;
  c.begin(text);
  const bool first = projection == Projection::first_angle;
  cell(c, t.x0, t.y0, wide, "Title", fields.title, 5, top);
  cell(c, x_number, y1, 70, "Drawing number", fields.number);
  cell(c, x_revision, y1, 25, "Revision", fields.revision);
  cell(c, x_scale, y1, x_right - x_scale, "Scale", scale_label(ratio));
  cell(c, x_right, y1, t.x1 - x_right, "Sheet", "1/1, " + sheet.name);
  cell(c, t.x0, y2, 70, "Created by", fields.author);
  cell(c, x_date, y2, x_units - x_date, "Date", fields.date);
  cell(c, x_units, y2, x_right - x_units, "Units", units);
  cell(c, x_right, y2, t.x1 - x_right, "Projection", first ? "first angle" : "third angle");
  c.end();

  // ISO 5456-2's symbol: a truncated cone, axis horizontal, small end on the left, in a front view
  // (a trapezoid) and the view from its left (two circles), placed as the method places that view:
  // on the right in first angle, on the left in third angle. h = 3.5 mm lettering: the large
  // diameter is 2h, the small one h, the cone 2h long, lines h/10 wide.
  const double h = 3.5, big = 2 * h, small = h, length = 2 * h, gap = 5;
  const double mid_x = (x_right + t.x1) / 2, mid_y = (t.y0 + y1) / 2;
  const double total = length + gap + big;
  const double left = mid_x - total / 2;
  const double cone_x0 = first ? left : left + big + gap, circles_x = first ? left + length + gap + big / 2 : left + big / 2;
  c.begin({"projection-symbol", first ? "first-angle" : "third-angle", pen_of(h / 10)});
  SheetPath cone;
  cone.move(cone_x0, mid_y - small / 2);
  cone.line(cone_x0 + length, mid_y - big / 2);
  cone.line(cone_x0 + length, mid_y + big / 2);
  cone.line(cone_x0, mid_y + small / 2);
  cone.close();
  c.path(cone);
  c.circle(circles_x, mid_y, big / 2);
  c.circle(circles_x, mid_y, small / 2);
  c.begin({"", "center", pen_of(0.18)});
  SheetPath axes;  // the symbol's centre lines, continuous at this size
  axes.move(left - 1.5, mid_y);
  axes.horizontal(left + total + 1.5);
  axes.move(circles_x, mid_y - big / 2 - 1.5);
  axes.vertical(mid_y + big / 2 + 1.5);
  c.path(axes);
  c.end();
  c.end();
}

void paint_view(Canvas& c, const SheetLines& lines, const Placement& at, const std::vector<std::string>& parts,
                const DrawingStyle& style, const std::string& prefix) {
  const LineWidths widths = line_widths(style.line_group).value_or(LineWidths{});
  const DrawingCurves& curves = lines.curves;
  // Each part's lines in a group of its own inside the class's group, so that a part can be
  // switched off: ids are unique ("part-NAME-visible", "part-NAME-hidden", "part-NAME-thin"), the
  // class names the part in all. Classes by precedence_rank: 0 visible, 1 hidden, 2 thin.
  auto group = [&](int rank) {
    static const char* const names[] = {"visible", "hidden", "thin"};
    const std::string name = names[rank];
    auto of_class = [&](const auto& item) { return item.thin ? rank == 2 : item.visible ? rank == 0 : rank == 1; };
    GroupStyle g;
    g.id = prefix + name;
    if (!prefix.empty() || rank == 2) g.cls = name;
    g.pen = rank == 0 ? pen_of(widths.wide) : rank == 1 ? pen_of(widths.narrow, widths.hidden_dashes) : pen_of(widths.narrow);
    g.line_caps = true;
    c.begin(g);
    for (std::uint32_t part = 0; part < parts.size(); ++part) {
      bool open = false;
      auto open_group = [&] {
        if (open) return;
        open = true;
        c.begin(GroupStyle::named(prefix + "part-" + parts[part] + "-" + name, "part-" + parts[part]));
      };
      for (const auto& p : curves.paths) {
        if (!of_class(p) || p.mesh != part) continue;
        open_group();
        c.path(sheet_path(p, at));
      }
      for (const auto& circle : curves.circles) {
        if (!of_class(circle) || circle.mesh != part) continue;
        open_group();
        c.circle(at.x(circle.centre[0]), at.y(circle.centre[1]), at.scale * circle.radius);
      }
      for (const auto& e : curves.ellipses) {
        if (!of_class(e) || e.mesh != part) continue;
        open_group();
        c.path(sheet_ellipse(e, at));
      }
      if (open) c.end();
    }
    c.end();
  };
  if (!lines.shadows.empty()) {
    // Shadows (hlr draw --sun): surface detail of the visible faces, filled light grey without
    // an outline, below every line.
    GroupStyle g = GroupStyle::named(prefix + "shadows");
    g.fill = std::array<double, 3>{0.82, 0.82, 0.82};
    c.begin(g);
    for (const auto& area : lines.shadows) {
      SheetPath p;
      auto contour = [&](const std::vector<std::array<double, 2>>& points) {
        for (std::size_t i = 0; i < points.size(); ++i) {
          if (i == 0) p.move(at.x(points[i][0]), at.y(points[i][1]));
          else p.line(at.x(points[i][0]), at.y(points[i][1]));
        }
        p.close();
      };
      contour(area.outer);
      for (const auto& h : area.holes) contour(h);
      c.path(p);
    }
    c.end();
  }
  if (style.hidden) group(1);  // below the visible lines
  if (has_thin_lines(curves)) group(2);  // smooth lines, thin continuous: only when there are any
  group(0);
  if (lines.centre_lines.empty()) return;
  // Centre lines: a long dash centred on each line's middle (where marks cross at the centre).
  GroupStyle g;
  g.id = prefix + "center";
  g.cls = "center";
  g.pen = pen_of(widths.narrow, widths.centre_dashes);
  g.line_caps = true;
  c.begin(g);
  double period = 0;
  for (double d : widths.centre_dashes) period += d;
  for (const auto& l : lines.centre_lines) {
    SheetPath p;
    p.move(at.x(l.a[0]), at.y(l.a[1]));
    p.line(at.x(l.b[0]), at.y(l.b[1]));
    const double length = at.scale * std::hypot(l.b[0] - l.a[0], l.b[1] - l.a[1]);
    double offset = period > 0 ? std::fmod(widths.centre_dashes[0] / 2 - length / 2, period) : 0;
    if (offset < 0) offset += period;
    c.path(p, offset);
  }
  c.end();
}

}  // namespace hlr::exporter::detail
