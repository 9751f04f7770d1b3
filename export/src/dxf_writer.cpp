// The parts of hlr's DXF documents (dxf_writer.hpp).
#include "dxf_writer.hpp"

#include "numbers.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

namespace hlr::exporter::detail {
namespace {

constexpr double pi = 3.14159265358979323846;
double degrees(double radians) { return radians * 180 / pi; }

// DXF R2000 text is in the drawing's code page: characters beyond ASCII are written \U+XXXX.
std::string dxf_string(const std::string& utf8) {
  std::string out;
  for (std::size_t i = 0; i < utf8.size();) {
    const unsigned char c = static_cast<unsigned char>(utf8[i]);
    if (c < 0x80) {
      out += char(c);
      ++i;
      continue;
    }
    const int extra = c >= 0xF0 ? 3 : c >= 0xE0 ? 2 : c >= 0xC0 ? 1 : 0;
    unsigned code = c & (0x3F >> extra);
    std::size_t k = 1;
    for (; k <= std::size_t(extra) && i + k < utf8.size(); ++k) code = (code << 6) | (static_cast<unsigned char>(utf8[i + k]) & 0x3F);
    i += k;
    char buf[16];
    const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, code, 16);
    std::string hex(buf, end);
    for (char& h : hex) h = static_cast<char>(std::toupper(static_cast<unsigned char>(h)));
    out += "\\U+" + std::string(hex.size() < 4 ? 4 - hex.size() : 0, '0') + hex;
  }
  return out;
}

void polyline(DL_Dxf& dxf, DxfText& out, const std::vector<Point2>& points, bool closed, const DL_Attributes& a) {
  if (points.size() < 2) return;
  dxf.writePolyline(out, DL_PolylineData(static_cast<int>(points.size()), 0, 0, closed ? 1 : 0), a);
  for (const Point2& p : points) dxf.writeVertex(out, DL_VertexData(p[0], p[1], 0.0, 0.0));
  dxf.writePolylineEnd(out);
}

// An arc from angle `from` to `to` (radians) of the circle (cx, cy, r), going counter-clockwise
// if `ccw`: DXF's ARC always goes counter-clockwise from its start angle to its end angle.
void arc(DL_Dxf& dxf, DxfText& out, double cx, double cy, double r, double from, double to, bool ccw,
         const DL_Attributes& a) {
  const double start = ccw ? from : to, end = ccw ? to : from;
  dxf.writeArc(out, DL_ArcData(cx, cy, 0.0, r, degrees(start), degrees(end)), a);
}

class DxfCanvas final : public Canvas {
 public:
  DxfCanvas(DL_Dxf& dxf, DxfText& out, double height, std::string layer)
      : dxf_(dxf), out_(out), height_(height), layer_(std::move(layer)) {}

  void begin(const GroupStyle& g) override { widths_.push_back(g.pen ? g.pen->width : widths_.empty() ? 0.25 : widths_.back()); }
  void end() override { widths_.pop_back(); }

  void path(const SheetPath& p, double) override {
    std::vector<Point2> run;
    bool arcs = false;
    Point2 first{}, at{};
    auto flush = [&] {
      polyline(dxf_, out_, run, false, attributes());
      run.clear();
    };
    for (const auto& item : p.items) {
      switch (item.op) {
        case SheetPath::Op::move:
          flush();
          first = at = {item.x, item.y};
          run.push_back(flip(at));
          break;
        case SheetPath::Op::line: at = {item.x, item.y}; run.push_back(flip(at)); break;
        case SheetPath::Op::horizontal: at[0] = item.x; run.push_back(flip(at)); break;
        case SheetPath::Op::vertical: at[1] = item.y; run.push_back(flip(at)); break;
        case SheetPath::Op::arc:
          flush();
          arcs = true;
          // Sheet angles run clockwise (y down): angle a is -a in the DXF, and growing on the
          // sheet is clockwise there.
          arc(dxf_, out_, item.cx, height_ - item.cy, item.r, -item.a0, -item.a1, !item.increasing, attributes());
          at = {item.x, item.y};
          run.push_back(flip(at));
          break;
        case SheetPath::Op::ellipse:
          // Sheet views write their ellipses themselves (dxf_curves); the canvas draws borders
          // and symbols, which have none: its end point suffices.
          at = {item.x, item.y};
          run.push_back(flip(at));
          break;
        case SheetPath::Op::close:
          if (!arcs && run.size() > 2 && flip(first) == run.front()) {
            polyline(dxf_, out_, run, true, attributes());
            run.clear();
          } else {
            run.push_back(flip(first));
          }
          break;
      }
    }
    flush();
  }

  void rect(double x, double y, double w, double h, std::optional<double> width) override {
    const DL_Attributes a = width ? attributes(*width) : attributes();
    polyline(dxf_, out_, {flip({x, y}), flip({x + w, y}), flip({x + w, y + h}), flip({x, y + h})}, true, a);
  }

  void circle(double cx, double cy, double r) override {
    dxf_.writeCircle(out_, DL_CircleData(cx, height_ - cy, 0.0, r), attributes());
  }

