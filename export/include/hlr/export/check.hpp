// hlr export, check: how a drawing classifies its lines compared with a reference drawing of the
// same lines (the exact one), a picture of where they differ, and PNG encoding.
//
// Two drawings of one scene and view hold the same lines in the same order, whatever decided
// their visibility (the kernels and the raster path share the exact feature edges and
// intersection segments). compare_drawings walks the two partitions of every line's parameter
// together, weights each span by the reference line's image length, and keeps the maximal spans
// where the classes differ.
#pragma once

#include <hlr/export/lines.hpp>
#include <hlr/hidden_line/raster.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace hlr::exporter {

enum class Difference : std::uint8_t {
  hidden_in_candidate,   // the reference draws it visible, the candidate hidden
  visible_in_candidate,  // the reference draws it hidden, the candidate visible
  missing_in_candidate,  // the candidate has no piece there (its line projects to a point)
};

struct DisagreeingPiece {
  std::uint32_t line = 0;
  double t0 = 0, t1 = 0;  // along the line
  Difference difference = Difference::hidden_in_candidate;
  Point2 a, b;            // image ends, model units
  double length = 0;      // image length
};

struct Agreement {
  double total_length = 0;      // image length of all the reference's lines
  double agreeing_length = 0;   // of which both drawings classify alike
  std::vector<DisagreeingPiece> pieces;
  std::string invalid;  // why the candidate is not a valid drawing of the reference's lines; empty if it is
  double fraction() const { return total_length > 0 ? agreeing_length / total_length : 1.0; }
  std::size_t count(Difference d) const;
  double length(Difference d) const;
};

Agreement compare_drawings(const LineDrawing& reference, const LineDrawing& candidate);

// The reference drawing in grey (visible darker than hidden) with the disagreeing pieces over it,
// three pixels wide: red where the candidate hides a visible line, blue where it shows a hidden
// one, orange where it has none. `resolution` pixels along the longer side.
hidden_line::RasterImage difference_image(const LineDrawing& reference, const Agreement& agreement, int resolution);

// What `hlr check` reports, and its JSON (hlr-check/1, docs/FORMATS.md).
struct CheckedMethod {
  std::string method;   // "raster", "epick", "double"
  int resolution = 0;   // raster: pixels
  double seconds = 0;   // the method's drawing, without reading the meshes
  std::string failure;  // why the method produced no drawing (an inexact kernel's error); empty if it did
  Agreement agreement;  // against the reference, when it produced one
  std::string name() const { return resolution > 0 ? method + " " + std::to_string(resolution) : method; }
};
struct CheckReport {
  InputInfo input;
  ViewInfo view;
  double reference_seconds = 0;  // the exact drawing
  double reference_visible_length = 0, reference_hidden_length = 0;
  std::vector<CheckedMethod> methods;
};
std::string check_json(const CheckReport& report);

// The image as a PNG file (8-bit RGB).
std::string png_document(const hidden_line::RasterImage& image);

}  // namespace hlr::exporter
