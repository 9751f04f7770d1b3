// The line drawing of a scene, by a kernel or by the raster path: what `hlr draw` and `hlr check`
// both run. Times exclude reading the meshes; times.write is the rounding of the exact drawing and
// the freeing of the exact solution, if it is freed (the start of the output stage).
#pragma once

#include "scene_options.hpp"

#include <hlr/export/lines.hpp>

#include <atomic>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace hlr::app {

struct LineRunSettings {
  double crease = 30;
  bool intersections = true;
  bool progress = false;  // stage lines on stderr
  // Leave the exact solution (polygons, visibility map, lines, drawing segments) to the process's
  // exit instead of freeing it once the drawing is rounded: for a command that writes its outputs
  // and exits (hlr draw). Freeing millions of lazy exact numbers one by one took 2.9 s of a 46 s
  // run on 300k faces; the operating system takes the memory back at once. hlr check solves
  // several times in one run: it frees.
  bool free_at_exit = false;
};

// --crease DEG and --no-intersections, into `settings`.
void add_line_options(CLI::App& cmd, LineRunSettings& settings);

// The exact intersection segments of the scene, if the settings ask for them, and their time.
// They do not depend on the view: they are found once, by the first run that asks, and a kernel
// run finds them beside its polygon stages when a second thread is free.
class Intersections {
 public:
  Intersections(const Scene& scene, const LineRunSettings& settings) : scene_(scene), settings_(settings) {}
  const std::vector<hidden_line::IntersectionSegment>& segments() const;  // finds them on the first call
  double seconds() const {
    segments();
    return seconds_;
  }
  bool found() const { return found_; }

 private:
  const Scene& scene_;
  LineRunSettings settings_;
  mutable std::once_flag once_;
  mutable std::vector<hidden_line::IntersectionSegment> segments_;
  mutable double seconds_ = 0;
  mutable std::atomic<bool> found_ = false;
};

// The drawing by kernel `kind`; an inexact kernel's failure throws inexact_kernel_failure's
// UserError naming `options.meshes`.
exporter::LineDrawing kernel_drawing(const SceneOptions& options, const Scene& scene, const View& view, KernelKind kind,
                                     const Intersections& intersections, const LineRunSettings& settings);

// The raster path's drawing, and the RasterDrawing for images of it.
struct RasterRun {
  std::unique_ptr<hidden_line::RasterDrawing> raster;
  exporter::LineDrawing drawing;
};
RasterRun raster_drawing(const Scene& scene, const View& view, int resolution, const Intersections& intersections,
                         const LineRunSettings& settings);

}  // namespace hlr::app
