// The SVG canvas (canvas.hpp): an SVG 1.1 document in millimetres, numbers with at most four
// decimals (0.1 µm: below anything a plotter or a viewer shows), through numbers.hpp.
#include "canvas.hpp"

#include "numbers.hpp"
#include "text.hpp"

#include <cmath>

namespace hlr::exporter::detail {
namespace {

class SvgCanvas final : public Canvas {
 public:
  SvgCanvas(double width, double height, const std::string& title) {
    out_.reserve(1 << 16);
    out_ += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"";
    mm(width);
    out_ += "mm\" height=\"";
    mm(height);
    out_ += "mm\" viewBox=\"0 0 ";
    mm(width);
    out_ += ' ';
    mm(height);
    out_ += "\">\n<title>";
    out_ += xml_escape(title);
    out_ += "</title>\n<rect width=\"";
    mm(width);
    out_ += "\" height=\"";
    mm(height);
    out_ += "\" fill=\"#fff\"/>\n";
  }

  void begin(const GroupStyle& g) override {
    out_ += "<g";
    if (!g.id.empty()) out_ += " id=\"" + xml_escape(g.id) + '"';
    if (!g.cls.empty()) out_ += " class=\"" + xml_escape(g.cls) + '"';
    if (g.pen) {
      out_ += " fill=\"none\" stroke=\"#000\" stroke-width=\"";
      mm(g.pen->width);
      out_ += '"';
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
          // rx ry rotation large-arc sweep x y; sweep 1 is the direction of growing angle (SVG's
          // "positive angle", clockwise as seen with y down). Arcs are at most half a turn.
          out_ += 'A';
          mm(item.r);
          out_ += ' ';
          mm(item.r);
          out_ += " 0 0 ";
          out_ += item.increasing ? '1' : '0';
          out_ += ' ';
          mm(item.x);
          out_ += ' ';
          mm(item.y);
          break;
        case SheetPath::Op::close: out_ += 'Z'; break;
      }
    }
    out_ += '"';
    if (dash_offset != 0) {
      out_ += " stroke-dashoffset=\"";
      mm(dash_offset);
      out_ += '"';
    }
    out_ += "/>\n";
  }

  void rect(double x, double y, double width, double height, std::optional<double> stroke_width) override {
    out_ += "<rect x=\"";
    mm(x);
    out_ += "\" y=\"";
    mm(y);
    out_ += "\" width=\"";
    mm(width);
    out_ += "\" height=\"";
    mm(height);
    out_ += '"';
    if (stroke_width) {
      out_ += " stroke-width=\"";
      mm(*stroke_width);
      out_ += '"';
    }
    out_ += "/>\n";
  }

  void circle(double cx, double cy, double r) override {
    out_ += "<circle cx=\"";
    mm(cx);
    out_ += "\" cy=\"";
    mm(cy);
    out_ += "\" r=\"";
    mm(r);
    out_ += "\"/>\n";
  }

  void text(double x, double y, double size, const std::string& text) override {
    out_ += "<text x=\"";
    mm(x);
    out_ += "\" y=\"";
    mm(y);
    out_ += "\" font-size=\"";
    mm(size);
    out_ += "\">";
    out_ += xml_escape(text);
    out_ += "</text>\n";
  }

  std::string finish() override {
    out_ += "</svg>\n";
    return std::move(out_);
  }

 private:
  void mm(double v) { append_fixed(out_, v, 4); }
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
