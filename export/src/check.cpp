// compare_drawings, difference_image and png_document (hlr/export/check.hpp).
#include <hlr/export/check.hpp>

#include "document_json.hpp"

#include <nlohmann/json.hpp>
#include <png.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hlr::exporter {
namespace {

// The pieces of every line, by line index (make_drawing writes them in line order).
std::vector<std::vector<const DrawingPiece*>> pieces_by_line(const LineDrawing& d) {
  std::vector<std::vector<const DrawingPiece*>> out(d.stats.lines);
  for (const DrawingPiece& p : d.pieces)
    if (p.line < out.size()) out[p.line].push_back(&p);
  return out;
}

double image_length(const DrawingPiece& p) { return std::hypot(p.b[0] - p.a[0], p.b[1] - p.a[1]); }

// Why one line's pieces are not a partition of [0, 1] in increasing order; empty when they are.
std::string partition_defect(const std::vector<const DrawingPiece*>& pieces) {
  if (pieces.empty()) return {};
  if (pieces.front()->t0 != 0 || pieces.back()->t1 != 1) return "its pieces do not span the whole line";
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    if (!(pieces[k]->t0 < pieces[k]->t1)) return "a piece is empty or reversed";
    if (k + 1 < pieces.size() && pieces[k]->t1 != pieces[k + 1]->t0) return "its pieces leave a gap or overlap";
  }
  return {};
}

}  // namespace

std::size_t Agreement::count(Difference d) const {
  return static_cast<std::size_t>(std::count_if(pieces.begin(), pieces.end(), [&](const auto& p) { return p.difference == d; }));
}

double Agreement::length(Difference d) const {
  double sum = 0;
  for (const auto& p : pieces)
    if (p.difference == d) sum += p.length;
  return sum;
}

Agreement compare_drawings(const LineDrawing& reference, const LineDrawing& candidate) {
  Agreement out;
  if (reference.stats.lines != candidate.stats.lines) {
    out.invalid = "it has " + std::to_string(candidate.stats.lines) + " lines where the reference has " +
                  std::to_string(reference.stats.lines);
    return out;
  }
  const auto ref = pieces_by_line(reference);
  const auto cand = pieces_by_line(candidate);
  for (std::uint32_t line = 0; line < ref.size(); ++line) {
    const auto& r = ref[line];
    const auto& c = cand[line];
    if (const std::string defect = partition_defect(c); !defect.empty()) {
      out.invalid = "line " + std::to_string(line) + ": " + defect;
      return out;
    }
    if (r.empty()) continue;  // seen end-on: no length to agree on
    if (!c.empty() && (c[0]->kind != r[0]->kind || c[0]->mesh != r[0]->mesh || c[0]->edge != r[0]->edge)) {
      out.invalid = "line " + std::to_string(line) + " is not the reference's line";
      return out;
    }
    double line_length = 0;
    for (const DrawingPiece* p : r) line_length += image_length(*p);
    out.total_length += line_length;
    const Point3 a = r.front()->a, b = r.back()->b;
    auto add_difference = [&](double t0, double t1, Difference d) {
      if (!out.pieces.empty() && out.pieces.back().line == line && out.pieces.back().t1 == t0 &&
          out.pieces.back().difference == d) {
        out.pieces.back().t1 = t1;
      } else {
        out.pieces.push_back({line, t0, t1, d, {}, {}, 0});
      }
    };
    if (c.empty()) {
      add_difference(0, 1, Difference::missing_in_candidate);
    } else {
      // Both partitions of [0, 1], walked together.
      std::size_t i = 0, j = 0;
      double t = 0;
      while (i < r.size() && j < c.size()) {
        const double end = std::min(r[i]->t1, c[j]->t1);
        if (r[i]->visible == c[j]->visible)
          out.agreeing_length += (end - t) * line_length;
        else
          add_difference(t, end, r[i]->visible ? Difference::hidden_in_candidate : Difference::visible_in_candidate);
        t = end;
        if (r[i]->t1 == end) ++i;
        if (c[j]->t1 == end) ++j;
      }
    }
    for (auto it = out.pieces.rbegin(); it != out.pieces.rend() && it->line == line; ++it) {
      it->length = (it->t1 - it->t0) * line_length;
      it->a = {a[0] + it->t0 * (b[0] - a[0]), a[1] + it->t0 * (b[1] - a[1])};
      it->b = {a[0] + it->t1 * (b[0] - a[0]), a[1] + it->t1 * (b[1] - a[1])};
    }
  }
  return out;
}

