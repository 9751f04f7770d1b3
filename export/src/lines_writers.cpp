// The kernel-independent writers of hlr/export/lines.hpp: sheets, chaining of the drawing
// segments into polylines, and the one-view SVG, PDF and DXF documents of `hlr draw` (the
// hlr-lines/1 JSON is in lines_json.cpp). Everything here works on plain doubles; the one rounding
// of the exact result happened in make_drawing.
//
// SVG and PDF are painted by paint.cpp on a canvas (canvas.hpp); the DXF is written with dxflib
// through dxf_writer.hpp. Line styles after ISO 128-20 (lines.hpp, line_widths), in the 0.5 mm
// line group by default:
//   visible  continuous wide line, 0.5 mm;
//   hidden   dashed narrow line, 0.25 mm, dash 12d = 3 mm, gap 3d = 0.75 mm (d = line width);
//   centre   long-dash dotted narrow line, 0.25 mm, dash 24d = 6 mm, gaps 3d, dot 0.5d.
#include <hlr/export/lines.hpp>

#include "dxf_writer.hpp"
#include "paint.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace hlr::exporter {
namespace {

// Chains of one class (precedence_rank); segments of different meshes are never joined (each
// part's lines are its own).
std::vector<DrawingPolyline> chain_class(const std::vector<DrawingSegment>& segments, int rank) {
  std::vector<const DrawingSegment*> mine;  // this class's segments of non-zero length, in input order
  for (const auto& s : segments)
    if (precedence_rank(s) == rank && s.a != s.b) mine.push_back(&s);
  // The segments' ends, end 2i being mine[i]'s a and 2i + 1 its b, grouped by mesh and point:
  // sorted stably, so that a point's ends stay in segment order. Exact equality of endpoints:
  // -0.0 and 0.0 are one point, as they should be.
  const std::size_t end_count = 2 * mine.size();
  auto point = [&](std::uint32_t end) -> const Point2& { return end % 2 ? mine[end / 2]->b : mine[end / 2]->a; };
  auto before = [&](std::uint32_t e, std::uint32_t f) {
    const std::uint32_t me = mine[e / 2]->mesh, mf = mine[f / 2]->mesh;
    return me != mf ? me < mf : point(e) < point(f);
  };
  std::vector<std::uint32_t> ends(end_count);
  for (std::uint32_t e = 0; e < end_count; ++e) ends[e] = e;
  std::stable_sort(ends.begin(), ends.end(), before);
  // The ends at the point of end e are ends[first[at[e]], first[at[e] + 1]).
  std::vector<std::uint32_t> at(end_count), first;
  for (std::size_t k = 0; k < end_count; ++k) {
    if (k == 0 || before(ends[k - 1], ends[k])) first.push_back(std::uint32_t(k));
    at[ends[k]] = std::uint32_t(first.size() - 1);
  }
  first.push_back(std::uint32_t(end_count));
  auto degree = [&](std::uint32_t end) { return first[at[end] + 1] - first[at[end]]; };

  std::vector<bool> used(mine.size(), false);
  // Walks on from `end` (an end of segment `via`) through points of degree two.
  auto walk = [&](std::uint32_t end, std::size_t via, std::vector<Point2>& points) {
    for (;;) {
      if (degree(end) != 2) return;
      const std::uint32_t* incident = &ends[first[at[end]]];
      const std::size_t next = incident[0] / 2 == via ? incident[1] / 2 : incident[0] / 2;
      if (used[next]) return;
      used[next] = true;
      end = mine[next]->a == point(end) ? std::uint32_t(2 * next + 1) : std::uint32_t(2 * next);  // its other end
      points.push_back(point(end));
      via = next;
    }
  };

  std::vector<DrawingPolyline> chains;
  for (std::size_t seed = 0; seed < mine.size(); ++seed) {
    if (used[seed]) continue;
    used[seed] = true;
    DrawingPolyline chain;
    chain.visible = mine[seed]->visible;
    chain.thin = mine[seed]->thin;
    chain.mesh = mine[seed]->mesh;
    chain.points = {mine[seed]->a, mine[seed]->b};
    walk(std::uint32_t(2 * seed + 1), seed, chain.points);
    const Point2 start = chain.points.front();
    if (chain.points.size() > 2 && chain.points.back() == start && degree(std::uint32_t(2 * seed)) == 2) {
      chain.points.pop_back();  // went round a loop
      chain.closed = true;
    } else {
      std::vector<Point2> back;
      walk(std::uint32_t(2 * seed), seed, back);
      chain.points.insert(chain.points.begin(), back.rbegin(), back.rend());
    }
    chains.push_back(std::move(chain));
  }
  return chains;
}

// The drawing's centre on the area's centre; view y up, sheet y down.
detail::Placement placement(const SheetLines& lines, const detail::SheetFrame& frame) {
  if (lines.centre) return {frame.area.cx(), frame.area.cy(), lines.scale, (*lines.centre)[0], (*lines.centre)[1]};
  const Bounds b = sheet_bounds(lines).value_or(Bounds{});
  return {frame.area.cx(), frame.area.cy(), lines.scale, (b.x0 + b.x1) / 2, (b.y0 + b.y1) / 2};
}

std::string paint_drawing(std::unique_ptr<detail::Canvas> canvas, const LineDrawing& drawing, const DrawingStyle& style,
                          const SheetLines& lines) {
  const detail::SheetFrame frame = detail::frame_of(style.sheet, detail::draw_title_height);
  detail::paint_frame(*canvas, style.sheet, frame);
  detail::paint_draw_title(*canvas, drawing, frame, lines.scale / style.unit_mm);
  detail::paint_view(*canvas, lines, placement(lines, frame), part_names(drawing), style, "");
  return canvas->finish();
}

std::string sheet_title(const LineDrawing& drawing, const DrawingStyle& style, const SheetLines& lines) {
  return "hlr drawing, " + style.sheet.name + ", " + drawing_scale_label(drawing, lines.scale / style.unit_mm);
}

}  // namespace

