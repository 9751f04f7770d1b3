// hlr export, polygons: the clipper as a job on plain polygons, and its contracts
// (docs/FORMATS.md): hlr-polygons/1 in, hlr-clip/1 out.
//
//   parse_polygons  reads an hlr-polygons/1 document into double coordinates. Only structure is
//                   checked there: the document's shape, the format tag, that every coordinate is
//                   a finite number within the accepted range, and that every contour has at
//                   least 3 distinct vertices. Geometric validity (simple contours, holes inside)
//                   is the clipper's normalize_polygon, in clip_polygons.
//   clip_polygons   each subject polygon clipped by the union of the clip polygons: the inside
//                   and outside pieces, every output edge tagged with the input edge it lies on,
//                   and the check area(inside) + area(outside) = area(subject) made in the
//                   kernel's own arithmetic. Everything is decided in the kernel; the pieces are
//                   rounded once at the end.
//   clip_json       the hlr-clip/1 document of an outcome.
#pragma once

#include <hlr/kernel/errors.hpp>
#include <hlr/kernel/kernel.hpp>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace hlr::exporter {

inline constexpr const char* kPolygonsFormat = "hlr-polygons/1";

// Coordinates beyond this magnitude are rejected: the inexact kernels evaluate products of
// coordinate differences (degree 2 and 3) in double, and they must not overflow.
inline constexpr double kMaxCoordinate = 1e100;

using RawPoint = std::array<double, 2>;
using RawContour = std::vector<RawPoint>;

struct RawPolygon {
  RawContour outer;
  std::vector<RawContour> holes;
};

// The whole file as bytes. Throws UserError(path, "cannot open (...)" / "cannot read (...)").
std::string read_text_file(const std::string& path);

// Parses an hlr-polygons/1 document; `path` only names the file in messages. Throws UserError.
std::vector<RawPolygon> parse_polygons(const std::string& text, const std::string& path);

inline std::vector<RawPolygon> read_polygons_file(const std::string& path) {
  return parse_polygons(read_text_file(path), path);
}

struct ClipOptions {
  KernelKind kernel = KernelKind::exact;
  std::string subject_name = "subject", clip_name = "clip";  // the files, in messages
  bool exact_values = false;  // also keep every vertex and area as exact "p/q" strings
  StopToken stop;             // polled between clip polygons
};

// Where an output edge lies: edge `edge` (input vertex edge -> edge + 1) of contour `contour`
// (0 = outer, h + 1 = hole h) of polygon `polygon` of the subject or the clip polygons.
struct EdgeSource {
  const char* role = nullptr;  // "subject" | "clip"
  std::uint32_t polygon = 0, contour = 0, edge = 0;
};

using ExactPoint2Text = std::array<std::string, 2>;

struct ClipPiece {
  std::uint32_t subject = 0;  // the subject polygon it is part of
  std::int64_t clip = -1;     // inside pieces: the clip polygon it is inside of
  RawPolygon polygon;         // outer counter-clockwise, holes clockwise, rounded
  std::vector<EdgeSource> outer_edges;
  std::vector<std::vector<EdgeSource>> hole_edges;
  std::vector<ExactPoint2Text> outer_exact;  // with exact_values
  std::vector<std::vector<ExactPoint2Text>> holes_exact;
};

struct ClipOutcome {
  KernelKind kernel = KernelKind::exact;
  bool exact_values = false;
  std::size_t subjects = 0, clips = 0;
  std::vector<ClipPiece> inside, outside;  // by subject, then clip polygon
  double subject_area = 0, inside_area = 0, outside_area = 0;
  std::string subject_area_exact, inside_area_exact, outside_area_exact;  // with exact_values
  bool identity_holds = true;          // per subject polygon, in the kernel's arithmetic
  std::size_t identity_failure = 0;    // the first subject polygon where it does not
  std::string identity_text;           // "exact identity holds", "identity off by ..."
  double seconds = 0;                  // clipping, without building the polygons
};

// Throws UserError naming options.subject_name or clip_name for an invalid polygon and for an
// inexact kernel that fails or produces a non-finite coordinate.
ClipOutcome clip_polygons(const std::vector<RawPolygon>& subjects, const std::vector<RawPolygon>& clips,
                          const ClipOptions& options = {});

// hlr-clip/1; with outcome.exact_values also "outer_exact", "holes_exact" and the exact areas.
std::string clip_json(const ClipOutcome& outcome);

// The shortest text that reads back as the same double; plain decimals for everyday magnitudes
// ("100000", not "1e+05").
std::string number_text(double v);

}  // namespace hlr::exporter
