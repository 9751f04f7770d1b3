// hlr hidden_line, raster: the image-space path after the P-buffer paper (Wang, seeds/002): a
// Z-buffer of the scene's faces at a chosen resolution, and hidden lines dashed by a pattern.
// It is the fast preview, a peer in the speed-versus-accuracy chart, and the cross-check of the
// exact engine. It is inexact on purpose: floating point, a float depth buffer, a depth offset
// (DESIGN.md: floating-point shortcuts belong to the named inexact paths).
//
// RasterDrawing takes the same lines as classify_lines (the exact feature edges, then the exact
// intersection segments, in the same order) and only decides visibility differently:
//   - the Z-buffer holds, per pixel centre, the depth of the nearest face (normalized to the
//     scene's depth range, as float) pushed back by a polygon offset of kSlopeOffset pixels times
//     the face's depth slope, and the id of that face (an item buffer);
//   - classify() tests every line at pixel spacing: a sample is visible when its pixel holds no
//     face, one of the line's own faces, or a face no nearer than the line there.
// Its pieces start and end on the sample grid, so agreement with the exact path is a matter of
// pixel size (docs/STABILITY.md says where and why they differ).
//
// pbuffer() renders the drawing as an image:
//   - DashPattern::paper is the paper's single pass: faces in input order, each one's interior
//     pixels then its feature lines; a nearer interior pixel erases the frame where the pattern
//     blocks, a farther line pixel is drawn where the pattern passes (never for a smooth line,
//     which is not drawn hidden; a nearer interior pixel erases its frame wholly). The pattern is an 8x8 tile
//     indexed by screen position (a chessboard of 4x4 squares, the one the paper discusses), so
//     dashes depend on where a line lies on screen, and diagonal lines come out solid or missing;
//   - DashPattern::arc_length draws the classified pieces instead: hidden samples are dashed by
//     their arc length along their own line, so every line gets regular dashes whatever its angle.
#pragma once

#include <hlr/hidden_line/lines.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

namespace hlr::hidden_line {

// The pixel grid over the drawing, in the orthonormal view frame (model units). Pixel (i, j) is
// column i from the left, row j from the top; its centre is at column i + 0.5, row j + 0.5.
struct RasterGrid {
  int width = 1, height = 1;
  double pixel = 1;        // model units per pixel
  double left = 0, top = 0;  // view x of the image's left edge, view y of its top edge
  double column(double x) const { return (x - left) / pixel; }
  double row(double y) const { return (top - y) / pixel; }
};

// The grid of `resolution` pixels along the longer side of the box x0..x1, y0..y1 with a margin
// of 2 pixels, the other side as long as it needs (any box, even an empty or a point one).
RasterGrid raster_grid(double x0, double y0, double x1, double y1, int resolution);

struct RasterOptions {
  int resolution = 1024;  // pixels along the longer side of the image, 16..16384
  // The view-plane window the image shows, x0, y0, x1, y1 in the orthonormal view frame (model
  // units; a perspective view's image plane at focal length 1), laid out as raster_grid lays out
  // a drawing's box: several images of one window share their pixel size and placement (the
  // frames of an animation). Nothing: the scene's own box (raster_extent). What lies outside the
  // window is clipped: no pixel, no line sample.
  std::optional<std::array<double, 4>> window;
};

// The box the raster path fits an image of `view` to when no window is given: the scene's
// vertices (and a perspective view's crossings with its near plane) not behind the near plane,
// x0, y0, x1, y1 in the orthonormal view frame; all zero when there are none.
std::array<double, 4> raster_extent(const std::vector<Mesh>& meshes, const View& view);

enum class DashPattern { paper, arc_length };

// 8-bit RGB, row-major from the top row, 3 bytes per pixel.
struct RasterImage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;
};

class RasterDrawing {
 public:
  // Builds the Z-buffer. Throws std::invalid_argument for a resolution outside 16..16384.
  RasterDrawing(const std::vector<Mesh>& meshes, const View& view, const std::vector<IntersectionSegment>& intersections,
                const LineOptions& options, const RasterOptions& raster);
  ~RasterDrawing();
  RasterDrawing(const RasterDrawing&) = delete;
  RasterDrawing& operator=(const RasterDrawing&) = delete;

  const RasterGrid& grid() const;
  const ViewFrame<DoubleKernel>& frame() const;

  // The lines of classify_lines, split into pieces by depth tests at pixel spacing. Points are in
  // the unnormalized double frame, like classify_lines on DoubleKernel.
  LineSet<DoubleKernel> classify() const;

  RasterImage pbuffer(DashPattern pattern) const;

 private:
  struct Impl;
  Impl* impl_;
};

// Splits the image of a to b (orthonormal view x, y) into n = ceil(length in pixels) equal steps
// and calls visit(column, row, k, n) for step k, whose middle is at line parameter (k + 0.5) / n
// and lies in pixel (column, row); nothing when a == b. Steps whose middle is outside the grid are
// skipped. Shared by the raster path and the diff image of `hlr check`.
template <class Visit>
void for_each_pixel_step(const RasterGrid& grid, double ax, double ay, double bx, double by, Visit&& visit) {
  const double c0 = grid.column(ax), r0 = grid.row(ay), c1 = grid.column(bx), r1 = grid.row(by);
  const double steps = std::ceil(std::hypot(c1 - c0, r1 - r0));
  if (!(steps > 0)) return;
  const long n = static_cast<long>(steps);
  for (long k = 0; k < n; ++k) {
    const double t = (double(k) + 0.5) / double(n);
    const double c = c0 + t * (c1 - c0), r = r0 + t * (r1 - r0);
    if (!(c >= 0 && r >= 0 && c < grid.width && r < grid.height)) continue;
    visit(static_cast<int>(c), static_cast<int>(r), k, n);
  }
}

}  // namespace hlr::hidden_line
