// The line and surface jobs (jobs.hpp), for each kernel. The stages are instantiated in the
// modules' instantiate_<kernel>.cpp files: this file only chains them.
#include <hlr/export/jobs.hpp>
#include <hlr/hidden_line/parallel.hpp>

#include <tbb/global_control.h>
#include <tbb/task_group.h>

#include <memory>
#include <optional>
#include <stdexcept>

namespace hlr::exporter {
namespace {

hidden_line::LineOptions line_options(const DrawOptions& options) {
  hidden_line::LineOptions lines;
  lines.features.crease_degrees = options.crease;
  lines.features.smooth_edges = options.smooth_edges;
  lines.intersections = options.intersections;
  lines.stop = options.progress.stop;
  lines.free_at_exit = options.free_at_exit;
  return lines;
}

// Frees, on every thread, what only the line classification reads: the later stages need the
// vertices' image points alone.
template <class K>
void release_all_but_image_points(hidden_line::Sources<K>& sources) {
  hidden_line::free_in_parallel(sources.polygons);
  hidden_line::free_in_parallel(sources.lines);
  hidden_line::free_each_in_parallel(sources.view_points);
  hidden_line::Sources<K> rest;
  rest.image_points = std::move(sources.image_points);
  rest.stats = sources.stats;
  std::swap(rest, sources);
}

// With DrawOptions::free_at_exit, releases `owned` instead of freeing it however the scope is
// left: at the end of the job or by an exception (a stop, which freeing would delay by seconds).
template <class T>
struct LeftToExit {
  std::unique_ptr<T>& owned;
  bool enabled;
  ~LeftToExit() {
    if (enabled) (void)owned.release();  // not a leak: the process ends
  }
};

// The exact solution of a view: what the drawing is rounded from.
template <class K>
struct Solution {
  hidden_line::Sources<K> sources;
  hidden_line::VisibilityMap<K> map;
  hidden_line::LineSet<K> lines;
  std::vector<hidden_line::DrawnSegment<K>> segments;
};

// The exact solution freed on every thread: lazy numbers by the million, half a second on one
// thread at 1M faces, with the other idle.
template <class K>
void free_in_parallel(std::unique_ptr<Solution<K>>& solution) {
  hidden_line::free_in_parallel(solution->lines.lines);
  release_all_but_image_points(solution->sources);  // already done after the lines stage, unless sorted
  hidden_line::free_each_in_parallel(solution->sources.image_points);
  solution.reset();
}

template <class K>
LineDrawing solve(const Scene& scene, const View& view, const SceneIntersections& intersections,
                  SceneIntersections* own_intersections, const DrawOptions& options) {
  using hidden_line::seconds_since;
  const Progress& progress = options.progress;
  const ViewFrame<K> frame(view, scene.meshes);
  StageTimes times;
  auto solution = std::make_unique<Solution<K>>();
  const LeftToExit<Solution<K>> left_to_exit{solution, options.free_at_exit};
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
  // A stop asked for while the intersections are found beside waits for them: the task group
  // must not be destroyed while its task runs.
  auto check = [&] {
    try {
      progress.check();
    } catch (const Cancelled&) {
      if (beside) beside->wait();
      throw;
    }
  };
  check();
  auto mark = std::chrono::steady_clock::now();
  progress.report(std::to_string(scene.input.faces) + " faces; building polygons (" +
                  kernel_name(kernel_kind_of<K>()) + ")");
  // The lines need no area sort (classify_lines against the sources); shadows cast into the
  // view are cut to the visible polygons, so they do.
  const bool sorted = !options.shadow_lights.empty();
  hidden_line::SourceOptions sources;
  sources.stop = progress.stop;
  sources.line_origins = sorted;
  if constexpr (std::is_same_v<K, ExactKernel>) {
    sources.culled = options.culled_faces;
    sources.depth_planes = sorted || frame.perspective();  // else decided in model space
  }
  solution->sources = hidden_line::build_sources<K>(scene.meshes, frame, sources);
  times.sources = seconds_since(mark);
  check();
  if (sorted) {
    progress.report("sorting " + std::to_string(solution->sources.polygons.size()) + " polygons");
    mark = std::chrono::steady_clock::now();
    solution->map = hidden_line::area_sort<K>(solution->sources, {.keep_hidden = false, .stop = progress.stop});
    times.sort = seconds_since(mark);
  }
  if (beside) {
    beside->wait();
    if (options.lines_stage_begins) options.lines_stage_begins();
  }
  times.intersections = intersections.seconds();
  check();
  progress.report("classifying feature lines");
  mark = std::chrono::steady_clock::now();
  solution->lines = sorted ? hidden_line::classify_lines<K>(scene.meshes, frame, solution->sources, solution->map,
                                                            intersections.segments(), line_options(options))
                           : hidden_line::classify_lines<K>(scene.meshes, frame, solution->sources,
                                                            intersections.segments(), line_options(options));
  // What the later stages do not read is freed (its cost in the lines stage): they grow into pages
  // already touched, which costs less than fresh ones, and the peak is lower.
  if (!sorted) release_all_but_image_points(solution->sources);
  if (own_intersections) own_intersections->release();
  if (options.output_stage_begins) options.output_stage_begins();
  times.lines = seconds_since(mark);
  check();
  progress.report("drawing coincident pieces once (ISO 128 precedence)");
  mark = std::chrono::steady_clock::now();
  solution->segments = hidden_line::drawing_segments<K>(solution->lines, progress.stop, &solution->sources.image_points);
  times.precedence = seconds_since(mark);
  std::vector<DrawingArea> shadows;
  // Shadow polygons are projected into the view without a near plane: orthographic views only.
  if (!options.shadow_lights.empty() && frame.perspective())
    throw std::invalid_argument("shadows in a perspective drawing are not supported yet");
  if (!options.shadow_lights.empty()) {
    if constexpr (std::is_same_v<K, ExactKernel>) {
      check();
      progress.report("shadows of " + std::to_string(options.shadow_lights.size()) + " light(s)");
      hidden_line::ShadowOptions shadow_options;
      shadow_options.light_views = false;
      std::optional<hidden_line::ShadowResult> own;
      if (!options.shadows) own = hidden_line::cast_shadows(scene, options.shadow_lights, shadow_options);
      const hidden_line::ShadowResult& result = options.shadows ? *options.shadows : *own;
      auto rounded = [&](const clip::Contour<K>& c) {
        std::vector<std::array<double, 2>> points;
        for (const auto& q : c.points) points.push_back({frame.rounded(q, 0), frame.rounded(q, 1)});
        return points;
      };
      for (const auto& piece : hidden_line::shadows_in_view(result, frame, solution->sources, solution->map)) {
        DrawingArea& area = shadows.emplace_back();
        area.outer = rounded(piece.outer);
        for (const auto& h : piece.holes) area.holes.push_back(rounded(h));
      }
    } else {
      throw std::invalid_argument("shadows in a drawing need the exact kernel");
    }
  }
  // The stages' own times overlap where the intersections were found beside the polygons.
  times.total = seconds_since(begin) + (found_before ? times.intersections : 0);

  // The output stage starts here: the one rounding of the exact result, then the exact solution
  // freed (or left to the process's exit: see DrawOptions::free_at_exit).
  mark = std::chrono::steady_clock::now();
  LineDrawing drawing =
      make_drawing<K>(scene.input, frame, kernel_kind_of<K>(), solution->lines, std::move(solution->segments), progress.stop);
  if (options.drawing_rounded) options.drawing_rounded();
  if (!options.free_at_exit || options.free_once_drawn) free_in_parallel(solution);
  attach_source_curves(drawing, scene.meshes);
  times.write = seconds_since(mark);
  drawing.crease_degrees = options.crease;
  drawing.times = times;
  drawing.shadows = std::move(shadows);
  return drawing;
}

// `shared`, or the scene's own intersections in `own`.
const SceneIntersections& intersections_of(const Scene& scene, const DrawOptions& options,
                                           const SceneIntersections* shared, std::unique_ptr<SceneIntersections>& own) {
  if (shared) return *shared;
  own = std::make_unique<SceneIntersections>(scene, options.intersections, options.progress);
  return *own;
}

}  // namespace

LineDrawing draw_lines(const Scene& scene, const View& view, const DrawOptions& options,
                       const SceneIntersections* shared) {
  std::unique_ptr<SceneIntersections> own;
  const LeftToExit<SceneIntersections> left_to_exit{own, options.free_at_exit};
  const SceneIntersections& intersections = intersections_of(scene, options, shared, own);
  try {
    return with_kernel(options.kernel,
                       [&]<class K>(KernelKind) { return solve<K>(scene, view, intersections, own.get(), options); });
  } catch (const clip::ClipError& e) {
    if (options.kernel == KernelKind::exact) throw;
    throw hidden_line::inexact_kernel_failure(scene, options.kernel, e);
  }
}

RasterRun draw_raster(const Scene& scene, const View& view, int resolution, const DrawOptions& options,
                      const SceneIntersections* shared) {
  hidden_line::RasterOptions raster;
  raster.resolution = resolution;
  return draw_raster(scene, view, raster, options, shared);
}

RasterRun draw_raster(const Scene& scene, const View& view, const hidden_line::RasterOptions& raster,
                      const DrawOptions& options, const SceneIntersections* shared) {
  const int resolution = raster.resolution;
  using hidden_line::seconds_since;
  std::unique_ptr<SceneIntersections> own;
  const SceneIntersections& intersections = intersections_of(scene, options, shared, own);
  RasterRun run;
  StageTimes times;
  times.intersections = intersections.seconds();
  options.progress.check();
  options.progress.report("Z-buffer at " + std::to_string(resolution) + " pixels");
  auto mark = std::chrono::steady_clock::now();
  run.raster = std::make_unique<hidden_line::RasterDrawing>(scene.meshes, view, intersections.segments(),
                                                            line_options(options), raster);
  const double zbuffer = seconds_since(mark);
  options.progress.check();
  mark = std::chrono::steady_clock::now();
  const hidden_line::LineSet<DoubleKernel> lines = run.raster->classify();
  times.lines = seconds_since(mark);
  times.total = times.intersections + zbuffer + times.lines;
  mark = std::chrono::steady_clock::now();
  run.drawing = make_raster_drawing(scene.input, *run.raster, lines, resolution);
  times.write = seconds_since(mark);
  run.drawing.crease_degrees = options.crease;
  run.drawing.times = times;
  run.drawing.zbuffer_seconds = zbuffer;
  return run;
}

// ---- surfaces -------------------------------------------------------------------------------

struct SurfacesSolution::Impl {
  virtual ~Impl() = default;
  virtual std::vector<std::string> json(bool exact, double written_before) const = 0;
  virtual std::string svg() const = 0;
  Summary summary;
  StageTimes times;
  KernelKind kernel = KernelKind::exact;
};

namespace {

template <class K>
struct SurfacesImpl final : SurfacesSolution::Impl {
  SurfacesImpl(const Scene& scene, hidden_line::ViewSolution<K> solved) : scene(scene), solution(std::move(solved)) {}
  SurfacesDocument<K> document() const {
    return {scene.input, scene.meshes, solution.frame, solution.sources, solution.map, kernel, times};
  }
  std::vector<std::string> json(bool exact, double written_before) const override {
    SurfacesDocument<K> doc = document();
    doc.times.write = written_before;
    return surfaces_json(doc, exact);
  }
  std::string svg() const override { return surfaces_svg(document()); }
  const Scene& scene;
  hidden_line::ViewSolution<K> solution;
};

}  // namespace

std::string SurfacesSolution::json(bool exact, double written_before) const {
  const std::vector<std::string> parts = impl_->json(exact, written_before);
  std::size_t size = 0;
  for (const std::string& part : parts) size += part.size();
  std::string text;
  text.reserve(size);
  for (const std::string& part : parts) text += part;
  return text;
}
void SurfacesSolution::write_json(bool exact, double written_before,
                                  const std::function<void(std::string_view)>& sink) const {
  for (const std::string& part : impl_->json(exact, written_before)) sink(part);
}
std::string SurfacesSolution::svg() const { return impl_->svg(); }
const SurfacesSolution::Summary& SurfacesSolution::summary() const { return impl_->summary; }
const StageTimes& SurfacesSolution::times() const { return impl_->times; }
KernelKind SurfacesSolution::kernel() const { return impl_->kernel; }

SurfacesSolution solve_surfaces(const Scene& scene, const View& view, const SurfacesOptions& options,
                                double read_seconds) {
  return with_kernel(options.kernel, [&]<class K>(KernelKind kind) {
    options.progress.report(std::to_string(scene.input.faces) + " faces read; building polygons");
    hidden_line::SolveOptions solve;
    solve.sources = options.sources;
    solve.progress = options.progress;
    auto impl = std::make_shared<SurfacesImpl<K>>(scene, hidden_line::solve_view<K>(scene, view, solve));
    impl->kernel = kind;
    impl->times = impl->solution.times;
    impl->times.read = read_seconds;
    impl->times.total += read_seconds;
    impl->summary = {impl->solution.sources.stats, impl->solution.map.stats, impl->solution.map.visible.size(),
                     impl->solution.map.hidden.size()};
    return SurfacesSolution(std::move(impl));
  });
}

}  // namespace hlr::exporter
