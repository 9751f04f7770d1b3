// The painter of sheets (SVG and PDF, through canvas.hpp): the ISO 5457 frame, the title blocks
// of `hlr draw` and of `hlr sheet` (ISO 7200), the ISO 5456-2 projection symbol, and the lines
// of a view placed on the sheet. Shared by lines_writers.cpp (one view) and sheet_writers.cpp.
//
// Sheet millimetres, SVG axes: origin top left, y down. A view is placed by its origin and scale:
// a point (x, y) of the view (model units, y up) is at (ox + scale x, oy - scale y) on the sheet.
#pragma once

#include "canvas.hpp"

#include <hlr/export/lines.hpp>
#include <hlr/export/sheet.hpp>

#include <string>
#include <vector>

namespace hlr::exporter::detail {

struct Box {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  double width() const { return x1 - x0; }
  double height() const { return y1 - y0; }
  double cx() const { return (x0 + x1) / 2; }
  double cy() const { return (y0 + y1) / 2; }
};

// ISO 5457 drawing-space frame (20 mm filing margin on the left, 10 mm elsewhere), the title block
// bottom right inside it (at most 180 mm wide, `title_height` tall), and the drawing area: the
// frame's inside above the title block's strip (the full frame width, so that the area stays a
// rectangle) less a clearance, so that lines never touch frame or title block.
struct SheetFrame {
  Box frame, title, area;
};
inline constexpr double draw_title_height = 20;   // hlr draw: two 10 mm rows
inline constexpr double sheet_title_height = 32;  // hlr sheet: rows of 12, 10 and 10 mm
SheetFrame frame_of(const Sheet& sheet, double title_height);

// Line widths of the sheet furniture: frame and title block outline wide (ISO 5457, ISO 7200),
// title block rulings narrow.
inline constexpr double frame_width = 0.7, ruling_width = 0.35;

void paint_frame(Canvas& canvas, const Sheet& sheet, const SheetFrame& frame);
// hlr draw's title block: files, view, scale, and the program.
void paint_draw_title(Canvas& canvas, const LineDrawing& drawing, const SheetFrame& frame, double ratio);
// hlr sheet's ISO 7200 title block with the projection symbol in it.
void paint_sheet_title(Canvas& canvas, const SheetFields& fields, const Sheet& sheet, const SheetFrame& frame,
                       Projection projection, double ratio, const std::string& units);

// The view point (rx, ry) goes to the sheet point (ox, oy): a sheet's views have (rx, ry) at their
// origin, hlr draw's one view the centre of its lines, placed on the drawing area's centre.
struct Placement {
  double ox = 0, oy = 0, scale = 1;
  double rx = 0, ry = 0;
  double x(double vx) const { return ox + (vx - rx) * scale; }
  double y(double vy) const { return oy - (vy - ry) * scale; }
};

// A view's lines: the shadows (filled, if the drawing has any), the hidden group (if
// style.hidden), the thin group (smooth lines, if it has any), the visible group and the
// centre-line group (if it has any), each with a group per part. `prefix` starts the groups' ids
// ("" for hlr draw's "hidden", "thin", "visible", "center"; "view-front-" in a sheet).
void paint_view(Canvas& canvas, const SheetLines& lines, const Placement& at, const std::vector<std::string>& parts,
                const DrawingStyle& style, const std::string& prefix);

}  // namespace hlr::exporter::detail
