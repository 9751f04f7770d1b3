// The hidden-surface job of a view (jobs.hpp), for each kernel. The stages themselves are
// instantiated in instantiate_<kernel>.cpp: this file only chains them.
#include <hlr/hidden_line/jobs.hpp>
#include <hlr/hidden_line/parallel.hpp>

namespace hlr::hidden_line {

const std::vector<IntersectionSegment>& SceneIntersections::segments() const {
  std::call_once(once_, [this] {
    if (!wanted_) return;
    progress_.report("finding where faces penetrate");
    const auto start = std::chrono::steady_clock::now();
    segments_ = intersection_lines(scene_.meshes, progress_.stop);
    seconds_ = seconds_since(start);
  });
  found_ = true;
  return segments_;
}

void SceneIntersections::release() { free_in_parallel(segments_); }

UserError inexact_kernel_failure(const Scene& scene, KernelKind kind, const std::exception& e) {
  return UserError(scene.input.files.empty() ? std::string("scene") : scene.input.files.front(),
                   std::string("the ") + kernel_name(kind) + " kernel failed on this view (" + e.what() +
                       "); the exact kernel does not");
}

template <class K>
ViewSolution<K> solve_view(const Scene& scene, const View& view, const SolveOptions& options) {
  ViewSolution<K> solution{ViewFrame<K>(view, scene.meshes), {}, {}, {}};
  const Progress& progress = options.progress;
  const auto start = std::chrono::steady_clock::now();
  try {
    progress.check();
    SourceOptions sources = options.sources;
    sources.stop = progress.stop;
    solution.sources = build_sources<K>(scene.meshes, solution.frame, sources);
    solution.times.sources = seconds_since(start);
    progress.check();
    progress.report("sorting " + std::to_string(solution.sources.polygons.size()) + " polygons");
    const auto mark = std::chrono::steady_clock::now();
    AreaSortOptions sort = options.sort;
    sort.stop = progress.stop;
    solution.map = area_sort<K>(solution.sources, sort);
    solution.times.sort = seconds_since(mark);
  } catch (const clip::ClipError& e) {
    if constexpr (Geometry<K>::exact_constructions) throw;
    else throw inexact_kernel_failure(scene, kernel_kind_of<K>(), e);
  }
  solution.times.total = seconds_since(start);
  return solution;
}

HLR_HIDDEN_LINE_JOBS_DECLARE(ExactKernel, )
HLR_HIDDEN_LINE_JOBS_DECLARE(EpickKernel, )
HLR_HIDDEN_LINE_JOBS_DECLARE(DoubleKernel, )

}  // namespace hlr::hidden_line
