// make_drawing as a template over the kernel; included only by instantiate_*.cpp.
#pragma once

#include <hlr/export/lines.hpp>

namespace hlr::exporter {

// Coordinates of the unnormalized frame are correctly rounded to double, then divided by the axis
// scale (|X|, |Y|, |Z| are irrational in general, so this is the closest the output can be).
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
  auto round = [&](const FT& value, int axis) { return G::to_double(value) / frame.scale(axis) + 0.0; };  // no -0
  for (const auto& line : lines.lines) {
    auto at = [&](const FT& t) -> Point3 {
      return {round(line.a.x + t * (line.b.x - line.a.x), 0), round(line.a.y + t * (line.b.y - line.a.y), 1),
              round(line.a.z + t * (line.b.z - line.a.z), 2)};
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
      d.pieces.push_back(p);
    }
  }
  for (const auto& s : segments)
    d.segments.push_back({{round(G::x(s.a), 0), round(G::y(s.a), 1)}, {round(G::x(s.b), 0), round(G::y(s.b), 1)}, s.visible});
  return d;
}

}  // namespace hlr::exporter
