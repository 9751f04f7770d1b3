// The PDF canvas (canvas.hpp), drawn with cairo (Debian's libcairo2-dev): a vector PDF of one
// page the size of the sheet. User space is millimetres (the page is in points: 72 per inch), so
// line widths and dashes are the SVG's numbers. Text uses cairo's toy font API ("sans-serif",
// through fontconfig), embedded as a subset.
//
// The same drawing gives the same bytes: cairo would stamp the creation time into the document's
// information dictionary, so the creation date is set to a fixed one (2000-01-01; PDF readers show
// it as the document's date).
#include "canvas.hpp"

#include <cairo-pdf.h>
#include <cairo.h>

#include <cmath>
#include <stdexcept>

namespace hlr::exporter::detail {
namespace {

constexpr double points_per_mm = 72 / 25.4;

class PdfCanvas final : public Canvas {
 public:
  PdfCanvas(double width, double height, const std::string& title) {
    surface_ = cairo_pdf_surface_create_for_stream(&PdfCanvas::append, this, width * points_per_mm, height * points_per_mm);
    cairo_pdf_surface_set_metadata(surface_, CAIRO_PDF_METADATA_TITLE, title.c_str());
    cairo_pdf_surface_set_metadata(surface_, CAIRO_PDF_METADATA_CREATOR, "hlr");
    cairo_pdf_surface_set_metadata(surface_, CAIRO_PDF_METADATA_CREATE_DATE, "2000-01-01T00:00:00Z");
    cr_ = cairo_create(surface_);
    cairo_scale(cr_, points_per_mm, points_per_mm);
    cairo_set_source_rgb(cr_, 0, 0, 0);
    cairo_select_font_face(cr_, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    pens_.push_back(Pen{});
  }
  ~PdfCanvas() override {
    if (cr_) cairo_destroy(cr_);
    if (surface_) cairo_surface_destroy(surface_);
  }

  void begin(const GroupStyle& g) override {
    pens_.push_back(g.pen ? *g.pen : pens_.back());
    fills_.push_back(g.fill ? g.fill : fills_.empty() ? std::nullopt : fills_.back());
  }
  void end() override {
    pens_.pop_back();
    fills_.pop_back();
  }

  void path(const SheetPath& p, double dash_offset) override {
    cairo_new_path(cr_);
    for (const auto& item : p.items) {
      double x = 0, y = 0;
      switch (item.op) {
        case SheetPath::Op::move: cairo_move_to(cr_, item.x, item.y); break;
        case SheetPath::Op::line: cairo_line_to(cr_, item.x, item.y); break;
        case SheetPath::Op::horizontal:
          cairo_get_current_point(cr_, &x, &y);
          cairo_line_to(cr_, item.x, y);
          break;
        case SheetPath::Op::vertical:
          cairo_get_current_point(cr_, &x, &y);
          cairo_line_to(cr_, x, item.y);
          break;
        case SheetPath::Op::arc:
          // cairo's positive direction is that of growing angle, as on the canvas.
          if (item.increasing) cairo_arc(cr_, item.cx, item.cy, item.r, item.a0, item.a1);
          else cairo_arc_negative(cr_, item.cx, item.cy, item.r, item.a0, item.a1);
          break;
        case SheetPath::Op::ellipse:
          // The unit circle in the ellipse's frame: cairo keeps the path in device space, so the
          // transform is gone again before the stroke (whose width stays round).
          cairo_save(cr_);
          cairo_translate(cr_, item.cx, item.cy);
          cairo_rotate(cr_, item.rotation);
          cairo_scale(cr_, item.r, item.ry);
          if (item.increasing) cairo_arc(cr_, 0, 0, 1, item.a0, item.a1);
          else cairo_arc_negative(cr_, 0, 0, 1, item.a0, item.a1);
          cairo_restore(cr_);
          break;
        case SheetPath::Op::close: cairo_close_path(cr_); break;
      }
    }
    if (!fills_.empty() && fills_.back()) {
      // A filled area (a shadow): even-odd, in its colour, no outline.
      const auto& rgb = *fills_.back();
      cairo_set_fill_rule(cr_, CAIRO_FILL_RULE_EVEN_ODD);
      cairo_set_source_rgb(cr_, rgb[0], rgb[1], rgb[2]);
      cairo_fill(cr_);
      cairo_set_source_rgb(cr_, 0, 0, 0);
      return;
    }
    stroke(dash_offset);
  }

  void rect(double x, double y, double width, double height, std::optional<double> stroke_width) override {
    cairo_new_path(cr_);
    cairo_rectangle(cr_, x, y, width, height);
    stroke(0, stroke_width);
  }

  void circle(double cx, double cy, double r) override {
    cairo_new_path(cr_);
    cairo_arc(cr_, cx, cy, r, 0, 2 * M_PI);
    cairo_close_path(cr_);
    stroke(0);
  }

  void text(double x, double y, double size, const std::string& text) override {
    cairo_new_path(cr_);
    cairo_set_font_size(cr_, size);
    cairo_move_to(cr_, x, y);
    cairo_show_text(cr_, text.c_str());
    cairo_new_path(cr_);
  }

  std::string finish() override {
    cairo_show_page(cr_);
    cairo_destroy(cr_);
    cr_ = nullptr;
    cairo_surface_finish(surface_);
    const cairo_status_t status = cairo_surface_status(surface_);
    cairo_surface_destroy(surface_);
    surface_ = nullptr;
    if (status != CAIRO_STATUS_SUCCESS) throw std::runtime_error(std::string("cairo: ") + cairo_status_to_string(status));
    return std::move(out_);
  }

 private:
  static cairo_status_t append(void* self, const unsigned char* data, unsigned int length) {
    static_cast<PdfCanvas*>(self)->out_.append(reinterpret_cast<const char*>(data), length);
    return CAIRO_STATUS_SUCCESS;
  }

  void stroke(double dash_offset, std::optional<double> width = {}) {
    const Pen& pen = pens_.back();
    cairo_set_line_width(cr_, width ? *width : pen.width);
    cairo_set_line_cap(cr_, CAIRO_LINE_CAP_BUTT);
    cairo_set_line_join(cr_, CAIRO_LINE_JOIN_ROUND);
    cairo_set_dash(cr_, pen.dashes.data(), int(pen.dashes.size()), dash_offset);
    cairo_stroke(cr_);
  }

  std::vector<std::optional<std::array<double, 3>>> fills_;  // per open group
  cairo_surface_t* surface_ = nullptr;
  cairo_t* cr_ = nullptr;
  std::vector<Pen> pens_;
  std::string out_;
};

}  // namespace

std::unique_ptr<Canvas> pdf_canvas(double width_mm, double height_mm, const std::string& title) {
  return std::make_unique<PdfCanvas>(width_mm, height_mm, title);
}

}  // namespace hlr::exporter::detail
