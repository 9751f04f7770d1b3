// The SVG canvas (canvas.hpp): an SVG 1.1 document in millimetres, numbers with at most four
// decimals (0.1 µm: below anything a plotter or a viewer shows), through numbers.hpp.
#include "canvas.hpp"

#include "numbers.hpp"
#include "text.hpp"

#include <cmath>
#include <cstdio>

namespace hlr::exporter::detail {
namespace {

class SvgCanvas final : public Canvas {
 public:
  SvgCanvas(double width, double height, const std::string& title) {
    out_.reserve(1 << 16);
    out_ += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\"";
    attr("width", width, "mm");
    attr("height", height, "mm");
    out_ += " viewBox=\"0 0";
    for (double v : {width, height}) {
      out_ += ' ';
      mm(v);
    }
    out_ += "\">\n<title>";
    out_ += xml_escape(title);
    out_ += "</title>\n<rect";
    attr("width", width);
    attr("height", height);
    out_ += " fill=\"#fff\"/>\n";
  }

  void begin(const GroupStyle& g) override {
    out_ += "<g";
    if (!g.id.empty()) out_ += " id=\"" + xml_escape(g.id) + '"';
    if (!g.cls.empty()) out_ += " class=\"" + xml_escape(g.cls) + '"';
    if (g.pen) {
      out_ += " fill=\"none\" stroke=\"#000\"";
      attr("stroke-width", g.pen->width);
      if (!g.pen->dashes.empty()) {
        out_ += " stroke-dasharray=\"";
        for (std::size_t i = 0; i < g.pen->dashes.size(); ++i) {
          if (i) out_ += ' ';
          mm(g.pen->dashes[i]);
        }
        out_ += '"';
      }
    }
    if (g.line_caps) out_ += " stroke-linecap=\"butt\" stroke-linejoin=\"round\"";
    if (g.lettering) out_ += " font-family=\"sans-serif\" fill=\"#000\"";
    if (g.fill) {
      char colour[8];
      std::snprintf(colour, sizeof colour, "#%02x%02x%02x", int(std::lround(255 * (*g.fill)[0])),
                    int(std::lround(255 * (*g.fill)[1])), int(std::lround(255 * (*g.fill)[2])));
      out_ += " fill=\"" + std::string(colour) + "\" stroke=\"none\" fill-rule=\"evenodd\"";
    }
    out_ += ">\n";
  }

  void end() override { out_ += "</g>\n"; }

  void path(const SheetPath& p, double dash_offset) override {
    out_ += "<path d=\"";
    for (const auto& item : p.items) {
      switch (item.op) {
        case SheetPath::Op::move: point('M', item.x, item.y); break;
        case SheetPath::Op::line: point('L', item.x, item.y); break;
        case SheetPath::Op::horizontal:
          out_ += 'H';
          mm(item.x);
          break;
        case SheetPath::Op::vertical:
          out_ += 'V';
          mm(item.y);
          break;
        case SheetPath::Op::arc:
        case SheetPath::Op::ellipse: {
          // rx ry rotation large-arc sweep x y; sweep 1 is the direction of growing angle (SVG's
          // "positive angle", clockwise as seen with y down). Arcs are at most half a turn; a
          // circle's arc has ry = rx and no rotation.
          const bool circle = item.op == SheetPath::Op::arc;
          out_ += 'A';
          mm(item.r);
          out_ += ' ';
          mm(circle ? item.r : item.ry);
          out_ += ' ';
          mm(circle ? 0.0 : item.rotation * 180 / 3.14159265358979323846);
          out_ += " 0 ";
          out_ += item.increasing ? '1' : '0';
          out_ += ' ';
          mm(item.x);
          out_ += ' ';
          mm(item.y);
          break;
        }
        case SheetPath::Op::close: out_ += 'Z'; break;
      }
    }
    out_ += '"';
    if (dash_offset != 0) attr("stroke-dashoffset", dash_offset);
    out_ += "/>\n";
  }

  void rect(double x, double y, double width, double height, std::optional<double> stroke_width) override {
    out_ += "<rect";
    attr("x", x);
    attr("y", y);
    attr("width", width);
    attr("height", height);
    if (stroke_width) attr("stroke-width", *stroke_width);
    out_ += "/>\n";
  }

  void circle(double cx, double cy, double r) override {
    out_ += "<circle";
    attr("cx", cx);
    attr("cy", cy);
    attr("r", r);
    out_ += "/>\n";
  }

  void text(double x, double y, double size, const std::string& text) override {
    out_ += "<text";
    attr("x", x);
    attr("y", y);
    attr("font-size", size);
    out_ += '>';
    out_ += xml_escape(text);
    out_ += "</text>\n";
  }

  std::string finish() override {
    out_ += "</svg>\n";
    return std::move(out_);
  }

 private:
  void mm(double v) { append_fixed(out_, v, 4); }
  // name="v" (with a unit after the number, if given), after a space.
  void attr(const char* name, double v, const char* unit = "") {
    out_ += ' ';
    out_ += name;
    out_ += "=\"";
    mm(v);
    out_ += unit;
    out_ += '"';
  }
  void point(char op, double x, double y) {
    out_ += op;
    mm(x);
    out_ += ' ';
    mm(y);
  }
  std::string out_;
};

}  // namespace

std::unique_ptr<Canvas> svg_canvas(double width_mm, double height_mm, const std::string& title) {
  return std::make_unique<SvgCanvas>(width_mm, height_mm, title);
}

}  // namespace hlr::exporter::detail