// ---------------------------------------------------------------------------------------------

std::optional<Sheet> sheet_by_name(const std::string& name) {
  std::string upper = name;
  for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  // ISO 216 A series, landscape (width > height).
  static const Sheet sheets[] = {
      {"A0", 1189, 841}, {"A1", 841, 594}, {"A2", 594, 420}, {"A3", 420, 297}, {"A4", 297, 210}};
  for (const Sheet& s : sheets)
    if (s.name == upper) return s;
  return std::nullopt;
}

std::vector<DrawingPolyline> chain_segments(const std::vector<DrawingSegment>& segments) {
  std::vector<DrawingPolyline> chains;
  for (int rank = 0; rank < 3; ++rank) {
    auto of_class = chain_class(segments, rank);
    chains.insert(chains.end(), std::make_move_iterator(of_class.begin()), std::make_move_iterator(of_class.end()));
  }
  return chains;
}

double LineDrawing::length(bool visible) const {
  double sum = 0;
  for (const auto& seg : segments)
    if (seg.visible == visible) sum += std::hypot(seg.b[0] - seg.a[0], seg.b[1] - seg.a[1]);
  return sum;
}

std::string lines_svg(const LineDrawing& drawing, const DrawingStyle& style, const SheetLines& lines) {
  return paint_drawing(detail::svg_canvas(style.sheet.width_mm, style.sheet.height_mm, sheet_title(drawing, style, lines)),
                       drawing, style, lines);
}

std::string lines_pdf(const LineDrawing& drawing, const DrawingStyle& style, const SheetLines& lines) {
  return paint_drawing(detail::pdf_canvas(style.sheet.width_mm, style.sheet.height_mm, sheet_title(drawing, style, lines)),
                       drawing, style, lines);
}

