#include "run_scope.hpp"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

namespace hlr::app {

RunScope::RunScope(const RunLimits& limits, int threads)
    : threads_(threads > 0 ? std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                                   static_cast<std::size_t>(threads))
                           : nullptr),
      deadline_(limits.timeout),
      display_(ProgressDisplay::mode_for(limits.progress)),
      limits_(limits) {
  // The pool's workers start with the run, not inside the first stage that asks for them: like
  // TBB's other one-time set-up, it is the process starting, the same for every drawing.
  if (tbb::this_task_arena::max_concurrency() > 1) tbb::parallel_for(0, 64, [](int) {});
}

Scene RunScope::read(const std::vector<std::string>& paths, const cad::CadOptions& cad, std::string_view one,
                     std::string_view many) {
  display_.stage("reading " + std::to_string(paths.size()) + " " + std::string(paths.size() == 1 ? one : many));
  return read_scene(paths, limits_, cad);
}

void RunScope::finish(const Scene* scene) {
  display_.stage("");
  if (scene) print_warnings(*scene);
}

}  // namespace hlr::app
