// hlr export, lines: a hidden-line drawing as a document.
//
//   make_drawing  rounds a LineSet (and its drawing segments, which it takes and frees once
//                 rounded) to the orthonormal view frame in model units: the one place where the
//                 exact result is rounded.
//   lines_json    the hlr-lines/1 contract (DESIGN.md, docs/FORMATS.md): every piece, visible and
//                 hidden, with its kind and mesh edge (write_lines_json: the same, written out as
//                 it is made).
//   sheet_lines   what a sheet shows of a drawing in a style: its scale, the sheet segments
//                 (sheet_segments: the drawing segments after near-coincident ones are merged at
//                 the drawing's resolution) and their chains. Worked out once, it is handed to
//                 both writers below (and its counts to the JSON's stats), so that a command
//                 writing SVG and DXF merges and chains once.
//                 Circles and arcs are recovered from the chains there (curves.hpp), and the
//                 circles' centre marks made.
//   lines_svg     a drawing on a sheet, in millimetres: visible lines continuous wide, hidden lines
//                 dashed narrow, centre lines long-dash dotted narrow (ISO 128, docs/FORMATS.md),
//                 each part's lines in a group of its own.
//   lines_pdf     the same sheet as a vector PDF (cairo), line widths and dashes in millimetres.
//   lines_dxf     the same drawing as DXF R2000 in model units, layers VISIBLE and HIDDEN (one
//                 pair per part when the scene has several meshes) and CENTER, their linetypes
//                 defined in the file, polylines as LWPOLYLINE, circles and arcs as CIRCLE and ARC.
//
// SVG, PDF and DXF draw the sheet lines. Merging and curve recovery are tolerances on rounded
// output, for the eye; the JSON keeps every piece as the exact engine made it.
//
// Writers return the document; the caller writes it to disk (atomically).
#pragma once

