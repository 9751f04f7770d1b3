// The source's true circles on a sheet (hlr/export/lines.hpp: ViewCurve, attach_source_curves).
//
// The exact engine decides which runs of a circle's polyline are visible and which are hidden;
// this only replaces the geometry of each run, after merging, by the circle it stands for: a run
// that closes is the whole circle (face-on: DXF CIRCLE, SVG/PDF circle) or ellipse, an open run an
// arc from its first point to its last, both projected onto the curve (radially; on an ellipse,
// at the parameter of their direction from the centre). The ends move by at most the
// tessellation's deflection (ends inside a tessellation segment, where visibility changes, by its
// sagitta): output geometry, no decision of the exact path.
#pragma once

#include <hlr/export/lines.hpp>

namespace hlr::exporter::detail {

// The curves of the segments on source curves that the view draws as curves, added to `curves`
// (paths of one arc step, circles, ellipses); the other segments, in their order, returned.
std::vector<DrawingSegment> draw_source_curves(const LineDrawing& drawing, const std::vector<DrawingSegment>& segments,
                                               DrawingCurves& curves);

}  // namespace hlr::exporter::detail