  void text(double x, double y, double size, const std::string& text) override {
    const Point2 p = flip({x, y});
    dxf_.writeText(out_, DL_TextData(p[0], p[1], 0.0, p[0], p[1], 0.0, size, 1.0, 0, 0, 0, dxf_string(text), "Standard", 0.0),
                   attributes());
  }

  std::string finish() override { return {}; }

 private:
  Point2 flip(const Point2& p) const { return {p[0], height_ - p[1]}; }
  DL_Attributes attributes(double width) const {
    return DL_Attributes(layer_, 256, static_cast<int>(std::lround(width * 100)), "BYLAYER", 1.0);
  }
  DL_Attributes attributes() const { return attributes(widths_.empty() ? 0.25 : widths_.back()); }

  DL_Dxf& dxf_;
  DxfText& out_;
  double height_;
  std::string layer_;
  std::vector<double> widths_;
};

}  // namespace

void DxfText::dxfReal(int gc, double value) const {
  code(gc);
  append_round_trip(out_, value);
  out_ += '\n';
}

void DxfText::dxfInt(int gc, int value) const {
  char buf[16];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, value);
  group(gc, std::string_view(buf, std::size_t(end - buf)));
}

void DxfText::dxfHex(int gc, int value) const {
  char buf[16];
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, static_cast<unsigned>(value), 16);
  for (char* c = buf; c != end; ++c) *c = static_cast<char>(std::toupper(static_cast<unsigned char>(*c)));
  group(gc, std::string_view(buf, std::size_t(end - buf)));
}

// Group codes right-aligned in three columns, as DXF writers customarily do.
void DxfText::code(int gc) const {
  out_ += gc < 10 ? "  " : gc < 100 ? " " : "";
  char buf[16];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, gc);
  out_.append(buf, std::size_t(end - buf));
  out_ += '\n';
}

void DxfText::group(int gc, std::string_view value) const {
  code(gc);
  out_ += value;
  out_ += '\n';
}

void dxf_linetypes(DL_Dxf& dxf, DxfText& out, const LineWidths& widths) {
  auto pattern = [](const std::vector<double>& dashes) {
    std::vector<double> p;  // DXF: dashes positive, gaps negative, a dot 0
    for (std::size_t i = 0; i < dashes.size(); ++i) p.push_back(i % 2 ? -dashes[i] : dashes[i]);
    return p;
  };
  auto total = [](const std::vector<double>& dashes) {
    double t = 0;
    for (double d : dashes) t += d;
    return t;
  };
  std::vector<double> hidden = pattern(widths.hidden_dashes), centre = pattern(widths.centre_dashes);
  out.tableLinetypes(5);
  dxf.writeLinetype(out, DL_LinetypeData("BYBLOCK", "", 0, 0, 0.0));
  dxf.writeLinetype(out, DL_LinetypeData("BYLAYER", "", 0, 0, 0.0));
  dxf.writeLinetype(out, DL_LinetypeData("CONTINUOUS", "Solid line", 0, 0, 0.0));
  dxf.writeLinetype(out, DL_LinetypeData("HIDDEN", "ISO 128 dashed __ __ __ __", 0, int(hidden.size()),
                                         total(widths.hidden_dashes), hidden.data()));
  dxf.writeLinetype(out, DL_LinetypeData("CENTER", "ISO 128 long-dash dotted ____ . ____ .", 0, int(centre.size()),
                                         total(widths.centre_dashes), centre.data()));
  out.tableEnd();
}

void dxf_layers(DL_Dxf& dxf, DxfText& out, const std::vector<DxfLayer>& layers) {
  // Lineweights in hundredths of a millimetre; -3 is "default".
  out.tableLayers(1 + int(layers.size()));
  dxf.writeLayer(out, DL_LayerData("0", 0), DL_Attributes("", 7, -3, "CONTINUOUS", 1.0));
  for (const auto& l : layers)
    dxf.writeLayer(out, DL_LayerData(l.name, 0),
                   DL_Attributes("", l.colour, static_cast<int>(std::lround(l.width_mm * 100)), l.linetype, 1.0));
  out.tableEnd();
}

void dxf_other_tables(DL_Dxf& dxf, DxfText& out, const std::vector<std::string>& blocks) {
  out.tableStyle(1);
  dxf.writeStyle(out, DL_StyleData("Standard", 0, 0.0, 1.0, 0.0, 0, 2.5, "txt", ""));
  out.tableEnd();
  dxf.writeView(out);
  dxf.writeUcs(out);
  out.tableAppid(1);
  dxf.writeAppid(out, "ACAD");
  out.tableEnd();
  dxf.writeDimStyle(out, 2.5, 1.25, 0.625, 0.625, 2.5);
  dxf.writeBlockRecord(out);
  for (const auto& name : blocks) dxf.writeBlockRecord(out, name);
  out.tableEnd();
  out.sectionEnd();
}

