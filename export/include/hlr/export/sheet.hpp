// hlr export, sheet: several views of one scene on one drawing sheet, as a drafter lays it out
// (DESIGN.md, "Drawing sheets"; docs/FORMATS.md, "hlr sheet").
//
//   lay_out_sheet  places the views after ISO 5456-2 (first or third angle) at one ISO 5455 scale
//                  that fits them all with room between them, or at the given scale (a SheetError
//                  when they do not fit). The principal views are aligned in model coordinates:
//                  front, top and bottom share their sheet x for a model point, front and the side
//                  and back views their sheet y. Other views (iso, a direction) take free corners.
//                  Each view's lines are the one-view sheet's (lines.hpp, sheet_lines_at) at the
//                  common scale, with centre lines added on the cylinders whose circles another,
//                  orthogonal view shows.
//   sheet_svg      the sheet as SVG: one group <g id="view-NAME"> per view, ISO 7200 title block
//                  and ISO 5456-2 projection symbol outside them.
//   sheet_pdf      the same sheet as a vector PDF (cairo).
//   sheet_dxf      the same sheet as DXF R2000 in millimetres: one block VIEW_NAME per view (model
//                  units) inserted at its place and scale; layers VISIBLE, HIDDEN, CENTER, BORDER.
#pragma once

#include <hlr/export/lines.hpp>

#include <stdexcept>
#include <string>
#include <vector>

namespace hlr::exporter {

enum class Projection { first_angle, third_angle };

// The title block's fields (ISO 7200); empty ones are left blank.
struct SheetFields {
  std::string title, number, author, date, revision;
};

struct SheetSpec {
  DrawingStyle style;  // sheet, scale (none: fit), hidden lines, resolution, line group, units
  Projection projection = Projection::third_angle;
  SheetFields fields;
};

// One view to place: its name as the user gave it ("front", "iso", "custom") and its drawing.
struct SheetViewInput {
  std::string name;
  const LineDrawing* drawing = nullptr;
};

// A placed view: a point (x, y) of its drawing (model units, y up) is at (ox + scale x,
// oy - scale y) on the sheet (mm, y down).
struct PlacedView {
  std::string name;
  const LineDrawing* drawing = nullptr;
  SheetLines lines;
  double ox = 0, oy = 0;
  int row = 0, column = 0;  // its cell: front at (0, 0), rows grow downwards, columns to the right
};

struct SheetLayout {
  double scale = 1;  // sheet mm per model unit (the ratio times style.unit_mm)
  double ratio = 1;  // the ISO 5455 scale, sheet to part
  std::vector<PlacedView> views;
  std::size_t circles = 0, arcs = 0, centre_lines = 0;  // over all views
};

// A sheet that cannot be made: one line, for the user ("--scale 20:1: the views need ...").
struct SheetError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The cell of a named view after ISO 5456-2 (row -1 above the front view, 1 below; column -1 to
// its left, 1 to its right, 2 beyond that), or nothing for a view that is not a principal one.
std::optional<std::pair<int, int>> principal_cell(const std::string& view, Projection projection);

// Minimum room between views and around the group of views, mm on the sheet.
inline constexpr double view_gap_mm = 10;

SheetLayout lay_out_sheet(const std::vector<SheetViewInput>& views, const SheetSpec& spec);

std::string sheet_svg(const SheetLayout& layout, const SheetSpec& spec);
std::string sheet_pdf(const SheetLayout& layout, const SheetSpec& spec);
std::string sheet_dxf(const SheetLayout& layout, const SheetSpec& spec);

}  // namespace hlr::exporter
