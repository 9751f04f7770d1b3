// hlr export, jobs: the library's entry points, one call per job, as the hlr program runs them.
//
//   draw_lines      the line drawing of a view by a kernel (exact by default): sources, area
//                   sort, line classification, ISO 128 precedence, and the one rounding
//                   (make_drawing). The result's `times` has every stage.
//   draw_raster     the same drawing by the raster path (a Z-buffer of N pixels), for images
//                   and for cross-checks.
//   solve_surfaces  the hidden-surface solution of a view, as the documents of `hlr surfaces`.
//   clip_polygons   (polygons.hpp) the clipper on plain polygons.
//
// Writers (lines.hpp, surfaces.hpp, sheet.hpp) turn the results into documents; the caller
// writes the files. Jobs throw hlr::UserError for input they cannot use, hlr::Cancelled when the
// options' Progress asks them to stop.
#pragma once

#include <hlr/export/lines.hpp>
#include <hlr/export/surfaces.hpp>
#include <hlr/hidden_line/jobs.hpp>
#include <hlr/hidden_line/shadows.hpp>

#include <functional>
#include <memory>
#include <string>

namespace hlr::exporter {

using hidden_line::Progress;
using hidden_line::SceneIntersections;

struct DrawOptions {
  KernelKind kernel = KernelKind::exact;
  double crease = 30;          // degrees: an edge is a crease when its faces meet at more than this
  bool intersections = true;   // lines where faces penetrate
  SmoothEdges smooth_edges = SmoothEdges::off;  // smooth (tangent) edges: FeatureOptions
  // Leave the exact solution (polygons, visibility map, lines, drawing segments) and the scene's
  // own intersections to the process's exit instead of freeing them, once the drawing is rounded
  // or when the run is stopped: for a program that writes its outputs and exits. Freeing millions
  // of lazy exact numbers one by one took 2.9 s of a 46 s run on 300k faces when this was added
  // (and delayed a stop at 1M faces by 2 s; 0.4 s at 1M by the sixteenth run, free_once_drawn);
  // the operating system takes the memory back at once.
  bool free_at_exit = false;
  // With free_at_exit, still free the solution once the drawing is rounded (a stop leaves it to the
  // exit all the same): the outputs are then made in its pages instead of on top of the lines
  // stage's peak. At 1M faces it frees in about 0.4 s, 110 MB below the peak (docs/BENCHMARKS.md).
  bool free_once_drawn = false;
  // Shadows as surface detail (LineDrawing::shadows): the shadow areas of these lights on the
  // visible faces. Exact kernel only (std::invalid_argument otherwise); draw_lines only.
  std::vector<hidden_line::Light> shadow_lights;
  // The shadows of shadow_lights already solved for this scene (hidden_line::cast_shadows), or
  // null: they are solved here. Several views of one scene (hlr sheet) solve each light once.
  const hidden_line::ShadowResult* shadows = nullptr;
  // Per mesh, per face: faces no eye of the view can see (hidden_line::fuzzy_cull), left out of
  // the area sort, or null. The exact kernel only (the others ignore it): there the drawing is the
  // same with them and without them.
  const std::vector<std::vector<bool>>* culled_faces = nullptr;
  // Called once the lines are classified and what only that stage reads is freed, before the
  // output stage (draw_lines only): where a program may have its allocator hand free pages back
  // to the operating system (app/src/program_allocator.hpp). Null: nothing is called.
  std::function<void()> output_stage_begins;
  // Called once the drawing is rounded, before the solution is freed (free_once_drawn, draw_lines
  // only): the outputs then take less than it frees, so a program may have its allocator keep the
  // pages freed from here for them, rather than hand each back and fault it in again. Null: nothing
  // is called.
  std::function<void()> drawing_rounded;
  // Called as the lines stage begins when the penetrations were found beside the polygons, on a
  // second thread (draw_lines only): that search's freed pages then lie between the polygons' in
  // runs too short for the lines' array, and a program may hand them back to the operating system
  // rather than keep them beside it. Null: nothing is called.
  std::function<void()> lines_stage_begins;
  Progress progress;
};

// `intersections`: the scene's penetration lines, shared by several views of it (the scene's own
// are found otherwise); they must have been made with options.intersections.
LineDrawing draw_lines(const Scene& scene, const View& view, const DrawOptions& options = {},
                       const SceneIntersections* intersections = nullptr);

// The raster path's drawing, and the RasterDrawing for images of it (png_document(pbuffer())).
struct RasterRun {
  std::unique_ptr<hidden_line::RasterDrawing> raster;
  LineDrawing drawing;
};
RasterRun draw_raster(const Scene& scene, const View& view, int resolution, const DrawOptions& options = {},
                      const SceneIntersections* intersections = nullptr);
// The same with every raster option (RasterOptions::window: an image of a given view-plane window).
RasterRun draw_raster(const Scene& scene, const View& view, const hidden_line::RasterOptions& raster,
                      const DrawOptions& options = {}, const SceneIntersections* intersections = nullptr);

struct SurfacesOptions {
  KernelKind kernel = KernelKind::exact;
  hidden_line::SourceOptions sources;
  Progress progress;
};

// The solution of one view with its documents. It refers to the scene it was solved from, which
// must outlive it.
class SurfacesSolution {
 public:
  struct Summary {
    hidden_line::SourceStats sources;
    hidden_line::AreaSortStats sort;
    std::size_t visible = 0, hidden = 0;  // polygons
  };
  // hlr-surfaces/1; `exact` adds the "p/q" values. Its stats count the making of the document in
  // the write stage, and `written_before` too: the seconds this run's other outputs took.
  std::string json(bool exact, double written_before = 0) const;
  // The same text, handed to `sink` in parts (a large document is made in chunks on every thread).
  void write_json(bool exact, double written_before, const std::function<void(std::string_view)>& sink) const;
  std::string svg() const;
  const Summary& summary() const;
  const StageTimes& times() const;
  KernelKind kernel() const;

  struct Impl;
  explicit SurfacesSolution(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}

 private:
  std::shared_ptr<const Impl> impl_;
};

// times.read is the caller's to set (the solution's times() come without it).
SurfacesSolution solve_surfaces(const Scene& scene, const View& view, const SurfacesOptions& options = {},
                                double read_seconds = 0);

}  // namespace hlr::exporter