void dxf_curves(DL_Dxf& dxf, DxfText& out, const DrawingCurves& curves, bool hidden,
                const std::function<std::string(int, std::uint32_t)>& layer, double ltscale) {
  for (const int rank : {1, 2, 0}) {
    if (rank == 1 && !hidden) continue;
    auto of_class = [rank](const auto& item) { return item.thin ? rank == 2 : item.visible ? rank == 0 : rank == 1; };
    for (const auto& path : curves.paths) {
      if (!of_class(path)) continue;
      const DL_Attributes a(layer(rank, path.mesh), 256, -1, "BYLAYER", ltscale);
      const bool straight = std::none_of(path.steps.begin(), path.steps.end(), [](const PathStep& s) { return s.arc; });
      std::vector<Point2> run{path.start};
      Point2 from = path.start;
      for (const auto& step : path.steps) {
        if (step.arc) {
          polyline(dxf, out, run, false, a);
          const double a0 = std::atan2(from[1] - step.centre[1], from[0] - step.centre[0]);
          const double a1 = std::atan2(step.to[1] - step.centre[1], step.to[0] - step.centre[0]);
          arc(dxf, out, step.centre[0], step.centre[1], step.radius, a0, a1, step.ccw, a);
          run = {step.to};
        } else {
          run.push_back(step.to);
        }
        from = step.to;
      }
      if (path.closed && !straight) run.push_back(path.start);
      polyline(dxf, out, run, path.closed && straight, a);
    }
    for (const auto& c : curves.circles) {
      if (!of_class(c)) continue;
      dxf.writeCircle(out, DL_CircleData(c.centre[0], c.centre[1], 0.0, c.radius),
                      DL_Attributes(layer(rank, c.mesh), 256, -1, "BYLAYER", ltscale));
    }
    for (const auto& e : curves.ellipses) {
      if (!of_class(e)) continue;
      dxf.writeEllipse(out, DL_EllipseData(e.centre[0], e.centre[1], 0.0, e.major[0], e.major[1], 0.0, e.ratio, e.t0, e.t1),
                       DL_Attributes(layer(rank, e.mesh), 256, -1, "BYLAYER", ltscale));
    }
  }
}

void dxf_hatches(DL_Dxf& dxf, DxfText& out, const std::vector<DrawingArea>& areas, const std::string& layer) {
  const DL_Attributes a(layer, 256, -1, "BYLAYER", 1.0);
  for (const auto& area : areas) {
    const DL_HatchData hatch(int(1 + area.holes.size()), true, 1.0, 0.0, "SOLID");
    dxf.writeHatch1(out, hatch, a);
    auto loop = [&](const std::vector<std::array<double, 2>>& c) {
      const DL_HatchLoopData data(int(c.size()));
      dxf.writeHatchLoop1(out, data);
      for (std::size_t i = 0; i < c.size(); ++i) {
        const auto& p = c[i];
        const auto& q = c[(i + 1) % c.size()];
        dxf.writeHatchEdge(out, DL_HatchEdgeData(p[0], p[1], q[0], q[1]));
      }
      dxf.writeHatchLoop2(out, data);
    };
    loop(area.outer);
    for (const auto& h : area.holes) loop(h);
    dxf.writeHatch2(out, hatch, a);
  }
}

void dxf_centre_lines(DL_Dxf& dxf, DxfText& out, const std::vector<CentreLine>& lines, const std::string& layer,
                      double ltscale) {
  for (const auto& l : lines)
    dxf.writeLine(out, DL_LineData(l.a[0], l.a[1], 0.0, l.b[0], l.b[1], 0.0), DL_Attributes(layer, 256, -1, "BYLAYER", ltscale));
}

int dxf_insunits(const std::string& units) {
  if (units == "cm") return 5;
  if (units == "m") return 6;
  if (units == "in") return 1;
  return 4;  // mm
}

std::string dxf_header(unsigned long handseed, int insunits, double ltscale, const Bounds& extents) {
  DxfText header;
  header.comment("hlr");
  header.sectionHeader();
  header.dxfString(9, "$ACADVER");
  header.dxfString(1, "AC1015");
  header.dxfString(9, "$HANDSEED");
  header.dxfHex(5, static_cast<int>(handseed));
  header.dxfString(9, "$INSUNITS");
  header.dxfInt(70, insunits);
  header.dxfString(9, "$MEASUREMENT");  // metric, but for inches
  header.dxfInt(70, insunits == 1 ? 0 : 1);
  header.dxfString(9, "$LTSCALE");
  header.dxfReal(40, ltscale);
  header.dxfString(9, "$LWDISPLAY");  // show the layers' lineweights
  header.dxfInt(290, 1);
  header.dxfString(9, "$EXTMIN");
  header.dxfReal(10, extents.x0);
  header.dxfReal(20, extents.y0);
  header.dxfReal(30, 0.0);
  header.dxfString(9, "$EXTMAX");
  header.dxfReal(10, extents.x1);
  header.dxfReal(20, extents.y1);
  header.dxfReal(30, 0.0);
  header.sectionEnd();
  return std::move(header.text());
}

std::unique_ptr<Canvas> dxf_canvas(DL_Dxf& dxf, DxfText& out, double sheet_height, const std::string& layer) {
  return std::make_unique<DxfCanvas>(dxf, out, sheet_height, layer);
}

}  // namespace hlr::exporter::detail
