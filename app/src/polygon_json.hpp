// Reading the hlr-polygons/1 format (docs/FORMATS.md) into plain double coordinates.
//
// Only structure is checked here: the document's shape, the format tag, that every coordinate is a
// finite number within the accepted range, and that every contour has at least 3 distinct
// vertices. Geometric validity (simple contours, holes inside) is the clipper's normalize_polygon.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace hlr::app {

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

}  // namespace hlr::app
