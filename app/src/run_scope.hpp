// What every command's run sets up and ends with, in one place:
//
//   RunScope run(options.limits, options.threads);  // thread limit, --timeout, progress display
//   const Scene scene = run.read(options.meshes, options.cad);  // stage "reading 2 meshes"
//   job.progress = run.progress();
//   ...
//   run.finish(scene);  // the progress line ends, then the importer's warnings
//
// The limits hold for as long as the RunScope lives.
#pragma once

#include "interrupt.hpp"
#include "progress_display.hpp"
#include "scene_options.hpp"

#include <tbb/global_control.h>

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace hlr::app {

class RunScope {
 public:
  // threads: oneTBB's limit (0: every core); the output does not depend on it.
  explicit RunScope(const RunLimits& limits, int threads = 0);
  RunScope(const RunScope&) = delete;
  RunScope& operator=(const RunScope&) = delete;

  // Reads every mesh and CAD model as the stage "reading 1 <one>" or "reading N <many>"
  // (read_scene: throws ImportError, or UserError beyond --max-faces).
  Scene read(const std::vector<std::string>& paths, const cad::CadOptions& cad, std::string_view one = "mesh",
             std::string_view many = "meshes");

  exporter::Progress progress() { return display_.progress(); }
  void stage(std::string_view what) { display_.stage(what); }

  // The run succeeded: ends the progress line, then prints the warnings of the scene it read.
  void finish(const Scene* scene = nullptr);
  void finish(const Scene& scene) { finish(&scene); }

 private:
  std::unique_ptr<tbb::global_control> threads_;
  Deadline deadline_;
  ProgressDisplay display_;
  RunLimits limits_;
};

}  // namespace hlr::app
