// make_drawing as a template over the kernel; included only by instantiate_*.cpp.
//
// Rounding is most of an exact drawing's output stage: every piece end and every drawing segment
// end is an exact number whose nearest double takes an exact evaluation (GMP) the first time.
// So lines and segments are rounded in parallel (oneTBB, as line classification: Epeck's lazy
// numbers may be evaluated from several threads), each into its own place, so that the drawing
// does not depend on the number of threads; and on the exact kernel a piece end equal to an end
// of its line (t = 0 or 1, known from the interval of t) is that end, and a piece that starts
// where the one before it ends (the same number) starts at that rounded point. Both give the
// same double as the general formula, without the arithmetic: the exact value is the same. The
// ends of intersection lines in orthographic views come rounded with the lines (from how they were
// built, kernel/exact_output.hpp: no lazy numbers), and drawing segments are rounded by way of
// their line and parameters, so that their ends take that way too.
#pragma once

#include <hlr/export/lines.hpp>

#include <hlr/hidden_line/parallel.hpp>

namespace hlr::exporter {

// Coordinates are rounded by ViewFrame::rounded, as in hlr-surfaces/1.
template <class K>
LineDrawing make_drawing(const InputInfo& input, const ViewFrame<K>& frame, KernelKind kernel,
                         const hidden_line::LineSet<K>& lines,
                         std::vector<hidden_line::DrawnSegment<K>> segments, StopToken stop) {
  using G = Geometry<K>;
  using FT = typename G::FT;
  LineDrawing d;
  d.input = input;
  d.view = view_info(frame);
  d.kernel = kernel;
  d.stats = lines.stats;

  // Each line's ends as written, rounded once for its pieces and its drawing segments: an
  // intersection's by way of its ends' recipes where they apply (rounded as its lines were
  // classified), and a mesh edge's input vertices the same way when their intervals do not settle
  // the rounding (in any view but the axis ones), rather than by evaluating their lazy view
  // coordinates.
  const RecipeRounding recipe_rounding(frame.view());
  std::vector<std::array<Point3, 2>> ends(lines.lines.size());
  auto round_ends = [&](std::size_t index) {
    const auto& line = lines.lines[index];
    for (int end = 0; end < 2; ++end) {
      Point3& written = ends[index][end];
      const ViewPoint<K>& p = end == 0 ? line.a : line.b;
      if constexpr (G::exact_constructions) {
        std::optional<std::array<double, 3>> v;
        if (line.rounded_ends != line.kNotRounded) {
          v = lines.rounded_ends[line.rounded_ends][end];
        } else if (line.has_model_ends) {
          auto settled = [](const FT& c) { return G::interval(c).first == G::interval(c).second; };
          if (!settled(p.x) || !settled(p.y) || !settled(p.z))
            v = recipe_rounding.nearest({ModelPointRecipe::Kind::input_point, lines.model_end(line, end)});
        }
        if (v) {
          for (int axis = 0; axis < 3; ++axis) written[axis] = (*v)[axis] / frame.scale(axis) + 0.0;
          continue;
        }
      }
      written = {frame.rounded(p.x, 0), frame.rounded(p.y, 1), frame.rounded(p.z, 2)};
    }
  };
  // The point at t of line `index` as written (z too when the axes are 3), once its ends are.
  auto at = [&](std::size_t index, const FT& t, int axes = 3) -> Point3 {
    if constexpr (G::exact_constructions) {
      const auto [lo, hi] = G::interval(t);
      if (lo == hi && (lo == 0 || lo == 1)) return ends[index][lo == 0 ? 0 : 1];
    }
    const auto& line = lines.lines[index];
    const FT* from[3] = {&line.a.x, &line.a.y, &line.a.z};
    const FT* to[3] = {&line.b.x, &line.b.y, &line.b.z};
    Point3 written{};
    for (int axis = 0; axis < axes; ++axis) written[axis] = frame.rounded_between(*from[axis], *to[axis], t, axis);
    return written;
  };

  // The ends first: the segments are rounded by way of them, and then freed before the pieces are
  // made, which lowers the run's peak.
  hidden_line::parallel_chunks(lines.lines.size(), 256, [&](const auto& range) {
    stop.check();
    for (std::size_t index = range.begin(); index != range.end(); ++index)
      if (!lines.lines[index].pieces.empty()) round_ends(index);
  });
  hidden_line::resize_in_parallel(d.segments, segments.size());
  hidden_line::parallel_chunks(segments.size(), 256, [&](const auto& range) {
    stop.check();
    for (std::size_t i = range.begin(); i != range.end(); ++i) {
      const auto& s = segments[i];
      Point2 a, b;
      if constexpr (G::exact_constructions) {
        // The same exact points by way of their line (one with pieces), whose ends are rounded.
        const Point3 pa = at(s.line, s.t0, 2), pb = at(s.line, s.t1, 2);
        a = {pa[0], pa[1]};
        b = {pb[0], pb[1]};
      } else {
        a = {frame.rounded(s.a, 0), frame.rounded(s.a, 1)};
        b = {frame.rounded(s.b, 0), frame.rounded(s.b, 1)};
      }
      d.segments[i] = {a, b, s.visible, s.mesh, s.meeting_degrees, s.line, -1, s.thin};
    }
  });
  std::vector<hidden_line::DrawnSegment<K>>().swap(segments);
  // Line i's pieces go to d.pieces[first[i], first[i + 1]).
  std::vector<std::size_t> first(lines.lines.size() + 1, 0);
  for (std::size_t i = 0; i < lines.lines.size(); ++i) first[i + 1] = first[i] + lines.lines[i].pieces.size();
  hidden_line::resize_in_parallel(d.pieces, first.back());
  hidden_line::parallel_chunks(lines.lines.size(), 64, [&](const auto& range) {
    stop.check();
    for (std::size_t index = range.begin(); index != range.end(); ++index) {
      const auto& line = lines.lines[index];
      if (line.pieces.empty()) continue;
      DrawingPiece* out = &d.pieces[first[index]];
      for (std::size_t k = 0; k < line.pieces.size(); ++k) {
        const auto& piece = line.pieces[k];
        DrawingPiece& p = out[k];
        const bool shared = k > 0 && G::same_number(piece.t0, line.pieces[k - 1].t1);
        if (shared) {
          p.a = out[k - 1].b;
          p.t0 = out[k - 1].t1;
        } else {
          p.a = at(index, piece.t0);
          p.t0 = G::to_double(piece.t0);
        }
        p.b = at(index, piece.t1);
        p.t1 = G::to_double(piece.t1);
        p.visible = piece.visible;
        p.kind = line.kind;
        p.mesh = line.mesh;
        p.has_edge = line.kind != FeatureKind::intersection;
        p.edge = {line.v0, line.v1};
        p.line = std::uint32_t(index);
      }
    }
  });

  return d;
}

}  // namespace hlr::exporter
