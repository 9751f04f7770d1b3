// The kernel-dependent writers (surfaces, and the rounding of line drawings) instantiated for
// DoubleKernel, and the raster path's drawing (its lines are on DoubleKernel).
#include "lines_impl.hpp"
#include "surfaces_impl.hpp"

namespace hlr::exporter {
HLR_EXPORT_SURFACES_DECLARE(hlr::DoubleKernel, )
HLR_EXPORT_LINES_DECLARE(hlr::DoubleKernel, )

LineDrawing make_raster_drawing(const InputInfo& input, const hidden_line::RasterDrawing& raster,
                                const hidden_line::LineSet<DoubleKernel>& lines, int resolution) {
  std::vector<hidden_line::DrawnSegment<DoubleKernel>> segments;
  for (const auto& line : lines.lines)
    for (const auto& piece : line.pieces) {
      // As drawing_segments draws smooth lines: visible pieces thin, hidden ones not at all.
      const bool smooth = line.kind == FeatureKind::smooth;
      if (smooth && !piece.visible) continue;
      auto at = [&](double t) { return DoublePoint{line.a.x + t * (line.b.x - line.a.x), line.a.y + t * (line.b.y - line.a.y)}; };
      segments.push_back(
          {at(piece.t0), at(piece.t1), piece.visible, line.mesh, line.meeting_degrees, 0, smooth, piece.t0, piece.t1});
    }
  LineDrawing drawing = make_drawing<DoubleKernel>(input, raster.frame(), KernelKind::floating, lines, std::move(segments));
  const hidden_line::RasterGrid& grid = raster.grid();
  drawing.raster = RasterInfo{resolution, grid.width, grid.height, grid.pixel};
  return drawing;
}
}  // namespace hlr::exporter
