// The kernel-independent writers of hlr/export/lines.hpp: the sheet and its scale, chaining of the
// drawing segments into polylines, and the SVG and DXF documents (the hlr-lines/1 JSON is in
// lines_json.cpp). Everything here works on plain doubles; the one rounding of the exact result
// happened in make_drawing.
//
// Line styles after ISO 128-20 (line types 01 and 02) in the 0.5 mm line group:
//   visible  continuous wide line, 0.5 mm;
//   hidden   dashed narrow line, 0.25 mm, dash 12d = 3 mm, gap 3d = 0.75 mm (d = line width).
//
// The DXF is written with Debian's dxflib (libdxflib-dev). Evaluated against ezdxf 0.18's audit
// (recover.readfile, then doc.audit()) on a drawing with layers, a dashed linetype and
// LWPOLYLINEs: no errors. ezdxf does repair 13 missing owner handles (330) in the OBJECTS section
// dxflib writes (dictionaries, layouts, MLINESTYLE), reported as fixes, not errors, and its strict
// ezdxf.readfile takes the file as it is. dxflib writes only to a named file and hard-codes
// $HANDSEED FFFF, so a writer subclass below collects the text in memory instead (with
// round-trip numbers), and the HEADER section is written once the last handle is known.
#include <hlr/export/lines.hpp>

#include "numbers.hpp"

#include <dl_dxf.h>
#include <dl_writer_ascii.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <string_view>

