#include "run_scope.hpp"

namespace hlr::app {

RunScope::RunScope(const RunLimits& limits, int threads)
    : threads_(threads > 0 ? std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                                   static_cast<std::size_t>(threads))
                           : nullptr),
      deadline_(limits.timeout),
      display_(ProgressDisplay::mode_for(limits.progress)),
      limits_(limits) {}

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
