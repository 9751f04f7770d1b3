// What the SVG and the PDF of a sheet are drawn on: one painter (paint.hpp) draws a sheet once,
// on a Canvas, and the canvas makes the document. SvgCanvas writes SVG text; PdfCanvas draws with
// cairo into a PDF. Everything is in sheet millimetres, origin top left, y down (SVG's axes).
//
// Groups carry the line style (a Pen) as SVG groups do; the PDF canvas keeps a stack of them.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace hlr::exporter::detail {

struct Pen {
  double width = 0.5;
  std::vector<double> dashes;  // on, off, ... (mm); empty: continuous
};

struct GroupStyle {
  std::string id, cls;      // either may be empty
  std::optional<Pen> pen;   // lines in the group: black, unfilled, this width and dash pattern
  bool line_caps = false;   // butt caps, round joins (the drawing's lines)
  bool lettering = false;   // text in the group: sans-serif, black
  std::optional<std::array<double, 3>> fill;  // paths in the group: filled in this colour (RGB 0..1), no stroke

  static GroupStyle named(std::string id, std::string cls = {}) {
    GroupStyle g;
    g.id = std::move(id), g.cls = std::move(cls);
    return g;
  }
};

// A path in sheet millimetres. Arcs carry both what SVG needs (end point, radius, flags) and what
// cairo needs (centre, angles): angles are atan2(y - cy, x - cx) on the sheet (y down), and
// `increasing` says the arc runs from a0 to a1 with the angle growing (clockwise as seen). An arc
// never spans more than half a turn (the painter splits longer ones), so that its SVG flags are
// never ill-conditioned.
struct SheetPath {
  enum class Op : std::uint8_t { move, line, horizontal, vertical, arc, ellipse, close };
  struct Item {
    Op op;
    double x = 0, y = 0;  // end point (horizontal: x only; vertical: y only)
    double cx = 0, cy = 0, r = 0, a0 = 0, a1 = 0;
    bool increasing = false;
    double ry = 0, rotation = 0;  // ellipse: r is the semi-axis turned by `rotation` (radians, as angles)
  };
  std::vector<Item> items;
  void move(double x, double y) { items.push_back({Op::move, x, y}); }
  void line(double x, double y) { items.push_back({Op::line, x, y}); }
  void horizontal(double x) { items.push_back({Op::horizontal, x, 0}); }
  void vertical(double y) { items.push_back({Op::vertical, 0, y}); }
  void close() { items.push_back({Op::close}); }
  // An arc of the circle (cx, cy, r) from angle a0 to a1, ending at (x, y).
  void arc(double x, double y, double cx, double cy, double r, double a0, double a1, bool increasing) {
    items.push_back({Op::arc, x, y, cx, cy, r, a0, a1, increasing});
  }
  // An arc of the ellipse with centre (cx, cy) and semi-axes rx (at angle `rotation`) and ry,
  // the points centre + rx cos a along the first axis + ry sin a along the second, from a = a0 to
  // a1 (at most half a turn, as arcs), ending at (x, y).
  void ellipse(double x, double y, double cx, double cy, double rx, double ry, double rotation, double a0, double a1,
               bool increasing) {
    items.push_back({Op::ellipse, x, y, cx, cy, rx, a0, a1, increasing, ry, rotation});
  }
  bool empty() const { return items.empty(); }
};

class Canvas {
 public:
  virtual ~Canvas() = default;
  virtual void begin(const GroupStyle& group) = 0;
  virtual void end() = 0;
  // `dash_offset` shifts the group's dash pattern along this path (mm).
  virtual void path(const SheetPath& path, double dash_offset = 0) = 0;
  // A rectangle's outline, in its own width if given.
  virtual void rect(double x, double y, double width, double height, std::optional<double> stroke_width = {}) = 0;
  virtual void circle(double cx, double cy, double r) = 0;
  // Text with its baseline starting at (x, y), `size` mm high (UTF-8).
  virtual void text(double x, double y, double size, const std::string& text) = 0;
  // The finished document.
  virtual std::string finish() = 0;
};

// `title` is the SVG's <title>, or the PDF's title in its metadata.
std::unique_ptr<Canvas> svg_canvas(double width_mm, double height_mm, const std::string& title);
std::unique_ptr<Canvas> pdf_canvas(double width_mm, double height_mm, const std::string& title);

}  // namespace hlr::exporter::detail