hidden_line::RasterImage difference_image(const LineDrawing& reference, const Agreement& agreement, int resolution) {
  double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
  for (const DrawingPiece& p : reference.pieces)
    for (const Point3& q : {p.a, p.b}) {
      x0 = std::min(x0, q[0]), x1 = std::max(x1, q[0]);
      y0 = std::min(y0, q[1]), y1 = std::max(y1, q[1]);
    }
  if (!(x0 <= x1)) x0 = y0 = x1 = y1 = 0;
  const hidden_line::RasterGrid grid = hidden_line::raster_grid(x0, y0, x1, y1, resolution);
  hidden_line::RasterImage image{grid.width, grid.height,
                                 std::vector<std::uint8_t>(std::size_t(grid.width) * grid.height * 3, 255)};
  using Color = std::array<std::uint8_t, 3>;
  auto draw = [&](const Point2& a, const Point2& b, Color color, int radius) {
    hidden_line::for_each_pixel_step(grid, a[0], a[1], b[0], b[1], [&](int column, int row, long, long) {
      for (int r = std::max(0, row - radius); r <= std::min(grid.height - 1, row + radius); ++r)
        for (int c = std::max(0, column - radius); c <= std::min(grid.width - 1, column + radius); ++c)
          std::copy(color.begin(), color.end(), &image.rgb[(std::size_t(r) * grid.width + c) * 3]);
    });
  };
  for (const bool visible : {false, true})
    for (const DrawingPiece& p : reference.pieces)
      if (p.visible == visible)
        draw({p.a[0], p.a[1]}, {p.b[0], p.b[1]}, visible ? Color{120, 120, 120} : Color{200, 200, 200}, 0);
  for (const DisagreeingPiece& d : agreement.pieces) {
    const Color color = d.difference == Difference::hidden_in_candidate    ? Color{220, 0, 0}
                        : d.difference == Difference::visible_in_candidate ? Color{0, 90, 255}
                                                                            : Color{255, 150, 0};
    draw(d.a, d.b, color, 1);
  }
  return image;
}

std::string check_json(const CheckReport& report) {
  using nlohmann::json;
  json methods = json::array();
  for (const CheckedMethod& m : report.methods) {
    json entry = {{"method", m.method}, {"seconds", m.seconds}};
    if (m.resolution > 0) entry["resolution"] = m.resolution;
    const Agreement& a = m.agreement;
    if (!m.failure.empty()) {
      entry["status"] = "failed";
      entry["message"] = m.failure;
    } else if (!a.invalid.empty()) {
      entry["status"] = "invalid";
      entry["message"] = a.invalid;
    } else {
      entry["status"] = "ok";
      auto difference = [&](Difference d) { return json{{"pieces", a.count(d)}, {"length", a.length(d)}}; };
      entry["agreement"] = {{"fraction", a.fraction()},
                            {"total_length", a.total_length},
                            {"agreeing_length", a.agreeing_length},
                            {"hidden_in_candidate", difference(Difference::hidden_in_candidate)},
                            {"visible_in_candidate", difference(Difference::visible_in_candidate)},
                            {"missing_in_candidate", difference(Difference::missing_in_candidate)}};
    }
    methods.push_back(std::move(entry));
  }
  json out = {{"format", "hlr-check/1"},
              {"input", detail::input_json(report.input)},
              {"view", detail::view_json(report.view)},
              {"reference",
               {{"method", "exact"},
                {"seconds", report.reference_seconds},
                {"drawn_visible_length", report.reference_visible_length},
                {"drawn_hidden_length", report.reference_hidden_length}}},
              {"methods", std::move(methods)}};
  return out.dump(1) + "\n";
}

std::string png_document(const hidden_line::RasterImage& image) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!png || !info) {
    png_destroy_write_struct(&png, nullptr);
    throw std::runtime_error("PNG: out of memory");
  }
  std::string out;
  // libpng reports errors by longjmp; nothing here owns anything that a jump would leak but `out`.
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    throw std::runtime_error("PNG: libpng could not encode the image");
  }
  png_set_write_fn(
      png, &out,
      [](png_structp p, png_bytep data, png_size_t size) {
        static_cast<std::string*>(png_get_io_ptr(p))->append(reinterpret_cast<const char*>(data), size);
      },
      nullptr);
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width), static_cast<png_uint_32>(image.height), 8,
               PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (int row = 0; row < image.height; ++row)
    png_write_row(png, const_cast<png_bytep>(&image.rgb[std::size_t(row) * image.width * 3]));
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return out;
}

}  // namespace hlr::exporter
