#include "line_runs.hpp"

#include <tbb/global_control.h>
#include <tbb/task_group.h>

#include <iostream>
#include <optional>

namespace hlr::app {
namespace {

void stage(const LineRunSettings& settings, const std::string& what) {
  if (settings.progress) std::cerr << ("hlr: " + what + '\n');  // one write: stages may run side by side
}

hidden_line::LineOptions line_options(const LineRunSettings& settings) {
  hidden_line::LineOptions options;
  options.features.crease_degrees = settings.crease;
  options.intersections = settings.intersections;
  return options;
}

// The exact solution of a view: what the drawing is rounded from.
template <class K>
struct Solution {
  hidden_line::Sources<K> sources;
  hidden_line::VisibilityMap<K> map;
  hidden_line::LineSet<K> lines;
  std::vector<hidden_line::DrawnSegment<K>> segments;
};

template <class K>
exporter::LineDrawing solve(const Scene& scene, const View& view, KernelKind kind, const Intersections& intersections,
                            const LineRunSettings& settings) {
  const ViewFrame<K> frame(view);
  exporter::StageTimes times;
  auto solution = std::make_unique<Solution<K>>();
  const auto begin = std::chrono::steady_clock::now();
  const bool found_before = intersections.found();
  // Beside the polygon stages when a second thread is free. Otherwise first: on a small scene,
  // starting the scheduler would take longer than they do, and with one thread, found first they
  // are found on a fresh heap (at 1M faces, after the sort they took twice as long).
  constexpr std::size_t kFacesBeside = 2000;
  const bool second_thread = tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism) > 1;
  std::optional<tbb::task_group> beside;
  if (second_thread && scene.input.faces >= kFacesBeside) beside.emplace().run([&] { intersections.segments(); });
  else intersections.segments();
  auto mark = std::chrono::steady_clock::now();
  stage(settings, std::to_string(scene.input.faces) + " faces; building polygons (" + kernel_name(kind) + ")");
  solution->sources = hidden_line::build_sources<K>(scene.meshes, frame);
  times.sources = seconds_since(mark);
  stage(settings, "sorting " + std::to_string(solution->sources.polygons.size()) + " polygons");
  mark = std::chrono::steady_clock::now();
  // A drawing needs only the visible polygons: what the front pieces hide is not kept.
  solution->map = hidden_line::area_sort<K>(solution->sources, {.keep_hidden = false});
  times.sort = seconds_since(mark);
  if (beside) beside->wait();
  times.intersections = intersections.seconds();
  stage(settings, "classifying feature lines");
  mark = std::chrono::steady_clock::now();
  solution->lines = hidden_line::classify_lines<K>(scene.meshes, frame, solution->sources, solution->map,
                                                   intersections.segments(), line_options(settings));
  times.lines = seconds_since(mark);
  mark = std::chrono::steady_clock::now();
  solution->segments = hidden_line::drawing_segments<K>(solution->lines);
  times.precedence = seconds_since(mark);
  // The stages' own times overlap where the intersections were found beside the polygons.
  times.total = seconds_since(begin) + (found_before ? times.intersections : 0);

  // The output stage starts here: the one rounding of the exact result, then the exact solution
  // freed (or left to the process's exit: see LineRunSettings).
  mark = std::chrono::steady_clock::now();
  exporter::LineDrawing drawing =
      exporter::make_drawing<K>(scene.input, frame, kind, solution->lines, solution->segments);
  if (settings.free_at_exit) (void)solution.release();  // not a leak: see LineRunSettings::free_at_exit
  else solution.reset();
  times.write = seconds_since(mark);
  drawing.crease_degrees = settings.crease;
  drawing.times = times;
  return drawing;
}

}  // namespace

void add_line_options(CLI::App& cmd, LineRunSettings& settings) {
  cmd.add_option("--crease", settings.crease, "an edge is a crease when its faces meet at more than DEG degrees")
      ->check(CLI::Range(0.0, 180.0))
      ->capture_default_str()
      ->type_name("DEG");
  cmd.add_flag_callback(
      "--no-intersections", [&settings] { settings.intersections = false; }, "leave out the lines where faces penetrate");
}

const std::vector<hidden_line::IntersectionSegment>& Intersections::segments() const {
  std::call_once(once_, [this] {
    if (!settings_.intersections) return;
    stage(settings_, "finding where faces penetrate");
    const auto start = std::chrono::steady_clock::now();
    segments_ = hidden_line::intersection_lines(scene_.meshes);
    seconds_ = seconds_since(start);
  });
  found_ = true;
  return segments_;
}

exporter::LineDrawing kernel_drawing(const SceneOptions& options, const Scene& scene, const View& view, KernelKind kind,
                                     const Intersections& intersections, const LineRunSettings& settings) {
  try {
    return with_kernel(kind, [&]<class K>(KernelKind k) { return solve<K>(scene, view, k, intersections, settings); });
  } catch (const clip::ClipError& e) {
    throw inexact_kernel_failure(options, kind, e);
  }
}

RasterRun raster_drawing(const Scene& scene, const View& view, int resolution, const Intersections& intersections,
                         const LineRunSettings& settings) {
  RasterRun run;
  exporter::StageTimes times;
  times.intersections = intersections.seconds();
  stage(settings, "Z-buffer at " + std::to_string(resolution) + " pixels");
  auto mark = std::chrono::steady_clock::now();
  hidden_line::RasterOptions raster;
  raster.resolution = resolution;
  run.raster = std::make_unique<hidden_line::RasterDrawing>(scene.meshes, view, intersections.segments(),
                                                            line_options(settings), raster);
  const double zbuffer = seconds_since(mark);
  mark = std::chrono::steady_clock::now();
  const hidden_line::LineSet<DoubleKernel> lines = run.raster->classify();
  times.lines = seconds_since(mark);
  times.total = times.intersections + zbuffer + times.lines;
  mark = std::chrono::steady_clock::now();
  run.drawing = exporter::make_raster_drawing(scene.input, *run.raster, lines, resolution);
  times.write = seconds_since(mark);
  run.drawing.crease_degrees = settings.crease;
  run.drawing.times = times;
  run.drawing.zbuffer_seconds = zbuffer;
  return run;
}

}  // namespace hlr::app
