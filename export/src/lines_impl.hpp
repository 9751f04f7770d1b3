// make_drawing as a template over the kernel; included only by instantiate_*.cpp.
#pragma once

#include <hlr/export/lines.hpp>

namespace hlr::exporter {

// Coordinates are rounded by ViewFrame::rounded, as in hlr-surfaces/1.
template <class K>
LineDrawing make_drawing(const InputInfo& input, const ViewFrame<K>& frame, KernelKind kernel,
                         const hidden_line::LineSet<K>& lines,
                         const std::vector<hidden_line::DrawnSegment<K>>& segments) {
  using G = Geometry<K>;
  using FT = typename G::FT;
  LineDrawing d;
  d.input = input;
  d.view = view_info(frame);
  d.kernel = kernel;
  d.stats = lines.stats;
  for (std::uint32_t index = 0; index < lines.lines.size(); ++index) {
    const auto& line = lines.lines[index];
    auto at = [&](const FT& t) -> Point3 {
      return {frame.rounded(line.a.x + t * (line.b.x - line.a.x), 0),
              frame.rounded(line.a.y + t * (line.b.y - line.a.y), 1),
              frame.rounded(line.a.z + t * (line.b.z - line.a.z), 2)};
    };
    for (const auto& piece : line.pieces) {
      DrawingPiece p;
      p.a = at(piece.t0);
      p.b = at(piece.t1);
      p.visible = piece.visible;
      p.kind = line.kind;
      p.mesh = line.mesh;
      p.has_edge = line.kind != FeatureKind::intersection;
      p.edge = {line.v0, line.v1};
      p.line = index;
      p.t0 = Geometry<K>::to_double(piece.t0);
      p.t1 = Geometry<K>::to_double(piece.t1);
      d.pieces.push_back(p);
    }
  }
  for (const auto& s : segments)
    d.segments.push_back({{frame.rounded(G::x(s.a), 0), frame.rounded(G::y(s.a), 1)},
                          {frame.rounded(G::x(s.b), 0), frame.rounded(G::y(s.b), 1)},
                          s.visible, s.mesh, s.meeting_degrees});
  return d;
}

}  // namespace hlr::exporter