#include <hlr/export/curves.hpp>
#include <hlr/export/surfaces.hpp>
#include <hlr/hidden_line/lines.hpp>
#include <hlr/hidden_line/raster.hpp>

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hlr::exporter {

using Point3 = std::array<double, 3>;

// One piece of hlr-lines/1: view coordinates in model units.
struct DrawingPiece {
  Point3 a, b;
  bool visible = true;
  FeatureKind kind = FeatureKind::boundary;
  std::uint32_t mesh = 0;
  bool has_edge = false;  // false for intersection lines (JSON "edge": null)
  std::array<std::uint32_t, 2> edge{};
  std::uint32_t line = 0;  // index of its line in the LineSet (lines seen end-on have no piece)
  double t0 = 0, t1 = 1;   // its span along that line, rounded
};

// A segment the drawing shows, after precedence (in model units), and the mesh it is drawn for.
struct DrawingSegment {
  Point2 a, b;
  bool visible = true;
  std::uint32_t mesh = 0;
  double meeting_degrees = 90;  // intersection lines: the angle at which their surfaces meet
  std::uint32_t line = 0;       // index of its line in the LineSet
  std::int32_t curve = -1;      // the LineDrawing::source_curves it lies on, or -1
  bool thin = false;            // a visible piece of a smooth line: thin continuous (ISO 128 01.1)
};
// The ISO 128-20 precedence of a segment's class: 0 visible (continuous wide), 1 hidden (dashed
// narrow), 2 thin (continuous narrow: smooth lines). Where lines coincide, the lower one is drawn.
inline int precedence_rank(const DrawingSegment& s) { return s.thin ? 2 : s.visible ? 0 : 1; }

// A source circle (Mesh::source_curves: a CAD model's circular B-rep edge) as an orthographic
// view sees it, in view coordinates: its centre, and the ellipse it projects to, with major
// semi-axis `major` (a vector of length radius) and `ratio` = |cos| of the angle between its
// plane's normal and the view direction. face_on: the normal is parallel to the view direction,
// decided exactly on the doubles (normal x direction = 0 in rationals): the image is the circle
// itself. edge_on (normal . direction = 0, likewise): a segment, drawn as the polyline.
struct ViewCurve {
  Point2 centre{}, major{};
  double radius = 0, ratio = 1;
  bool face_on = false, edge_on = false;
  std::uint32_t mesh = 0;
};

// Set when a drawing comes from the raster path (hidden_line/raster.hpp) instead of a kernel.
struct RasterInfo {
  int resolution = 0, width = 0, height = 0;
  double pixel = 0;  // model units per pixel
};

// A filled area of a drawing (hlr draw --sun: a shadow on a visible face), in view coordinates
// like the segments: outer counter-clockwise, holes clockwise.
struct DrawingArea {
  std::vector<std::array<double, 2>> outer;
  std::vector<std::vector<std::array<double, 2>>> holes;
};

struct LineDrawing {
  InputInfo input;
  ViewInfo view;
  KernelKind kernel = KernelKind::exact;
  std::optional<RasterInfo> raster;      // JSON "kernel": "raster" and a "raster" object
  std::vector<DrawingPiece> pieces;      // JSON: every piece
  std::vector<DrawingSegment> segments;  // SVG and DXF
  std::vector<ViewCurve> source_curves;  // attach_source_curves: what DrawingSegment::curve indexes
  std::vector<DrawingArea> shadows;      // SVG and DXF: with DrawOptions::shadow_lights
  hidden_line::LineStats stats;
  double crease_degrees = 30;
  StageTimes times;
  double zbuffer_seconds = 0;  // raster path: building the Z-buffer
  // Set by the caller from sheet_segments: how many segments the SVG and DXF merge, and at which
  // distance on the sheet (JSON stats "merged_segments", "merge_distance_mm"); absent: not written.
  std::optional<std::size_t> merged_segments;
  double merge_distance_mm = 0;
  // Likewise, the intersection segments left out as contact lines ("contact_segments",
  // "contact_degrees").
  std::size_t contact_segments = 0;
  double contact_degrees = 0;
  // Likewise, the circles and arcs the sheet recovered ("circles", "arcs"); absent: not written.
  struct CurveCounts {
    std::size_t circles = 0, arcs = 0;
  };
  std::optional<CurveCounts> curves;
  // A frame of `hlr frames`: its group of eyes and what the fuzzy culling of that group left out of
  // the area sort (JSON stats "cull"); absent: not written.
  struct CullCounts {
    std::size_t group = 0, part = 0, parts = 1, patches = 0, culled = 0;
    double fuzzy_seconds = 0;                // the group's fuzzy passes
    std::optional<double> unculled_seconds;  // --cull-report: this frame solved without culling
    std::optional<double> group_saved_seconds;  // --cull-report: FrameGroup::saved_seconds
  };
  std::optional<CullCounts> cull;
  // Total image-plane length of `segments` (what a drawing shows), visible and hidden, model units.
  double visible_length() const { return length(true); }
  double hidden_length() const { return length(false); }

 private:
  double length(bool visible) const;
};

template <class K>
LineDrawing make_drawing(const InputInfo& input, const ViewFrame<K>& frame, KernelKind kernel,
                         const hidden_line::LineSet<K>& lines, std::vector<hidden_line::DrawnSegment<K>> segments,
                         StopToken stop = {});

// The raster path's drawing: every piece is drawn as it is (no precedence step; the raster
// classification decides one class per pixel step).
LineDrawing make_raster_drawing(const InputInfo& input, const hidden_line::RasterDrawing& raster,
                                const hidden_line::LineSet<DoubleKernel>& lines, int resolution);

// Sets drawing.source_curves from the meshes' Mesh::source_curves and marks the segments that lie
// on them (by their line's mesh edge), in an orthographic view; a perspective one keeps none.
void attach_source_curves(LineDrawing& drawing, const std::vector<Mesh>& meshes);

// Sheet sizes after ISO 216, landscape.
struct Sheet {
  std::string name;  // "A4"
  double width_mm = 297, height_mm = 210;
};
// A0..A4 by name (any letter case); nothing for an unknown name.
std::optional<Sheet> sheet_by_name(const std::string& name);

struct DrawingStyle {
  Sheet sheet;
  std::optional<double> scale;  // drawing mm per model unit; none: the largest ISO 5455 scale that fits
  bool hidden = true;           // draw hidden lines (dashed); false: visible lines only
  double merge_distance = 0.01; // mm on the sheet: the drawing's resolution (0: merge nothing)
  // Intersection lines where two surfaces meet at less than this many degrees are contact lines of
  // nearly tangent surfaces (a shaft in a bore, tessellated differently): not drawn (0: all drawn).
  double contact_degrees = 10;
  // ISO 128 line group: the width of the wide (visible) lines, mm; narrow lines are half as wide
  // (0.18 in the 0.35 group), dashes in proportion (line_widths).
  double line_group = 0.5;
  bool circles = true;       // recover circles and arcs (curves.hpp) at merge_distance
  bool centre_lines = true;  // centre marks on circles seen face-on (sheets: also cylinder axes)
  // What one model unit is, in millimetres (--units: mm 1, cm 10, m 1000, in 25.4), and its name.
  // `scale` and the scales below are sheet millimetres per model unit; the title block writes the
  // ratio of sheet to part, scale / unit_mm.
  double unit_mm = 1;
  std::string units = "mm";
};

// The widths (mm) and dash patterns (mm, on and off) of ISO 128-20's line types in a line group:
// 01.2 continuous wide (visible), 02.1 dashed narrow (hidden: dash 12d, gap 3d), 04.1 long-dash
// dotted narrow (centre: dash 24d, gap 3d, dot 0.5d, gap 3d), d the narrow width.
struct LineWidths {
  double wide = 0.5, narrow = 0.25;
  std::vector<double> hidden_dashes, centre_dashes;
};
// Nothing for a line group other than 0.25, 0.35, 0.5, 0.7 and 1.
std::optional<LineWidths> line_widths(double line_group);

// The ISO 5455 scale 1, 2 or 5 x 10^k nearest to `ratio` from below (the ratio itself when it is
// one, up to rounding), and whether a ratio is one of them.
double iso_scale_at_most(double ratio);
bool is_iso_scale(double ratio);
// "1:5", "2:1", "1:2.5": a ratio of sheet to part.
std::string scale_label(double ratio);
// What a drawing's title block says of its scale: scale_label, or "NTS (perspective)".
std::string drawing_scale_label(const LineDrawing& drawing, double ratio);

// The scale a drawing is made at: style.scale, or the largest ISO 5455 scale (1:1, 1:2, 1:5, ...,
// 2:1, 5:1, ...) at which the drawing fits the sheet's drawing area (times style.unit_mm).
double drawing_scale(const LineDrawing& drawing, const DrawingStyle& style);

// Near-coincident segments drawn once, after ISO 128 precedence. Visible segments are taken first,
// then hidden ones, then thin ones (precedence_rank), each class in input order; a segment loses every part that runs along an
// already kept segment within `distance` (model units): whole duplicates are dropped, collinear
// overlaps trimmed, and leftovers shorter than `distance` dropped; an overlap shorter than
// `distance` is left alone (segments meeting end to end). "Along" means nearly parallel
// (directions within about 0.6 degrees), so that lines crossing or meeting another one are never
// cut. A trimmed end at a kept segment's end is moved onto that end, so chains stay joined. Kept
// segments keep their input order; `merged` counts the segments dropped or shortened. A uniform
// grid finds the candidates: no all-pairs scan.
struct MergedSegments {
  std::vector<DrawingSegment> segments;
  std::size_t merged = 0;
  std::size_t contact = 0;  // sheet_segments: intersection segments left out as contact lines
};
MergedSegments merge_segments(const std::vector<DrawingSegment>& segments, double distance);
namespace detail {
// The same merge with every kept segment and piece a candidate for every segment: the tests'
// oracle for merge_segments' grids.
MergedSegments merge_segments_all_pairs(const std::vector<DrawingSegment>& segments, double distance);
}  // namespace detail

// What the SVG and DXF of `drawing` show with `style`: the drawn classes (hidden ones only if
// style.hidden) without the contact lines (style.contact_degrees), merged at style.merge_distance
// mm on the sheet, that is merge_distance / scale in model units at the drawing's scale.
MergedSegments sheet_segments(const LineDrawing& drawing, const DrawingStyle& style);
// Sets the drawing's sheet counts (merged_segments, merge_distance_mm, contact_segments,
// contact_degrees) from what sheet_segments made of it with `style`.
void record_sheet_counts(LineDrawing& drawing, const MergedSegments& merged, const DrawingStyle& style);

// The name of each part (mesh) of a drawing, from its name in the source where it has one
// (InputInfo::parts: a STEP product), else from its input file's stem: letters, digits, '_' and
// '-' kept, any other run of characters made one '_', "mesh" when nothing is left, and "-2", "-3",
// ... added where a name (compared in any letter case, as DXF layer names are) is taken already.
// One name per input file, and "mesh-N" for a mesh index beyond them.
std::vector<std::string> part_names(const LineDrawing& drawing);

// Drawing segments of one class and one mesh joined end to end (DrawingPolyline, curves.hpp):
// segments whose endpoints are equal doubles are joined through every point where exactly two
// segments of that class and mesh meet (the exact engine makes shared endpoints identical, so no
// tolerance). Visible chains first, then hidden ones, each in the order of their first segment in
// the input; a closed loop has `closed` set and does not repeat its first point.
std::vector<DrawingPolyline> chain_segments(const std::vector<DrawingSegment>& segments);

// The sheet of `drawing` in `style`, for lines_svg, lines_pdf and lines_dxf.
struct SheetLines {
  double scale = 1;                      // sheet mm per model unit
  MergedSegments merged;                 // sheet_segments(drawing, style)
  std::vector<DrawingPolyline> chains;   // chain_segments(merged.segments)
  DrawingCurves curves;                  // the chains with their circles and arcs (what is drawn)
  std::vector<CentreLine> centre_lines;  // centre marks, model units
  std::vector<DrawingArea> shadows;      // LineDrawing::shadows
  // The view point that hlr draw's sheet puts on its drawing area's centre (model units); none:
  // the centre of the drawn lines. The frames of one sequence share one (frames.hpp).
  std::optional<std::array<double, 2>> centre;
};
// Without style.scale, the scale is drawing_scale's, or the next smaller ISO scale if the
// recovered circles (which reach out beyond their polygons) do not fit at it.
SheetLines sheet_lines(const LineDrawing& drawing, const DrawingStyle& style);
// The same lines at a given scale.
SheetLines sheet_lines_at(const LineDrawing& drawing, const DrawingStyle& style, double scale);

// What the drawn lines of a sheet cover, in model units: nothing when none is drawn.
struct Bounds {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  double width() const { return x1 - x0; }
  double height() const { return y1 - y0; }
};
std::optional<Bounds> sheet_bounds(const SheetLines& sheet);
// The largest ISO 5455 scale (times style.unit_mm) at which a box of `bounds` (model units) fits
// the drawing area of hlr draw's sheet in `style`.
double fitting_scale(const Bounds& bounds, const DrawingStyle& style);

// Why a one-view sheet does not fit its sheet's drawing area at its scale ("the drawing needs
// 400 x 120 mm at 2:1; the drawing area of A4 is 257 x 160 mm"), or nothing when it fits.
std::optional<std::string> sheet_overflow(const SheetLines& sheet, const DrawingStyle& style);

// The hlr-lines/1 document, handed to `sink` in blocks of about a megabyte as it is made (the
// document of a large drawing is never held whole; `sink` writes the blocks out, in order). Its
// stats.stage_seconds.write is drawing.times.write, or with `write_seconds` what that returns: it
// is called once, when every piece has gone to the sink but the last block and only the stats and
// the view are left, so that a caller timing its output stage can count the JSON's own making and
// nearly all of its writing in it. stats.seconds is times.total plus that time: the run from
// reading the meshes to the (nearly) finished document.
void write_lines_json(const LineDrawing& drawing, const std::function<void(std::string_view)>& sink,
                      const std::function<double()>& write_seconds = {});
// hlr draw's JSON when no sheet is drawn: sheet_segments, which only the stats need then
// (merged_segments, contact_segments), runs beside the writing of the pieces on a second thread,
// and record_sheet_counts before the stats are written. Returns what sheet_segments made.
MergedSegments write_lines_json_merging(LineDrawing& drawing, const DrawingStyle& style,
                                        const std::function<void(std::string_view)>& sink,
                                        const std::function<double()>& write_seconds = {});
// The same document as one string.
std::string lines_json(const LineDrawing& drawing, const std::function<double()>& write_seconds = {});
// `sheet` must be sheet_lines(drawing, style); the overloads without it work it out themselves.
std::string lines_svg(const LineDrawing& drawing, const DrawingStyle& style, const SheetLines& sheet);
std::string lines_pdf(const LineDrawing& drawing, const DrawingStyle& style, const SheetLines& sheet);
std::string lines_dxf(const LineDrawing& drawing, const DrawingStyle& style, const SheetLines& sheet);
std::string lines_svg(const LineDrawing& drawing, const DrawingStyle& style);
std::string lines_pdf(const LineDrawing& drawing, const DrawingStyle& style);
std::string lines_dxf(const LineDrawing& drawing, const DrawingStyle& style);

#define HLR_EXPORT_LINES_DECLARE(K, EXTERN)                                                              \
  EXTERN template LineDrawing make_drawing<K>(const InputInfo&, const ViewFrame<K>&, KernelKind,         \
                                              const hidden_line::LineSet<K>&,                            \
                                              std::vector<hidden_line::DrawnSegment<K>>, StopToken);

HLR_EXPORT_LINES_DECLARE(ExactKernel, extern)
HLR_EXPORT_LINES_DECLARE(EpickKernel, extern)
HLR_EXPORT_LINES_DECLARE(DoubleKernel, extern)

}  // namespace hlr::exporter
