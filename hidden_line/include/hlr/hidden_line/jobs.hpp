// hlr hidden_line, jobs: the library's entry points for one view, as the hlr program runs them.
//
//   solve_view          the hidden-surface solution of a view: sources, then the area sort, with
//                       the time of each stage (what `hlr surfaces` writes).
//   SceneIntersections  the penetration lines of a scene, found once and shared by every view of
//                       it (they live in model space); a line job finds them beside its polygon
//                       stages when a second thread is free.
//
// Every job takes a Progress: a line per stage for a progress display, and two ways to stop it
// (the job then throws hlr::Cancelled): a question asked between stages, and a StopToken that the
// long stages poll as they go. Line drawings and
// documents are export's jobs (export/jobs.hpp); they take the same Progress.
#pragma once

#include <hlr/hidden_line/lines.hpp>
#include <hlr/hidden_line/visibility.hpp>
#include <hlr/kernel/errors.hpp>
#include <hlr/kernel/scene.hpp>

#include <atomic>
#include <chrono>
#include <functional>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

namespace hlr::hidden_line {

struct Progress {
  std::function<void(std::string_view)> stage;  // "sorting 1200 polygons": a stage begins
  std::function<bool()> cancelled;              // asked between stages: true stops the job
  StopToken stop;                               // polled within the long stages too

  void report(const std::string& what) const {
    if (stage) stage(what);
  }
  void check() const {
    stop.check();
    if (cancelled && cancelled()) throw Cancelled();
  }
};

// Seconds per stage, reported in "stats".
struct StageTimes {
  double read = 0, sources = 0, sort = 0, total = 0;     // total: reading and solving, every stage but `write`
  double intersections = 0, lines = 0, precedence = 0;  // hlr draw: penetrations, classification, ISO 128 precedence
  // hlr draw: the output stage, from the end of precedence to the finished JSON document (rounding
  // the exact drawing, the sheet lines, the SVG, DXF and PNG, the JSON itself); see lines_json.
  double write = 0;
};

inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The penetration segments of a scene (empty when `wanted` is false) and the time they took.
// Found on the first call of segments(), from any thread, once.
class SceneIntersections {
 public:
  SceneIntersections(const Scene& scene, bool wanted, Progress progress = {})
      : scene_(scene), wanted_(wanted), progress_(std::move(progress)) {}
  const std::vector<IntersectionSegment>& segments() const;
  double seconds() const {
    segments();
    return seconds_;
  }
  bool found() const { return found_; }
  // Frees the segments, on every thread, when no view needs them any more: the owner's call, after
  // which segments() is empty. A line drawing has copied what it needs from them once its lines
  // are classified.
  void release();

 private:
  const Scene& scene_;
  bool wanted_;
  Progress progress_;
  mutable std::once_flag once_;
  mutable std::vector<IntersectionSegment> segments_;
  mutable double seconds_ = 0;
  mutable std::atomic<bool> found_ = false;
};

struct SolveOptions {
  SourceOptions sources;
  AreaSortOptions sort;
  Progress progress;
};

template <class K>
struct ViewSolution {
  ViewFrame<K> frame;
  Sources<K> sources;
  VisibilityMap<K> map;
  StageTimes times;  // sources, sort and total (without reading)
};

// Throws hlr::UserError naming the scene's first file when an inexact kernel contradicts itself
// (the exact kernel never does on valid input), and Cancelled.
template <class K>
ViewSolution<K> solve_view(const Scene& scene, const View& view, const SolveOptions& options = {});

// The error for a run whose inexact kernel contradicted itself.
UserError inexact_kernel_failure(const Scene& scene, KernelKind kind, const std::exception& e);

#define HLR_HIDDEN_LINE_JOBS_DECLARE(K, EXTERN) \
  EXTERN template ViewSolution<K> solve_view<K>(const Scene&, const View&, const SolveOptions&);

HLR_HIDDEN_LINE_JOBS_DECLARE(ExactKernel, extern)
HLR_HIDDEN_LINE_JOBS_DECLARE(EpickKernel, extern)
HLR_HIDDEN_LINE_JOBS_DECLARE(DoubleKernel, extern)

}  // namespace hlr::hidden_line
