// hlr export, curves: true circles and arcs recovered from the chained lines of a drawing, and
// the centre marks of the circles.
//
// A tessellated hole or boss reaches the drawing as a closed polygon, or as runs of segments along
// a circle when it is partly hidden or meets other lines. recover_curves finds them on the sheet
// lines (the drawing's chains, after merging) so that SVG, PDF and DXF can write a circle as a
// circle: what cutting services and CAD programs expect. This is output-side geometry in double,
// decided at the drawing's resolution; the exact pieces (hlr-lines/1) are not touched.
//
// The rule (docs/FORMATS.md, "Circles and arcs"): a run of at least three segments whose
// vertices all lie within `tolerance` of one fitted circle, going round it one way in even steps
// (their angles within `tolerance`, as arc length, of an even division, as tessellations divide
// circles: an ellipse's steps are not even) of at most 46 degrees (a circle of 8 segments has
// 45), and not within `tolerance` of a straight line, is an arc; a closed chain that goes round once that way is a circle. The two ends of an
// open chain may also lie on the chord that leaves the circle's last vertex (where a line becomes
// hidden, or a merged line was trimmed, in the middle of a tessellation segment).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace hlr::exporter {

using Point2 = std::array<double, 2>;

// Drawing segments of one class and one mesh joined end to end (lines.hpp, chain_segments): a
// closed loop has `closed` set and does not repeat its first point.
struct DrawingPolyline {
  std::vector<Point2> points;
  bool closed = false;
  bool visible = true;
  std::uint32_t mesh = 0;
  bool thin = false;  // visible, drawn thin (DrawingSegment::thin); likewise in the curves below
};

// One step of a path, from the point before it to `to`: a straight line, or an arc of the
// circle (centre, radius) going counter-clockwise (view axes, y up) or clockwise.
struct PathStep {
  Point2 to{};
  bool arc = false;
  Point2 centre{};
  double radius = 0;
  bool ccw = true;
};

// A chain as lines and arcs. The ends of an arc lie on its circle (vertices of the chain moved
// onto it radially, by at most the tolerance, or at a chain's end by at most the chord's sagitta).
struct DrawingPath {
  Point2 start{};
  std::vector<PathStep> steps;
  bool closed = false;  // a last line back to `start`
  bool visible = true;
  std::uint32_t mesh = 0;
  bool thin = false;
};

struct DrawingCircle {
  Point2 centre{};
  double radius = 0;
  bool visible = true;
  std::uint32_t mesh = 0;
  bool thin = false;
};

// An arc of an ellipse (a source circle seen at a slant, source_curves.hpp), as DXF's ELLIPSE
// has it: the points centre + cos t major + sin t ratio major', major' = major turned a quarter
// turn counter-clockwise, for t from t0 to t1 counter-clockwise (radians; a whole one: closed).
struct DrawingEllipse {
  Point2 centre{}, major{};
  double ratio = 1;  // minor over major, in (0, 1]
  double t0 = 0, t1 = 0;
  bool closed = false;
  bool visible = true;
  std::uint32_t mesh = 0;
  bool thin = false;
};

// The point of `e` at parameter t.
Point2 ellipse_point(const DrawingEllipse& e, double t);

struct DrawingCurves {
  std::vector<DrawingPath> paths;  // in the order of the chains
  std::vector<DrawingCircle> circles;
  std::vector<DrawingEllipse> ellipses;  // only from source curves
  std::size_t arcs = 0;  // arc steps in `paths`
  struct {
    std::size_t circles = 0, arcs = 0;
  } from_source;  // of `circles` and `arcs`, those of source curves (the rest recovered)
};

// Whether any path, circle or ellipse of `curves` is thin (a smooth line's visible piece).
bool has_thin_lines(const DrawingCurves& curves);

// The chains as paths, circles and arcs where the rule above finds them (tolerance in the
// chains' units; 0 or less: none, every chain a path of lines).
DrawingCurves recover_curves(const std::vector<DrawingPolyline>& chains, double tolerance);

// A centre line, in the drawing's units.
struct CentreLine {
  Point2 a{}, b{};
};

// The centre marks of the circles seen face-on: every circle, and every circle that arcs of one
// centre and radius go round once together (a partly hidden hole), gets two lines through its
// centre along the view's axes, `overshoot` beyond it; concentric circles (within `tolerance`)
// share the marks of the largest one.
std::vector<CentreLine> centre_marks(const DrawingCurves& curves, double tolerance, double overshoot);

// Circles and arcs seen face-on, for the centre lines of other views: each circle of `curves`, and
// each set of arcs of one circle that goes round once, grouped by centre (within `tolerance`).
struct FaceOnCircle {
  Point2 centre{};
  std::vector<double> radii;  // of the circles with this centre, ascending
};
std::vector<FaceOnCircle> face_on_circles(const DrawingCurves& curves, double tolerance);

}  // namespace hlr::exporter