namespace hlr::exporter {
namespace {

// ---------------------------------------------------------------------------------------------
// Sheet layout (millimetres, SVG axes: origin top left, y down).

// ISO 5457 drawing-space frame: 20 mm filing margin on the left, 10 mm elsewhere.
constexpr double frame_left = 20, frame_margin = 10;
// ISO 7200 title block, bottom right inside the frame: at most 180 mm wide; two 10 mm rows.
constexpr double title_width = 180, title_row = 10, title_height = 2 * title_row;
// The drawing area is the frame's inside above the title block's strip (the full frame width,
// so that the area stays a rectangle), less a clearance so lines never touch frame or title block.
constexpr double area_clearance = 5;
// Line widths of the sheet furniture: frame and title block outline wide (ISO 5457, ISO 7200),
// title block rulings narrow.
constexpr double frame_width = 0.7, ruling_width = 0.35;
// ISO 128-20 line types 01 (visible) and 02 (hidden) in the 0.5 mm line group.
constexpr double visible_width = 0.5, hidden_width = 0.25;
constexpr double hidden_dash = 12 * hidden_width, hidden_gap = 3 * hidden_width;  // 3 mm, 0.75 mm

struct Box {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  double width() const { return x1 - x0; }
  double height() const { return y1 - y0; }
  double cx() const { return (x0 + x1) / 2; }
  double cy() const { return (y0 + y1) / 2; }
};

struct SheetLayout {
  Box frame, title, area;
};

SheetLayout layout_of(const Sheet& sheet) {
  SheetLayout l;
  l.frame = {frame_left, frame_margin, sheet.width_mm - frame_margin, sheet.height_mm - frame_margin};
  l.title = {l.frame.x1 - std::min(title_width, l.frame.width()), l.frame.y1 - title_height, l.frame.x1, l.frame.y1};
  l.area = {l.frame.x0 + area_clearance, l.frame.y0 + area_clearance, l.frame.x1 - area_clearance,
            l.title.y0 - area_clearance};
  return l;
}

bool is_drawn(const DrawingSegment& s, const DrawingStyle& style) { return s.visible || style.hidden; }

// Bounding box of the drawn segments in view coordinates; nothing when none is drawn.
std::optional<Box> drawn_bounds(const LineDrawing& drawing, const DrawingStyle& style) {
  std::optional<Box> box;
  for (const auto& s : drawing.segments) {
    if (!is_drawn(s, style)) continue;
    for (const Point2& p : {s.a, s.b}) {
      if (!box) box = Box{p[0], p[1], p[0], p[1]};
      box->x0 = std::min(box->x0, p[0]);
      box->y0 = std::min(box->y0, p[1]);
      box->x1 = std::max(box->x1, p[0]);
      box->y1 = std::max(box->y1, p[1]);
    }
  }
  return box;
}

// ---------------------------------------------------------------------------------------------
// Numbers.

// A document's text, appended to in place; numbers through numbers.hpp, so that no number makes a
// stream or a string of its own.
struct Text {
  std::string s;
  Text& operator<<(std::string_view v) {
    s += v;
    return *this;
  }
  Text& operator<<(char c) {
    s += c;
    return *this;
  }
};

// Sheet millimetres: 0.1 µm is below anything a plotter or a viewer shows.
struct Mm {
  double v;
};
Mm mm(double v) { return {v}; }
Text& operator<<(Text& out, Mm v) {
  detail::append_fixed(out.s, v.v, 4);
  return out;
}

using detail::fixed;

// "1:5", "2:1", "1:2.5".
std::string scale_label(double scale) {
  return scale >= 1 ? fixed(scale, 4) + ":1" : "1:" + fixed(1 / scale, 4);
}

std::string xml_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string base_name(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

// At most `chars` characters (UTF-8 aware: never cuts inside a character), "…" when cut.
std::string shorten(const std::string& s, std::size_t chars) {
  std::size_t count = 0, i = 0;
  for (; i < s.size(); ++i) {
    if ((static_cast<unsigned char>(s[i]) & 0xC0) == 0x80) continue;  // continuation byte
    if (count == chars) return s.substr(0, i) + "\u2026";
    ++count;
  }
  return s;
}

// ---------------------------------------------------------------------------------------------
// Chaining.

// Chains of one class; segments of different meshes are never joined (each part's lines are its own).
std::vector<DrawingPolyline> chain_class(const std::vector<DrawingSegment>& segments, bool visible) {
  std::vector<const DrawingSegment*> mine;  // this class's segments of non-zero length, in input order
  for (const auto& s : segments)
    if (s.visible == visible && s.a != s.b) mine.push_back(&s);
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
    chain.visible = visible;
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

// ---------------------------------------------------------------------------------------------
// SVG.

void svg_title_block(Text& out, const LineDrawing& drawing, const SheetLayout& l, double scale) {
  const Box& t = l.title;
  const double view_width = 70, scale_width = 50;  // the bottom row's cells; "hlr" takes the rest
  out << "<g id=\"title-block\" fill=\"none\" stroke=\"#000\" stroke-width=\"" << mm(ruling_width) << "\">\n"
      << "<path d=\"M" << mm(t.x0) << ' ' << mm(t.y0 + title_row) << 'H' << mm(t.x1) << 'M'
      << mm(t.x0 + view_width) << ' ' << mm(t.y0 + title_row) << 'V' << mm(t.y1) << 'M'
      << mm(t.x0 + view_width + scale_width) << ' ' << mm(t.y0 + title_row) << 'V' << mm(t.y1) << "\"/>\n"
      << "<rect x=\"" << mm(t.x0) << "\" y=\"" << mm(t.y0) << "\" width=\"" << mm(t.width()) << "\" height=\""
      << mm(t.height()) << "\" stroke-width=\"" << mm(frame_width) << "\"/>\n"
      << "</g>\n";

  std::string files;
  for (const auto& f : drawing.input.files) files += (files.empty() ? "" : ", ") + base_name(f);
  std::string view = drawing.view.name.empty() ? "custom" : drawing.view.name;
  if (view == "custom") {
    const auto& d = drawing.view.direction;
    view += " (" + fixed(d[0], 6) + ", " + fixed(d[1], 6) + ", " + fixed(d[2], 6) + ")";
  }
  // Lettering after ISO 3098: 2.5 mm labels over 3.5 mm values; a character is about 0.6 h wide.
  auto cell = [&](double x, double y, double width, const std::string& label, const std::string& value) {
    const auto fit = static_cast<std::size_t>(std::max(1.0, (width - 4) / (0.6 * 3.5)));
    out << "<text x=\"" << mm(x + 2) << "\" y=\"" << mm(y + 3.5) << "\" font-size=\"2.5\">" << label
        << "</text>\n"
        << "<text x=\"" << mm(x + 2) << "\" y=\"" << mm(y + 8.5) << "\" font-size=\"3.5\">"
        << xml_escape(shorten(value, fit)) << "</text>\n";
  };
  out << "<g id=\"title-text\" font-family=\"sans-serif\" fill=\"#000\">\n";
  cell(t.x0, t.y0, t.width(), "Files", files);
  cell(t.x0, t.y0 + title_row, view_width, "View", view);
  cell(t.x0 + view_width, t.y0 + title_row, scale_width, "Scale", scale_label(scale));
  cell(t.x0 + view_width + scale_width, t.y0 + title_row, t.width() - view_width - scale_width, "Drawn by",
       drawing.raster ? "hlr, raster " + std::to_string(drawing.raster->resolution) + " px" : std::string("hlr"));
  out << "</g>\n";
}

// The ISO 5457 frame and centring marks (from the sheet edge to 5 mm inside the frame; the bottom
// one stops at the frame where the title block lies under it).
void svg_frame(Text& out, const Sheet& sheet, const SheetLayout& l) {
  const Box& f = l.frame;
  const double mx = sheet.width_mm / 2, my = sheet.height_mm / 2;
  const double bottom_mark_end = mx >= l.title.x0 ? f.y1 : f.y1 - 5;
  out << "<g id=\"frame\" fill=\"none\" stroke=\"#000\" stroke-width=\"" << mm(frame_width) << "\">\n"
      << "<rect x=\"" << mm(f.x0) << "\" y=\"" << mm(f.y0) << "\" width=\"" << mm(f.width()) << "\" height=\""
      << mm(f.height()) << "\"/>\n"
      << "<path d=\"M" << mm(mx) << " 0V" << mm(f.y0 + 5) << 'M' << mm(mx) << ' ' << mm(sheet.height_mm) << 'V'
      << mm(bottom_mark_end) << "M0 " << mm(my) << 'H' << mm(f.x0 + 5) << 'M' << mm(sheet.width_mm) << ' ' << mm(my)
      << 'H' << mm(f.x1 - 5) << "\"/>\n"
      << "</g>\n";
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

double drawing_scale(const LineDrawing& drawing, const DrawingStyle& style) {
  if (style.scale) return *style.scale;
  const auto bounds = drawn_bounds(drawing, style);
  if (!bounds) return 1;
  const Box area = layout_of(style.sheet).area;
  const double w = bounds->width(), h = bounds->height();
  double largest = HUGE_VAL;  // the largest scale that fits, before rounding down to ISO 5455
  if (w > 0) largest = std::min(largest, area.width() / w);
  if (h > 0) largest = std::min(largest, area.height() / h);
  if (!std::isfinite(largest) || largest <= 0) return 1;  // a point, or an area too small to tell

  // ISO 5455: 1, 2 and 5 times a power of ten. A scale is kept as drawing:model, so that the fit
  // test multiplies by whole numbers instead of dividing by rounded powers of ten.
  auto fits = [&](double on_sheet, double in_model) {
    return w * on_sheet <= area.width() * in_model && h * on_sheet <= area.height() * in_model;
  };
  const int top = std::clamp(static_cast<int>(std::floor(std::log10(largest))) + 1, -300, 300);
  for (int e = top; e >= -300; --e) {
    const double power = std::pow(10.0, std::abs(e));
    for (double m : {5.0, 2.0, 1.0}) {
      const double on_sheet = e >= 0 ? m * power : m, in_model = e >= 0 ? 1 : power;
      if (fits(on_sheet, in_model)) return on_sheet / in_model;
    }
  }
  return 1;
}

std::vector<DrawingPolyline> chain_segments(const std::vector<DrawingSegment>& segments) {
  auto chains = chain_class(segments, true);
  auto hidden = chain_class(segments, false);
  chains.insert(chains.end(), std::make_move_iterator(hidden.begin()), std::make_move_iterator(hidden.end()));
  return chains;
}

double LineDrawing::length(bool visible) const {
  double sum = 0;
  for (const auto& seg : segments)
    if (seg.visible == visible) sum += std::hypot(seg.b[0] - seg.a[0], seg.b[1] - seg.a[1]);
  return sum;
}

std::string lines_svg(const LineDrawing& drawing, const DrawingStyle& style, const SheetLines& lines) {
  const Sheet& sheet = style.sheet;
  const SheetLayout l = layout_of(sheet);
  const double scale = lines.scale;
  const Box bounds = drawn_bounds(drawing, style).value_or(Box{});
  // The drawing's centre on the area's centre; view y up, sheet y down.
  auto sheet_x = [&](double x) { return l.area.cx() + (x - bounds.cx()) * scale; };
  auto sheet_y = [&](double y) { return l.area.cy() - (y - bounds.cy()) * scale; };

  Text out;
  out.s.reserve(4096 + 32 * drawing.segments.size());
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" << mm(sheet.width_mm) << "mm\" height=\""
      << mm(sheet.height_mm) << "mm\" viewBox=\"0 0 " << mm(sheet.width_mm) << ' ' << mm(sheet.height_mm) << "\">\n"
      << "<title>hlr drawing, " << xml_escape(sheet.name) << ", " << scale_label(scale) << "</title>\n"
      << "<rect width=\"" << mm(sheet.width_mm) << "\" height=\"" << mm(sheet.height_mm) << "\" fill=\"#fff\"/>\n";
  svg_frame(out, sheet, l);
  svg_title_block(out, drawing, l, scale);

  // Each part's lines in a group of its own inside the class's group, so that a part can be
  // switched off: ids are unique ("part-NAME-visible", "part-NAME-hidden"), the class names the
  // part in both.
  const auto& chains = lines.chains;
  const auto names = part_names(drawing);
  auto group = [&](bool visible) {
    if (visible)
      out << "<g id=\"visible\" fill=\"none\" stroke=\"#000\" stroke-width=\"" << mm(visible_width) << '"';
    else
      out << "<g id=\"hidden\" fill=\"none\" stroke=\"#000\" stroke-width=\"" << mm(hidden_width)
          << "\" stroke-dasharray=\"" << mm(hidden_dash) << ' ' << mm(hidden_gap) << '"';
    out << " stroke-linecap=\"butt\" stroke-linejoin=\"round\">\n";
    for (std::uint32_t part = 0; part < names.size(); ++part) {
      bool open = false;
      for (const auto& c : chains) {
        if (c.visible != visible || c.mesh != part) continue;
        if (!open)
          out << "<g id=\"part-" << xml_escape(names[part]) << (visible ? "-visible" : "-hidden") << "\" class=\"part-"
              << xml_escape(names[part]) << "\">\n";
        open = true;
        out << "<path d=\"";
        for (std::size_t i = 0; i < c.points.size(); ++i)
          out << (i == 0 ? 'M' : 'L') << mm(sheet_x(c.points[i][0])) << ' ' << mm(sheet_y(c.points[i][1]));
        out << (c.closed ? "Z" : "") << "\"/>\n";
      }
      if (open) out << "</g>\n";
    }
    out << "</g>\n";
  };
  if (style.hidden) group(false);  // below the visible lines
  group(true);
  out << "</svg>\n";
  return std::move(out.s);
}

namespace {

// dxflib's writer, collecting the text in memory. DL_WriterA only writes to a named file; every
// group goes through these virtual functions, so the file it was given ("") is never opened.
class DxfText : public DL_WriterA {
 public:
  DxfText() : DL_WriterA("", DL_Codes::AC1015) {}
  std::string& text() { return out_; }

  void dxfReal(int gc, double value) const override {
    code(gc);
    detail::append_round_trip(out_, value);
    out_ += '\n';
  }
  void dxfInt(int gc, int value) const override {
    char buf[16];
    const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, value);
    group(gc, std::string_view(buf, std::size_t(end - buf)));
  }
  void dxfHex(int gc, int value) const override {
    char buf[16];
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, static_cast<unsigned>(value), 16);
    for (char* c = buf; c != end; ++c) *c = static_cast<char>(std::toupper(static_cast<unsigned char>(*c)));
    group(gc, std::string_view(buf, std::size_t(end - buf)));
  }
  void dxfString(int gc, const char* value) const override { group(gc, value); }
  void dxfString(int gc, const std::string& value) const override { group(gc, value); }

 private:
  // Group codes right-aligned in three columns, as DXF writers customarily do.
  void code(int gc) const {
    out_ += gc < 10 ? "  " : gc < 100 ? " " : "";
    char buf[16];
    const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, gc);
    out_.append(buf, std::size_t(end - buf));
    out_ += '\n';
  }
  void group(int gc, std::string_view value) const {
    code(gc);
    out_ += value;
    out_ += '\n';
  }
  mutable std::string out_;
};

}  // namespace

std::string lines_dxf(const LineDrawing& drawing, const DrawingStyle& style, const SheetLines& lines) {
  const double scale = lines.scale;
  const Box bounds = drawn_bounds(drawing, style).value_or(Box{});
  const std::string hidden_ltype = "HIDDEN";
  // Everything after the HEADER first, so that $HANDSEED can name the next free handle.
  DL_Dxf dxf;  // writes R2000 (AC1015) unless told otherwise
  DxfText body;
  body.text().reserve(8192 + 64 * drawing.segments.size());
  body.sectionTables();
  dxf.writeVPort(body);

  double dashed[] = {hidden_dash, -hidden_gap};  // model units; $LTSCALE makes them millimetres on paper
  body.tableLinetypes(4);
  dxf.writeLinetype(body, DL_LinetypeData("BYBLOCK", "", 0, 0, 0.0));
  dxf.writeLinetype(body, DL_LinetypeData("BYLAYER", "", 0, 0, 0.0));
  dxf.writeLinetype(body, DL_LinetypeData("CONTINUOUS", "Solid line", 0, 0, 0.0));
  dxf.writeLinetype(body, DL_LinetypeData(hidden_ltype, "ISO 128 dashed __ __ __ __", 0, 2,
                                          hidden_dash + hidden_gap, dashed));
  body.tableEnd();

  // One mesh: layers VISIBLE and HIDDEN. Several: a pair per part, NAME-VISIBLE and NAME-HIDDEN
  // with the part's name in upper case (DXF layer names are compared in any case), every part's
  // pair defined even where it has no line, so that a CAD user finds every part.
  const auto names = part_names(drawing);
  const bool per_part = drawing.input.files.size() > 1;
  auto layer = [&](std::uint32_t mesh, bool visible) {
    std::string name = visible ? "VISIBLE" : "HIDDEN";
    if (!per_part) return name;
    std::string part = names[mesh];  // part_names names every mesh a segment has
    for (char& c : part) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return part + "-" + name;
  };
  const std::uint32_t layer_pairs = per_part ? std::uint32_t(names.size()) : 1;
  // Lineweights in hundredths of a millimetre; -3 is "default".
  body.tableLayers(1 + 2 * int(layer_pairs));
  dxf.writeLayer(body, DL_LayerData("0", 0), DL_Attributes("", 7, -3, "CONTINUOUS", 1.0));
  for (std::uint32_t part = 0; part < layer_pairs; ++part) {
    dxf.writeLayer(body, DL_LayerData(layer(part, true), 0),
                   DL_Attributes("", 7, static_cast<int>(visible_width * 100), "CONTINUOUS", 1.0));
    dxf.writeLayer(body, DL_LayerData(layer(part, false), 0),
                   DL_Attributes("", 8, static_cast<int>(hidden_width * 100), hidden_ltype, 1.0));
  }
  body.tableEnd();

  body.tableStyle(1);
  dxf.writeStyle(body, DL_StyleData("Standard", 0, 0.0, 1.0, 0.0, 0, 2.5, "txt", ""));
  body.tableEnd();
  dxf.writeView(body);
  dxf.writeUcs(body);
  body.tableAppid(1);
  dxf.writeAppid(body, "ACAD");
  body.tableEnd();
  dxf.writeDimStyle(body, 2.5, 1.25, 0.625, 0.625, 2.5);
  dxf.writeBlockRecord(body);
  body.tableEnd();
  body.sectionEnd();

  body.sectionBlocks();
  for (const char* block : {"*Model_Space", "*Paper_Space", "*Paper_Space0"}) {
    dxf.writeBlock(body, DL_BlockData(block, 0, 0.0, 0.0, 0.0));
    dxf.writeEndBlock(body, block);
  }
  body.sectionEnd();

  // Hidden first, so that viewers drawing in file order put the visible lines on top.
  body.sectionEntities();
  for (const bool visible : {false, true}) {
    if (!visible && !style.hidden) continue;
    for (const auto& c : lines.chains) {
      if (c.visible != visible) continue;
      dxf.writePolyline(body, DL_PolylineData(static_cast<int>(c.points.size()), 0, 0, c.closed ? 1 : 0),
                        DL_Attributes(layer(c.mesh, c.visible), 256, -1, "BYLAYER", 1.0));
      for (const Point2& p : c.points) dxf.writeVertex(body, DL_VertexData(p[0], p[1], 0.0, 0.0));
      dxf.writePolylineEnd(body);
    }
  }
  body.sectionEnd();
  dxf.writeObjects(body);
  dxf.writeObjectsEnd(body);
  body.dxfEOF();

  DxfText header;
  header.comment("hlr");
  header.sectionHeader();
  header.dxfString(9, "$ACADVER");
  header.dxfString(1, "AC1015");
  header.dxfString(9, "$HANDSEED");
  header.dxfHex(5, static_cast<int>(body.getNextHandle()));
  header.dxfString(9, "$INSUNITS");  // millimetres
  header.dxfInt(70, 4);
  header.dxfString(9, "$MEASUREMENT");  // metric
  header.dxfInt(70, 1);
  header.dxfString(9, "$LTSCALE");  // dashes of 3 mm and gaps of 0.75 mm when plotted at the drawing's scale
  header.dxfReal(40, 1 / scale);
  header.dxfString(9, "$LWDISPLAY");  // show the layers' lineweights
  header.dxfInt(290, 1);
  header.dxfString(9, "$EXTMIN");
  header.dxfReal(10, bounds.x0);
  header.dxfReal(20, bounds.y0);
  header.dxfReal(30, 0.0);
  header.dxfString(9, "$EXTMAX");
  header.dxfReal(10, bounds.x1);
  header.dxfReal(20, bounds.y1);
  header.dxfReal(30, 0.0);
  header.sectionEnd();
  std::string text = std::move(header.text());
  text += body.text();
  return text;
}

std::string lines_svg(const LineDrawing& drawing, const DrawingStyle& style) {
  return lines_svg(drawing, style, sheet_lines(drawing, style));
}

std::string lines_dxf(const LineDrawing& drawing, const DrawingStyle& style) {
  return lines_dxf(drawing, style, sheet_lines(drawing, style));
}

}  // namespace hlr::exporter