std::string lines_dxf(const LineDrawing& drawing, const DrawingStyle& style, const SheetLines& lines) {
  const LineWidths widths = line_widths(style.line_group).value_or(LineWidths{});
  // Everything after the HEADER first, so that $HANDSEED can name the next free handle.
  DL_Dxf dxf;  // writes R2000 (AC1015) unless told otherwise
  detail::DxfText body;
  body.text().reserve(8192 + 64 * drawing.segments.size());
  body.sectionTables();
  dxf.writeVPort(body);
  detail::dxf_linetypes(dxf, body, widths);

  // One mesh: layers VISIBLE and HIDDEN. Several: a pair per part, NAME-VISIBLE and NAME-HIDDEN
  // with the part's name in upper case (DXF layer names are compared in any case), every part's
  // pair defined even where it has no line, so that a CAD user finds every part. CENTER always.
  const auto names = part_names(drawing);
  const bool per_part = drawing.input.files.size() > 1;
  auto layer = [&](int rank, std::uint32_t mesh) {
    std::string name = rank == 0 ? "VISIBLE" : rank == 1 ? "HIDDEN" : "THIN";
    if (!per_part) return name;
    std::string part = names[mesh];  // part_names names every mesh a segment has
    for (char& c : part) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return part + "-" + name;
  };
  const std::uint32_t layer_pairs = per_part ? std::uint32_t(names.size()) : 1;
  std::vector<detail::DxfLayer> layers;
  // Smooth lines (thin continuous, ISO 128 01.1) have a layer THIN (NAME-THIN per part) when the
  // drawing has any.
  const bool thin = has_thin_lines(lines.curves);
  for (std::uint32_t part = 0; part < layer_pairs; ++part) {
    layers.push_back({layer(0, part), 7, widths.wide, "CONTINUOUS"});
    layers.push_back({layer(1, part), 8, widths.narrow, "HIDDEN"});
    if (thin) layers.push_back({layer(2, part), 7, widths.narrow, "CONTINUOUS"});
  }
  layers.push_back({"CENTER", 1, widths.narrow, "CENTER"});
  if (!lines.shadows.empty()) layers.push_back({"SHADOW", 9, widths.narrow, "CONTINUOUS"});
  detail::dxf_layers(dxf, body, layers);
  detail::dxf_other_tables(dxf, body, {});

  body.sectionBlocks();
  for (const char* block : {"*Model_Space", "*Paper_Space", "*Paper_Space0"}) {
    dxf.writeBlock(body, DL_BlockData(block, 0, 0.0, 0.0, 0.0));
    dxf.writeEndBlock(body, block);
  }
  body.sectionEnd();

  body.sectionEntities();
  detail::dxf_hatches(dxf, body, lines.shadows, "SHADOW");
  detail::dxf_curves(dxf, body, lines.curves, style.hidden, layer, 1.0);
  detail::dxf_centre_lines(dxf, body, lines.centre_lines, "CENTER", 1.0);
  body.sectionEnd();
  dxf.writeObjects(body);
  dxf.writeObjectsEnd(body);
  body.dxfEOF();

  // Model units; $LTSCALE makes the dashes their millimetres when plotted at the drawing's scale.
  std::string text = detail::dxf_header(body.getNextHandle(), detail::dxf_insunits(style.units), 1 / lines.scale,
                                        sheet_bounds(lines).value_or(Bounds{}));
  text += body.text();
  return text;
}

std::string lines_svg(const LineDrawing& drawing, const DrawingStyle& style) {
  return lines_svg(drawing, style, sheet_lines(drawing, style));
}

std::string lines_pdf(const LineDrawing& drawing, const DrawingStyle& style) {
  return lines_pdf(drawing, style, sheet_lines(drawing, style));
}

std::string lines_dxf(const LineDrawing& drawing, const DrawingStyle& style) {
  return lines_dxf(drawing, style, sheet_lines(drawing, style));
}

}  // namespace hlr::exporter
