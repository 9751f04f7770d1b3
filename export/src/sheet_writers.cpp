// The documents of a drawing sheet (hlr/export/sheet.hpp): SVG and PDF painted by paint.cpp, DXF
// with dxflib (dxf_writer.hpp). All three draw the same layout.
#include <hlr/export/sheet.hpp>

#include "dxf_writer.hpp"
#include "paint.hpp"

#include <algorithm>
#include <cctype>

namespace hlr::exporter {
namespace {

std::string document_title(const SheetLayout& layout, const SheetSpec& spec) {
  const std::string what = spec.fields.title.empty() ? "hlr sheet" : spec.fields.title;
  return what + ", " + spec.style.sheet.name + ", " + scale_label(layout.ratio);
}

std::string paint_sheet(std::unique_ptr<detail::Canvas> canvas, const SheetLayout& layout, const SheetSpec& spec) {
  const DrawingStyle& style = spec.style;
  const detail::SheetFrame frame = detail::frame_of(style.sheet, detail::sheet_title_height);
  detail::paint_frame(*canvas, style.sheet, frame);
  detail::paint_sheet_title(*canvas, spec.fields, style.sheet, frame, spec.projection, layout.ratio, style.units);
  for (const auto& v : layout.views) {
    const std::string id = "view-" + v.name;
    canvas->begin(detail::GroupStyle::named(id, "view"));
    detail::paint_view(*canvas, v.lines, {v.ox, v.oy, layout.scale}, part_names(*v.drawing), style, id + "-");
    canvas->end();
  }
  return canvas->finish();
}

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

std::string sheet_svg(const SheetLayout& layout, const SheetSpec& spec) {
  const Sheet& sheet = spec.style.sheet;
  return paint_sheet(detail::svg_canvas(sheet.width_mm, sheet.height_mm, document_title(layout, spec)), layout, spec);
}

std::string sheet_pdf(const SheetLayout& layout, const SheetSpec& spec) {
  const Sheet& sheet = spec.style.sheet;
  return paint_sheet(detail::pdf_canvas(sheet.width_mm, sheet.height_mm, document_title(layout, spec)), layout, spec);
}

// The sheet in millimetres (y up, origin at the sheet's bottom left corner): frame, title block
// and symbol on BORDER in model space, each view a block VIEW_NAME of its lines in model units
// (the view's own coordinates), inserted at its origin's place, scaled by the sheet's scale. An
// entity in a block has the linetype scale 1 / scale, so that its dashes are the SVG's millimetres
// on the sheet once the insert scales it.
std::string sheet_dxf(const SheetLayout& layout, const SheetSpec& spec) {
  const DrawingStyle& style = spec.style;
  const Sheet& sheet = style.sheet;
  const LineWidths widths = line_widths(style.line_group).value_or(LineWidths{});
  DL_Dxf dxf;
  detail::DxfText body;
  body.sectionTables();
  dxf.writeVPort(body);
  detail::dxf_linetypes(dxf, body, widths);
  std::vector<detail::DxfLayer> layers{{"VISIBLE", 7, widths.wide, "CONTINUOUS"},
                                       {"HIDDEN", 8, widths.narrow, "HIDDEN"},
                                       {"CENTER", 1, widths.narrow, "CENTER"},
                                       {"BORDER", 7, detail::frame_width, "CONTINUOUS"}};
  // Smooth lines (thin continuous, ISO 128 01.1): a layer of their own, when a view has any.
  if (std::any_of(layout.views.begin(), layout.views.end(), [](const PlacedView& v) { return has_thin_lines(v.lines.curves); }))
    layers.push_back({"THIN", 7, widths.narrow, "CONTINUOUS"});
  // Shadows (hlr sheet --sun): solid hatches in the view blocks, as hlr draw writes them.
  if (std::any_of(layout.views.begin(), layout.views.end(), [](const PlacedView& v) { return !v.lines.shadows.empty(); }))
    layers.push_back({"SHADOW", 9, widths.narrow, "CONTINUOUS"});
  detail::dxf_layers(dxf, body, layers);
  std::vector<std::string> blocks;
  for (const auto& v : layout.views) blocks.push_back("VIEW_" + upper(v.name));
  detail::dxf_other_tables(dxf, body, blocks);

  body.sectionBlocks();
  for (const char* block : {"*Model_Space", "*Paper_Space", "*Paper_Space0"}) {
    dxf.writeBlock(body, DL_BlockData(block, 0, 0.0, 0.0, 0.0));
    dxf.writeEndBlock(body, block);
  }
  const double ltscale = 1 / layout.scale;
  for (std::size_t i = 0; i < layout.views.size(); ++i) {
    const PlacedView& v = layout.views[i];
    dxf.writeBlock(body, DL_BlockData(blocks[i], 0, 0.0, 0.0, 0.0));
    detail::dxf_hatches(dxf, body, v.lines.shadows, "SHADOW");  // below the lines, as hlr draw
    detail::dxf_curves(dxf, body, v.lines.curves, style.hidden,
                       [](int rank, std::uint32_t) { return std::string(rank == 0 ? "VISIBLE" : rank == 1 ? "HIDDEN" : "THIN"); },
                       ltscale);
    detail::dxf_centre_lines(dxf, body, v.lines.centre_lines, "CENTER", ltscale);
    dxf.writeEndBlock(body, blocks[i]);
  }
  body.sectionEnd();

  body.sectionEntities();
  {
    const detail::SheetFrame frame = detail::frame_of(sheet, detail::sheet_title_height);
    auto canvas = detail::dxf_canvas(dxf, body, sheet.height_mm, "BORDER");
    detail::paint_frame(*canvas, sheet, frame);
    detail::paint_sheet_title(*canvas, spec.fields, sheet, frame, spec.projection, layout.ratio, style.units);
  }
  for (std::size_t i = 0; i < layout.views.size(); ++i) {
    const PlacedView& v = layout.views[i];
    dxf.writeInsert(body,
                    DL_InsertData(blocks[i], v.ox, sheet.height_mm - v.oy, 0.0, layout.scale, layout.scale, 1.0, 0.0, 1, 1,
                                  0.0, 0.0),
                    DL_Attributes("0", 256, -1, "BYLAYER", 1.0));
  }
  body.sectionEnd();
  dxf.writeObjects(body);
  dxf.writeObjectsEnd(body);
  body.dxfEOF();

  std::string text = detail::dxf_header(body.getNextHandle(), 4, 1.0, Bounds{0, 0, sheet.width_mm, sheet.height_mm});
  text += body.text();
  return text;
}

}  // namespace hlr::exporter
